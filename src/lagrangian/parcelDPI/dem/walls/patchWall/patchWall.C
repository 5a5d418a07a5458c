/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "patchWall.H"
#include "Pstream.H"
#include "Map.H"
#include "labelIOList.H"
#include "polyMesh.H"
#include "wordRes.H"
#include "processorPolyPatch.H"
#include "SubList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace demWalls
{
    defineTypeNameAndDebug(patchWall, 0);
    addToRunTimeSelectionTable(demWall, patchWall, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::demWalls::patchWall::globalPatches
(
    const polyBoundaryMesh& pbm,
    const wordReList& patchNames
)
{
    // The global patches are the same on every processor and in serial:
    // without the processor patches, so is the selection
    labelList ids(pbm.patchSet(patchNames, false, true).sortedToc());
    label n = 0;
    for (const label patchi : ids)
    {
        if (!isA<processorPolyPatch>(pbm[patchi]))
        {
            ids[n++] = patchi;
        }
    }
    ids.setSize(n);
    return ids;
}


void Foam::demWalls::patchWall::checkMesh
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    if (!mesh)
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name << " of type patch in dictionary "
            << dict.name() << " needs the CFD mesh, but the engine was "
            << "constructed without one" << exit(FatalIOError);
    }
}


Foam::Tuple2<Foam::pointField, Foam::triFaceList>
Foam::demWalls::patchWall::surface
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    checkMesh(name, dict, mesh);

    const polyBoundaryMesh& pbm = mesh->boundaryMesh();
    const wordRes patchNames(dict.get<wordRes>("patches"));

    // Every entry must select something: a typo would silently drop a wall.
    // Processor patches are never walls, whatever the pattern: they exist
    // only in a decomposed run, and a wall must be the same at any
    // processor count (a parcel would bounce off a sub-domain's border)
    for (const wordRe& pn : patchNames)
    {
        if (globalPatches(pbm, wordReList(1, pn)).empty())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << pn << "' of 'patches' of wall " << name
                << " in dictionary " << dict.name()
                << " matches no patch of the mesh (processor patches are"
                << " never walls)" << nl
                << "    Patches: "
                << flatOutput(SubList<word>(pbm.names(), pbm.nNonProcessor()))
                << exit(FatalIOError);
        }
    }

    const labelList ids(globalPatches(pbm, patchNames));

    wordList selected(ids.size());
    forAll(ids, i)
    {
        selected[i] = pbm[ids[i]].name();
    }

    // Undecomposed labels of this processor's faces and points (identity
    // in serial)
    labelList faceAddr(identity(mesh->nFaces()));
    labelList pointAddr(identity(mesh->nPoints()));
    if (Pstream::parRun())
    {
        const fileName dir(mesh->facesInstance()/polyMesh::meshSubDir);
        IOobject faceIO
        (
            "faceProcAddressing", dir, *mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        IOobject pointIO
        (
            "pointProcAddressing", mesh->pointsInstance()/polyMesh::meshSubDir,
            *mesh, IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if
        (
            !faceIO.typeHeaderOk<labelIOList>(true)
         || !pointIO.typeHeaderOk<labelIOList>(true)
        )
        {
            FatalIOErrorInFunction(dict)
                << "Wall " << name << " of type patch in a parallel run needs"
                << " decomposePar's faceProcAddressing and"
                << " pointProcAddressing in " << dir
                << " (decompose the case with decomposePar)"
                << exit(FatalIOError);
        }
        // faceProcAddressing holds (undecomposed face + 1), negative when
        // flipped; boundary faces keep their orientation
        const labelIOList fpa(faceIO);
        forAll(fpa, facei)
        {
            faceAddr[facei] = mag(fpa[facei]) - 1;
        }
        pointAddr = labelIOList(pointIO);
    }

    // Local faces as (undecomposed face label, undecomposed point labels)
    // and the coordinates of their points
    DynamicList<label> faceIds;
    DynamicList<face> faces;
    Map<point> coords;
    for (const label patchi : ids)
    {
        const polyPatch& pp = pbm[patchi];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            const face& f = pp[i];
            face g(f.size());
            forAll(f, k)
            {
                g[k] = pointAddr[f[k]];
                coords.set(g[k], mesh->points()[f[k]]);
            }
            faceIds.append(faceAddr[facei]);
            faces.append(g);
        }
    }

    // Everything to everyone: the wall is small next to the volume mesh
    List<labelList> allIds(Pstream::nProcs());
    List<faceList> allFaces(Pstream::nProcs());
    List<Map<point>> allCoords(Pstream::nProcs());
    allIds[Pstream::myProcNo()] = faceIds;
    allFaces[Pstream::myProcNo()] = faces;
    allCoords[Pstream::myProcNo()] = coords;
    Pstream::gatherList(allIds);
    Pstream::scatterList(allIds);
    Pstream::gatherList(allFaces);
    Pstream::scatterList(allFaces);
    Pstream::gatherList(allCoords);
    Pstream::scatterList(allCoords);

    // Undecomposed face order; compact point labels in undecomposed order
    Map<face> byId;
    Map<point> allPoints;
    forAll(allIds, proci)
    {
        forAll(allIds[proci], i)
        {
            byId.set(allIds[proci][i], allFaces[proci][i]);
        }
        forAllConstIters(allCoords[proci], iter)
        {
            allPoints.set(iter.key(), iter.val());
        }
    }

    const labelList pointIds(allPoints.sortedToc());
    Map<label> compact(2*pointIds.size());
    pointField points(pointIds.size());
    forAll(pointIds, i)
    {
        compact.insert(pointIds[i], i);
        points[i] = allPoints[pointIds[i]];
    }

    DynamicList<triFace> tris;
    for (const label id : byId.sortedToc())
    {
        const face& f = byId[id];
        for (label k = 1; k + 1 < f.size(); ++k)
        {
            tris.append
            (
                triFace(compact[f[0]], compact[f[k]], compact[f[k + 1]])
            );
        }
    }

    // What the wall is made of: the same lines at any processor count
    Info<< "    Wall " << name << ": patches " << flatOutput(selected) << ", "
        << byId.size() << " faces, " << tris.size() << " triangles" << endl;

    return Tuple2<pointField, triFaceList>
    (
        std::move(points),
        triFaceList(std::move(tris))
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::patchWall::patchWall
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
        {"patches"}
    )
{}


Foam::demWalls::patchWall::patchWall
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
:
    patchWall(name, dict, surface(name, dict, mesh))
{}


// ************************************************************************* //
