/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "sphereRegion.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace packingRegions
{
    defineTypeNameAndDebug(sphereRegion, 0);
    addToRunTimeSelectionTable(packingRegion, sphereRegion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingRegions::sphereRegion::sphereRegion(const dictionary& dict)
:
    centre_(checked(dict, {"centre", "radius"}).get<point>("centre")),
    radius_(readLength(dict, "radius"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::packingRegions::sphereRegion::candidate
(
    Random& rnd,
    const scalar r
) const
{
    const scalar a = radius_ - r;
    return
        centre_
      + a*vector
        (
            2*rnd.sample01<scalar>() - 1,
            2*rnd.sample01<scalar>() - 1,
            2*rnd.sample01<scalar>() - 1
        );
}


Foam::scalar Foam::packingRegions::sphereRegion::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


Foam::boundBox Foam::packingRegions::sphereRegion::bounds() const
{
    return boundBox
    (
        centre_ - vector::uniform(radius_),
        centre_ + vector::uniform(radius_)
    );
}


bool Foam::packingRegions::sphereRegion::contains
(
    const point& p,
    const scalar r
) const
{
    return magSqr(p - centre_) <= sqr(radius_ - r) && r <= radius_;
}


bool Foam::packingRegions::sphereRegion::fits(const scalar r) const
{
    return r <= radius_;
}


// ************************************************************************* //
