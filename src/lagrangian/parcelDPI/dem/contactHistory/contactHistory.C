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
#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::pair<std::size_t, std::size_t> Foam::contactHistory::range
(
    const label globalId
) const
{
    const std::uint64_t lo = key(globalId, 0);
    const std::uint64_t hi = lo | 0xFFFFFFFFu;
    const auto first = store_.begin();
    const auto last = first + nSorted_;
    const auto b = std::lower_bound
    (
        first, last, lo,
        [](const entry& e, const std::uint64_t k) { return e.key < k; }
    );
    const auto e = std::upper_bound
    (
        b, last, hi,
        [](const std::uint64_t k, const entry& e) { return k < e.key; }
    );
    return {std::size_t(b - first), std::size_t(e - first)};
}


void Foam::contactHistory::sortUnique
(
    const std::size_t from,
    const bool unique
) const
{
    const auto byKey = [](const entry& a, const entry& b)
    {
        return a.key < b.key;
    };
    if (unique)
    {
        // In place (a stable sort takes a buffer of up to the entries'
        // size)
        std::sort(store_.begin() + from, store_.end(), byKey);
    }
    else
    {
        // Stable, so that of equal keys the last given stays (as a map's
        // assignment kept it)
        std::stable_sort(store_.begin() + from, store_.end(), byKey);
    }

    std::size_t out = from;
    for (std::size_t i = from; i < store_.size(); ++i)
    {
        if (i + 1 < store_.size() && store_[i + 1].key == store_[i].key)
        {
            continue;
        }
        if (store_[i].xi != vector::zero)
        {
            store_[out++] = store_[i];
        }
    }
    store_.resize(out);
}


void Foam::contactHistory::sortIn() const
{
    if (callOwner_.empty())
    {
        return;
    }

    // An owner given twice: only its last call counts. (The callers give
    // each owner once between two reads; this keeps the meaning of
    // "replace" if one does not.)
    std::vector<std::pair<label, label>> last(callOwner_.size());
    for (std::size_t c = 0; c < callOwner_.size(); ++c)
    {
        last[c] = {callOwner_[c], label(c)};
    }
    std::sort(last.begin(), last.end());
    bool repeated = false;
    for (std::size_t c = 1; c < last.size(); ++c)
    {
        repeated = repeated || last[c].first == last[c - 1].first;
    }
    if (repeated)
    {
        std::size_t out = nSorted_;
        for (std::size_t i = nSorted_; i < store_.size(); ++i)
        {
            const label owner = label(std::int32_t(store_[i].key >> 32));
            // The owner's last call: the end of its run in last
            const auto it = std::upper_bound
            (
                last.begin(), last.end(),
                std::pair<label, label>(owner, labelMax)
            );
            if ((it - 1)->second == callOf_[i - nSorted_])
            {
                store_[out++] = store_[i];
            }
        }
        store_.resize(out);
    }

    // The new entries sorted, then merged with the sorted ones, whose
    // owners given again are zero already (erase), and the zeros dropped
    const std::size_t nOld = nSorted_;
    sortUnique(nOld, false);
    std::inplace_merge
    (
        store_.begin(),
        store_.begin() + nOld,
        store_.end(),
        [](const entry& a, const entry& b) { return a.key < b.key; }
    );
    store_.erase
    (
        std::remove_if
        (
            store_.begin(),
            store_.end(),
            [](const entry& e) { return e.xi == vector::zero; }
        ),
        store_.end()
    );
    nSorted_ = store_.size();

    std::vector<label>().swap(callOf_);
    std::vector<label>().swap(callOwner_);
}


Foam::label Foam::contactHistory::size() const
{
    sortIn();
    label n = 0;
    for (const entry& e : store_)
    {
        n += (e.xi != vector::zero);
    }
    return n;
}


void Foam::contactHistory::clear()
{
    std::vector<entry>().swap(store_);
    nSorted_ = 0;
    std::vector<label>().swap(callOf_);
    std::vector<label>().swap(callOwner_);
}


