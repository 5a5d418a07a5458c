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
    nearSkin_(0),
    nearCurrent_(false),
    nNearBuilds_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pairContacts::build
(
    const demState& s,
    const contactModels& models,
    const scalar range
)
{
    const label n = s.size();

    // A near list of the old half list means nothing for the new one
    nearCurrent_ = false;

    search_.build
    (
        s,
        [&models](const scalar ri, const scalar rj)
        {
            return models.maxPairRange(ri, rj);
        }
    );

    // The half list in globalId order
    const DynamicList<labelPair>& pairs = search_.pairs();
    const label np = pairs.size();
    const labelUList& id = s.globalId;

    labelList byId(identity(n));
    std::sort
    (
        byId.begin(),
        byId.end(),
        [&id](const label a, const label b) { return id[a] < id[b]; }
    );

    labelList fill(n, 0);
    for (const labelPair& pr : pairs)
    {
        ++fill[pr.first()];
    }

    pairRow_.setSize(n);
    pairStart_.setSize(n + 1);
    label nRows = 0;
    label k = 0;
    for (const label i : byId)
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
        pairJ_[fill[pr.first()]++] = pr.second();
    }

    for (label a = 0; a < nRows; ++a)
    {
        std::sort
        (
            pairJ_.begin() + pairStart_[a],
            pairJ_.begin() + pairStart_[a + 1],
            [&id](const label a, const label b) { return id[a] < id[b]; }
        );
    }

    // The cut-off of the global range (as before per-pair ranges) is kept
    // where it is the smaller, so that a pair at the edge of the range is
    // decided exactly as it was; the per-pair one has a margin far above
    // round-off, so it drops only pairs that are certainly out of range
    pairCut2_.setSize(np);
    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            const label j = pairJ_[k];
            const scalar rSum = s.r[i] + s.r[j];
            const scalar pairRange = models.maxPairRange(s.r[i], s.r[j]);
            pairCut2_[k] = min
            (
                sqr(rSum + range),
                sqr((rSum + pairRange)*(1 + 1e-9))
            );
        }
    }
}


void Foam::pairContacts::syncHistory(contactHistory& h) const
{
    if (nearCurrent_)
    {
        h.syncPairs(nearK_);
    }
}


bool Foam::pairContacts::nearValid(const demState& s) const
{
    if (!nearCurrent_ || nearX0_.size() != s.size())
    {
        return false;
    }

    const scalar maxMove2 = sqr(0.5*nearSkin_);
    forAll(nearX0_, p)
    {
        if (magSqr(s.x[p] - nearX0_[p]) > maxMove2)
        {
            return false;
        }
    }
    return true;
}


void Foam::pairContacts::buildNear
(
    const demState& s,
    const scalar dt,
    contactHistory& h
)
{
    // A near build about every 25 steps at the fastest row's speed (its
    // cost is about one sweep without forces), within 5 % and 100 % of the
    // Verlet skin
    // The history of the last near list of this half list, to carry over
    syncHistory(h);

    const scalar skin = search_.skin();
    scalar v2Max = 0;
    for (const vector& v : s.v)
    {
        v2Max = max(v2Max, magSqr(v));
    }
    nearSkin_ = min(skin, max(0.05*skin, 2*25*sqrt(v2Max)*dt));

    nearX0_ = s.x;

    const label np = pairJ_.size();
    nearStart_.setSize(pairRow_.size() + 1);
    nearK_.setSize(np);
    nearJ_.setSize(np);
    nearCut2_.setSize(np);

    label m = 0;
    forAll(pairRow_, a)
    {
        nearStart_[a] = m;
        const point& xi = s.x[pairRow_[a]];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            const label j = pairJ_[k];
            // Left out: at least sqrt(pairCut2) + nearSkin apart, so at
            // least sqrt(pairCut2) while no row moves more than half the
            // near skin (the margin covers round-off)
            const scalar reach =
                (sqrt(pairCut2_[k]) + nearSkin_)*(1 + 1e-9);
            if (magSqr(xi - s.x[j]) < sqr(reach))
            {
                nearK_[m] = k;
                nearJ_[m] = j;
                nearCut2_[m] = pairCut2_[k];
                ++m;
            }
        }
    }
    nearStart_[pairRow_.size()] = m;
    nearK_.setSize(m);
    nearJ_.setSize(m);
    nearCut2_.setSize(m);

    h.toNear(nearK_);
    nearCurrent_ = true;

    ++nNearBuilds_;
}


// ************************************************************************* //
