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


void Foam::contactHistory::erase(const label globalId)
{
    const std::uint64_t lo = key(globalId, 0);
    const std::uint64_t hi = lo | 0xFFFFFFFFu;
    store_.erase(store_.lower_bound(lo), store_.upper_bound(hi));
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


void Foam::contactHistory::take
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
)
{
    history(globalId, partnerKeys, xi);
    erase(globalId);
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

    erase(globalId);

    forAll(xi, i)
    {
        set(globalId, partnerKeys[i], xi[i]);
    }
}


void Foam::contactHistory::load(const labelUList& ids)
{
    nearFromStore_ = true;

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


void Foam::contactHistory::toNear
(
    const labelUList& pairRow,
    const labelUList& nearStart,
    const labelUList& nearJ,
    const labelUList& nearK,
    const labelUList& oldNearK
)
{
    const label m = nearK.size();
    List<vector> xi(m, Zero);
    List<bool> has(m, false);

    if (nearFromStore_)
    {
        forAll(pairRow, a)
        {
            const label idi = workingIds_[pairRow[a]];
            for (label k = nearStart[a]; k < nearStart[a + 1]; ++k)
            {
                xi[k] = find(idi, workingIds_[nearJ[k]]);
                has[k] = (xi[k] != vector::zero);
            }
        }
    }
    else
    {
        if (oldNearK.size() != nearXi_.size())
        {
            FatalErrorInFunction
                << "The previous near list (" << oldNearK.size()
                << " pairs) is not the one of the working history ("
                << nearXi_.size() << ")" << abort(FatalError);
        }

        // Both lists ascend in the listed pair: one merge
        label o = 0;
        forAll(nearK, k)
        {
            while (o < oldNearK.size() && oldNearK[o] < nearK[k])
            {
                ++o;
            }
            if (o < oldNearK.size() && oldNearK[o] == nearK[k])
            {
                xi[k] = nearXi_[o];
                has[k] = nearHasXi_[o];
            }
        }
    }

    nearXi_.transfer(xi);
    nearHasXi_.transfer(has);
    nearFromStore_ = false;
}


void Foam::contactHistory::flush
(
    const labelUList& pairRow,
    const labelUList& nearStart,
    const labelUList& nearJ
)
{
    if (!workingValid_)
    {
        return;
    }
    if (nearFromStore_ || nearJ.size() != nearXi_.size())
    {
        FatalErrorInFunction
            << "The working history has no near list to write back ("
            << nearXi_.size() << " pairs against " << nearJ.size() << ")"
            << abort(FatalError);
    }

    store_.clear();

    forAll(pairRow, a)
    {
        const label idi = workingIds_[pairRow[a]];
        for (label k = nearStart[a]; k < nearStart[a + 1]; ++k)
        {
            if (nearHasXi_[k] && nearXi_[k] != vector::zero)
            {
                set(idi, workingIds_[nearJ[k]], nearXi_[k]);
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
