/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "cloudRecord.H"
#include "writtenTimes.H"
#include "PstreamReduceOps.H"
#include "OSspecific.H"
#include "stringOps.H"
#include "cloud.H"
#include "IFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cloudRecord::refuseMissingFields
(
    const Time& time,
    const word& cloudName,
    const string& missing
)
{
    const fileName cloudDir(time.timeName()/cloud::prefix/cloudName);
    const bool decomposedToo =
        isDir(time.globalPath()/"processor0"/time.timeName());
    // (collective in parallel, where a processor may stop here alone)
    const word last
    (
        Pstream::parRun()
      ? word::null
      : writtenTimes::lastComplete(time.path(), time.value(), cloudName)
    );
    FatalIOErrorInFunction(time.controlDict())
        << "The restart time " << time.timeName() << " (startFrom/startTime"
        << " in " << time.controlDict().name() << ") has the parcels of"
        << " cloud " << cloudName << " but not all their fields: "
        << stringOps::trim(missing).c_str() << nl;
    if (decomposedToo && !Pstream::parRun())
    {
        FatalIOError
            << "    The time was reconstructed from processor0/"
            << time.timeName() << " ...: reconstructPar without a"
            << " lagrangian field selection leaves out the contact"
            << " histories (contactKeys, contactXi). Run reconstructPar"
            << " -time " << time.timeName() << " -lagrangianFields"
            << " '(\".*\")', or restart in parallel from the processor"
            << " directories";
    }
    else
    {
        FatalIOError
            << "    The cloud's files in " << cloudDir << " were deleted or"
            << " not copied (every field a run writes is needed)";
        if (last.size())
        {
            FatalIOError
                << "; restore them, or restart from " << last
                << " (startFrom startTime; startTime " << last << ";)";
        }
    }
    FatalIOError<< exit(FatalIOError);
}


void Foam::cloudRecord::checkState
(
    const IOdictionary& outputProperties,
    const dictionary& demDict,
    const Time& time,
    const word& cloudName,
    const label nParcels
)
{
    // Parcels without the state written with them (uniform/ deleted or
    // not copied): the models, the type table and the ids issued are
    // unknown, and nothing below could be checked
    const bool stateMissing = !outputProperties.found("dpiCloud");
    if (nParcels && returnReduce(stateMissing, orOp<bool>()))
    {
        const word last
        (
            writtenTimes::lastComplete(time.path(), time.value(), cloudName)
        );
        FatalIOErrorInFunction(outputProperties)
            << "Time " << time.timeName() << " has " << nParcels
            << " parcels of cloud " << cloudName << " but not the cloud"
            << " state written with them ("
            << outputProperties.objectPath() << " is missing)."
            << nl << "    Without it the models, the type table and the"
            << " ids issued are unknown and a restart cannot be checked."
            << " Restore " << time.timeName() << "/uniform (written with"
            << " every time; decomposePar and reconstructPar copy it)";
        if (last.size())
        {
            FatalIOError<< " or restart from " << last;
        }
        FatalIOError<< "." << exit(FatalIOError);
    }

    // A restart may change material and model coefficients, not the
    // choice of models: the state written (histories, forces) belongs to
    // the models that wrote it
    const dictionary written
    (
        outputProperties.subOrEmptyDict("dpiCloud").subOrEmptyDict("models")
    );
    for (const word& key : written.toc())
    {
        const word before(written.get<word>(key));
        const word now(demDict.get<word>(key));
        if (before != now)
        {
            FatalIOErrorInFunction(demDict)
                << "Restart with " << key << " " << now << " in dictionary "
                << demDict.name() << ", but the state at time "
                << time.timeName() << " was written with "
                << key << " " << before << "." << nl
                << "    A restart may change the models' coefficients, not"
                << " the models: set " << key << " " << before << ";"
                << exit(FatalIOError);
        }
    }
}


void Foam::cloudRecord::checkCloudPresent
(
    const IOdictionary& outputProperties,
    const dictionary& cloudDict,
    const Time& time,
    const word& cloudName,
    const label nParcels,
    const label nIssued,
    const label nGone,
    const bool injectors
)
{
    // A start time without parcels is legitimate (injection ahead, or the
    // gas alone), unless the state written with that time says parcels were
    // issued and did not all leave: then the cloud was not written or not
    // reconstructed, and going on would silently run without the powder
    if (nParcels > 0)
    {
        return;
    }

    const word cloudDir(time.timeName()/cloud::prefix/cloudName);
    if (nIssued > nGone)
    {
        // Never advise going on without the cloud: name the latest time
        // that has it (a parallel run's times may need reconstructing)
        const word last
        (
            writtenTimes::lastComplete(time.path(), time.value(), cloudName)
        );
        // OpenFOAM reads the parcels from the one file that 'geometry' in
        // the time's cloudProperties names (coordinates since v1706): say
        // which, and whether the other is there (a file lost or renamed)
        const fileName propsPath
        (
            time.path()/time.timeName()/"uniform"/cloud::prefix/cloudName
           /"cloudProperties"
        );
        word geometry("coordinates");
        if (isFile(propsPath))
        {
            IFstream is(propsPath);
            geometry =
                dictionary(is).getOrDefault<word>("geometry", "positions");
        }
        const word other(geometry == "positions" ? "coordinates" : "positions");
        const fileName readFile(time.path()/cloudDir/geometry);
        std::string why
        (
            isFile(readFile) || isFile(readFile + ".gz")
          ? "is empty"
          : "is missing"
        );
        if (isFile(time.path()/cloudDir/other))
        {
            why += "; " + other + " is there, but OpenFOAM reads the parcels"
                " from " + geometry + " ('geometry " + geometry + "' in "
              + time.timeName() + "/uniform/" + cloud::prefix + "/"
              + cloudName + "/cloudProperties)";
        }
        FatalIOErrorInFunction(outputProperties)
            << "Time " << time.timeName() << " has no parcels of"
            << " cloud " << cloudName << " (" << (cloudDir/geometry).c_str() << " "
            << why.c_str() << "), but the cloud state in "
            << outputProperties.objectPath() << " says " << nIssued
            << " parcels were issued and " << nGone << " left the domain."
            << nl << "    Restart from a time written with the cloud";
        if (last.size())
        {
            FatalIOError
                << ": the latest before this one is " << last
                << " (startFrom startTime; startTime " << last << ";)";
        }
        FatalIOError
            << ". After a parallel run, reconstructPar -lagrangianFields"
            << " '(\".*\")' writes the cloud into the case's times."
            << exit(FatalIOError);
    }

    if (!injectors)
    {
        WarningInFunction
            << "No parcels at time " << time.timeName()
            << " (" << cloudDir << " is empty or missing) and no injectors in "
            << cloudDict.name()
            << ": the cloud stays empty" << endl;
    }
}


Foam::dictionary Foam::cloudRecord::models(const dictionary& demDict)
{
    dictionary models;
    for
    (
        const word key
      : {"normalModel", "tangentialModel", "rollingModel", "cohesionModel"}
    )
    {
        models.add(key, demDict.get<word>(key));
    }
    return models;
}


// ************************************************************************* //
