/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "contactHistory.H"
#include "error.H"
#include "Map.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::contactHistory::find
(
    const label owner,
    const label partner
) const
{
    const auto iter = store_.find(key(owner, partner));
    return iter == store_.end() ? vector::zero : iter->second;
}


void Foam::contactHistory::set
(
    const label owner,
    const label partner,
    const vector& xi
)
{
    if (xi == vector::zero)
    {
        store_.erase(key(owner, partner));
    }
    else
    {
        store_[key(owner, partner)] = xi;
    }
}


void Foam::contactHistory::history
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
) const
{
    const std::uint64_t lo = key(globalId, 0);
    const std::uint64_t hi = lo | 0xFFFFFFFFu;

    for
    (
        auto iter = store_.lower_bound(lo);
        iter != store_.end() && iter->first <= hi;
        ++iter
    )
    {
        partnerKeys.append(label(std::int32_t(iter->first & 0xFFFFFFFFu)));
        xi.append(iter->second);
    }
}


void Foam::contactHistory::setHistory
(
    const label globalId,
    const labelUList& partnerKeys,
    const UList<vector>& xi
)
{
    if (partnerKeys.size() != xi.size())
    {
        FatalErrorInFunction
            << "Parcel " << globalId << ": " << partnerKeys.size()
            << " partner keys but " << xi.size() << " history vectors"
            << exit(FatalError);
    }

    const std::uint64_t lo = key(globalId, 0);
    const std::uint64_t hi = lo | 0xFFFFFFFFu;
    store_.erase(store_.lower_bound(lo), store_.upper_bound(hi));

    forAll(xi, i)
    {
        set(globalId, partnerKeys[i], xi[i]);
    }
}


void Foam::contactHistory::load
(
    const labelUList& ids,
    const labelUList& pairRow,
    const labelUList& pairStart,
    const labelUList& pairJ
)
{
    const label np = pairJ.size();
    pairXi_.setSize(np);
    pairHasXi_.setSize(np);
    forAll(pairRow, a)
    {
        const label idi = ids[pairRow[a]];
        for (label k = pairStart[a]; k < pairStart[a + 1]; ++k)
        {
            pairXi_[k] = find(idi, ids[pairJ[k]]);
            pairHasXi_[k] = (pairXi_[k] != vector::zero);
        }
    }

    Map<label> oldRow;
    List<DynamicList<wallContact>> oldState;
    if (wallState_.size() == workingIds_.size())
    {
        oldRow.resize(2*workingIds_.size());
        forAll(workingIds_, q)
        {
            oldRow.insert(workingIds_[q], q);
        }
        oldState.transfer(wallState_);
    }

    const label n = ids.size();
    wallState_.setSize(n);
    DynamicList<label> keys;
    DynamicList<vector> xis;
    for (label p = 0; p < n; ++p)
    {
        wallState_[p].clear();

        const auto iter = oldRow.cfind(ids[p]);
        if (iter.found() && iter.val() < oldState.size())
        {
            wallState_[p] = oldState[iter.val()];
            continue;
        }

        keys.clear();
        xis.clear();
        history(ids[p], keys, xis);
        forAll(keys, c)
        {
            if (keys[c] < 0)
            {
                const label code = -1 - keys[c];
                wallContact w;
                w.wall = code % maxWalls;
                w.key = code/maxWalls;
                w.n = Zero;     // unknown until the next evaluation
                w.xi = xis[c];
                wallState_[p].append(w);
            }
        }
    }

    workingIds_ = ids;
    workingValid_ = true;
}


void Foam::contactHistory::toNear(const labelUList& nearK)
{
    nearXi_.setSize(nearK.size());
    nearHasXi_.setSize(nearK.size());
    forAll(nearK, m)
    {
        nearXi_[m] = pairXi_[nearK[m]];
        nearHasXi_[m] = pairHasXi_[nearK[m]];
    }
}


void Foam::contactHistory::syncPairs(const labelUList& nearK)
{
    if (nearK.size() != nearXi_.size())
    {
        return;
    }
    pairXi_ = Zero;
    pairHasXi_ = false;
    forAll(nearK, m)
    {
        pairXi_[nearK[m]] = nearXi_[m];
        pairHasXi_[nearK[m]] = nearHasXi_[m];
    }
}


void Foam::contactHistory::flush
(
    const labelUList& pairRow,
    const labelUList& pairStart,
    const labelUList& pairJ
)
{
    if (!workingValid_)
    {
        return;
    }

    store_.clear();

    forAll(pairRow, a)
    {
        const label idi = workingIds_[pairRow[a]];
        for (label k = pairStart[a]; k < pairStart[a + 1]; ++k)
        {
            if (pairHasXi_[k] && pairXi_[k] != vector::zero)
            {
                set(idi, workingIds_[pairJ[k]], pairXi_[k]);
            }
        }
    }

    forAll(wallState_, p)
    {
        for (const wallContact& w : wallState_[p])
        {
            set(workingIds_[p], wallPartnerKey(w.wall, w.key), w.xi);
        }
    }
}


// ************************************************************************* //