void Foam::contactHistory::reserve(const label n)
{
    store_.reserve(store_.size() + n);
    callOf_.reserve(callOf_.size() + n);
}


Foam::vector Foam::contactHistory::find
(
    const label owner,
    const label partner
) const
{
    sortIn();
    const std::uint64_t k = key(owner, partner);
    const auto last = store_.begin() + nSorted_;
    const auto it = std::lower_bound
    (
        store_.begin(), last, k,
        [](const entry& e, const std::uint64_t k) { return e.key < k; }
    );
    return (it != last && it->key == k) ? it->xi : vector::zero;
}


void Foam::contactHistory::erase(const label globalId)
{
    // Zeroed in place, not moved out: collect takes every row's contacts
    // one row after the other, and closing each gap would cost the whole
    // store every time. Reads skip zeros; the next sort drops them
    const auto r = range(globalId);
    for (std::size_t i = r.first; i < r.second; ++i)
    {
        store_[i].xi = vector::zero;
    }
}


void Foam::contactHistory::history
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
) const
{
    sortIn();
    const auto r = range(globalId);
    for (std::size_t i = r.first; i < r.second; ++i)
    {
        if (store_[i].xi != vector::zero)
        {
            partnerKeys.append
            (
                label(std::int32_t(store_[i].key & 0xFFFFFFFFu))
            );
            xi.append(store_[i].xi);
        }
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

    // The owner's sorted contacts go now; the new ones wait at the end
    // until the next read sorts them in (the hand-over gives every row's
    // contacts in turn: one sort for all)
    erase(globalId);

    // A zero xi is kept until the sort: it undoes an equal key before it
    // in the call (the sort keeps the last of equal keys, then drops zeros)
    const label call = label(callOwner_.size());
    callOwner_.push_back(globalId);
    forAll(xi, i)
    {
        store_.push_back({key(globalId, partnerKeys[i]), xi[i]});
        callOf_.push_back(call);
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
    // (max: GCC cannot tell that a size is not negative and warns of a
    // huge allocation, -Walloc-size-larger-than)
    List<bool> has(max(m, label(0)), false);

    if (nearFromStore_)
    {
        forAll(pairRow, a)
        {
            const label idi = workingIds_[pairRow[a]];
            for (label k = nearStart[a]; k < nearStart[a + 1]; ++k)
            {
                // Stored as the smaller globalId's; the sweep's first row
                // may be the other (neighbourSearch/order morton), whose
                // spring is the opposite
                const label idj = workingIds_[nearJ[k]];
                xi[k] = idi < idj ? find(idi, idj) : -find(idj, idi);
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

    // Rebuilt from the copy, at its size (a contact not in it has
    // separated): pairs whose xi is not zero, and the walls' contacts
    label n = 0;
    forAll(nearXi_, k)
    {
        n += (nearHasXi_[k] && nearXi_[k] != vector::zero);
    }
    for (const DynamicList<wallContact>& ws : wallState_)
    {
        n += ws.size();
    }
    clear();
    store_.reserve(n);

    forAll(pairRow, a)
    {
        const label idi = workingIds_[pairRow[a]];
        for (label k = nearStart[a]; k < nearStart[a + 1]; ++k)
        {
            if (nearHasXi_[k] && nearXi_[k] != vector::zero)
            {
                // As the smaller globalId's (toNear)
                const label idj = workingIds_[nearJ[k]];
                store_.push_back
                (
                    idi < idj
                  ? entry{key(idi, idj), nearXi_[k]}
                  : entry{key(idj, idi), -nearXi_[k]}
                );
            }
        }
    }

    forAll(wallState_, p)
    {
        for (const wallContact& w : wallState_[p])
        {
            store_.push_back
            (
                {key(workingIds_[p], wallPartnerKey(w.wall, w.key)), w.xi}
            );
        }
    }

    // Its keys are unique: a near pair once, a row's wall contact once
    sortUnique(0, true);
    nSorted_ = store_.size();
}


// ************************************************************************* //
