/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "forceCache.H"
#include "Map.H"
#include "splitmix.H"
#include <cstring>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

uint64_t Foam::forceCache::rowHash(const demState& s, const label p)
{
    uint64_t h = 0;
    for (const vector* w : {&s.x[p], &s.v[p], &s.omega[p]})
    {
        for (direction c = 0; c < vector::nComponents; ++c)
        {
            // + 0.0 makes -0 into +0: they compare equal as values
            const double value = w->component(c) + 0.0;
            uint64_t bits;
            std::memcpy(&bits, &value, sizeof(bits));
            h = splitmix(h ^ bits);
        }
    }
    return h;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::forceCache::store(const demState& s)
{
    const label n = s.size();
    id_ = s.globalId;
    hash_.setSize(n);
    for (label p = 0; p < n; ++p)
    {
        hash_[p] = rowHash(s, p);
    }
    valid_ = true;
}


bool Foam::forceCache::reuse
(
    const demState& s,
    List<vector>& f,
    List<vector>& t
) const
{
    const label n = s.size();

    if (!valid_ || n != hash_.size())
    {
        return false;
    }

    // Rows in the same order (the usual case): compare directly
    bool sameOrder = true;
    forAll(id_, p)
    {
        if (s.globalId[p] != id_[p])
        {
            sameOrder = false;
            break;
        }
    }

    labelList from(identity(n));
    if (!sameOrder)
    {
        // The cloud reordered its parcels: match them by globalId
        Map<label> rowOf(2*n);
        forAll(id_, p)
        {
            rowOf.insert(id_[p], p);
        }
        forAll(from, p)
        {
            const auto iter = rowOf.cfind(s.globalId[p]);
            if (!iter.found())
            {
                return false;
            }
            from[p] = iter.val();
        }
    }

    forAll(from, p)
    {
        if (rowHash(s, p) != hash_[from[p]])
        {
            return false;
        }
    }

    if (!sameOrder)
    {
        const List<vector> f0(f), t0(t);
        forAll(from, p)
        {
            f[p] = f0[from[p]];
            t[p] = t0[from[p]];
        }
    }

    return true;
}


// ************************************************************************* //
