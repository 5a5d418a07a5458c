/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demReports.H"
#include "OSspecific.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demReports::demReports
(
    const demEngine& engine,
    const fileName& dir,
    const word& startTime
)
:
    engine_(engine),
    diagFile_(nullptr),
    perfFile_(nullptr),
    statsFile_(nullptr),
    balance_(dir/"parcelBalance"/startTime)
{
    if (Pstream::master())
    {
        // postProcessing/<cloud>/<name>/<startTime>/<name>.dat
        auto open = [&](const word& name, const label digits)
        {
            const fileName series(dir/name/startTime);
            mkDir(series);
            autoPtr<OFstream> file(new OFstream(series/(name + ".dat")));
            file().precision(digits);
            return file;
        };

        diagFile_ = open("demDiagnostics", 10);
        diagFile_()
            << "# DEM diagnostics at the end of every fluid step" << nl
            << "# time kineticEnergy[J] rotationalEnergy[J] nPairContacts"
            << " nWallContacts maxOverlap/R* nParcels" << nl;

        perfFile_ = open("demPerformance", 8);
        perfFile_()
            << "# DEM cost on the master processor at the end of every"
            << " fluid step: wall-clock seconds since this run started,"
            << " summed (as the log's DEM performance line)" << nl
            << "# time subSteps pair wall neighbour integrate haloExchange"
            << " subStepFluidForces searches nearBuilds" << nl;

        if (engine.contactStats())
        {
            statsFile_ = open("contactStatistics", 10);
            engine.contactStats()->writeHeader(statsFile_());
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demReports::write
(
    const demDomain& domain,
    const scalar t,
    const label nParcels
)
{
    const demDiagnostics& d = engine_.diagnostics();

    const scalar ke = returnReduce(d.kineticEnergy, sumOp<scalar>());
    const scalar re = returnReduce(d.rotationalEnergy, sumOp<scalar>());
    const label nPair = returnReduce(d.nPairContacts, sumOp<label>());
    const label nWall = returnReduce(d.nWallContacts, sumOp<label>());
    const scalar maxOverlap = returnReduce(d.maxOverlapRatio, maxOp<scalar>());

    if (diagFile_.valid())
    {
        diagFile_()
            << t << ' ' << ke << ' ' << re << ' ' << nPair << ' ' << nWall
            << ' ' << maxOverlap << ' ' << nParcels << endl;
    }

    if (perfFile_.valid())
    {
        perfFile_()
            << t << ' ' << engine_.nSteps()
            << ' ' << engine_.timePair() << ' ' << engine_.timeWall()
            << ' ' << engine_.timeNeighbour()
            << ' ' << engine_.timeIntegrate()
            << ' ' << engine_.timeHalo() << ' ' << engine_.timeExternal()
            << ' ' << engine_.neighbours().nBuilds()
            << ' ' << engine_.nNearBuilds() << endl;
    }

    if (const contactStatistics* stats = engine_.contactStats())
    {
        // collective: every processor's counts go to the master
        stats->write(t, statsFile_.valid() ? statsFile_() : Snull);
    }

    balance_.sample(t, domain.nOwned(), domain.nRows(), d.nPairContacts);

    Info<< "    DEM: " << engine_.nSteps() << " sub-steps so far"
        << ", contacts (pair, wall) = (" << nPair << ", " << nWall << ")"
        << ", max overlap/R* = " << maxOverlap
        << ", kinetic energy = " << ke << ", rotational = " << re << nl;

    // Collective builds: the same counts on every processor
    if (const processorHalo* halo = domain.halo())
    {
        Info<< "    DEM halo: " << halo->nGhosts() << " ghost rows on the "
            << "master, " << halo->nBuilds() << " builds so far, "
            << halo->nRebuilds() << " of them within a fluid step" << nl;
    }
}


// ************************************************************************* //
