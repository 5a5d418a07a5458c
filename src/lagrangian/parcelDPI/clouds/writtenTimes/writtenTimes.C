/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "writtenTimes.H"
#include "Time.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "HashSet.H"
#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
    // Every file under dir (recursively), relative to dir
    static void listFiles
    (
        const fileName& dir,
        const fileName& rel,
        DynamicList<fileName>& files
    )
    {
        for (const fileName& f : readDir(dir/rel, fileName::FILE, false))
        {
            files.append(rel.empty() ? f : rel/f);
        }
        for (const fileName& d : readDir(dir/rel, fileName::DIRECTORY, false))
        {
            listFiles(dir, rel.empty() ? d : rel/d, files);
        }
    }

    // Does the text end as a complete file: with OpenFOAM's end divider
    // "// ****...**** //", or (not strict) with the closing brace of its
    // last dictionary, as a hand-written field copied into a time may
    static bool endsCompletely(std::string text, const bool strict)
    {
        const auto last = text.find_last_not_of(" \t\r\n");
        if (last == std::string::npos)
        {
            return false;
        }
        text.resize(last + 1);
        if (!strict && text.back() == '}')
        {
            return true;
        }
        static const std::string tail("******** //");
        const auto start = text.rfind("// ****");
        return
            start != std::string::npos
         && text.size() >= tail.size()
         && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
    }

    // The last bytes of a plain file, or the last lines of a compressed one
    static std::string fileTail(const fileName& path, const off_t size)
    {
        if (path.hasExt("gz"))
        {
            // IFstream decompresses when given the name without .gz
            IFstream is(path.lessExt());
            std::string tail;
            string line;
            while (is.good())
            {
                is.getLine(line);
                if (line.find_first_not_of(" \t\r\n") != std::string::npos)
                {
                    tail = line;
                }
            }
            return tail;
        }

        std::ifstream is(path, std::ios::binary);
        const off_t n = min(size, off_t(256));
        is.seekg(size - n);
        std::string tail(n, '\0');
        is.read(&tail[0], n);
        tail.resize(is.gcount());
        return tail;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::instantList Foam::writtenTimes::times(const fileName& casePath)
{
    // findTimes lists 'constant' first (as time 0): not a time
    DynamicList<instant> ts;
    for (const instant& t : Time::findTimes(casePath, "constant"))
    {
        if (t.name() != "constant")
        {
            ts.append(t);
        }
    }
    return instantList(std::move(ts));
}


Foam::dictionary Foam::writtenTimes::controlDict(const fileName& casePath)
{
    // The global case's controlDict (a processor case has none of its own)
    const fileName path
    (
        (Pstream::parRun() ? casePath.path() : casePath)/"system/controlDict"
    );
    if (!isFile(path))
    {
        return dictionary();    // Time says what is wrong
    }
    IFstream is(path);
    return dictionary(is);
}


Foam::word Foam::writtenTimes::startTimeName(const fileName& casePath)
{
    const dictionary dict(controlDict(casePath));
    const instantList ts(times(casePath));
    if (dict.empty() || ts.empty())
    {
        return word::null;      // nothing to check: Time says what is wrong
    }

    const word startFrom(dict.getOrDefault<word>("startFrom", "startTime"));

    if (startFrom == "latestTime")
    {
        return ts.last().name();
    }
    if (startFrom == "firstTime")
    {
        return ts.first().name();
    }

    const scalar startTime = dict.getOrDefault<scalar>("startTime", 0);
    for (const instant& t : ts)
    {
        if (t.equal(startTime))
        {
            return t.name();
        }
    }
    return word::null;
}


void Foam::writtenTimes::checkStartWritten(const fileName& casePath)
{
    const dictionary dict(controlDict(casePath));
    const instantList ts(times(casePath));
    const word startFrom(dict.getOrDefault<word>("startFrom", "startTime"));
    if (dict.empty() || startFrom == "firstTime" || startFrom == "noTime")
    {
        return;     // nothing written can come before the first time
    }
    if (startFrom == "latestTime" && ts.empty())
    {
        return;     // Time says what is wrong
    }
    const scalar startTime =
    (
        startFrom == "latestTime"
      ? ts.last().value()
      : dict.getOrDefault<scalar>("startTime", 0)
    );

    // The times a run wrote (Time writes uniform/time with each), and the
    // latest of them before the start. A start time that a run did not
    // write (never written, or a directory without uniform/time: made by
    // hand, left empty by a killed run or a stray mkdir), after such a
    // time, starts with no parcels and no cloud state, and writes its own
    // times among the old run's: refused
    DynamicList<word> runTimes;
    word before;
    bool found = false;     // the start time's directory is there
    bool written = false;   // and a run wrote it: checkStart looks at it
    fileNameList startFiles;
    for (const instant& t : ts)
    {
        const fileName dir(casePath/t.name()/"uniform");
        const bool runOutput = isFile(dir/"time") || isFile(dir/"time.gz");
        if (t.equal(startTime))
        {
            found = true;
            written = runOutput;
            DynamicList<fileName> files;
            listFiles(casePath/t.name(), fileName::null, files);
            startFiles = std::move(files);
        }
        if (runOutput)
        {
            runTimes.append(t.name());
            if (t.value() < startTime)
            {
                before = t.name();
            }
        }
    }

    // Processor directories hold the same times: the master's decision,
    // taken by all (no processor leaves before the others)
    wordList runWritten(std::move(runTimes));
    Pstream::scatter(found);
    Pstream::scatter(written);
    Pstream::scatter(startFiles);
    Pstream::scatter(before);
    Pstream::scatter(runWritten);
    if (written || before.empty())
    {
        return;     // a run's output, or a fresh start: no run wrote before
    }
    if (!Pstream::master())
    {
        Pstream::exit(1);
    }
    const word startName(Time::timeName(startTime));
    FatalIOErrorInFunction(dict)
        << "Time " << startName << ", where this run would start (startFrom "
        << startFrom << " in " << dict.name() << "), ";
    if (!found)
    {
        FatalIOError<< "is not a written time of this case";
    }
    else
    {
        FatalIOError
            << "was not written by a run (no uniform/time; "
            << (
                   startFiles.empty()
                 ? word("the directory is empty")
                 : word(Foam::name(startFiles.size()) + (startFiles.size() == 1 ? " file" : " files"))
               )
            << ")";
    }
    FatalIOError
        << ": the run would start with no parcels and no cloud state, after"
        << " the times a run wrote up to " << runWritten.last() << "." << nl
        << "    ";
    if (found)
    {
        FatalIOError
            << "Remove it (rm -r " << startName << ") to go on from "
            << runWritten.last() << ", or set 'startFrom startTime;"
            << " startTime " << before << ";'. Written:";
    }
    else
    {
        FatalIOError
            << "Set startTime to a written time (the latest before "
            << startName << " is " << before << "; written:";
    }
    for (const word& t : runWritten)
    {
        FatalIOError<< ' ' << t;
    }
    FatalIOError
        << (found ? "." : ") or startFrom latestTime")
        << " To start again from the initial conditions, remove the"
        << " written times first." << exit(FatalIOError);
}


Foam::wordList Foam::writtenTimes::completeTimes
(
    const fileName& casePath,
    const word& cloudName
)
{
    DynamicList<word> names;
    for (const instant& t : times(casePath))
    {
        const fileName dir(casePath/t.name());
        if (!incompleteFiles(dir).empty())
        {
            continue;
        }
        if (cloudName.size())
        {
            const fileName cloudDir(dir/"lagrangian"/cloudName);
            bool found = false;
            for (const word f : {"coordinates", "positions"})
            {
                found = found || isFile(cloudDir/f) || isFile(cloudDir/f + ".gz");
            }
            if (!found)
            {
                continue;
            }
        }
        names.append(t.name());
    }
    return wordList(std::move(names));
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::stringList Foam::writtenTimes::incompleteFiles(const fileName& timeDir)
{
    DynamicList<string> problems;
    if (!isDir(timeDir))
    {
        return stringList();
    }

    // Time writes uniform/time first: its presence marks a run's output,
    // which always closes each file with the end divider
    const bool runOutput =
        isFile(timeDir/"uniform/time") || isFile(timeDir/"uniform/time.gz");

    DynamicList<fileName> files;
    listFiles(timeDir, fileName::null, files);
    for (const fileName& rel : files)
    {
        const fileName path(timeDir/rel);
        const off_t size = fileSize(path);
        if (size <= 0)
        {
            problems.append(rel + ": empty");
        }
        else if (runOutput)
        {
            // The cloud and the uniform state only the run writes (with the
            // divider); gas fields may be hand-written files copied in
            const bool strict =
                rel.starts_with("lagrangian/") || rel.starts_with("uniform/");
            if (!endsCompletely(fileTail(path, size), strict))
            {
                problems.append(rel + ": cut short (no end divider)");
            }
        }
    }
    return stringList(std::move(problems));
}


Foam::word Foam::writtenTimes::lastComplete
(
    const fileName& casePath,
    const scalar before,
    const word& cloudName
)
{
    // Each processor's complete times; the master keeps those complete on
    // all of them (processor directories hold the same time names)
    List<wordList> complete(Pstream::nProcs());
    complete[Pstream::myProcNo()] = completeTimes(casePath, cloudName);
    Pstream::gatherList(complete);

    word last;
    if (Pstream::master())
    {
        wordHashSet common(complete[0]);
        for (label proci = 1; proci < complete.size(); ++proci)
        {
            common &= wordHashSet(complete[proci]);
        }
        scalar lastValue = -GREAT;
        for (const word& name : common)
        {
            const scalar value = readScalar(name);
            if (value < before - SMALL && value > lastValue)
            {
                lastValue = value;
                last = name;
            }
        }
    }
    Pstream::scatter(last);
    return last;
}


void Foam::writtenTimes::checkStart(const argList& args)
{
    const fileName casePath(args.path());
    checkStartWritten(casePath);
    const word start(startTimeName(casePath));

    stringList problems;
    if (start.size())
    {
        problems = incompleteFiles(casePath/start);
        // Named as the user sees them from the case (plain strings: the
        // reasons are not valid file names)
        const string prefix
        (
            Pstream::parRun()
          ? "processor" + Foam::name(Pstream::myProcNo()) + "/" + start + "/"
          : start + "/"
        );
        for (string& p : problems)
        {
            p = prefix + p;
        }
    }

    List<stringList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = problems;
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    label nProblems = 0;
    for (const stringList& p : all)
    {
        nProblems += p.size();
    }
    if (!nProblems)
    {
        return;
    }

    const word last(lastComplete(casePath, readScalar(start)));

    // Every processor knows; the master alone says it (once in the log)
    if (!Pstream::master())
    {
        Pstream::exit(1);
    }

    // Time is not constructed yet: FatalError, not FatalIOError
    FatalErrorInFunction
        << "Time " << start << ", where this run would start (system/"
        << "controlDict startFrom/startTime), was not completely written:"
        << " the run that wrote it was probably stopped while writing it."
        << nl;
    label shown = 0;
    for (const stringList& p : all)
    {
        for (const string& s : p)
        {
            if (shown++ < 10)
            {
                FatalError<< "    " << s.c_str() << nl;
            }
        }
    }
    if (nProblems > 10)
    {
        FatalError<< "    ... and " << nProblems - 10 << " more" << nl;
    }
    if (last.size())
    {
        FatalError
            << "The last complete time is " << last << ". To go on from it,"
            << " remove the incomplete time (rm -r " << start
            << (Pstream::parRun() ? " processor*/" + start : std::string()).c_str()
            << ") or set 'startFrom startTime; startTime " << last << ";'"
            << " in system/controlDict.";
    }
    else
    {
        FatalError
            << "No earlier time is complete: the run can only start again"
            << " from its initial conditions.";
    }
    FatalError<< exit(FatalError);
}


// ************************************************************************* //
