/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiFluidCoupling.H"
#include "dpiSubStepForces.H"
#include "IOdictionary.H"
#include "dictKeys.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiFluidCoupling, 0);
}

const Foam::Enum<Foam::dpiFluidCoupling::updateMode>
Foam::dpiFluidCoupling::updateModeNames
({
    { updateMode::held, "held" },
    { updateMode::subStep, "subStep" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::dpiFluidCoupling::fluidPresent
(
    const fvMesh& mesh,
    const volVectorField& U
)
{
    if (mesh.foundObject<IOdictionary>("couplingProperties"))
    {
        const IOdictionary& cp =
            mesh.lookupObject<IOdictionary>("couplingProperties");
        return cp.getOrDefault<word>("fluid", "none") != "none";
    }

    return U.db().foundObject<volVectorField>(U.name());
}


const Foam::volScalarField& Foam::dpiFluidCoupling::lookupField
(
    const word& key,
    const word& defaultName,
    const word& user
) const
{
    const word name(dict_.getOrDefault<word>(key, defaultName));

    if (!mesh_.foundObject<volScalarField>(name))
    {
        FatalIOErrorInFunction(dict_)
            << "The gas field " << name << " (fluidCoupling/" << key
            << ") needed by " << user << " does not exist." << nl
            << "    Scalar fields of the case: "
            << mesh_.sortedNames<volScalarField>() << nl
            << "    Set fluidCoupling/" << key << " in " << dict_.name()
            << exit(FatalIOError);
    }

    return mesh_.lookupObject<volScalarField>(name);
}


void Foam::dpiFluidCoupling::checkTimeStep(const demMaterials& mat) const
{
    const scalar Dt = mesh_.time().deltaTValue();

    // Largest viscosity, smallest density and each type's smallest
    // primary: the shortest time
    const scalar muMax = gMax(mu_.primitiveField());
    const scalar rhoMin = gMin(rho_.primitiveField());
    const scalar nuMax = muMax/rhoMin;

    scalar tauMin = GREAT;
    word tauType;

    forAll(mat.names(), typei)
    {
        if (!mat.isParticleType(typei))
        {
            continue;
        }

        scalar tau = GREAT;
        forAll(forces_, i)
        {
            tau = min
            (
                tau,
                forces_[i].relaxationTime
                (
                    mat.size(typei).minDiameter(), mat.density(typei),
                    rhoMin, nuMax
                )
            );
        }

        if (tau < GREAT)
        {
            Info<< "    type " << mat.names()[typei]
                << (mat.size(typei).fixed() ? "" : " (its smallest size)")
                << ": relaxation time " << tau << " s, fluid step/tau "
                << Dt/tau << endl;
        }

        if (tau < tauMin)
        {
            tauMin = tau;
            tauType = mat.names()[typei];
        }
    }

    if (tauMin < GREAT && Dt > 0.2*tauMin)
    {
        WarningInFunction
            << "The fluid step " << Dt << " s exceeds a fifth of the "
            << "smallest particle relaxation time (type " << tauType
            << ", tau_p = " << tauMin << " s, ratio " << Dt/tauMin << ")."
            << nl
            << "    With dragUpdate held the transient drag is "
            << "inaccurate (unstable above a ratio of 2); reduce deltaT "
            << "below " << 0.2*tauMin << " s or set dragUpdate subStep in "
            << dict_.name() << endl;
    }
}


void Foam::dpiFluidCoupling::readGasFreeZones()
{
    if (!dict_.found("gasFreeZones"))
    {
        return;
    }
    const wordList names(dict_.get<wordList>("gasFreeZones"));
    const cellZoneMesh& zones = mesh_.cellZones();

    gasFreeCell_.setSize(mesh_.nCells(), false);
    label nCells = 0;
    for (const word& name : names)
    {
        // Zone names are the same on every processor (decomposePar keeps
        // empty zones), so the check is collective-free and the same
        // everywhere
        const label zonei = zones.findZoneID(name);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(dict_)
                << "fluidCoupling/gasFreeZones in " << dict_.name()
                << " names " << name << ", which is not a cellZone of the"
                << " mesh. The mesh's cellZones: " << zones.names() << nl
                << "    Name cellZones (blockMesh: a zone name in the"
                << " block's hex entry; topoSet: a cellZoneSet), or remove"
                << " gasFreeZones" << exit(FatalIOError);
        }
        for (const label celli : zones[zonei])
        {
            if (!gasFreeCell_[celli])
            {
                gasFreeCell_[celli] = true;
                ++nCells;
            }
        }
    }
    Info<< "Fluid coupling: no gas force in the cellZones " << names
        << " (" << returnReduce(nCells, sumOp<label>()) << " cells)" << endl;
}


void Foam::dpiFluidCoupling::setForces(demState& s)
{
    for (label i = 0; i < nRows_; ++i)
    {
        dpiFluidForce::sum
        (
            forces_, fluid_[i], s.v[i], 2*s.r[i], s.N[i],
            s.fExt[i], fCoupled_[i], spCoupled_[i]
        );
    }
}


void Foam::dpiFluidCoupling::advanceDispersion
(
    const demState& s,
    const scalar dt,
    label sub
)
{
    if (!dispersion_.valid())
    {
        return;
    }

    const label step = mesh_.time().timeIndex();
    for (label i = 0; i < nRows_; ++i)
    {
        fluid_[i].Uturb = dispersion_->update
        (
            fluid_[i].Uturb, sgs_[i], dt, dispersionKey_[i], step, sub
        );
    }
}


void Foam::dpiFluidCoupling::packStates
(
    List<vectorField>& vec,
    List<scalarField>& sca
) const
{
    namespace col = fluidColumns;
    vec.setSize(col::nFrozenVectors);
    sca.setSize(col::nFrozenScalars);
    for (vectorField& c : vec)
    {
        c.setSize(nRows_);
    }
    for (scalarField& c : sca)
    {
        c.setSize(nRows_, 0);
    }
    for (label i = 0; i < nRows_; ++i)
    {
        const dpiFluidForce::fluidState& fl = fluid_[i];
        vec[col::U][i] = fl.U;
        vec[col::Uturb][i] = fl.Uturb;
        vec[col::gradp][i] = fl.gradp;
        sca[col::alpha][i] = fl.alpha;
        sca[col::rho][i] = fl.rho;
        sca[col::nu][i] = fl.nu;
        if (dispersion_.valid())
        {
            sca[col::k][i] = sgs_[i].k;
            sca[col::tau][i] = sgs_[i].tau;
            sca[col::key][i] = dispersionKey_[i];
        }
        sca[col::gasFree][i] = fl.gasFree ? 1 : 0;
    }
}


void Foam::dpiFluidCoupling::setHeldForces(demState& s, const scalar Dt)
{
    advanceDispersion(s, Dt, 0);
    setForces(s);
}


Foam::autoPtr<Foam::dpiSubStepForces> Foam::dpiFluidCoupling::newSubStepForces
(
    const label n,
    const List<vectorField>& vecIn,
    const List<scalarField>& scaIn,
    const scalar dt,
    const label nSub
) const
{
    return autoPtr<dpiSubStepForces>
    (
        new dpiSubStepForces
        (
            forces_, dispersion_.get(), n, vecIn, scaIn, dt, nSub,
            refreshInterval_, mesh_.time().timeIndex()
        )
    );
}


void Foam::dpiFluidCoupling::subStepResults
(
    const dpiSubStepForces& f,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut
) const
{
    namespace col = fluidColumns;
    vecOut.setSize(col::nResultVectors);
    vecOut[col::impulse] = f.impulse();
    vecOut[col::uStar] = f.uStar();
    scaOut.setSize(col::nResultScalars);
    scaOut[col::spImpulse] = f.spImpulse();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiFluidCoupling::dpiFluidCoupling
(
    const dictionary& cloudDict,
    const fvMesh& mesh,
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu,
    const demMaterials& mat
)
:
    mesh_(mesh),
    dict_(cloudDict.subOrEmptyDict("fluidCoupling")),
    fluidOn_(fluidPresent(mesh, U)),
    update_
    (
        updateModeNames.getOrDefault("dragUpdate", dict_, updateMode::held)
    ),
    refreshInterval_(dict_.getOrDefault<label>("refreshInterval", 1)),
    interpolation_(dict_.getOrDefault<word>("interpolation", "cellPoint")),
    forces_(),
    gasFreeCell_(),
    U_(U),
    rho_(rho),
    mu_(mu),
    alpha_(nullptr),
    p_(nullptr),
    fluid_(),
    cell_(),
    fCoupled_(),
    spCoupled_(),
    spreadStart_(),
    spreadCells_(),
    spreadWeights_(),
    remote_(),
    remoteRow_(),
    remoteUTrans_(),
    remoteUCoeff_(),
    spImpulse_(),
    rowId_(),
    rowMass_(),
    nRows_(0),
    sampleTimeIndex_(-1),
    gasMomentum_(Zero),
    voidFraction_(nullptr),
    dispersion_(nullptr),
    sgs_()
{
    // The keys of fluidCoupling read here (alpha and p: lookupField);
    // forces, voidFraction and turbulentDispersion check their own
    dictKeys::warnUnknown
    (
        dict_,
        {
            "dragUpdate", "refreshInterval", "interpolation", "forces",
            "voidFraction", "turbulentDispersion", "alpha", "p",
            "gasFreeZones"
        }
    );

    const dictionary forcesDict(dict_.subOrEmptyDict("forces"));
    const wordList names(forcesDict.toc());
    const bool wantVoidFraction = dict_.found("voidFraction");
    const bool wantDispersion = dict_.found("turbulentDispersion");
    const bool wantGasFree = dict_.found("gasFreeZones");

    if (!fluidOn_ && (wantVoidFraction || wantDispersion || wantGasFree))
    {
        FatalIOErrorInFunction(dict_)
            << (
                   wantVoidFraction ? "voidFraction"
                 : wantDispersion ? "turbulentDispersion"
                 : "gasFreeZones"
               )
            << " is named in " << dict_.name() << ", but the case has no"
            << " gas (constant/couplingProperties: fluid none)." << nl
            << "    Set fluid incompressible, or remove it."
            << exit(FatalIOError);
    }

    if (wantVoidFraction)
    {
        voidFraction_ = dpiVoidFraction::New(dict_.subDict("voidFraction"));
    }

    readGasFreeZones();

    if (names.empty())
    {
        if (wantDispersion)
        {
            FatalIOErrorInFunction(dict_)
                << "turbulentDispersion is named in " << dict_.name()
                << " without forces: the subgrid velocity acts through the"
                << " drag. Name a drag (wenYuParcel) in fluidCoupling/forces"
                << exit(FatalIOError);
        }
        if (fluidOn_)
        {
            // Legitimate for a gas-only run or a one-way check, but more
            // often a forgotten fluidCoupling: say it
            IOWarningInFunction(dict_)
                << "The gas is on (constant/couplingProperties: fluid"
                << " incompressible) but " << dict_.name() << "/forces"
                << " names no force: the parcels feel no drag and the gas"
                << " no parcels. Name the drag (e.g. fluidCoupling { forces"
                << " { wenYuParcel {} pressureGradient {} } }), or set"
                << " fluid none for a DEM-only run." << endl;
        }
        return;
    }

    if (!fluidOn_)
    {
        FatalIOErrorInFunction(dict_)
            << "Particle forces " << names << " are named in "
            << dict_.name() << "/forces, but the case has no gas"
            << " (constant/couplingProperties: fluid none)." << nl
            << "    Drag and pressure-gradient forces need the gas: set"
            << " fluid incompressible, or remove the forces"
            << " (gravity acts through the parcel mass without them)."
            << exit(FatalIOError);
    }

    if (interpolation_ != "cellPoint" && interpolation_ != "cell")
    {
        FatalIOErrorInFunction(dict_)
            << "fluidCoupling/interpolation " << interpolation_
            << " is not one of (cellPoint cell)" << exit(FatalIOError);
    }

    if (refreshInterval_ < 1)
    {
        FatalIOErrorInFunction(dict_)
            << "fluidCoupling/refreshInterval " << refreshInterval_
            << " in " << dict_.name() << " is not a positive number of DEM"
            << " sub-steps (1: the forces and u* at every sub-step)"
            << exit(FatalIOError);
    }
    if (dict_.found("refreshInterval") && update_ != updateMode::subStep)
    {
        FatalIOErrorInFunction(dict_)
            << "fluidCoupling/refreshInterval is given in " << dict_.name()
            << " with dragUpdate " << updateModeNames[update_] << ": it is"
            << " the sub-steps between force evaluations of dragUpdate"
            << " subStep (held evaluates once per fluid step). Set"
            << " dragUpdate subStep, or remove refreshInterval"
            << exit(FatalIOError);
    }

    Info<< "Fluid coupling: forces " << names << ", dragUpdate "
        << updateModeNames[update_];
    if (update_ == updateMode::subStep)
    {
        Info<< " (refreshInterval " << refreshInterval_ << ")";
    }
    Info<< ", interpolation " << interpolation_ << endl;

    forces_.setSize(names.size());
    bool needP = false;
    forAll(names, i)
    {
        forces_.set
        (
            i,
            dpiFluidForce::New(names[i], forcesDict.subOrEmptyDict(names[i]))
        );
        needP = needP || forces_[i].needsPressureGradient();
    }

    alpha_ = &lookupField
    (
        "alpha",
        IOobject::groupName("alpha", U.group()),
        "the void fraction at the parcels"
    );

    if (needP)
    {
        p_ = &lookupField("p", "p", "pressureGradient");
    }

    if (wantDispersion)
    {
        bool drag = false;
        forAll(forces_, i)
        {
            drag = drag
             || (forces_[i].coupled() && forces_[i].velocityDependent());
        }
        if (!drag)
        {
            FatalIOErrorInFunction(dict_)
                << "turbulentDispersion is named in " << dict_.name()
                << " but none of the forces " << names << " is a drag: the"
                << " subgrid velocity acts through the drag. Add wenYuParcel"
                << exit(FatalIOError);
        }
        dispersion_.reset
        (
            new dpiTurbulentDispersion(dict_.subDict("turbulentDispersion"))
        );

        // The closure is an LES subgrid model: say so if the gas is not LES
        const word tpName
        (
            IOobject::groupName("turbulenceProperties", U.group())
        );
        if (mesh_.foundObject<IOdictionary>(tpName))
        {
            const word simType
            (
                mesh_.lookupObject<IOdictionary>(tpName)
               .getOrDefault<word>("simulationType", "laminar")
            );
            if (simType != "LES")
            {
                WarningInFunction
                    << "turbulentDispersion is an LES subgrid model (its k"
                    << " comes from the resolved strain and the filter"
                    << " width), but " << tpName << " selects "
                    << simType << ": the resolved flow is then not"
                    << " filtered at delta and u* has no consistent meaning"
                    << endl;
            }
        }
    }

    checkTimeStep(mat);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::dpiFluidCoupling::gasMomentum() const
{
    return returnReduce(gasMomentum_, sumOp<vector>());
}


// ************************************************************************* //
