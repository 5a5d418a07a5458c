/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    demEngine::checkStartState: the parcels a run starts from or has just
    injected, before any force is evaluated. A contact law assumes the
    parcels came together at a finite speed; a start inside another parcel
    or a wall releases the stored elastic energy at once (two API parcels
    overlapping by half a radius fly apart at ~50 m/s), and coincident
    centres have no contact normal at all (0/0 in the pair force): those
    are refused whatever dem/startOverlap/refuse allows.

\*---------------------------------------------------------------------------*/

#include "demEngine.H"
#include <sstream>
#include "HashTable.H"
#include "FixedList.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
    //- The worst start overlap seen: ratio delta/R*, the two globalIds
    //  (the second -1 for a wall) and the wall's index
    struct startOverlap
    {
        scalar ratio = 0;
        label idA = -1;
        label idB = -1;
        label wall = -1;
        label count = 0;
        //- 1 if a centre lies inside the other sphere (or on the wall)
        label inside = 0;
        //- A pair of coincident centres (no contact normal): the globalIds,
        //  -1 if none
        label sameA = -1;
        label sameB = -1;
    };

    //- A ratio to 3 digits: what the user needs to read
    static std::string threeDigits(const scalar x)
    {
        std::ostringstream os;
        os.precision(3);
        os << x;
        return os.str();
    }

    static Ostream& operator<<(Ostream& os, const startOverlap& o)
    {
        return os << o.ratio << ' ' << o.idA << ' ' << o.idB << ' '
            << o.wall << ' ' << o.count << ' ' << o.inside << ' '
            << o.sameA << ' ' << o.sameB;
    }

    static Istream& operator>>(Istream& is, startOverlap& o)
    {
        return is >> o.ratio >> o.idA >> o.idB >> o.wall >> o.count
            >> o.inside >> o.sameA >> o.sameB;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demEngine::checkStartState(const demState& s, const word& when)
{
    const label nOwned = s.owned();

    // A parcel with no size, no mass or a non-finite state cannot enter
    // any force law: name it
    for (label p = 0; p < nOwned; ++p)
    {
        const bool finite =
            std::isfinite(s.x[p].x()) && std::isfinite(s.x[p].y())
         && std::isfinite(s.x[p].z()) && std::isfinite(magSqr(s.v[p]))
         && std::isfinite(magSqr(s.omega[p]));
        if (!(s.r[p] > 0) || !(s.m[p] > 0) || !finite)
        {
            FatalErrorInFunction
                << "Parcel " << s.globalId[p] << " (" << when << ") has "
                << "diameter " << 2*s.r[p] << " m, mass " << s.m[p]
                << " kg, position " << s.x[p] << ", velocity " << s.v[p]
                << ", spin " << s.omega[p] << nl
                << "    every parcel needs d > 0, a mass > 0 and a finite"
                << " state: correct its entry in the injector's list or"
                << " the time directory's lagrangian fields"
                << exit(FatalError);
        }
    }

    const coarseGrainingModel& cg = materials_.coarseGraining();
    const scalar rMax = cg.maxRadius(s.r, s.typeId);

    // Pairs: a grid of cells 2 rMax wide (the contact radii: parcels that
    // meet each other at grown radii), so an overlapping pair lies in
    // neighbouring cells
    startOverlap warnPair, worst;
    const scalar h = 2*max(rMax, VSMALL);
    typedef FixedList<label, 3> cellKey;
    HashTable<DynamicList<label>, cellKey, cellKey::Hash<>> grid(2*s.size());
    auto keyOf = [h](const point& x)
    {
        cellKey k;
        k[0] = label(std::floor(x.x()/h));
        k[1] = label(std::floor(x.y()/h));
        k[2] = label(std::floor(x.z()/h));
        return k;
    };
    forAll(s.x, p)
    {
        grid(keyOf(s.x[p])).append(p);
    }

    for (label i = 0; i < nOwned; ++i)
    {
        const cellKey ki = keyOf(s.x[i]);
        cellKey k;
        for (k[0] = ki[0] - 1; k[0] <= ki[0] + 1; ++k[0])
        for (k[1] = ki[1] - 1; k[1] <= ki[1] + 1; ++k[1])
        for (k[2] = ki[2] - 1; k[2] <= ki[2] + 1; ++k[2])
        {
            const auto iter = grid.cfind(k);
            if (!iter.found())
            {
                continue;
            }
            for (const label j : *iter)
            {
                // Each pair once: by globalId (a pair with a halo copy is
                // seen by both owners, which report the same ids)
                if (s.globalId[j] <= s.globalId[i])
                {
                    continue;
                }
                const scalar rSum =
                    cg.radiusSum(s.r[i], s.typeId[i], s.r[j], s.typeId[j]);
                const scalar dist = mag(s.x[i] - s.x[j]);
                if (dist >= rSum)
                {
                    continue;
                }
                // Centres within round-off of each other: the pair force
                // divides by the distance (0/0), whatever the overlap
                // allowed
                if (dist <= 1e-9*rSum && worst.sameA < 0)
                {
                    worst.sameA = s.globalId[i];
                    worst.sameB = s.globalId[j];
                }
                const scalar Rstar = s.r[i]*s.r[j]/(s.r[i] + s.r[j]);
                const scalar ratio = (rSum - dist)/Rstar;
                if (ratio > overlap_.startWarn())
                {
                    ++worst.count;
                }
                if (ratio > worst.ratio)
                {
                    worst.ratio = ratio;
                    worst.idA = s.globalId[i];
                    worst.idB = s.globalId[j];
                    worst.wall = -1;
                    worst.inside = dist < max(s.r[i], s.r[j]);
                }
            }
        }
    }

    // Walls: the overlap of a sphere with a wall is r - distance (R* = r);
    // a centre on the wall gives 1
    if (walls_.size())
    {
        walls_.prepare(rMax);
    }
    DynamicList<demWallContact> contacts;
    for (label p = 0; p < nOwned; ++p)
    {
        forAll(walls_.walls(), w)
        {
            contacts.clear();
            walls_.walls()[w].findContacts(s.x[p], s.r[p], contacts);
            for (const demWallContact& c : contacts)
            {
                const scalar ratio = (s.r[p] - c.distance)/s.r[p];
                if (ratio > overlap_.startWarn())
                {
                    ++worst.count;
                }
                if (ratio > worst.ratio)
                {
                    worst.ratio = ratio;
                    worst.idA = s.globalId[p];
                    worst.idB = -1;
                    worst.wall = w;
                    worst.inside = c.distance <= 0;
                }
            }
        }
    }

    // The worst over all processors, the same decision everywhere
    List<startOverlap> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = worst;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    label nOver = 0;
    worst = startOverlap();
    labelPair same(-1, -1);
    for (const startOverlap& o : all)
    {
        nOver += o.count;
        if (o.ratio > worst.ratio)
        {
            worst = o;
        }
        if (o.sameA >= 0 && same.first() < 0)
        {
            same = labelPair(o.sameA, o.sameB);
        }
    }

    // No setting makes coincident centres work: refused, and nothing
    // advised but moving them apart
    if (same.first() >= 0)
    {
        FatalErrorInFunction
            << "Parcels " << same.first() << " and " << same.second()
            << " (" << when << ") have the same centre: a contact between"
            << " them has no direction, whatever dem/startOverlap/refuse"
            << " allows." << nl
            << "    Move or remove one of them (the injectors' positions,"
            << " or the time directory's lagrangian fields)"
            << exit(FatalError);
    }

    if (worst.ratio <= overlap_.startWarn())
    {
        return;
    }

    const std::string what
    (
        worst.wall < 0
      ? "parcels " + Foam::name(worst.idA) + " and " + Foam::name(worst.idB)
      : "parcel " + Foam::name(worst.idA) + " and wall "
      + walls_.walls()[worst.wall].name()
    );

    if (worst.ratio > overlap_.startRefuse())
    {
        FatalErrorInFunction
            << "The parcels " << when << " overlap: " << nOver
            << " contacts above " << overlap_.startWarn() << " R*, the largest "
            << threeDigits(worst.ratio).c_str() << " R* (" << what.c_str()
            << ")"
            << (
                   worst.inside
                 ? (worst.wall < 0 ? "; a centre inside the other parcel"
                                   : "; its centre on the wall")
                 : ""
               )
            << ". A contact starting this deep releases its elastic"
            << " energy at once (parcels fly apart at up to tens of m/s)."
            << nl
            << "    Move or remove those parcels (injector positions, packing"
            << " region away from the walls), or, for a packed start that"
            << " is meant to relax, raise dem/startOverlap/refuse above "
            << threeDigits(worst.ratio).c_str() << " (default 0.1; warn "
            << overlap_.startWarn() << ")"
            << (
                   cg.grows()
                 ? ". With coarseGraining " + cg.type() + ", API parcels"
                   " touch each other at their grown radii (sqrt(N) x the"
                   " primary's): place them that far apart, as"
                   " regionPacking does"
                 : std::string()
               ).c_str()
            << exit(FatalError);
    }

    WarningInFunction
        << "The parcels " << when << " overlap: " << nOver << " contacts"
        << " above " << overlap_.startWarn() << " R*, the largest "
        << threeDigits(worst.ratio).c_str() << " R* (" << what.c_str()
        << "); accepted up to"
        << " dem/startOverlap/refuse " << overlap_.startRefuse() << endl;
}


// ************************************************************************* //
