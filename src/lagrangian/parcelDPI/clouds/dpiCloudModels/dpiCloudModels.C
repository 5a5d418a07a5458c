/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiCloudModels.H"
#include "meshDomain.H"
#include "demPartition.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiCloudModels::dpiCloudModels
(
    const dictionary& props,
    const word& cloudName,
    const fvMesh& mesh,
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
)
{
    // The top-level keys: those the stock KinematicCloud reads (solution,
    // constantProperties, subModels, cloudFunctions), then those read here
    // and by dpiFluidCoupling. Each reader below checks its own dictionary
    dictKeys::warnUnknown
    (
        props,
        {
            "solution", "constantProperties", "subModels", "cloudFunctions",
            "dem", "injectors", "fluidCoupling", "trace", "agglomerates"
        }
    );

    if (!props.found("dem"))
    {
        FatalIOErrorInFunction(props)
            << "Missing sub-dictionary 'dem' in " << props.name() << nl
            << "    it holds the DEM time step, materials and contact models"
            << exit(FatalIOError);
    }

    // The engine's own keys first, so that a typo is named before a
    // reader stops on the entry it misses
    const dictionary& demDict = props.subDict("dem");
    demEngine::warnUnknownKeys(demDict);
    engine_.reset(new demEngine(demDict, &mesh));
    engine_->setTime(mesh.time().value());

    // Gas-particle forces: none unless fluidCoupling/forces
    coupling_.reset
    (
        new dpiFluidCoupling(props, mesh, U, rho, mu, engine_->materials())
    );

    // Parallel: the DEM either on its own partition of the parcels (load
    // balanced, dem/loadBalance rcb, the default) or on the mesh owners
    // with a halo of the mesh sub-domains' boxes
    if (demPartition::selected(demDict))
    {
        domain_.reset(new demPartition(demDict, engine_(), mesh));
    }
    else
    {
        domain_.reset(new meshDomain(engine_(), mesh));
    }

    injectors_.reset(new dpiInjectors(props, mesh, engine_->materials()));

    const Time& time = mesh.time();
    const fileName dir(time.globalPath()/"postProcessing"/cloudName);
    if (props.found("trace"))
    {
        trace_.reset
        (
            new demTrace(props.subDict("trace"), dir/"trace"/time.timeName())
        );
    }

    agglomerates_.reset
    (
        new agglomerateTracker
        (
            props.subOrEmptyDict("agglomerates"),
            dir/"agglomerates"/time.timeName()
        )
    );

    reports_.reset(new demReports(engine_(), dir, time.timeName()));
}


// ************************************************************************* //
