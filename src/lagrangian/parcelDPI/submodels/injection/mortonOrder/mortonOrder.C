/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "mortonOrder.H"
#include "boundBox.H"

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


Foam::labelList Foam::mortonOrder::order
(
    const UList<point>& x,
    const scalar cell
)
{
    labelList idx(identity(x.size()));
    if (x.size() < 2)
    {
        return idx;
    }

    const boundBox bb(x, false);
    const scalar span = max(cmptMax(bb.span()), VSMALL);
    const scalar h = max(cell, span/maxCells);

    List<uint64_t> codes(x.size());
    forAll(x, i)
    {
        const vector c((x[i] - bb.min())/h);
        codes[i] = code
        (
            min(label(c.x()), maxCells),
            min(label(c.y()), maxCells),
            min(label(c.z()), maxCells)
        );
    }

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


// ************************************************************************* //
