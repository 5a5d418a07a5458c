/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Application
    dpiFoam

Description
    CFD-DEM solver for dry powder inhalers: carriers and representative API
    parcels (each standing for N primary API particles) integrated by a DEM
    engine with Hertz contact, friction, rolling resistance and cohesion,
    optionally coupled to an incompressible PIMPLE gas with void fraction.

    constant/couplingProperties selects what the scene needs:
    \verbatim
    fluid       none;           // none: DEM only, no fluid fields, no PIMPLE
                                // incompressible: PIMPLE gas (see
                                // incompressibleGas)
    cloudName   dpiCloud;       // reads constant/<cloudName>Properties
    \endverbatim

    The fluid time step (controlDict deltaT) is the coupling interval; the
    DEM sub-steps at dem/timeStep of the cloud dictionary.

    Gas-particle forces (drag wenYuParcel, pressureGradient) are named in
    the cloud dictionary's fluidCoupling/forces (see dpiFluidCoupling); they
    need fluid incompressible. Order of a fluid step: the cloud samples the
    gas of the step's start and runs the DEM sub-steps (its forces' reaction
    into UTrans/UCoeff), the gas is solved with the new void fraction and
    that reaction, and the parcels receive the counterpart of the gas's
    implicit drag (momentum balance, see incompressibleGas).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicDPICloud.H"
#include "incompressibleGas.H"
#include "uniformDimensionedFields.H"
#include "Enum.H"
#include "writtenTimes.H"
#include "runStartCheck.H"
#include "runProgress.H"
#include "dictKeys.H"
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <chrono>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    enum class fluidType { none, incompressible };

    static const Enum<fluidType> fluidTypeNames
    ({
        { fluidType::none, "none" },
        { fluidType::incompressible, "incompressible" },
    });

    //- A still, unsolved carrier for DEM-only scenes: the cloud's interface
    //  wants fields, so these exist in memory only (never read or written)
    static tmp<volScalarField> stillScalar
    (
        const fvMesh& mesh,
        const word& name,
        const dimensionedScalar& value
    )
    {
        return tmp<volScalarField>::New
        (
            IOobject
            (
                name, mesh.time().timeName(), mesh,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh,
            value
        );
    }
}


