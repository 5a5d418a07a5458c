/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    demEngine's checks of the state it is given and of the state it leaves:
    the coarsening factors and types before a fluid step, the travel per
    DEM step and a non-finite state after it; the order of the pair sweep
    asked for, and the keys that give it.

\*---------------------------------------------------------------------------*/

#include "demEngine.H"
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


// ************************************************************************* //
