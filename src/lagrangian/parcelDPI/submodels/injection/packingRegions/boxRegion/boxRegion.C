/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "boxRegion.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace packingRegions
{
    defineTypeNameAndDebug(boxRegion, 0);
    addToRunTimeSelectionTable(packingRegion, boxRegion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingRegions::boxRegion::boxRegion(const dictionary& dict)
:
    min_(checked(dict, {"min", "max"}).get<point>("min")),
    max_(dict.get<point>("max"))
{
    for (direction c = 0; c < 3; ++c)
    {
        if (!(max_[c] > min_[c]))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'max' " << max_ << " of dictionary "
                << dict.name() << " must exceed 'min' " << min_
                << " in every component" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::packingRegions::boxRegion::candidate
(
    Random& rnd,
    const scalar r
) const
{
    const vector lo(min_ + vector::uniform(r));
    const vector span(max_ - min_ - vector::uniform(2*r));
    return
        lo
      + vector
        (
            span.x()*rnd.sample01<scalar>(),
            span.y()*rnd.sample01<scalar>(),
            span.z()*rnd.sample01<scalar>()
        );
}


Foam::scalar Foam::packingRegions::boxRegion::volume() const
{
    return cmptProduct(max_ - min_);
}


Foam::boundBox Foam::packingRegions::boxRegion::bounds() const
{
    return boundBox(min_, max_);
}


bool Foam::packingRegions::boxRegion::contains
(
    const point& p,
    const scalar r
) const
{
    for (direction c = 0; c < 3; ++c)
    {
        if (p[c] < min_[c] + r || p[c] > max_[c] - r)
        {
            return false;
        }
    }
    return true;
}


bool Foam::packingRegions::boxRegion::fits(const scalar r) const
{
    return cmptMin(max_ - min_) >= 2*r;
}


// ************************************************************************* //