int main(int argc, char *argv[])
{
    // The run's cost report (at its end) counts from here: wall-clock
    // seconds since t0
    using steadyClock = std::chrono::steady_clock;
    const steadyClock::time_point tMain = steadyClock::now();
    auto since = [](const steadyClock::time_point& t0)
    {
        return std::chrono::duration<double>(steadyClock::now() - t0).count();
    };

    #ifdef __GLIBC__
    // A fixed threshold for glibc to serve large blocks (>= 1 MB) straight
    // from the system, and give them back when freed. By default it rises
    // to the largest block freed so far, after which the DEM hand-over's
    // buffers and the neighbour lists, re-made every fluid step, are cut
    // from the heap between long-lived parcel data and leave holes there:
    // measured on a 50,000-carrier bed on 2 processes, the heap in use
    // stayed at ~66 MB per process while the heap grew by ~10 MB of holes
    // over five fluid steps (bench/packedBed)
    mallopt(M_MMAP_THRESHOLD, 1024*1024);

    // A fixed mmap threshold also fixes the trim threshold at glibc's
    // 128 kB: every fluid step the gas solve's temporary fields freed at
    // the top of the heap were handed back to the system and faulted in
    // again at the next step. Keeping up to 64 MB of free heap per process
    // took the quick inhaler's gas step from 7.1-8.4 s to 4.0-4.3 s over
    // 200 fluid steps (serial, 8,028 cells) for +2 % peak memory
    mallopt(M_TRIM_THRESHOLD, 64*1024*1024);
    #endif

    argList::addNote
    (
        "CFD-DEM solver for dry powder inhalers: carriers and coarse-grained"
        " API parcels with Hertz contact, friction, rolling resistance and"
        " cohesion, optionally in an incompressible gas."
    );

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    // Before Time reads the start time: a half-written one (a run killed
    // while writing) is refused with the last complete time to go on from
    writtenTimes::checkStart(args);

    #include "createTime.H"
    // Where OpenFOAM would loop for ever or run on silently: refused
    // before anything is read
    runStartCheck::timeControls(runTime);
    #include "createMesh.H"
    #include "checkDecomposition.H"
    runStartCheck::meshDimensions(mesh);
    #include "readGravitationalAcceleration.H"

    // dpiFoam's own input: a key given twice (the second silently merged
    // or kept) is refused, naming it
    const fileName constantDir(runTime.globalPath()/runTime.constant());
    dictKeys::refuseDuplicates(constantDir/"couplingProperties");

    IOdictionary couplingProperties
    (
        IOobject
        (
            "couplingProperties",
            runTime.constant(),
            mesh,
            IOobject::MUST_READ
        )
    );

    const fluidType fluid = fluidTypeNames.get("fluid", couplingProperties);
    const word cloudName
    (
        couplingProperties.lookupOrDefault<word>("cloudName", "dpiCloud")
    );

    Info<< "Fluid: " << fluidTypeNames[fluid] << nl << endl;

    dictKeys::refuseDuplicates(constantDir/(cloudName + "Properties"));

    autoPtr<incompressibleGas> gas;
    tmp<volScalarField> rhoStill;
    tmp<volScalarField> muStill;
    autoPtr<volVectorField> UStill;

    if (fluid == fluidType::incompressible)
    {
        gas.reset(new incompressibleGas(mesh, g));
        runStartCheck::breathInlet
        (
            gas->Uc(),
            mesh.lookupObject<volScalarField>("p")
        );
    }
    else
    {
        rhoStill = stillScalar(mesh, "rho.none", dimensionedScalar("rho", dimDensity, 1.0));
        muStill = stillScalar(mesh, "mu.none", dimensionedScalar(dimDynamicViscosity, Zero));
        UStill.reset
        (
            new volVectorField
            (
                IOobject
                (
                    "U.none", runTime.timeName(), mesh,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                mesh,
                dimensionedVector(dimVelocity, Zero)
            )
        );
    }

    Info<< "Constructing cloud " << cloudName << endl;
    // The stock KinematicCloud builds its sub-models before dpiFoam's
    // cloud can look at them: say first where a DPMFoam-style model goes
    runStartCheck::stockModels
    (
        IOdictionary
        (
            IOobject
            (
                cloudName + "Properties",
                runTime.constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    );

    basicDPICloud cloud
    (
        cloudName,
        gas.valid() ? gas->rhoc() : rhoStill(),
        gas.valid() ? gas->Uc() : UStill(),
        gas.valid() ? gas->muc() : muStill(),
        g
    );

    if (gas.valid())
    {
        gas->attach(cloud);
    }

    Info<< "\nStarting time loop\n" << endl;

    // Where the run's time goes, in wall-clock seconds of this process
    // (the master's, as printed): start-up (mesh, gas, cloud, injection),
    // the gas solve, the cloud's fluid steps (the DEM engine's share is
    // split in its performance line), and the rest (writing, function
    // objects)
    const scalar startUp = since(tMain);
    const steadyClock::time_point tLoop = steadyClock::now();
    scalar gasTime = 0, cloudTime = 0;

    // The simulated time done, the pace and the estimated end, in the log
    // and postProcessing/progress
    runProgress progress(runTime);

    while (runTime.run())
    {
        progress.start();
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        steadyClock::time_point t0 = steadyClock::now();
        if (gas.valid())
        {
            gas->correctTransport();
        }
        gasTime += since(t0);

        Info<< "Evolving " << cloud.name() << endl;
        t0 = steadyClock::now();
        cloud.evolve();
        cloudTime += since(t0);

        t0 = steadyClock::now();
        if (gas.valid())
        {
            gas->solve(cloud);
        }
        gasTime += since(t0);

        runTime.write();

        runTime.printExecutionTime(Info);
        progress.update();
    }

    const scalar loop = since(tLoop);
    Info<< "Cost (wall-clock s, this process): start-up " << startUp
        << ", gas " << gasTime << ", cloud " << cloudTime
        << ", the rest (writing, function objects) "
        << loop - gasTime - cloudTime
        << ", total " << startUp + loop << endl;

    // An inactive cloud (solution/active false: the gas alone) has no
    // engine to report on
    if (cloud.solution().active())
    {
        cloud.engine().writePerformance(Info);
        cloud.balance().summary(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
