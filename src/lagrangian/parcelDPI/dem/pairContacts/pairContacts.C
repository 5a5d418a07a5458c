/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "pairContacts.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pairContacts::pairContacts(const scalar skin)
:
    search_(skin),
    models_(nullptr),
    range_(0),
    cg_(nullptr),
    knocks_(false),
    nearSkin_(0),
    nearCurrent_(false),
    nNearBuilds_(0),
    sumListed_(0),
    sumNear_(0),
    copyPairs_(true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pairContacts::build
(
    const demState& s,
    const contactModels& models,
    const scalar range,
    const coarseGrainingModel& cg
)
{
    const label n = s.size();

    // A near list of the old half list means nothing for the new one
    nearCurrent_ = false;

    cg_ = &cg;
    knocks_ = cg.grows() && cg.knockShare() > 0;

    const auto pairRange = [&models](const scalar ri, const scalar rj)
    {
        return models.maxPairRange(ri, rj);
    };
    if (cg.grows())
    {
        // Parcels that meet each other at grown radii are searched at
        // those (their pairs with other rows are then listed a little
        // farther than needed, and trimmed at the near build)
        scalarList reach(s.r);
        forAll(reach, p)
        {
            reach[p] *= cg.factor(s.typeId[p]);
        }
        search_.build(s, reach, pairRange);
    }
    else
    {
        search_.build(s, pairRange);
    }

    // The half list in key order (demState::key). Unless copyPairs_, the pairs of two
    // halo copies (rows from s.owned() on) are left out: only owned rows
    // are integrated, and the owners evaluate these pairs; their forces on
    // the copies would be thrown away (50,000 carriers on 2 processes: 1
    // in 11 of a processor's near pairs)
    const DynamicList<labelPair>& pairs = search_.pairs();
    const label firstCopy = (copyPairs_ || knocks_) ? n : s.owned();
    const auto listed = [firstCopy](const labelPair& pr)
    {
        return pr.first() < firstCopy || pr.second() < firstCopy;
    };
    const UList<uint64_t>& key = s.key;

    labelList byKey(identity(n));
    std::sort
    (
        byKey.begin(),
        byKey.end(),
        [&key](const label a, const label b) { return key[a] < key[b]; }
    );

    labelList fill(n, 0);
    label np = 0;
    for (const labelPair& pr : pairs)
    {
        if (listed(pr))
        {
            ++fill[pr.first()];
            ++np;
        }
    }

    pairRow_.setSize(n);
    pairStart_.setSize(n + 1);
    label nRows = 0;
    label k = 0;
    for (const label i : byKey)
    {
        if (fill[i])
        {
            pairRow_[nRows] = i;
            pairStart_[nRows] = k;
            ++nRows;
            const label count = fill[i];
            fill[i] = k;
            k += count;
        }
    }
    pairStart_[nRows] = k;
    pairRow_.setSize(nRows);
    pairStart_.setSize(nRows + 1);

    pairJ_.setSize(np);
    for (const labelPair& pr : pairs)
    {
        if (listed(pr))
        {
            pairJ_[fill[pr.first()]++] = pr.second();
        }
    }

    for (label a = 0; a < nRows; ++a)
    {
        std::sort
        (
            pairJ_.begin() + pairStart_[a],
            pairJ_.begin() + pairStart_[a + 1],
            [&key](const label a, const label b) { return key[a] < key[b]; }
        );
    }

    tracked_.setSize(n);
    tracked_ = false;
    for (label a = 0; a < nRows; ++a)
    {
        tracked_[pairRow_[a]] = true;
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            tracked_[pairJ_[k]] = true;
        }
    }

    models_ = &models;
    range_ = range;

    search_.releasePairs();
}


bool Foam::pairContacts::nearValid(const demState& s) const
{
    if
    (
        !nearCurrent_
     || nearX0_.size() != s.size()
     || tracked_.size() != s.size()
    )
    {
        return false;
    }

    const scalar maxMove2 = sqr(0.5*nearSkin_);
    forAll(nearX0_, p)
    {
        if (tracked_[p] && magSqr(s.x[p] - nearX0_[p]) > maxMove2)
        {
            return false;
        }
    }
    return true;
}


namespace Foam
{
    // The loop of pairContacts::columnGeometry. Each iteration is
    // independent and the same arithmetic as one pair's alone, so the
    // compiler does two pairs per instruction (square roots and divisions:
    // the pair term -13 % on a packed bed of 2,000 carriers, no change at
    // 10,000, where the sweep waits on memory) with the same results to the
    // bit. (Its columns are arguments: with them as local restrict
    // pointers the compiler does not vectorise it.)
    static void pairGeometry
    (
        const label n,
        scalar* __restrict__ dx,
        scalar* __restrict__ dy,
        scalar* __restrict__ dz,
        scalar* __restrict__ delta,
        scalar* __restrict__ a,
        scalar* __restrict__ ratio,
        const scalar* __restrict__ r2,
        const scalar* __restrict__ rSum,
        const scalar* __restrict__ Rstar
    )
    {
        for (label k = 0; k < n; ++k)
        {
            const scalar r = std::sqrt(r2[k]);
            dx[k] /= r;
            dy[k] /= r;
            dz[k] /= r;
            delta[k] = rSum[k] - r;
            // A separated pair's is not used: 0, not the square root of a
            // negative number
            a[k] = std::sqrt(Rstar[k]*std::max(delta[k], scalar(0)));
            // The overlap ratio the diagnostics record (a division per
            // touching pair, here two per instruction)
            ratio[k] = delta[k]/Rstar[k];
        }
    }
}


