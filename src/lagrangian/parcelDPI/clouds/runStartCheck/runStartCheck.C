/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "runStartCheck.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "totalPressureFvPatchScalarField.H"
#include "Function1.H"
#include "OStringStream.H"
#include "IStringStream.H"

// * * * * * * * * * * * * * * * Local Constants  * * * * * * * * * * * * * //

namespace
{
    // Time directories a run may write before it is warned: each holds the
    // cloud and the fields, and a list of them is what a user browses (the
    // tutorials write at most a few hundred)
    const Foam::scalar maxWrites = 10000;
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::runStartCheck::timeControls(const Time& runTime)
{
    const dictionary& control = runTime.controlDict();
    const scalar t0 = runTime.value();
    const scalar dt = runTime.deltaTValue();

    // Time only adds deltaT: zero, negative or lost in the start time's
    // round-off, the loop never reaches endTime
    if (!(dt > 0) || !std::isfinite(dt) || !(t0 + dt > t0))
    {
        FatalIOErrorInFunction(control)
            << "deltaT " << dt << " in " << control.name() << " does not"
            << " advance the time from the start time "
            << runTime.timeName()
            << ": the run would never reach endTime "
            << Time::timeName(runTime.endTime().value()) << "." << nl
            << "    Set deltaT > 0: the fluid step (the coupling interval),"
            << " a whole number of dem/timeStep" << exit(FatalIOError);
    }

    // OpenFOAM counts the steps in a label (Time::timeIndex, and the
    // writeControl timeStep test on it): a deltaT so small that the steps
    // to endTime overflow it is a run that cannot end (deltaT 1e-30 to
    // 3e-7 s looped near 1e-25 s, a time directory every 10 steps)
    const scalar tEnd = runTime.endTime().value();
    const bool toEndTime =
        runTime.stopAt() == Time::stopAtControls::saEndTime && tEnd > t0;
    const scalar nSteps = toEndTime ? (tEnd - t0)/dt : 0;
    if (nSteps > labelMax)
    {
        FatalIOErrorInFunction(control)
            << "deltaT " << dt << " in " << control.name() << " makes "
            << nSteps << " steps from " << runTime.timeName()
            << " to endTime " << Time::timeName(tEnd) << ", more than the "
            << labelMax << " OpenFOAM can count: the run would not end."
            << nl << "    Set deltaT to the fluid step (the coupling"
            << " interval, a whole number of dem/timeStep), e.g. "
            << (tEnd - t0)/1000 << " for 1000 steps"
            << exit(FatalIOError);
    }

    // A write every few steps of a long run fills the disk with time
    // directories: said before the first one (purgeWrite keeps only the
    // last few, so it is not a flood)
    const label purge = control.getOrDefault<label>("purgeWrite", 0);
    const scalar interval =
        control.getOrDefault<scalar>("writeInterval", GREAT);
    const word writeCtrl(control.getOrDefault<word>("writeControl", "timeStep"));
    scalar nWrites = 0;
    if (writeCtrl == "timeStep")
    {
        nWrites = nSteps/max(interval, 1);
    }
    else if (writeCtrl == "runTime" || writeCtrl == "adjustableRunTime")
    {
        nWrites = (tEnd - t0)/max(interval, dt);
    }
    if (purge <= 0 && nWrites > maxWrites)
    {
        WarningInFunction
            << "writeControl " << writeCtrl << ", writeInterval " << interval
            << " and deltaT " << dt << " in " << control.name()
            << " write about " << nWrites << " time directories to endTime "
            << Time::timeName(tEnd) << " (more than " << maxWrites << ")."
            << nl << "    A larger writeInterval, or purgeWrite N to keep the"
            << " last N, saves the disk; the function objects' time series"
            << " in postProcessing/ do not need written times" << endl;
    }

    // Nothing to do is not an error (a restart at the end), but say so
    if
    (
        runTime.stopAt() == Time::stopAtControls::saEndTime
     && !(runTime.endTime().value() > t0)
    )
    {
        WarningInFunction
            << "endTime " << Time::timeName(runTime.endTime().value())
            << " in " << control.name() << " is not after the start time "
            << runTime.timeName()
            << ": the run makes no step" << endl;
    }

    // Function objects (stock ones too) run between timeStart and timeEnd
    const dictionary* functions = control.findDict("functions");
    if (!functions)
    {
        return;
    }
    for (const entry& e : *functions)
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& fo = e.dict();
        const scalar start = fo.getOrDefault<scalar>("timeStart", -VGREAT);
        const scalar end = fo.getOrDefault<scalar>("timeEnd", VGREAT);
        if (end < start)
        {
            FatalIOErrorInFunction(fo)
                << "Function object " << e.keyword() << " in "
                << fo.name() << " has timeEnd " << Time::timeName(end)
                << " before timeStart " << Time::timeName(start)
                << ": it would never run and"
                << " write only its files' headers." << nl
                << "    Give timeStart <= timeEnd (or leave one out)"
                << exit(FatalIOError);
        }
        if (end < t0 || start > tEnd)
        {
            WarningInFunction
                << "Function object " << e.keyword() << " in " << fo.name()
                << " runs "
                << (
                       end < t0
                     ? "until timeEnd " + Time::timeName(end) + ", before"
                     : "from timeStart " + Time::timeName(start) + ", after"
                   ).c_str()
                << " this run (" << runTime.timeName() << " to "
                << Time::timeName(tEnd) << "): it"
                << " writes nothing" << endl;
        }
    }
}


