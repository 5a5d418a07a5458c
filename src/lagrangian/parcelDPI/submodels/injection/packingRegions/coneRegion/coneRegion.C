/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "coneRegion.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace packingRegions
{
    defineTypeNameAndDebug(coneRegion, 0);
    addToRunTimeSelectionTable(packingRegion, coneRegion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingRegions::coneRegion::coneRegion
(
    const dictionary& dict,
    const bool cylinder
)
:
    p1_(Zero),
    p2_(Zero),
    radius1_(0),
    radius2_(0),
    axis_(0, 0, 1),
    length_(0),
    e1_(1, 0, 0),
    e2_(0, 1, 0)
{
    // The keys first: a misspelt one is named before the entry it misses
    checked
    (
        dict,
        cylinder
      ? wordList({"point1", "point2", "radius"})
      : wordList({"point1", "point2", "radius1", "radius2"})
    );
    p1_ = dict.get<point>("point1");
    p2_ = dict.get<point>("point2");
    if (cylinder)
    {
        radius1_ = readLength(dict, "radius");
        radius2_ = radius1_;
    }
    else
    {
        radius1_ = readLength(dict, "radius1", true);
        radius2_ = readLength(dict, "radius2", true);
        if (!(max(radius1_, radius2_) > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entries 'radius1' and 'radius2' of dictionary "
                << dict.name() << " are both zero" << exit(FatalIOError);
        }
    }

    const vector d(p2_ - p1_);
    length_ = mag(d);
    if (!(length_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'point1' and 'point2' of dictionary " << dict.name()
            << " coincide: the " << (cylinder ? "cylinder" : "cone")
            << " has no axis" << exit(FatalIOError);
    }
    axis_ = d/length_;

    // The Cartesian direction least aligned with the axis
    vector ref(1, 0, 0);
    if (mag(axis_.y()) < mag(axis_.x()) && mag(axis_.y()) <= mag(axis_.z()))
    {
        ref = vector(0, 1, 0);
    }
    else if (mag(axis_.z()) < mag(axis_.x()))
    {
        ref = vector(0, 0, 1);
    }
    e1_ = axis_ ^ ref;
    e1_ /= mag(e1_);
    e2_ = axis_ ^ e1_;
}


Foam::packingRegions::coneRegion::coneRegion(const dictionary& dict)
:
    coneRegion(dict, false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::packingRegions::coneRegion::candidate
(
    Random& rnd,
    const scalar r
) const
{
    const scalar a = max(radius1_, radius2_) - r;
    const scalar t = r + (length_ - 2*r)*rnd.sample01<scalar>();
    const scalar u = a*(2*rnd.sample01<scalar>() - 1);
    const scalar w = a*(2*rnd.sample01<scalar>() - 1);
    return p1_ + t*axis_ + u*e1_ + w*e2_;
}


Foam::scalar Foam::packingRegions::coneRegion::volume() const
{
    return
        constant::mathematical::pi*length_/3
       *(sqr(radius1_) + radius1_*radius2_ + sqr(radius2_));
}


Foam::boundBox Foam::packingRegions::coneRegion::bounds() const
{
    // The hull of the two end discs: a disc of radius r with unit normal a
    // reaches r sqrt(1 - a_i^2) along axis i (a box of the radius every way
    // would stick out along the axis, and an injector whose region fits
    // the mesh would be refused)
    vector reach;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        reach[i] = Foam::sqrt(max(scalar(0), 1 - sqr(axis_[i])));
    }
    boundBox bb(p1_ - radius1_*reach, p1_ + radius1_*reach);
    bb.add(p2_ - radius2_*reach);
    bb.add(p2_ + radius2_*reach);
    return bb;
}


bool Foam::packingRegions::coneRegion::contains
(
    const point& p,
    const scalar r
) const
{
    const vector d(p - p1_);
    const scalar t = d & axis_;
    if (t < r || t > length_ - r)
    {
        return false;
    }
    const scalar rho = mag(d - t*axis_);

    // Signed distance to the generator line through (0, R1) and (L, R2) in
    // the meridian plane, positive outside
    const scalar dR = radius2_ - radius1_;
    const scalar norm = sqrt(sqr(length_) + sqr(dR));
    const scalar dist = (-dR*t + length_*(rho - radius1_))/norm;
    return dist <= -r;
}


bool Foam::packingRegions::coneRegion::fits(const scalar r) const
{
    // Centres on the axis at t = r or t = L - r are the best candidates
    // near the wider end; check a few along the axis
    if (length_ < 2*r)
    {
        return false;
    }
    for (label k = 0; k <= 100; ++k)
    {
        const scalar t = r + (length_ - 2*r)*k/100.0;
        if (contains(p1_ + t*axis_, r))
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
