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
#include "mortonOrder.H"

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

    struct demStateClearStorage
    {
        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c.clearStorage();
        }
    };

    struct demStateTransfer
    {
        template<class T>
        void operator()(DynamicList<T>& c, DynamicList<T>& from) const
        {
            c.transfer(from);
        }
    };

    struct demStateCopyRow
    {
        label from;
        label to;

        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c[to] = c[from];
        }
    };

    //- A one-column operation applied to the first of two columns
    template<class Op>
    struct demStateFirstOnly
    {
        const Op& op;

        template<class T>
        void operator()(DynamicList<T>& c, DynamicList<T>&) const
        {
            op(c);
        }
    };

    //- The parcels of demState::writeRows, read (in the order written)
    struct demStateRowsIn
    {
        const List<point> x;
        const List<vector> v;
        const List<vector> omega;
        const List<scalar> r;
        const List<scalar> m;
        const List<scalar> N;
        const labelList typeId;
        const labelList globalId;

        explicit demStateRowsIn(Istream& is)
        :
            x(is), v(is), omega(is), r(is), m(is), N(is), typeId(is),
            globalId(is)
        {}

        //- Row `row` of s becomes parcel k
        void setRow(demState& s, const label k, const label row) const
        {
            s.set
            (
                row, x[k], v[k], omega[k], r[k], m[k], N[k], typeId[k],
                globalId[k]
            );
        }
    };

    struct demStateGrow
    {
        template<class T>
        void operator()(DynamicList<T>& c) const
        {
            c.append(pTraits<T>::zero);
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


template<class Op>
void Foam::demState::forEachColumn(const Op& op)
{
    forEachColumnWith(*this, demStateFirstOnly<Op>{op});
}


void Foam::demState::clear()
{
    forEachColumn(demStateClear());
    contactForcesValid = false;
    nOwned = -1;
}


void Foam::demState::clearStorage()
{
    forEachColumn(demStateClearStorage());
    contactForcesValid = false;
    nOwned = -1;
}


void Foam::demState::transfer(demState& s)
{
    forEachColumnWith(s, demStateTransfer());
    contactForcesValid = s.contactForcesValid;
    nOwned = s.nOwned;
    s.clearStorage();
}


void Foam::demState::copyRow(const label from, const label to)
{
    forEachColumn(demStateCopyRow{from, to});
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
    key[row] = uint64_t(globalIdi);
    fExt[row] = Zero;
    f[row] = Zero;
    torque[row] = Zero;
    fContact[row] = Zero;
    tContact[row] = Zero;
}


void Foam::demState::setMortonKeys
(
    const boundBox& frame,
    const scalar cell,
    const label from
)
{
    // 11 bits per direction: 33 bits of code above the 31 of a
    // non-negative label, one comparison of 64-bit integers
    const label n = size() - from;
    const List<uint64_t> codes
    (
        mortonOrder::codes(SubList<point>(x, n, from), cell, frame, 2047)
    );
    forAll(codes, k)
    {
        key[from + k] = (codes[k] << 31) | uint64_t(globalId[from + k]);
    }
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
    const demStateRowsIn in(is);
    const label n = in.x.size();
    const label row0 = (start < 0) ? size() : start;
    if (row0 + n > size())
    {
        resize(row0 + n);
    }
    for (label k = 0; k < n; ++k)
    {
        in.setRow(*this, k, row0 + k);
    }
    return n;
}


void Foam::demState::readRows(Istream& is, const labelUList& rows)
{
    const demStateRowsIn in(is);
    if (in.x.size() != rows.size())
    {
        FatalErrorInFunction
            << in.x.size() << " parcels read for " << rows.size() << " rows"
            << abort(FatalError);
    }
    forAll(rows, k)
    {
        in.setRow(*this, k, rows[k]);
    }
}


// ************************************************************************* //