void Foam::runStartCheck::meshDimensions(const polyMesh& mesh)
{
    // By the patches, not by nSolutionD alone: OpenFOAM counts a wedge
    // mesh's solution directions as 3 (the wedge's normal is not a
    // "reduced" direction of polyMesh::solutionD in v1912), and tracking a
    // parcel across a wedge patch never returns all the same. An empty
    // or wedge patch with faces is refused whatever nSolutionD says (a
    // patch of that type with no face anywhere reduces nothing)
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    DynamicList<word> reducing;
    bool wedge = false;
    for (const polyPatch& pp : pbm)
    {
        const bool isEmpty = isA<emptyPolyPatch>(pp);
        const bool isWedge = isA<wedgePolyPatch>(pp);
        if
        (
            (isEmpty || isWedge)
         && returnReduce(pp.size(), sumOp<label>()) > 0
        )
        {
            reducing.append(pp.name() + " (" + pp.type() + ")");
            wedge = wedge || isWedge;
        }
    }

    if (reducing.empty() && mesh.nSolutionD() == 3)
    {
        return;
    }

    // The boundary file is a list, not a dictionary: a dictionary named
    // after it carries the file name into the message
    dictionary context;
    context.name() = pbm.objectPath();
    FatalIOErrorInFunction(context)
        << "The mesh is "
        << (
               wedge
             ? std::string("axisymmetric (wedge)")
             : std::string(Foam::name(mesh.nSolutionD())) + "-D"
           ).c_str()
        << ": patches " << flatOutput(reducing) << " in "
        << pbm.objectPath() << "." << nl
        << "    dpiFoam needs a 3-D mesh: the DEM moves parcels in 3-D, and"
        << " OpenFOAM's tracking of a parcel that leaves the plane of an"
        << " empty or wedge mesh never returns. Give those patches another"
        << " type (wall, patch or symmetry; in blockMeshDict, then run"
        << " blockMesh again) and the mesh depth for the parcels (a full"
        << " 360-degree mesh for an axisymmetric device)"
        << exit(FatalIOError);
}


namespace
{

//- The entries of a patch field as its write() gives them (the stock
//  conditions keep their Function1s private)
template<class PatchField>
Foam::dictionary entries(const PatchField& pf)
{
    Foam::OStringStream os;
    pf.write(os);
    Foam::IStringStream is(os.str());
    return Foam::dictionary(is);
}

//- The least value of f over [t0, t1] and when (1001 samples: a breath
//  table's phases last far longer than a thousandth of a run)
std::pair<Foam::scalar, Foam::scalar> least
(
    const Foam::Function1<Foam::scalar>& f,
    const Foam::scalar t0,
    const Foam::scalar t1
)
{
    std::pair<Foam::scalar, Foam::scalar> m(f.value(t0), t0);
    const Foam::label n = 1000;
    for (Foam::label i = 1; i <= n; ++i)
    {
        const Foam::scalar t = t0 + (t1 - t0)*i/n;
        const Foam::scalar v = f.value(t);
        if (v < m.first)
        {
            m = std::make_pair(v, t);
        }
    }
    return m;
}

} // End anonymous namespace


