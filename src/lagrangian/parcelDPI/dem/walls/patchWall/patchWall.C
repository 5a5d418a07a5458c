/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "patchWall.H"
#include "polyMesh.H"
#include "wordRes.H"
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


Foam::pointField Foam::demWalls::patchWall::meshPoints
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    // The constructor's arguments are evaluated in any order: check here too
    checkMesh(name, dict, mesh);
    return mesh->points();
}


Foam::triFaceList Foam::demWalls::patchWall::triangulate
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    checkMesh(name, dict, mesh);

    const polyBoundaryMesh& pbm = mesh->boundaryMesh();
    const wordRes patchNames(dict.get<wordRes>("patches"));

    // Every entry must select something: a typo would silently drop a wall
    for (const wordRe& pn : patchNames)
    {
        const labelHashSet one(pbm.patchSet(wordReList(1, pn), false, true));
        if (one.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << pn << "' of 'patches' of wall " << name
                << " in dictionary " << dict.name()
                << " matches no patch of the mesh" << nl
                << "Patches: " << pbm.names() << exit(FatalIOError);
        }
    }

    const labelHashSet ids(pbm.patchSet(patchNames, false, true));

    DynamicList<triFace> tris;
    for (const label patchi : ids.sortedToc())
    {
        const polyPatch& pp = pbm[patchi];
        forAll(pp, facei)
        {
            const face& f = pp[facei];
            for (label k = 1; k + 1 < f.size(); ++k)
            {
                tris.append(triFace(f[0], f[k], f[k + 1]));
            }
        }
    }

    return triFaceList(std::move(tris));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::patchWall::patchWall
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
:
    triangleWall
    (
        name,
        dict,
        meshPoints(name, dict, mesh),
        triangulate(name, dict, mesh)
    )
{}


// ************************************************************************* //
