/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "mortonOrder.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::mortonOrder::maxCells = (label(1) << 21) - 1;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

uint64_t Foam::mortonOrder::code(const label i, const label j, const label k)
{
    uint64_t c = 0;
    for (int bit = 0; bit < 21; ++bit)
    {
        c |= uint64_t((i >> bit) & 1) << (3*bit);
        c |= uint64_t((j >> bit) & 1) << (3*bit + 1);
        c |= uint64_t((k >> bit) & 1) << (3*bit + 2);
    }
    return c;
}


Foam::List<uint64_t> Foam::mortonOrder::codes
(
    const UList<point>& x,
    const scalar cell,
    const boundBox& frame,
    const label nCells
)
{
    const scalar span = max(cmptMax(frame.span()), VSMALL);
    const scalar h = max(cell, span/nCells);

    // Clamped before the conversion (a point far outside would overflow)
    const scalar top = nCells;
    const auto cellOf = [top](const scalar s)
    {
        return label(min(max(s, scalar(0)), top));
    };

    List<uint64_t> c(x.size());
    forAll(x, i)
    {
        const vector s((x[i] - frame.min())/h);
        c[i] = code(cellOf(s.x()), cellOf(s.y()), cellOf(s.z()));
    }
    return c;
}


Foam::labelList Foam::mortonOrder::order(const UList<uint64_t>& codes)
{
    labelList idx(identity(codes.size()));

    // Stable: equal codes keep the list's order, so the result is the same
    // on every processor (each sorts the same list)
    std::stable_sort
    (
        idx.begin(),
        idx.end(),
        [&codes](const label a, const label b) { return codes[a] < codes[b]; }
    );

    return idx;
}


Foam::labelList Foam::mortonOrder::order
(
    const UList<point>& x,
    const scalar cell
)
{
    if (x.size() < 2)
    {
        return identity(x.size());
    }
    return order(codes(x, cell, boundBox(x, false)));
}


Foam::label Foam::mortonOrder::nDescents(const UList<uint64_t>& codes)
{
    label n = 0;
    for (label i = 1; i < codes.size(); ++i)
    {
        n += codes[i] < codes[i - 1];
    }
    return n;
}


// ************************************************************************* //
