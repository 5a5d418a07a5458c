/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "contactHistory.H"
#include "error.H"

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


// ************************************************************************* //
