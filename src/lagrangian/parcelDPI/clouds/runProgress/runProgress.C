/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include "OSspecific.H"
#include <ctime>
#include <cstdio>

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * //

namespace
{
    // A line when this much more of the run is done, or this much wall
    // clock has passed: about a hundred lines a run, one a minute at most
    // apart in a slow one
    const Foam::scalar shareStep = 0.01;
    const Foam::scalar wallStep = 60;
}


// * * * * * * * * * * * * * * Private Member Functions * * * * * * * * * * //

Foam::scalar Foam::runProgress::since(const clock::time_point& t)
{
    return std::chrono::duration<double>(clock::now() - t).count();
}


std::string Foam::runProgress::duration(const scalar seconds)
{
    const long s = long(seconds + 0.5);
    char buf[64];
    if (s >= 3600)
    {
        std::snprintf(buf, sizeof buf, "%ld h %ld min", s/3600, (s % 3600)/60);
    }
    else if (s >= 60)
    {
        std::snprintf(buf, sizeof buf, "%ld min %ld s", s/60, s % 60);
    }
    else
    {
        std::snprintf(buf, sizeof buf, "%ld s", s);
    }
    return buf;
}


void Foam::runProgress::write
(
    const scalar share,
    const scalar wall,
    const bool atEnd
)
{
    const scalar t = runTime_.value();
    const scalar tEnd = runTime_.endTime().value();

    // The pace so far; the rest of the run at that pace
    const scalar pace = wall > 0 ? (t - t0_)/wall : 0;     // s per s
    const scalar left = share > 0 ? wall*(1 - share)/share : 0;

    const std::time_t endsAt = std::time(nullptr) + std::time_t(left);
    char when[32];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&endsAt));

    // Rounded as a person reads them (the series keeps every digit)
    char numbers[64];
    std::snprintf
    (
        numbers, sizeof numbers, "%.1f %% of the run to endTime", 100*share
    );
    char paceText[32];
    std::snprintf(paceText, sizeof paceText, "%.3g", pace*1e3*3600);
    Info<< "Progress: t = " << runTime_.timeName() << " s, " << numbers
        << ' ' << Time::timeName(tEnd) << " s; " << paceText
        << " ms per wall hour; ";
    if (!atEnd)
    {
        Info<< "ends in about " << duration(left).c_str() << " (at "
            << when << ")" << endl;
    }
    else
    {
        Info<< "done in " << duration(wall).c_str() << endl;
    }

    if (file_.valid())
    {
        file_()
            << t << tab << share << tab << wall << tab << pace*1e3*3600
            << tab << left << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runProgress::runProgress(const Time& runTime)
:
    runTime_(runTime),
    t0_(runTime.value()),
    wall0_(clock::now()),
    started_(false),
    lastShare_(0),
    lastWall_(clock::now()),
    file_()
{
    if (Pstream::master())
    {
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/"progress"
           /runTime.timeName()
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"progress.dat"));
        file_()
            << "# Progress of the run from " << runTime.timeName()
            << " s to endTime " << Time::timeName(runTime.endTime().value())
            << " s (runProgress)" << nl
            << "# time [s]\tshare of the run\twall clock since the first"
            << " step [s]\tpace [simulated ms per wall hour]\t"
            << "estimated wall clock left [s]" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::runProgress::start()
{
    if (!started_)
    {
        started_ = true;
        wall0_ = clock::now();
        lastWall_ = wall0_;
    }
}


void Foam::runProgress::update()
{
    const scalar span = runTime_.endTime().value() - t0_;
    if (!(span > 0))
    {
        return;
    }
    const scalar share = min(max((runTime_.value() - t0_)/span, 0), 1);
    const bool atEnd =
        runTime_.value() > runTime_.endTime().value() - 0.5*runTime_.deltaTValue();

    // The wall clock is the master's: every process writes or not alike
    // (Info prints on the master; the decision needs no communication as
    // only the master's output is seen)
    if
    (
        atEnd
     || share - lastShare_ >= shareStep - SMALL
     || since(lastWall_) >= wallStep
    )
    {
        write(share, since(wall0_), atEnd);
        lastShare_ = share;
        lastWall_ = clock::now();
    }
}


// ************************************************************************* //
