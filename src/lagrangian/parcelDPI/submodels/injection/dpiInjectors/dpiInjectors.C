/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiInjectors.H"
#include "PstreamCombineReduceOps.H"
#include "splitmix.H"

#include <cstring>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpiInjectors::checkBounds() const
{
    // Before any packing: a region outside the mesh would otherwise be
    // packed first and fail on what the packing cannot reach, never
    // naming the mesh (the parcels' own positions are checked against the
    // mesh's cells when injected)
    const dictionary& injDict = cloudDict_.subDict("injectors");
    const boundBox& meshBb = mesh_.bounds();
    boundBox grown(meshBb);
    grown.inflate(1e-9);
    forAll(models_, i)
    {
        const boundBox bb(models_[i].bounds());
        if (bb.valid() && !grown.contains(bb))
        {
            FatalIOErrorInFunction(injDict.subDict(models_[i].name()))
                << "Injector " << models_[i].name() << " in "
                << injDict.name() << " places its particles in "
                << bb.min() << ' ' << bb.max() << ", outside the mesh"
                << " (bounds " << meshBb.min() << ' ' << meshBb.max()
                << ")." << nl << "    Move its positions or region"
                << " inside the mesh (lengths in metres)"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiInjectors::dpiInjectors
(
    const dictionary& cloudDict,
    const fvMesh& mesh,
    const demMaterials& materials
)
:
    cloudDict_(cloudDict),
    mesh_(mesh),
    materials_(materials),
    models_()
{
    if (!cloudDict.found("injectors"))
    {
        return;
    }
    const dictionary& injDict = cloudDict.subDict("injectors");
    const wordList names(injDict.toc());
    models_.setSize(names.size());
    forAll(names, i)
    {
        models_.set
        (
            i,
            dpiInjectionModel::New
            (
                names[i], injDict.subDict(names[i]), &materials
            )
        );
    }
    checkBounds();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpiInjectors::drawSizes
(
    const label injector,
    const scalar t0,
    const label start,
    DynamicList<injectionSpec>& specs
) const
{
    // Counter-based numbers of (injector, time, index): the same on every
    // processor and in a restart, with no generator state to keep
    uint64_t bits;
    std::memcpy(&bits, &t0, sizeof bits);
    const uint64_t stream =
        splitmix(splitmix(uint64_t(injector) + 1) ^ splitmix(bits));

    for (label i = start; i < specs.size(); ++i)
    {
        injectionSpec& s = specs[i];
        const label typei = materials_.names().find(s.type);
        if
        (
            s.d > 0 || typei < 0 || !materials_.isParticleType(typei)
         || materials_.size(typei).fixed()
        )
        {
            continue;       // given, or checked (and refused) below
        }
        const scalar u =
            scalar(splitmix(stream + uint64_t(i - start)) >> 11)
               /9007199254740992.0;    // 2^53
        s.d = materials_.size(typei).diameter(u);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dpiInjectors::due
(
    const scalar t0,
    const scalar t1,
    DynamicList<injectionSpec>& specs,
    labelList& owner,
    labelList& cell,
    labelList& typeIds
)
{
    // The curve's cell for `order morton`: the largest particle
    const scalar dMax = materials_.maxDiameter();

    specs.clear();
    forAll(models_, i)
    {
        const label start = specs.size();
        models_[i].inject(t0, t1, specs);
        drawSizes(i, t0, start, specs);
        models_[i].order(specs, start, dMax);
    }

    if (returnReduce(specs.empty(), andOp<bool>()))
    {
        specs.clear();
        return false;
    }

    // Owner processor of each position: local octree search, then one
    // element-wise min over processors (lowest processor wins, so the owner
    // does not depend on search order)
    const label notFound = Pstream::nProcs();
    owner.setSize(specs.size());
    owner = notFound;
    cell.setSize(specs.size());
    cell = -1;
    forAll(specs, i)
    {
        cell[i] = mesh_.findCell(specs[i].position);
        if (cell[i] >= 0)
        {
            owner[i] = Pstream::myProcNo();
        }
    }
    Pstream::listCombineGather(owner, minEqOp<label>());
    Pstream::listCombineScatter(owner);

    forAll(specs, i)
    {
        if (owner[i] == notFound)
        {
            FatalIOErrorInFunction(cloudDict_)
                << "A particle of type " << specs[i].type
                << " is injected at " << specs[i].position
                << ", outside the mesh (bounds " << mesh_.bounds() << ")." << nl
                << "    Check 'injectors' in " << cloudDict_.name()
                << exit(FatalIOError);
        }
    }

    // Types are checked on every processor so that all stop together
    const dictionary& injDict = cloudDict_.subDict("injectors");
    typeIds.setSize(specs.size());
    forAll(specs, i)
    {
        const label typei =
            materials_.typeIndex(specs[i].type, injDict, "type");
        typeIds[i] = typei;
        if (!materials_.isParticleType(typei))
        {
            const fileName typeDict
            (
                injDict.parent().name() + ".dem.types." + specs[i].type
            );
            FatalIOErrorInFunction(injDict)
                << "Injected type " << specs[i].type << " has no 'diameter'"
                << " (nor 'sizeDistribution')"
                << " in dictionary " << typeDict.c_str() << ": a type"
                << " without one is a wall material." << nl
                << "    Give type " << specs[i].type << " a diameter and a"
                << " density to inject it" << exit(FatalIOError);
        }
    }

    return true;
}


// ************************************************************************* //
