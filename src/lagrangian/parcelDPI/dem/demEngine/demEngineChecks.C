/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    demEngine's checks of the state it is given and of the state it leaves:
    the coarsening factors and types before a fluid step, the travel per
    DEM step and a non-finite state after it, the fluid step's overlaps
    and approach speeds (checkStep; the start's: demEngineStartCheck.C);
    the order of the pair sweep asked for, and the keys that give it.

\*---------------------------------------------------------------------------*/

#include "demEngine.H"
#include "PstreamReduceOps.H"
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::demEngine::readOrder(const dictionary& dict)
{
    const dictionary nsDict(dict.subOrEmptyDict("neighbourSearch"));
    const word order(nsDict.getOrDefault<word>("order", "globalId"));
    if (order != "globalId" && order != "morton")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown neighbourSearch/order '" << order
            << "' in dictionary " << dict.name() << nl
            << "    Valid choices: globalId (the default), morton"
            << exit(FatalIOError);
    }
    return order == "morton";
}


void Foam::demEngine::orderRows(demState& s, const label from) const
{
    if (!alongCurve_ || s.size() <= from)
    {
        return;
    }
    // Without a mesh (unit tests, serial) the rows' own box
    s.setMortonKeys
    (
        frame_.valid() ? frame_ : boundBox(s.x, false),
        materials_.maxDiameter(),
        from
    );
}


void Foam::demEngine::checkState(const demState& s) const
{
    scalar coarseN = -1;
    label coarseId = -1;

    forAll(s.N, i)
    {
        const scalar Ni = s.N[i];
        if (!(Ni > 0))
        {
            FatalErrorInFunction
                << "Parcel " << s.globalId[i] << " has N = " << Ni
                << "; the coarsening factor must be > 0"
                << exit(FatalError);
        }
        if (Ni > 1)
        {
            if (coarseN < 0)
            {
                coarseN = Ni;
                coarseId = s.globalId[i];
            }
            else if (Ni != coarseN)
            {
                FatalErrorInFunction
                    << "Parcels " << coarseId << " (N " << coarseN
                    << ") and " << s.globalId[i] << " (N " << Ni << ") are "
                    << "coarse-grained with different N > 1: the pair factor"
                    << " max(N_i, N_j) cannot conserve momentum between "
                    << "them (theory 2.4). Use one N for all parcels."
                    << exit(FatalError);
            }
        }
        if (s.typeId[i] < 0 || s.typeId[i] >= materials_.size())
        {
            FatalErrorInFunction
                << "Parcel " << s.globalId[i] << " has type index "
                << s.typeId[i] << "; types: " << materials_.names()
                << exit(FatalError);
        }
    }
}


void Foam::demEngine::checkEndState(const demState& s)
{
    const label n = s.owned();
    const scalar dt = timeStep_;

    // Travel per step in radii: once per fluid step (the contacts' checks
    // cannot see a parcel that jumps a wall or a partner between steps)
    for (label p = 0; p < n; ++p)
    {
        const scalar travel = mag(s.v[p])*dt/s.r[p];
        if (travel > diag_.stepMaxTravel)
        {
            diag_.stepMaxTravel = travel;
            diag_.travelId = s.globalId[p];
        }
    }

    // A non-finite state (only reachable with FOAM_SIGFPE off) must not be
    // written: the energies of the last sub-step sum every owned velocity
    if (!std::isfinite(diag_.kineticEnergy + diag_.rotationalEnergy))
    {
        for (label p = 0; p < n; ++p)
        {
            if
            (
                !std::isfinite(magSqr(s.x[p]))
             || !std::isfinite(magSqr(s.v[p]))
             || !std::isfinite(magSqr(s.omega[p]))
            )
            {
                FatalErrorInFunction
                    << "Parcel " << s.globalId[p] << " has a non-finite"
                    << " state at DEM time " << time_ << ": position "
                    << s.x[p] << ", velocity " << s.v[p] << ", spin "
                    << s.omega[p] << nl << "    Stopped before it is"
                    << " written; the last written time is intact. Look at"
                    << " this parcel's contacts and forces (trace"
                    << " { parcels (" << s.globalId[p] << "); })"
                    << exit(FatalError);
            }
        }
    }
}


