/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "surfaceRegion.H"
#include "caseSurface.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace packingRegions
{
    defineTypeNameAndDebug(surfaceRegion, 0);
    addToRunTimeSelectionTable(packingRegion, surfaceRegion, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::triSurface Foam::packingRegions::surfaceRegion::read
(
    const dictionary& dict
)
{
    checked(dict, {"file", "scale"});
    const triSurface surf
    (
        caseSurface::read
        (
            dict,
            "Region of dictionary " + dict.name() + " (shape surface)"
        )
    );

    // The inside test needs a closed surface: every edge on two triangles
    label nOpen = 0;
    for (const labelList& edgeFaces : surf.edgeFaces())
    {
        if (edgeFaces.size() != 2)
        {
            ++nOpen;
        }
    }
    const scalar volume = signedVolume(surf);
    if (surf.empty() || nOpen || !(mag(volume) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Region of dictionary " << dict.name() << " (shape surface):"
            << " the surface holds " << surf.size() << " triangles, "
            << nOpen << " edges not shared by exactly two of them, and"
            << " encloses " << mag(volume) << " m^3: a region must be a"
            << " closed surface" << exit(FatalIOError);
    }

    // The inside test (triSurfaceSearch) goes by the nearest triangle's
    // normal: neighbours that face opposite ways make it answer "inside"
    // and "outside" by patches, and the region packs where it should not
    // (or "does not fit"). Each edge of a consistently oriented surface
    // runs one way in one of its triangles and the other way in the other
    const edgeList& edges = surf.edges();
    const labelListList& edgeFaces = surf.edgeFaces();
    const List<labelledTri>& faces = surf.localFaces();
    label nMixed = 0;
    boundBox mixedBb;
    forAll(edges, edgei)
    {
        const labelList& ef = edgeFaces[edgei];
        if
        (
            faces[ef[0]].edgeDirection(edges[edgei])
         == faces[ef[1]].edgeDirection(edges[edgei])
        )
        {
            ++nMixed;
            mixedBb.add(surf.localPoints()[edges[edgei].start()]);
            mixedBb.add(surf.localPoints()[edges[edgei].end()]);
        }
    }
    if (nMixed)
    {
        FatalIOErrorInFunction(dict)
            << "Region of dictionary " << dict.name() << " (shape surface):"
            << " the triangles of " << caseSurface::path(dict) << " face"
            << " opposite ways across " << nMixed << " of its "
            << edges.size() << " edges (within " << mixedBb.min() << ' '
            << mixedBb.max() << "): the inside of the surface is not"
            << " defined." << nl
            << "    Orient its normals one way, outwards: e.g. surfaceOrient"
            << " <file> '(x y z)' <new file>, with (x y z) a point outside"
            << " the region" << exit(FatalIOError);
    }

    // Consistent but facing inwards (the signed volume < 0: an STL written
    // inside out, or a cavity's surface taken from the device's walls):
    // the enclosed space is still the region meant, so its triangles are
    // turned to face out and the run says so (was: "does not fit", every
    // point of the bed being "outside")
    if (volume < 0)
    {
        Info<< "    Region of dictionary " << dict.name() << ": the normals"
            << " of " << caseSurface::path(dict) << " point inwards (the"
            << " surface is inside out); packing the space it encloses,"
            << " with its triangles turned to face out" << endl;

        List<labelledTri> flipped(surf);
        for (labelledTri& t : flipped)
        {
            std::swap(t[1], t[2]);
        }
        return triSurface(flipped, surf.patches(), surf.points());
    }

    return surf;
}


Foam::scalar Foam::packingRegions::surfaceRegion::signedVolume
(
    const triSurface& surf
)
{
    // The divergence theorem over the triangles: > 0 when they face out
    const pointField& pts = surf.points();
    scalar v = 0;
    for (const labelledTri& t : surf)
    {
        v += (pts[t[0]] & (pts[t[1]] ^ pts[t[2]]))/6;
    }
    return v;
}


Foam::scalar Foam::packingRegions::surfaceRegion::depth(const point& p) const
{
    if (!bounds_.contains(p) || !search_->calcInside(pointField(1, p))[0])
    {
        return -1;
    }
    const pointIndexHit hit(search_->tree().findNearest(p, GREAT));
    return hit.hit() ? mag(hit.hitPoint() - p) : -1;
}


Foam::scalar Foam::packingRegions::surfaceRegion::largestDepth() const
{
    const label n = 16;
    const vector span(bounds_.span());
    point best(bounds_.centre());
    scalar d = depth(best);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label k = 0; k < n; ++k)
            {
                const point p
                (
                    bounds_.min()
                  + cmptMultiply(span, vector(i + 0.5, j + 0.5, k + 0.5)/n)
                );
                const scalar dp = depth(p);
                if (dp > d)
                {
                    best = p;
                    d = dp;
                }
            }
        }
    }

    // Climb from the best lattice point, one axis step at a time
    scalar step = cmptMax(span)/n;
    while (step > 1e-9*cmptMax(span))
    {
        bool moved = false;
        for (direction c = 0; c < 3; ++c)
        {
            for (const scalar sign : {-1.0, 1.0})
            {
                point p(best);
                p[c] += sign*step;
                const scalar dp = depth(p);
                if (dp > d)
                {
                    best = p;
                    d = dp;
                    moved = true;
                }
            }
        }
        if (!moved)
        {
            step /= 2;
        }
    }
    return max(d, scalar(0));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingRegions::surfaceRegion::surfaceRegion(const dictionary& dict)
:
    surface_(read(dict)),
    search_(nullptr),
    volume_(0),
    bounds_(surface_.points(), false),
    inscribed_(0)
{
    // The enclosed volume (read() has checked the surface closed and
    // turned it to face out)
    volume_ = signedVolume(surface_);

    search_.reset(new triSurfaceSearch(surface_));
    inscribed_ = largestDepth();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::packingRegions::surfaceRegion::candidate
(
    Random& rnd,
    const scalar r
) const
{
    const vector lo(bounds_.min() + vector::uniform(r));
    const vector span(bounds_.span() - vector::uniform(2*r));
    const scalar x = rnd.sample01<scalar>();
    const scalar y = rnd.sample01<scalar>();
    const scalar z = rnd.sample01<scalar>();
    return lo + cmptMultiply(span, vector(x, y, z));
}


Foam::scalar Foam::packingRegions::surfaceRegion::volume() const
{
    return volume_;
}


Foam::boundBox Foam::packingRegions::surfaceRegion::bounds() const
{
    return bounds_;
}


bool Foam::packingRegions::surfaceRegion::contains
(
    const point& p,
    const scalar r
) const
{
    if (!bounds_.contains(p))
    {
        return false;
    }
    if (!search_->calcInside(pointField(1, p))[0])
    {
        return false;
    }
    return !(r > 0 && search_->tree().findNearest(p, sqr(r)).hit());
}


bool Foam::packingRegions::surfaceRegion::fits(const scalar r) const
{
    return r <= inscribed_;
}


// ************************************************************************* //
