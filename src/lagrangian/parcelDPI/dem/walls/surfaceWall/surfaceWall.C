/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "surfaceWall.H"
#include "caseSurface.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace demWalls
{
    defineTypeNameAndDebug(surfaceWall, 0);
    addToRunTimeSelectionTable(demWall, surfaceWall, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::Tuple2<Foam::pointField, Foam::triFaceList>
Foam::demWalls::surfaceWall::surface
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    const triSurface surf
    (
        caseSurface::read(dict, "Wall " + name + " (type surface)")
    );
    if (surf.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name << ": the surface " << caseSurface::path(dict)
            << " holds no triangle" << exit(FatalIOError);
    }

    pointField points(surf.points());
    triFaceList tris(surf.size());
    forAll(surf, i)
    {
        tris[i] = triFace(surf[i][0], surf[i][1], surf[i][2]);
    }

    Info<< "    Wall " << name << ": surface " << caseSurface::path(dict) << ", "
        << tris.size() << " triangles on " << points.size() << " points"
        << endl;

    return Tuple2<pointField, triFaceList>
    (
        std::move(points),
        std::move(tris)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::surfaceWall::surfaceWall
(
    const word& name,
    const dictionary& dict,
    Tuple2<pointField, triFaceList>&& surf
)
:
    triangleWall
    (
        name,
        dict,
        std::move(surf.first()),
        std::move(surf.second()),
        {"file", "scale"}
    )
{}


Foam::demWalls::surfaceWall::surfaceWall
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
:
    surfaceWall(name, dict, surface(name, dict, mesh))
{}


// ************************************************************************* //