void Foam::demEngine::checkStep(const word& t)
{
    const demDiagnostics& d = diagnostics();

    // The largest values over all processors, with the contact of the
    // processor that holds them (ties: the largest ids, the same anywhere)
    auto worst = [](const scalar local, const label pair[2], labelPair& ids)
    {
        const scalar global = returnReduce(local, maxOp<scalar>());
        ids = labelPair(labelMin, labelMin);
        if (local == global)
        {
            ids = labelPair(pair[0], pair[1]);
        }
        reduce(ids.first(), maxOp<label>());
        reduce(ids.second(), maxOp<label>());
        return global;
    };
    labelPair overlapIds, approachIds;
    const scalar overlap = worst(d.stepMaxOverlapRatio, d.overlapPair, overlapIds);
    const scalar approach = worst(d.stepMaxApproach, d.approachPair, approachIds);

    auto contactName = [this](const labelPair& ids)
    {
        const label b = ids.second();
        return
            "parcel " + Foam::name(ids.first())
          + (
                b >= 0
              ? " with parcel " + Foam::name(b)
              : " with wall " + walls()[-1 - b].name()
            );
    };

    const scalar vMax = maxImpactVelocity();

    const scalar travel = returnReduce(d.stepMaxTravel, maxOp<scalar>());
    if (travel > 1)
    {
        const label id = returnReduce
        (
            d.stepMaxTravel == travel ? d.travelId : labelMin,
            maxOp<label>()
        );
        FatalErrorInFunction
            << "At time " << t << " parcel " << id << " moves "
            << travel << " radii per DEM step (|v| dem/timeStep / r): it"
            << " can cross a wall or another parcel between two steps"
            << " without any contact being seen." << nl
            << "    Check what drives it (the time step was checked for"
            << " timeStepCheck/maxImpactVelocity " << vMax << " m/s), or"
            << " lower dem/timeStep. The last written time is intact."
            << exit(FatalError);
    }

    if (overlap > overlapRefuse())
    {
        FatalErrorInFunction
            << "At time " << t << " the contact of "
            << contactName(overlapIds).c_str() << " reached an overlap of "
            << overlap << " R*, above dem/overlapCheck/refuse "
            << overlapRefuse() << ": the contact is far outside"
            << " what Hertz contact describes, and a little more takes a"
            << " parcel through its partner." << nl
            << "    The fastest approach in this fluid step was " << approach
            << " m/s"
            << (
                   approachIds.first() >= 0
                 ? " (" + contactName(approachIds) + ")"
                 : std::string()
               ).c_str()
            << "; the time step was checked for"
            << " timeStepCheck/maxImpactVelocity "
            << vMax << " m/s. Check the speeds and forces that drive it"
            << " (gravity, cohesion, drag), raise maxImpactVelocity to what"
            << " the scene reaches (the start-up check then says whether"
            << " dem/timeStep and the stiffness resolve it), or raise"
            << " dem/overlapCheck/refuse to go on. The last written time is"
            << " intact." << exit(FatalError);
    }
    if (overlap > overlapWarn() && overlap > 2*warnedOverlap_)
    {
        WarningInFunction
            << "At time " << t << " the contact of "
            << contactName(overlapIds).c_str() << " reached an overlap of "
            << overlap << " R*, above dem/overlapCheck/warn "
            << overlapWarn() << " (Hertz contact assumes small"
            << " overlaps; the run stops at refuse "
            << overlapRefuse() << "). Said again if it doubles."
            << endl;
        warnedOverlap_ = overlap;
    }
    if (approach > vMax && approach > 2*warnedApproach_)
    {
        WarningInFunction
            << "At time " << t << " " << contactName(approachIds).c_str()
            << " approached at " << approach << " m/s, above"
            << " timeStepCheck/maxImpactVelocity " << vMax << " m/s that"
            << " the time step and overlaps were checked for at start-up:"
            << " raise it to what the scene reaches. Said again if it"
            << " doubles." << endl;
        warnedApproach_ = approach;
    }
}



// ************************************************************************* //
