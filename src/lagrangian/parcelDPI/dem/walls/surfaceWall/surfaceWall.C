/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "surfaceWall.H"
#include "caseSurface.H"
#include "polyMesh.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "treeBoundBox.H"
#include "Random.H"
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

void Foam::demWalls::surfaceWall::warnHoles
(
    const word& name,
    const dictionary& dict,
    const triSurface& surf,
    const polyMesh* mesh
)
{
    // A wall surface may be open: doc/your-own-inhaler.md has the walls,
    // inlet and outlet close the device together, so the walls' STL is
    // open at the inlet and outlet, and a screen or a plate is a sheet.
    // Those rims lie on the gas mesh's boundary (the inlet and outlet
    // patches) or outside it, where no parcel goes. An open edge inside
    // the mesh, more than half a boundary face from its boundary, is a
    // hole a parcel passes through (a missing triangle of a CAD export,
    // was accepted silently): a warning, not an error, since a free edge
    // in the gas (a baffle's) can be meant
    const labelListList& edgeFaces = surf.edgeFaces();
    const edgeList& edges = surf.edges();
    const pointField& lp = surf.localPoints();
    DynamicList<label> open;
    forAll(edgeFaces, edgei)
    {
        if (edgeFaces[edgei].size() != 2)
        {
            open.append(edgei);
        }
    }
    if (!mesh || open.empty())
    {
        return;
    }

    // The mesh's own boundary (not processor faces), searched for the
    // nearest face; each processor answers for its part, and the nearest
    // and "in a cell" are combined over all
    const polyBoundaryMesh& pbm = mesh->boundaryMesh();
    DynamicList<label> bFaces;
    for (const polyPatch& pp : pbm)
    {
        if (!pp.coupled())
        {
            bFaces.append(identity(pp.size(), pp.start()));
        }
    }
    scalarField gap(open.size(), GREAT);
    labelList inside(open.size(), 0);
    if (bFaces.size())
    {
        Random rnd(123456);
        const treeBoundBox bb
        (
            treeBoundBox(mesh->points()).extend(rnd, 1e-4)
        );
        const indexedOctree<treeDataFace> tree
        (
            treeDataFace(false, *mesh, bFaces),
            bb,
            8,
            10,
            3.0
        );
        forAll(open, i)
        {
            const point mid(edges[open[i]].centre(lp));
            const pointIndexHit hit(tree.findNearest(mid, GREAT));
            if (hit.hit())
            {
                const label facei = bFaces[hit.index()];
                gap[i] =
                    mag(hit.hitPoint() - mid)
                  - 0.5*sqrt(mag(mesh->faceAreas()[facei]));
            }
            inside[i] = (mesh->findCell(mid) >= 0);
        }
    }
    Pstream::listCombineGather(gap, minEqOp<scalar>());
    Pstream::listCombineScatter(gap);
    Pstream::listCombineGather(inside, maxEqOp<label>());
    Pstream::listCombineScatter(inside);

    label nHoles = 0;
    boundBox holes;
    forAll(open, i)
    {
        if (inside[i] && gap[i] > 0)
        {
            ++nHoles;
            holes.add(lp[edges[open[i]].start()]);
            holes.add(lp[edges[open[i]].end()]);
        }
    }
    if (nHoles)
    {
        WarningInFunction
            << "Wall " << name << ": the surface " << caseSurface::path(dict)
            << " has " << nHoles << " open edges (on one triangle only, or"
            << " on more than two) inside the gas mesh, away from its"
            << " boundary, within " << holes.min() << ' ' << holes.max()
            << " (" << open.size() << " open edges in all, the others on"
            << " the mesh's boundary or outside it)." << nl
            << "    Parcels pass through a hole in a wall: close it in the"
            << " CAD (surfaceCheck lists the open edges), unless the wall"
            << " is meant to end there (a baffle's free edge)" << endl;
    }
}


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

    warnHoles(name, dict, surf, mesh);

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