void Foam::pairContacts::columnGeometry(const label n) const
{
    pairGeometry
    (
        n,
        dx_.data(),
        dy_.data(),
        dz_.data(),
        delta_.data(),
        a_.data(),
        ratio_.data(),
        r2_.cdata(),
        rSum_.cdata(),
        Rstar_.cdata()
    );
}


void Foam::pairContacts::buildNear
(
    const demState& s,
    const scalar dt,
    contactHistory& h
)
{
    // A near build about every 25 steps at the fastest row's speed (its
    // cost is about one sweep without forces), within 0.2 % and 100 % of
    // the Verlet skin. The floor decides only near rest (a settled bed),
    // where builds are rare whatever it is; there each near pair beyond
    // contact is streamed at every step for nothing: the 10,000-carrier
    // packed bed listed 31,500 near pairs at a floor of 5 %, 23,700 at
    // 0.2 % (6 near builds in 5,000 steps, pair term -15 %). Builds stay
    // at most one per 25 steps of the fastest row.
    // The listed pairs of the last near list of this half list, whose
    // history carries over
    labelList oldNearK;
    if (nearCurrent_)
    {
        oldNearK.transfer(nearK_);
    }

    const scalar skin = search_.skin();
    scalar v2Max = 0;
    forAll(s.v, p)
    {
        if (tracked_[p])
        {
            v2Max = max(v2Max, magSqr(s.v[p]));
        }
    }
    nearSkin_ = min(skin, max(0.002*skin, 2*25*sqrt(v2Max)*dt));

    nearX0_ = s.x;

    // Which listed pairs are near, then the near list at its size: sized
    // to the listed pairs (five to ten times as many in a packed bed) it
    // would set the run's peak memory
    const label np = pairJ_.size();
    List<bool> near(np);
    label m = 0;
    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        const point& xi = s.x[i];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            // Left out: at least sqrt(cut2) + nearSkin apart, so at least
            // sqrt(cut2) while no row moves more than half the near skin
            // (the margin covers round-off)
            const label j = pairJ_[k];
            const scalar reach = (sqrt(cut2(s, i, j)) + nearSkin_)*(1 + 1e-9);
            near[k] = magSqr(xi - s.x[j]) < sqr(reach);
            m += near[k];
        }
    }

    nearStart_.setSize(pairRow_.size() + 1);
    nearK_.clear();
    nearJ_.clear();
    nearCut2_.clear();
    nearRstar_.clear();
    nearMstar_.clear();
    nearRSum_.clear();
    nearK_.setSize(m);
    nearJ_.setSize(m);
    nearCut2_.setSize(m);
    nearRstar_.setSize(m);
    nearMstar_.setSize(m);
    nearRSum_.setSize(m);
    DynamicList<labelPair> seatPairs;

    m = 0;
    forAll(pairRow_, a)
    {
        nearStart_[a] = m;
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            if (near[k])
            {
                const label i = pairRow_[a];
                const label j = pairJ_[k];
                nearK_[m] = k;
                nearJ_[m] = j;
                nearCut2_[m] = cut2(s, i, j);
                nearRstar_[m] = s.r[i]*s.r[j]/(s.r[i] + s.r[j]);
                nearMstar_[m] = s.m[i]*s.m[j]/(s.m[i] + s.m[j]);
                nearRSum_[m] = radiusSum(s, i, j);
                if (knocks_)
                {
                    const label ti = s.typeId[i];
                    const label tj = s.typeId[j];
                    if (cg_->factor(ti) > 1 && cg_->seat(tj))
                    {
                        seatPairs.append(labelPair(i, j));
                    }
                    else if (cg_->factor(tj) > 1 && cg_->seat(ti))
                    {
                        seatPairs.append(labelPair(j, i));
                    }
                }
                ++m;
            }
        }
    }
    nearStart_[pairRow_.size()] = m;
    nearSeat_.transfer(seatPairs);

    h.toNear(pairRow_, nearStart_, nearJ_, nearK_, oldNearK);
    nearCurrent_ = true;

    ++nNearBuilds_;
    sumListed_ += pairJ_.size();
    sumNear_ += nearK_.size();
}


void Foam::pairContacts::findSeats(const demState& s) const
{
    nSeats_.setSize(s.size());
    nSeats_ = 0;
    seats_.setSize(maxSeats*s.size());

    // In near order: each parcel's seats in the key order of its pairs,
    // the same on every processor that sees the parcel's near pairs
    for (const labelPair& ps : nearSeat_)
    {
        const label p = ps.first();
        const label seat = ps.second();
        if (magSqr(s.x[p] - s.x[seat]) < sqr(s.r[p] + s.r[seat]))
        {
            if (nSeats_[p] < maxSeats)
            {
                seats_[maxSeats*p + nSeats_[p]++] = seat;
            }
        }
    }
}


Foam::label Foam::pairContacts::commonSeat
(
    const demState& s,
    const label i,
    const label j
) const
{
    label best = -1;
    for (label a = 0; a < nSeats_[i]; ++a)
    {
        const label c = seats_[maxSeats*i + a];
        for (label b = 0; b < nSeats_[j]; ++b)
        {
            if
            (
                seats_[maxSeats*j + b] == c
             && (best < 0 || s.globalId[c] < s.globalId[best])
            )
            {
                best = c;
            }
        }
    }
    return best;
}


// ************************************************************************* //