void Foam::runStartCheck::breathInlet
(
    const volVectorField& U,
    const volScalarField& p
)
{
    // A breath set backwards (a negative flow rate, a total pressure below
    // the outlet's) runs: the gas goes in at the mouthpiece and out at the
    // inlet. Warned about, not refused: breathing out into the device is
    // a handling error DPI studies simulate on purpose (the moisture and
    // powder it blows back), and a rig's breath table may hold an
    // exhalation before the inhalation. It is said with the patch, the
    // value and when, since nothing else in the run says so
    const Time& runTime = U.time();
    const scalar t0 = runTime.startTime().value();
    const scalar t1 = max(runTime.endTime().value(), t0);

    // The fixed static pressure the breath is driven against (the outlet's
    // fixedValue p), for a total-pressure inlet
    scalar pOut = -GREAT;
    word outName;
    forAll(p.boundaryField(), patchi)
    {
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        if
        (
            pp.fixesValue()
         && pp.type() != "totalPressure"
         && pp.type() != "uniformTotalPressure"
         && returnReduce(pp.size(), sumOp<label>()) > 0
        )
        {
            const scalar v = returnReduce
            (
                pp.size() ? max(pp) : -GREAT,
                maxOp<scalar>()
            );
            if (v > pOut)
            {
                pOut = v;
                outName = pp.patch().name();
            }
        }
    }

    forAll(U.boundaryField(), patchi)
    {
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        const fvPatchScalarField& pp = p.boundaryField()[patchi];
        const word& patchName = Up.patch().name();

        if (Up.type() == "flowRateInletVelocity")
        {
            const dictionary d(entries(Up));
            const word key
            (
                d.found("volumetricFlowRate")
              ? "volumetricFlowRate"
              : "massFlowRate"
            );
            const auto Q(Function1<scalar>::New(key, d));
            const auto m(least(Q(), t0, t1));
            if (m.first < 0)
            {
                WarningInFunction
                    << "The breath runs backwards at patch " << patchName
                    << ": " << U.name() << " flowRateInletVelocity " << key
                    << " is " << m.first << " at time " << m.second
                    << " (" << U.objectPath() << "), so the gas flows out"
                    << " through " << patchName << " (a flow rate > 0 is"
                    << " into the domain)." << nl
                    << "    Breathing out into the device may be meant; an"
                    << " inhalation needs " << key << " > 0 (60 L/min ="
                    << " 1e-3 m3/s)" << endl;
            }
        }

        if (pOut > -GREAT && pp.patch().name() != outName)
        {
            scalar p0 = GREAT;
            scalar when = t0;
            if (isA<totalPressureFvPatchScalarField>(pp))
            {
                const scalarField& f =
                    refCast<const totalPressureFvPatchScalarField>(pp).p0();
                p0 = returnReduce
                (
                    f.size() ? min(f) : GREAT,
                    minOp<scalar>()
                );
            }
            else if (pp.type() == "uniformTotalPressure")
            {
                const dictionary d(entries(pp));
                const auto f(Function1<scalar>::New("p0", d));
                const auto m(least(f(), t0, t1));
                p0 = m.first;
                when = m.second;
            }
            if (p0 < pOut)
            {
                WarningInFunction
                    << "The breath runs backwards at patch " << patchName
                    << ": " << p.name() << " " << pp.type() << " p0 "
                    << p0
                    << (
                           pp.type() == "totalPressure"
                         ? std::string()
                         : " at time " + std::string(Foam::name(when))
                       ).c_str()
                    << " is below the fixed " << p.name() << ' ' << pOut
                    << " of patch " << outName << " (" << p.objectPath()
                    << "), so the gas is driven from " << outName << " to "
                    << patchName << "." << nl
                    << "    Breathing out into the device may be meant; an"
                    << " inhalation needs p0 above the outlet's pressure by"
                    << " the drop over the gas density (4 kPa: 3333.3 more;"
                    << " dpiFoam's p is kinematic)" << endl;
            }
        }
    }
}


void Foam::runStartCheck::stockModels(const dictionary& cloudDict)
{
    // KinematicCloud reads its sub-models (and needs the four model keys),
    // but dpiFoam's parcels are moved by the DEM: a stock model named there
    // would do nothing or, for injection, add parcels without a DEM type or
    // id. A DPMFoam user's habit gets a message saying where the dpiFoam
    // model goes (doc/models.md)
    const dictionary sub(cloudDict.subOrEmptyDict("subModels"));

    struct stock { const char* key; bool isDict; const char* instead; };
    const stock models[] =
    {
        {"injectionModels", true,
            "injectors { <name> { type singleParticles | regionPacking; ..."
            " } } at the top level of the cloud dictionary"},
        {"particleForces", true,
            "fluidCoupling { forces { wenYuParcel {} pressureGradient {} } }"},
        {"dispersionModel", false,
            "fluidCoupling { turbulentDispersion { ... } } (the LES subgrid"
            " velocity)"},
        {"patchInteractionModel", false,
            "dem { walls { <name> { type patch; patches (...); material"
            " ...; } } } (walls are DEM contacts)"},
        {"stochasticCollisionModel", false,
            "dem { normalModel ...; tangentialModel ...; } (every contact"
            " is resolved by the DEM)"},
        {"surfaceFilmModel", false, "nothing: dpiFoam has no surface film"}
    };

    for (const stock& m : models)
    {
        bool named = false;
        word what;
        if (m.isDict)
        {
            const dictionary* d = sub.findDict(m.key);
            named = d && d->size();
            what = named ? word(d->toc()[0]) : word::null;
        }
        else if (sub.found(m.key))
        {
            what = sub.get<word>(m.key);
            named = (what != "none");
        }
        if (named)
        {
            FatalIOErrorInFunction(sub)
                << "subModels/" << m.key << " names " << what << " in "
                << sub.name() << ", a stock KinematicCloud model that"
                << " dpiFoam does not use (its parcels are moved by the DEM)."
                << nl << "    Leave it " << (m.isDict ? "empty ({})" : "none")
                << " and use " << m.instead << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
