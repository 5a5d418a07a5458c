/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demState.H"
#include "UIndirectList.H"
#include "scalarList.H"
#include "vectorList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace Foam
{
    // The column operations of demState (one per member function)
    struct demStateClear
    {
        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c.clear();
        }
    };

    struct demStateGrow
    {
        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c.append(T());
        }
    };

    struct demStateResize
    {
        label n;

        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c.setSize(n);
        }
    };

    struct demStateReorder
    {
        const labelUList& order;

        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            const List<T> rows(UIndirectList<T>(c, order));
            forAll(rows, k)
            {
                c[k] = rows[k];
            }
        }
    };

    struct demStateReserve
    {
        label n;

        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            if (c.capacity() < n)
            {
                c.setCapacity(n);
            }
        }
    };
}


void Foam::demState::clear()
{
    forEachColumn(demStateClear());
    contactForcesValid = false;
    nOwned = -1;
}


void Foam::demState::reserve(const label n)
{
    forEachColumn(demStateReserve{n});
}


void Foam::demState::resize(const label n)
{
    reserve(n);
    forEachColumn(demStateResize{n});
}


void Foam::demState::reorder(const labelUList& order)
{
    forEachColumn(demStateReorder{order});
}


void Foam::demState::set
(
    const label row,
    const point& xi,
    const vector& vi,
    const vector& omegai,
    const scalar ri,
    const scalar mi,
    const scalar Ni,
    const label typei,
    const label globalIdi
)
{
    x[row] = xi;
    v[row] = vi;
    omega[row] = omegai;
    r[row] = ri;
    m[row] = mi;
    N[row] = Ni;
    typeId[row] = typei;
    globalId[row] = globalIdi;
    fExt[row] = Zero;
    f[row] = Zero;
    torque[row] = Zero;
    fContact[row] = Zero;
    tContact[row] = Zero;
}


Foam::label Foam::demState::append
(
    const point& xi,
    const vector& vi,
    const vector& omegai,
    const scalar ri,
    const scalar mi,
    const scalar Ni,
    const label typei,
    const label globalIdi
)
{
    const label row = size();
    forEachColumn(demStateGrow());
    set(row, xi, vi, omegai, ri, mi, Ni, typei, globalIdi);
    return row;
}


void Foam::demState::writeRows(Ostream& os, const labelUList& rows) const
{
    // An indirect list is written as the list of its elements (read back
    // as a List), without a copy
    os  << UIndirectList<point>(x, rows)
        << UIndirectList<vector>(v, rows)
        << UIndirectList<vector>(omega, rows)
        << UIndirectList<scalar>(r, rows)
        << UIndirectList<scalar>(m, rows)
        << UIndirectList<scalar>(N, rows)
        << UIndirectList<label>(typeId, rows)
        << UIndirectList<label>(globalId, rows);
}


Foam::label Foam::demState::readRows(Istream& is, const label start)
{
    const List<point> xs(is);
    const List<vector> vs(is);
    const List<vector> omegas(is);
    const List<scalar> rs(is);
    const List<scalar> ms(is);
    const List<scalar> Ns(is);
    const labelList typeIds(is);
    const labelList globalIds(is);

    const label row0 = (start < 0) ? size() : start;
    if (row0 + xs.size() > size())
    {
        resize(row0 + xs.size());
    }
    forAll(xs, k)
    {
        set
        (
            row0 + k, xs[k], vs[k], omegas[k], rs[k], ms[k], Ns[k],
            typeIds[k], globalIds[k]
        );
    }
    return xs.size();
}


// ************************************************************************* //
