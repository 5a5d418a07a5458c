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
    return caseSurface::read
    (
        dict,
        "Region of dictionary " + dict.name() + " (shape surface)"
    );
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
    // The enclosed volume, by the divergence theorem over the triangles
    // (whichever way they face)
    const pointField& pts = surface_.points();
    for (const labelledTri& t : surface_)
    {
        volume_ += (pts[t[0]] & (pts[t[1]] ^ pts[t[2]]))/6;
    }
    volume_ = mag(volume_);

    // The inside test needs a closed surface: every edge on two triangles
    label nOpen = 0;
    for (const labelList& edgeFaces : surface_.edgeFaces())
    {
        if (edgeFaces.size() != 2)
        {
            ++nOpen;
        }
    }
    if (surface_.empty() || nOpen || !(volume_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Region of dictionary " << dict.name() << " (shape surface):"
            << " the surface holds " << surface_.size() << " triangles, "
            << nOpen << " edges not shared by exactly two of them, and"
            << " encloses " << volume_ << " m^3: a region must be a closed"
            << " surface" << exit(FatalIOError);
    }

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
