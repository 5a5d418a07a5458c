/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "wallContacts.H"

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
