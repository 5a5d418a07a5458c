/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "forceCache.H"
#include "Map.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::forceCache::store(const demState& s)
{
    id_ = s.globalId;
    x_ = s.x;
    v_ = s.v;
    omega_ = s.omega;
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

    if (!valid_ || n != x_.size())
    {
        return false;
    }

    // Rows in the same order (the usual case): compare directly
    bool sameOrder = true;
    forAll(x_, p)
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
        const label q = from[p];
        if (s.x[p] != x_[q] || s.v[p] != v_[q] || s.omega[p] != omega_[q])
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
