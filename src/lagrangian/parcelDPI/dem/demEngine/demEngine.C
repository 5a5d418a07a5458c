/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demEngine.H"
#include <cmath>
#include "pairScaling.H"
#include "demContact.H"
#include "dictKeys.H"
#include "polyMesh.H"
#include "Time.H"
#include "IOmanip.H"
#include <algorithm>
#include <chrono>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demEngine, 0);
}


const Foam::wordList Foam::demEngine::keys
({
    "timeStep",
    "types",
    "pairs",
    "normalModel",
    "tangentialModel",
    "rollingModel",
    "cohesionModel",
    "coarseGraining",
    "walls",
    "neighbourSearch",
    "timeStepCheck",
    "startOverlap",
    "overlapCheck",
    "loadBalance",
    "contactStatistics"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Wall-clock seconds since an arbitrary origin
inline double wallClock()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::demEngine::readSkin(const dictionary& dict) const
{
    // Default: the smallest particle diameter
    const dictionary nsDict(dict.subOrEmptyDict("neighbourSearch"));
    dictKeys::warnUnknown(nsDict, {"skin", "order"});

    // No type with a diameter: the parcels' types were given none (a type
    // without one is a wall material), which is what to say, not the skin
    bool anyParticleType = false;
    forAll(materials_.names(), t)
    {
        anyParticleType = anyParticleType || materials_.isParticleType(t);
    }
    if (!anyParticleType)
    {
        const dictionary& types = dict.subDict("types");
        FatalIOErrorInFunction(types)
            << "No type in dictionary " << types.name() << " has a"
            << " 'diameter' or 'sizeDistribution' (types "
            << flatOutput(materials_.names())
            << "): a type without one is a wall material, and parcels"
            << " cannot be made of it." << nl
            << "    Give the types parcels are made of a diameter and a"
            << " density" << exit(FatalIOError);
    }
    const scalar skin =
        nsDict.getOrDefault<scalar>("skin", materials_.minMedianDiameter());
    if (!(skin > 0))
    {
        FatalIOErrorInFunction(dict)
            << "The neighbour-search skin must be > 0 (got " << skin
            << "); set neighbourSearch { skin ...; } in dictionary "
            << dict.name() << exit(FatalIOError);
    }
    return skin;
}


void Foam::demEngine::checkDiameters
(
    const dictionary& dict,
    const polyMesh& mesh
) const
{
    // A parcel lives in the mesh's cells: a type's diameter above the
    // mesh's smallest extent cannot be placed anywhere, and is a typing
    // error (a diameter in um for m, 1e300). Said for what it is, before
    // the skin, the time step check and the neighbour search take it in
    // (was: "The neighbour-search skin must be > 0")
    const boundBox meshBb(mesh.points(), true);
    const scalar extent = cmptMin(meshBb.span());
    const dictionary& types = dict.subDict("types");
    forAll(materials_.names(), t)
    {
        if (!materials_.isParticleType(t))
        {
            continue;
        }
        const scalar d = materials_.size(t).maxDiameter();
        if (!(d < extent))
        {
            const word& name = materials_.names()[t];
            FatalIOErrorInFunction(types.subDict(name))
                << (
                       materials_.size(t).fixed()
                     ? "Entry 'diameter'" : "The largest diameter"
                   )
                << " = " << d << " in dictionary "
                << types.subDict(name).name() << " is larger than the mesh"
                << " (bounds " << meshBb.min() << ' ' << meshBb.max()
                << ", " << extent << " m across at its narrowest): a"
                << " parcel of type " << name << " fits nowhere in it." << nl
                << "    Diameters are in metres (5e-6 for 5 um), as the"
                << " mesh" << exit(FatalIOError);
        }
    }
}


void Foam::demEngine::flushHistory()
{
    if (!history_.workingValid())
    {
        return;
    }
    history_.flush(pairs_.rows(), pairs_.nearStarts(), pairs_.nearPartners());
}


void Foam::demEngine::rebuild(const demState& s)
{
    const double t0 = wallClock();

    flushHistory();

    const scalar rMax = s.maxRadius();

    pairs_.build
    (
        s, models_, models_.maxRange(rMax), materials_.coarseGraining()
    );
    walls_.markNearWalls
    (
        s, models_, rMax, models_.maxRange(rMax), pairs_.search().skin(),
        pairs_.tracked()
    );
    history_.load(s.globalId);
    buildNear(s);

    timeNeighbour_ += wallClock() - t0;
}


void Foam::demEngine::buildNear(const demState& s)
{
    pairs_.buildNear(s, timeStep_, history_);

    // The wall candidates within the near skin: valid as long as the near
    // list (no row has moved more than half the near skin)
    const scalar rMax = s.maxRadius();
    walls_.findCandidates
    (
        s, models_, rMax, models_.maxRange(rMax), pairs_.nearSkin(),
        pairs_.tracked()
    );
}


void Foam::demEngine::evaluate
(
    demState& s,
    const bool advance,
    const label checkedRows
)
{
    const label n = s.size();

    double t0 = wallClock();

    if
    (
        !history_.workingValid()
     || pairs_.search().needsRebuild(s, checkedRows)
    )
    {
        rebuild(s);
    }
    else
    {
        if (!pairs_.nearValid(s))
        {
            buildNear(s);
        }
        timeNeighbour_ += wallClock() - t0;
    }

    diag_.nPairContacts = 0;
    diag_.nWallContacts = 0;
    diag_.maxOverlapRatio = 0;

    t0 = wallClock();

    fContact_.setSize(n);
    tContact_.setSize(n);
    fContact_ = Zero;
    tContact_ = Zero;

    kernel_->pairForces
    (
        pairs_, s, materials_, timeStep_, advance, history_,
        fContact_, tContact_, diag_
    );

    double t1 = wallClock();
    timePair_ += t1 - t0;

    kernel_->wallForces
    (
        walls_, s, materials_, timeStep_, advance, history_,
        fContact_, tContact_, diag_
    );

    timeWall_ += wallClock() - t1;
}


void Foam::demEngine::totalForces(demState& s) const
{
    forAll(s.x, p)
    {
        s.f[p] = totalForce(s, p);
        s.torque[p] = tContact_[p];
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::label Foam::demEngine::warnUnknownKeys(const dictionary& dict)
{
    wordList known(keys);
    const label nWarnings = contactModels::warnUnusedCoeffs(dict, known);

    // The coarse-graining models' coefficients: the selector says when
    // they belong to a model not selected
    for
    (
        const word& model
      : coarseGrainingModel::dictionaryConstructorTablePtr_->sortedToc()
    )
    {
        known.append(model + "Coeffs");
    }

    return nWarnings + dictKeys::warnUnknown(dict, known);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demEngine::demEngine(const dictionary& dict, const polyMesh* mesh)
:
    timeStep_(dict.get<scalar>("timeStep")),
    materials_(dict),
    models_(dict),
    kernel_(contactKernel::New(models_, dict)),
    walls_(dict, mesh, materials_),
    pairs_(readSkin(dict)),
    timeStepCheck_(dict),
    overlap_(dict),
    g_(Zero),
    time_(0),
    history_(),
    diag_(),
    timePair_(0),
    timeWall_(0),
    timeNeighbour_(0),
    timeIntegrate_(0),
    timeExternal_(0),
    timeHalo_(0),
    nSteps_(0),
    nParticleSteps_(0),
    halo_(nullptr),
    alongCurve_(readOrder(dict)),
    frame_(mesh ? mesh->bounds() : boundBox())
{
    if (dict.getOrDefault<bool>("contactStatistics", false))
    {
        stats_.reset(new contactStatistics(materials_.names()));
        diag_.stats = stats_.get();
    }

    if (!(timeStep_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'timeStep' = " << timeStep_ << " in dictionary "
            << dict.name() << " must be > 0" << exit(FatalIOError);
    }

    if (mesh)
    {
        checkDiameters(dict, *mesh);
    }

    Info<< "DEM engine: " << materials_.size() << " types "
        << materials_.names() << ", " << walls_.size() << " walls, skin "
        << pairs_.search().skin() << " m, pairs swept in "
        << (alongCurve_ ? "morton" : "globalId") << " order" << endl;
    Info<< "    ";
    materials_.coarseGraining().describe(Info, materials_.names());
    Info<< endl;

    timeStepCheck_.check
    (
        dict, timeStep_, materials_, models_.normal(), walls_.materials()
    );

    // The fluid step (controlDict deltaT) is run as a whole number of DEM
    // steps: checked here, before any parcel is read, rather than at the
    // first step. A fluid step below one DEM step would run no DEM step at
    // all while the time loop goes on, and one of more DEM steps than a
    // label counts would trap in the conversion
    if (mesh)
    {
        const scalar Dt = mesh->time().deltaTValue();
        const scalar ratio = Dt/timeStep_;
        if (!(ratio < labelMax) || ratio < 1 - 1e-6)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'timeStep' = " << timeStep_ << " s in dictionary "
                << dict.name() << " against the fluid step deltaT " << Dt
                << " s of " << mesh->time().controlDict().name() << ": "
                << (
                       ratio < 1
                     ? "the fluid step is shorter than one DEM step, so no"
                       " DEM step would ever run"
                     : "the fluid step would hold " + Foam::name(ratio)
                     + " DEM steps, more than the "
                     + Foam::name(labelMax) + " a step can count"
                   ).c_str()
                << "." << nl
                << "    deltaT must be a whole number of DEM timeSteps,"
                << " from 1 to " << labelMax << " (the tutorials use 1 to"
                << " 100; timeStepCheck gives the stable DEM step)"
                << exit(FatalIOError);
        }
        nSubSteps(Dt);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demEngine::evolve
(
    demState& s,
    const scalar Dt,
    const vector& g,
    demObserver* obs,
    demSubStepForces* ext
)
{
    const label nSub = nSubSteps(Dt);
    if (nSub == 0)
    {
        return;
    }

    checkState(s);

    // Only owned rows are integrated; ghosts (halo copies) are refreshed
    // by the halo from their owners
    const label n = s.owned();
    const scalar dt = timeStep_;
    const scalar t0 = time_;

    g_ = g;

    // Forces of the starting state: those of the last sub-step if the cloud
    // has not touched the state since (so splitting a run into evolve calls
    // changes nothing), else a re-evaluation that leaves the history as is
    if (cache_.reuse(s, fContact_, tContact_))
    {
        totalForces(s);
    }
    else if (s.contactForcesValid)
    {
        // Given by the caller (restart, or parcels handed back unchanged)
        fContact_ = s.fContact;
        tContact_ = s.tContact;
        totalForces(s);
    }
    else
    {
        evaluate(s, false);
        totalForces(s);
    }

    // Per owned row, the half-step factors dt/(2M), dt/(2I), evaluated once
    // per evolve instead of twice per sub-step (two divisions each), by the
    // same expressions so the update is unchanged to the bit
    double tc = wallClock();

    halfStepV_.setSize(n);
    halfStepOmega_.setSize(n);
    for (label p = 0; p < n; ++p)
    {
        const scalar M = s.N[p]*s.m[p];
        const scalar I = 0.4*M*sqr(s.r[p]);
        halfStepV_[p] = 0.5*dt/M;
        halfStepOmega_[p] = 0.5*dt/I;
    }

    timeIntegrate_ += wallClock() - tc;

    for (label step = 0; step < nSub; ++step)
    {
        tc = wallClock();

        // The external forces of this sub-step, from its starting state
        // (timed apart: they are the gas's, not the engine's); the total
        // force of the first half kick then includes them, computed in the
        // kick's pass as totalForces would (ghost rows keep the previous
        // sub-step's: only owned rows are kicked)
        if (ext)
        {
            ext->setForces(step, s);
            const double te = wallClock();
            timeExternal_ += te - tc;
            tc = te;
        }
        auto kickForce = [&](const label p)
        {
            if (ext)
            {
                const vector f(totalForce(s, p));
                s.f[p] = f;
                return f;
            }
            return s.f[p];
        };

        // Values just stored are not read back (a store read back by a
        // wider load stalls the pipeline).
        // After the first sub-step (which checks everything: the cloud may
        // have changed the rows) the owned rows are the particles of the
        // neighbour list's build, and their move since the build is
        // measured here, saving a pass over the rows in needsRebuild
        const List<point>& x0 = pairs_.search().x0();
        const bool track =
            step > 0 && pairs_.search().valid() && x0.size() == s.size();
        scalar maxMove2 = 0;

        if (track)
        {
            for (label p = 0; p < n; ++p)
            {
                const vector v(s.v[p] + halfStepV_[p]*kickForce(p));
                s.v[p] = v;
                s.omega[p] += halfStepOmega_[p]*s.torque[p];
                const point x(s.x[p] + dt*v);
                s.x[p] = x;
                maxMove2 = max(maxMove2, magSqr(x - x0[p]));
            }
        }
        else
        {
            for (label p = 0; p < n; ++p)
            {
                const vector v(s.v[p] + halfStepV_[p]*kickForce(p));
                s.v[p] = v;
                s.omega[p] += halfStepOmega_[p]*s.torque[p];
                s.x[p] += dt*v;
            }
        }

        timeIntegrate_ += wallClock() - tc;

        if (halo_)
        {
            tc = wallClock();
            halo_->update(s);
            timeHalo_ += wallClock() - tc;
        }

        // As neighbourSearch::needsRebuild decides
        const bool ownedChecked =
            track && !(maxMove2 > sqr(0.5*pairs_.search().skin()));

        evaluate(s, true, ownedChecked ? n : 0);

        tc = wallClock();

        // Total forces (as totalForces) and the second half kick in one
        // pass over the rows. The energies are the diagnostics' of the
        // evolve's end (written per fluid step, checked in checkEndState):
        // summed at its last sub-step only, the other sub-steps' kicks are
        // free of their two running sums
        const bool last = (step + 1 == nSub);
        scalar Ek = 0, Er = 0;
        for (label p = 0; p < n; ++p)
        {
            const vector f(totalForce(s, p));
            const vector t(tContact_[p]);
            s.f[p] = f;
            s.torque[p] = t;
            const vector v(s.v[p] + halfStepV_[p]*f);
            const vector omega(s.omega[p] + halfStepOmega_[p]*t);
            s.v[p] = v;
            s.omega[p] = omega;
            if (last)
            {
                const scalar M = s.N[p]*s.m[p];
                Ek += 0.5*M*magSqr(v);
                Er += 0.5*(0.4*M*sqr(s.r[p]))*magSqr(omega);
            }
        }
        for (label p = n; p < s.size(); ++p)
        {
            s.f[p] = totalForce(s, p);
            s.torque[p] = tContact_[p];
        }

        timeIntegrate_ += wallClock() - tc;

        time_ = t0 + (step + 1)*dt;
        diag_.time = time_;
        if (last)
        {
            diag_.kineticEnergy = Ek;
            diag_.rotationalEnergy = Er;
        }
        ++nSteps_;
        nParticleSteps_ += n;

        if (obs)
        {
            obs->subStep(time_, s);
        }
    }

    checkEndState(s);

    flushHistory();

    s.fContact = fContact_;
    s.tContact = tContact_;
    s.contactForcesValid = true;

    cache_.store(s);
}


Foam::scalar Foam::demEngine::interactionReach(const scalar rMax) const
{
    return 2*rMax + models_.maxRange(rMax) + pairs_.search().skin();
}


void Foam::demEngine::haloReach
(
    const demState& s,
    const scalar Dt,
    scalar& range,
    scalar& margin
) const
{
    // The contact radii: parcels that meet each other at grown radii
    // (coarseGrainingModel) reach that far
    scalar rMax = materials_.coarseGraining().maxRadius(s.r, s.typeId);
    scalar vMax = 0;
    for (label row = 0; row < s.size(); ++row)
    {
        vMax = max(vMax, mag(s.v[row]));
    }
    reduce(rMax, maxOp<scalar>());
    reduce(vMax, maxOp<scalar>());

    range = interactionReach(rMax);

    // Enough for the fluid step while the parcels are slow (both parcels
    // of a pair travelling towards each other, 1.5 x the fastest speed for
    // moderate acceleration), so the halo is built once per fluid step; at
    // most one Verlet skin, past which the halo is built again within the
    // fluid step (processorHalo) rather than take in the fastest parcel's
    // travel over the whole of it. One skin: the halo is then built about
    // as often as that parcel's own travel rebuilds the neighbour lists
    // (half a skin); of 0.5, 1 and 2 skins it was the fastest on the
    // full-size inhaler's spray
    margin = min(2*1.5*vMax*Dt, neighbours().skin());
}


void Foam::demEngine::evaluateForces(demState& s)
{
    checkState(s);
    evaluate(s, true);
    totalForces(s);
    cache_.invalidate();
}


void Foam::demEngine::history
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
) const
{
    history_.history(globalId, partnerKeys, xi);
}


void Foam::demEngine::reserveHistory(const label n)
{
    editHistory();
    history_.reserve(n);
}


void Foam::demEngine::setHistory
(
    const label globalId,
    const labelUList& partnerKeys,
    const UList<vector>& xi
)
{
    editHistory();
    history_.setHistory(globalId, partnerKeys, xi);
}


void Foam::demEngine::takeHistory
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
)
{
    editHistory();
    history_.take(globalId, partnerKeys, xi);
}


void Foam::demEngine::releaseHistory()
{
    editHistory();
    history_.clear();
}


void Foam::demEngine::editHistory()
{
    // Bring the store up to date before editing it; the working arrays are
    // reloaded from it at the next evaluation
    flushHistory();
    history_.invalidate();
    cache_.invalidate();
    pairs_.search().clear();
}


void Foam::demEngine::writePerformance(Ostream& os) const
{
    const scalar total =
        timePair_ + timeWall_ + timeNeighbour_ + timeIntegrate_;

    auto pct = [&](const scalar t)
    {
        return total > 0 ? 100*t/total : 0;
    };

    os  << "DEM performance: " << nSteps_ << " steps, "
        << (total > 0 ? nParticleSteps_/total : 0) << " particle-steps/s"
        << nl
        << "    pair " << timePair_ << " s (" << pct(timePair_) << " %), "
        << "wall " << timeWall_ << " s (" << pct(timeWall_) << " %), "
        << "neighbour " << timeNeighbour_ << " s (" << pct(timeNeighbour_)
        << " %, " << pairs_.search().nBuilds() << " builds, "
        << pairs_.nNearBuilds() << " near builds, "
        << label(pairs_.meanNear() + 0.5) << " of "
        << label(pairs_.meanListed() + 0.5)
        << " listed pairs near on average), "
        << "integrate " << timeIntegrate_ << " s ("
        << pct(timeIntegrate_) << " %)";
    if (halo_)
    {
        // Not in the rate either: the exchange (and the wait for the
        // slowest processor) is the parallel overhead
        os  << ", halo exchange " << timeHalo_ << " s (not in the rate)";
    }
    if (timeExternal_ > 0)
    {
        // Not in the rate: the gas forces cost what the fluid model costs
        os  << ", sub-step fluid forces " << timeExternal_ << " s (not in"
            << " the rate)";
    }
    os  << endl;
}


// ************************************************************************* //
