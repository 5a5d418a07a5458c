/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "planeWall.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace demWalls
{
    defineTypeNameAndDebug(planeWall, 0);
    addToRunTimeSelectionTable(demWall, planeWall, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::planeWall::planeWall
(
    const word& name,
    const dictionary& dict,
    const polyMesh*
)
:
    demWall(name, dict, {"point", "normal"}),
    origin_(dict.get<point>("point")),
    normal_(dict.get<vector>("normal"))
{
    const scalar magN = mag(normal_);

    if (magN < VSMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'normal' of wall " << name << " in dictionary "
            << dict.name() << " is a zero vector" << exit(FatalIOError);
    }

    normal_ /= magN;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demWalls::planeWall::beyond(const boundBox& bb) const
{
    const pointField corners(bb.points());
    scalar lo = GREAT, hi = -GREAT;
    for (const point& c : corners)
    {
        const scalar h = (c - origin_) & normal_;
        lo = min(lo, h);
        hi = max(hi, h);
    }
    return (lo > 0 ? lo : hi < 0 ? -hi : 0);
}


void Foam::demWalls::planeWall::findContacts
(
    const point& x,
    const scalar reach,
    DynamicList<demWallContact>& contacts
) const
{
    const scalar h = (x - origin_) & normal_;

    if (mag(h) < reach)
    {
        demWallContact c;
        c.key = 0;
        c.n = (h >= 0) ? normal_ : -normal_;
        c.distance = mag(h);
        contacts.append(c);
    }
}


// ************************************************************************* //
