/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "incompressibleGas.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "extrapolatedCalculatedFvPatchFields.H"


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

// Not fvc::reconstruct: in OpenFOAM 1912 it evaluates inv(tmp T) & tmp S,
// whose product reuses the storage of the vector tmp S in place while the
// field loops declare their pointers __restrict__, so the optimised build
// may write the x and y components before reading them for z. Wherever the
// face-area tensor T has off-diagonal terms (the O-grid's skewed cells) the
// velocity came out wrong (an inlet cell of the O-grid tube got Uz = -6.3
// m/s at the first step instead of -1.3e-5, and the run diverged within 3
// steps; on orthogonal boxes T is diagonal and the error vanishes). The
// same reconstruction here with named operands, so the product is written
// to fresh storage (tests/cases/gasOGridTube). SfHat = Sf/|Sf| and
// invT = inv(sum over the cell's faces of SfHat Sf) are the caller's,
// computed once.
Foam::tmp<Foam::volVectorField> reconstructFlux
(
    const Foam::surfaceScalarField& ssf,
    const Foam::surfaceVectorField& SfHat,
    const Foam::volTensorField& invT
)
{
    using namespace Foam;

    const fvMesh& mesh = ssf.mesh();
    const volVectorField sumFlux(fvc::surfaceSum(SfHat*ssf));

    tmp<volVectorField> tU
    (
        new volVectorField
        (
            IOobject
            (
                "reconstruct(" + ssf.name() + ')',
                ssf.instance(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            invT & sumFlux,
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );
    tU.ref().correctBoundaryConditions();

    return tU;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::incompressibleGas::readPhaseName(const fvMesh& mesh)
{
    return IOdictionary
    (
        IOobject
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ
        )
    ).get<word>("continuousPhase");
}


void Foam::incompressibleGas::updateVoidFraction(const basicDPICloud& cloud)
{
    alphac_ = max(1.0 - cloud.theta(), alphacMin_);
    alphac_.correctBoundaryConditions();
    alphacf_ = fvc::interpolate(alphac_);
    alphaPhic_ = alphacf_*phic_;
}


void Foam::incompressibleGas::keepOldVoidFraction()
{
    // On a restart, keep the starting void fraction as the old time level
    // from now on, so that the first fluid step's ddt(alphac) sees the
    // change of the cloud over the step exactly as the straight run does
    // (left lazy, oldTime() is created from the already updated field at
    // the first step: ddt(alphac) = 0 there). A fresh run keeps the lazy
    // behaviour on purpose: its first step injects the parcels, which
    // appear without displacing the gas (otherwise N primaries appearing at
    // once would push the gas aside and break the N invariance)
    if (mesh_.time().timeIndex() > 0)
    {
        alphac_.oldTime();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::incompressibleGas::incompressibleGas
(
    fvMesh& mesh,
    const uniformDimensionedVectorField& g
)
:
    mesh_(mesh),
    g_(g),
    pimple_(mesh),
    phaseName_(readPhaseName(mesh)),
    Uc_
    (
        IOobject
        (
            IOobject::groupName("U", phaseName_),
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    p_
    (
        IOobject
        (
            "p",
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh
    ),
    phic_
    (
        IOobject
        (
            IOobject::groupName("phi", phaseName_),
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        linearInterpolate(Uc_) & mesh.Sf()
    ),
    pRefCell_(0),
    pRefValue_(0),
    transport_(Uc_, phic_),
    rhoc_
    (
        IOobject
        (
            IOobject::groupName("rho", phaseName_),
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar
        (
            IOobject::groupName("rho", phaseName_),
            dimDensity,
            transport_
        )
    ),
    muc_
    (
        IOobject
        (
            IOobject::groupName("mu", phaseName_),
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        rhoc_*transport_.nu()
    ),
    alphac_
    (
        IOobject
        (
            IOobject::groupName("alpha", phaseName_),
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0)
    ),
    alphacMin_(0),
    alphacf_("alphacf", fvc::interpolate(alphac_)),
    alphaPhic_(IOobject::groupName("alphaPhi", phaseName_), alphacf_*phic_),
    turbulence_(nullptr),
    cumulativeContErr_(0),
    maxCo_
    (
        mesh.time().controlDict().getOrDefault<scalar>("maxCo", 1)
    ),
    warnedCo_(0),
    SfHat_("SfHat", mesh.Sf()/mesh.magSf()),
    invT_("invT", inv(fvc::surfaceSum(SfHat_*mesh.Sf())))
{
    setRefCell(p_, pimple_.dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_.name());

    turbulence_ = turbulenceModelType::New
    (
        alphac_,
        Uc_,
        alphaPhic_,
        phic_,
        transport_
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::incompressibleGas::attach(const basicDPICloud& cloud)
{
    // With a void fraction model (fluidCoupling/voidFraction) its alphaMin
    // is the floor, the same the drag sees through alpha
    // (an inactive cloud, the gas alone, has no coupling)
    const dpiVoidFraction* vf =
        cloud.solution().active()
      ? cloud.fluidCoupling().voidFraction()
      : nullptr;
    if (vf)
    {
        alphacMin_ = vf->alphaMin();
        Info<< "Void fraction floor " << alphacMin_
            << " (fluidCoupling/voidFraction/alphaMin)" << endl;
        updateVoidFraction(cloud);
        keepOldVoidFraction();
        return;
    }

    const dictionary& cp =
        cloud.particleProperties().subDict("constantProperties");

    const scalar alphaMax = cp.get<scalar>("alphaMax");
    if (alphaMax <= 0 || alphaMax >= 1)
    {
        FatalIOErrorInFunction(cp)
            << "constantProperties/alphaMax = " << alphaMax
            << " in " << cloud.particleProperties().name()
            << " must lie in (0, 1): the void fraction floor is 1 - alphaMax"
            << exit(FatalIOError);
    }
    alphacMin_ = 1 - alphaMax;

    updateVoidFraction(cloud);
    keepOldVoidFraction();
}


void Foam::incompressibleGas::correctTransport()
{
    transport_.correct();
    muc_ = rhoc_*transport_.nu();
}


void Foam::incompressibleGas::solve(basicDPICloud& cloud)
{
    const Time& runTime = mesh_.time();
    volVectorField& Uc = Uc_;
    volScalarField& p = p_;
    surfaceScalarField& phic = phic_;

    updateVoidFraction(cloud);

    // Cloud momentum source: the implicit drag coefficient stays in the
    // momentum matrix; the explicit part joins gravity in the cell force
    // fc below
    fvVectorMatrix cloudSU(cloud.SU(Uc));

    // Explicit cell force per unit volume over rho [m/s2]: the particles' reaction and gravity on the gas (model A:
    // alpha g). It enters the cell velocity as rAU fc, cell by cell, so
    // that the gas gains exactly sum(fc V) (momentum balance with the
    // parcels), and the face fluxes as flux(rAU fc), as DPMFoam's face
    // force, so that a force balanced by the pressure gradient (still
    // gas, hydrostatics, walls through fixedFluxPressure) gives no flux.
    // The boundary value (zero gradient) carries the force into the
    // fixedFluxPressure walls
    volVectorField fc
    (
        IOobject("cloudAndGravityForce", runTime.timeName(), mesh_),
        mesh_,
        dimensionedVector(dimAcceleration, Zero),
        zeroGradientFvPatchVectorField::typeName
    );
    fc.primitiveFieldRef() =
        -cloudSU.source()/(rhoc_.primitiveField()*mesh_.V().field());
    if (cloud.solution().coupled())
    {
        // Model A: gravity on the gas's own mass; the gas displaced by the
        // parcels comes back as the reaction of their pressure force
        fc.primitiveFieldRef() += alphac_.primitiveField()*g_.value();
    }
    else
    {
        // One-way: the gas ignores the parcels' momentum, so also the
        // reaction of their pressure force that completes alpha g to g at
        // rest; alpha g alone would make every parcel's cell a buoyant
        // plume of the gas (theta g) that nothing balances
        fc.primitiveFieldRef() += g_.value();
    }
    fc.correctBoundaryConditions();
    cloudSU.source() = Zero;

    {
        scalarField sumPhi
        (
            fvc::surfaceSum(mag(phic))().primitiveField()
        );
        const scalar CoNum =
            0.5*gMax(sumPhi/mesh_.V().field())*runTime.deltaTValue();
        Info<< "Courant Number max: " << CoNum << endl;

        // The fluid step is fixed (it is the coupling interval): say when
        // it is too long for the gas, once and again whenever it doubles
        if (CoNum > maxCo_ && CoNum > 2*warnedCo_)
        {
            WarningInFunction
                << "Courant number " << CoNum << " of the gas at time "
                << runTime.timeName() << " is above maxCo " << maxCo_
                << " (system/controlDict, default 1): the PISO correctors"
                << " and the frozen coupling are inaccurate or unstable"
                << " there. Lower deltaT (the coupling interval, a whole"
                << " number of DEM steps)." << endl;
            warnedCo_ = CoNum;
        }
    }

    while (pimple_.loop())
    {
        // Conservative form of alpha DU/Dt (no -U (ddt(alpha) +
        // div(alphaPhi)) term): the sum over the cells of the matrix is
        // the change of the gas momentum plus boundary fluxes, whatever
        // the continuity error of the convecting flux alphaPhic (updated
        // after every pressure corrector, so that from the second outer
        // corrector on it satisfies the continuity of this step)
        fvVectorMatrix UcEqn
        (
            fvm::ddt(alphac_, Uc) + fvm::div(alphaPhic_, Uc)
          + turbulence_->divDevRhoReff(Uc)
         ==
            (1.0/rhoc_)*cloudSU
        );

        UcEqn.relax();

        volScalarField rAUc(1.0/UcEqn.A());
        surfaceScalarField rAUcf("Dp", fvc::interpolate(rAUc));

        const surfaceScalarField phicForces(fvc::flux(rAUc*fc));

        if (pimple_.momentumPredictor())
        {
            Foam::solve
            (
                UcEqn
             ==
                fc
              - reconstructFlux
                (
                    fvc::snGrad(p)*mesh_.magSf(), SfHat_, invT_
                )
            );
        }

        while (pimple_.correct())
        {
            volVectorField HbyA(constrainHbyA(rAUc*UcEqn.H(), Uc, p));

            surfaceScalarField phiHbyA
            (
                "phiHbyA",
                fvc::flux(HbyA) + alphacf_*rAUcf*fvc::ddtCorr(Uc, phic)
            );

            if (p.needReference())
            {
                adjustPhi(phiHbyA, Uc, p);
            }

            phiHbyA += phicForces;

            constrainPressure(p, Uc, phiHbyA, rAUcf);

            while (pimple_.correctNonOrthogonal())
            {
                fvScalarMatrix pEqn
                (
                    fvm::laplacian(alphacf_*rAUcf, p)
                 ==
                    fvc::ddt(alphac_) + fvc::div(alphacf_*phiHbyA)
                );

                pEqn.setReference(pRefCell_, pRefValue_);
                pEqn.solve(mesh_.solver(p.select(pimple_.finalInnerIter())));

                if (pimple_.finalNonOrthogonalIter())
                {
                    phic = phiHbyA - pEqn.flux()/alphacf_;
                    p.relax();
                    Uc = HbyA
                      + rAUc*fc
                      - rAUc*reconstructFlux
                        (
                            (pEqn.flux()/alphacf_)/rAUcf, SfHat_, invT_
                        );
                    Uc.correctBoundaryConditions();
                }
            }

            alphaPhic_ = alphacf_*phic;

            // Continuity error of the gas with void fraction
            volScalarField contErr
            (
                fvc::ddt(alphac_) + fvc::div(alphaPhic_)
            );
            const scalar sumLocalContErr =
                runTime.deltaTValue()
               *mag(contErr)().weightedAverage(mesh_.V()).value();
            const scalar globalContErr =
                runTime.deltaTValue()
               *contErr.weightedAverage(mesh_.V()).value();
            cumulativeContErr_ += globalContErr;
            Info<< "time step continuity errors : sum local = "
                << sumLocalContErr << ", global = " << globalContErr
                << ", cumulative = " << cumulativeContErr_ << endl;
        }

        if (pimple_.turbCorr())
        {
            turbulence_->correct();
        }
    }

    // The parcels' share of the implicit drag (momentum balance)
    if (cloud.solution().active())
    {
        cloud.fluidCoupling().correctParcels(cloud, Uc);
    }
}


// ************************************************************************* //
