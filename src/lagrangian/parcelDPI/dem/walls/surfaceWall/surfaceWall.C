/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "surfaceWall.H"
#include "triSurface.H"
#include "polyMesh.H"
#include "Time.H"
#include "OSspecific.H"
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
    fileName file(dict.get<fileName>("file"));
    file.expand();
    if (!file.isAbsolute())
    {
        file =
        (
            mesh
          ? mesh->time().globalPath()/mesh->time().constant()/"triSurface"
          : cwd()
        )/file;
    }
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name << " (type surface): no file " << file
            << nl << "    A relative `file` is taken in the case's"
            << " constant/triSurface; any format OpenFOAM's triSurface"
            << " reads (STL, OBJ, VTK, ...)." << exit(FatalIOError);
    }

    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (scale <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name << ": scale " << scale << " must be > 0"
            << " (1e-3 for a file in mm)" << exit(FatalIOError);
    }

    // Reading merges the vertices an STL repeats per triangle
    const triSurface surf(file);
    if (surf.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name << ": the surface " << file
            << " holds no triangle" << exit(FatalIOError);
    }

    pointField points(scale*surf.points());
    triFaceList tris(surf.size());
    forAll(surf, i)
    {
        tris[i] = triFace(surf[i][0], surf[i][1], surf[i][2]);
    }

    Info<< "    Wall " << name << ": surface " << file << ", "
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
