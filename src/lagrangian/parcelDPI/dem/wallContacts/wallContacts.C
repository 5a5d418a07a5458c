/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "wallContacts.H"
#include "polyMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wallContacts::prepare(const scalar reach)
{
    if (reach > reach_)
    {
        // A little margin so a slightly larger parcel does not re-bin
        reach_ = 1.1*reach;
        for (demWall& w : walls_)
        {
            w.prepare(reach_);
        }
    }
}


void Foam::wallContacts::checkAgainstMesh
(
    const dictionary& wallsDict,
    const polyMesh& mesh
) const
{
    // The parcels live in the mesh: a wall only acts where it meets it. A
    // wall that lies beyond the mesh by more than the mesh's own size is
    // in other units (mm for m: 1000x; cm: 100x), and the parcels meet no
    // wall where the device has one. Within that, a part beyond the mesh
    // is harmless (an STL of more than the meshed part) but said; a
    // snapped mesh lies within a cell of its STL, well below 5 %
    const boundBox meshBb(mesh.points(), true);
    const scalar size = mag(meshBb.span());
    forAll(walls_, wi)
    {
        const demWall& w = walls_[wi];
        const dictionary& wd = wallsDict.subDict(w.name());
        const scalar d = w.beyond(meshBb);
        if (d > size)
        {
            FatalIOErrorInFunction(wd)
                << "Wall " << w.name() << " in " << wallsDict.name()
                << " reaches " << d << " m beyond the mesh (bounds "
                << meshBb.min() << ' ' << meshBb.max() << ", "
                << size << " m across): " << d/size << " times the mesh's"
                << " size." << nl
                << "    Walls are in metres, as the mesh: an STL in mm needs"
                << " `scale 1e-3;` in the wall's dictionary"
                << exit(FatalIOError);
        }
        if (d > 0.05*size)
        {
            WarningInFunction
                << "Wall " << w.name() << " in " << wallsDict.name()
                << " reaches " << d << " m beyond the mesh (bounds "
                << meshBb.min() << ' ' << meshBb.max() << "): no parcel"
                << " gets there. Is it the device's wall, in metres?" << endl;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallContacts::wallContacts
(
    const dictionary& dict,
    const polyMesh* mesh,
    const demMaterials& materials
)
:
    walls_(),
    material_(),
    reach_(0)
{
    const dictionary* wallsDict = dict.findDict("walls");
    if (!wallsDict)
    {
        return;
    }

    const wordList names(wallsDict->toc());

    if (names.size() > contactHistory::maxWalls)
    {
        FatalIOErrorInFunction(*wallsDict)
            << names.size() << " walls in dictionary " << wallsDict->name()
            << "; at most " << contactHistory::maxWalls << " are supported"
            << " (merge walls of the same material into one triangles or"
            << " patch wall)" << exit(FatalIOError);
    }

    walls_.setSize(names.size());
    material_.setSize(names.size());

    forAll(names, wi)
    {
        const dictionary& wd = wallsDict->subDict(names[wi]);
        walls_.set(wi, demWall::New(names[wi], wd, mesh));
        material_[wi] =
            materials.typeIndex(walls_[wi].material(), wd, "material");
    }

    if (mesh)
    {
        checkAgainstMesh(*wallsDict, *mesh);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::wallContacts::markNearWalls
(
    const demState& s,
    const contactModels& models,
    const scalar rMax,
    const scalar range,
    const scalar skin,
    List<bool>& tracked
)
{
    if (walls_.empty())
    {
        return;
    }

    prepare(rMax + range + skin);

    DynamicList<label> found;
    forAll(s.x, p)
    {
        if (tracked[p])
        {
            continue;
        }
        const scalar query = searchReach(s.r[p], models, skin);
        forAll(walls_, w)
        {
            found.clear();
            walls_[w].findCandidates(s.x[p], query, found);
            if (found.size())
            {
                tracked[p] = true;
                break;
            }
        }
    }
}


void Foam::wallContacts::findCandidates
(
    const demState& s,
    const contactModels& models,
    const scalar rMax,
    const scalar range,
    const scalar skin,
    const List<bool>& tracked
)
{
    // Walls must see every sphere within its radius plus cohesion range,
    // and, for the near-wall test below, the skin
    prepare(rMax + range + skin);

    const label n = s.size();
    const label nWalls = walls_.size();
    nearWall_.clear();
    candStart_.setSize(n*nWalls + 1);
    cand_.clear();
    for (label p = 0; p < n; ++p)
    {
        const scalar query = searchReach(s.r[p], models, skin);
        const label start = cand_.size();
        forAll(walls_, w)
        {
            candStart_[p*nWalls + w] = cand_.size();
            if (tracked[p])
            {
                walls_[w].findCandidates(s.x[p], query, cand_);
            }
        }
        if (cand_.size() > start)
        {
            nearWall_.append(p);
        }
    }
    candStart_[n*nWalls] = cand_.size();
}


// ************************************************************************* //
