/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiInjectionModel.H"
#include "dictKeys.H"
#include "mortonOrder.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiInjectionModel, 0);
    defineRunTimeSelectionTable(dpiInjectionModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiInjectionModel::dpiInjectionModel
(
    const word& name,
    const dictionary& dict,
    const wordList& modelKeys
)
:
    name_(name),
    dict_(dict),
    SOI_(dict.lookupOrDefault<scalar>("SOI", 0)),
    morton_(false)
{
    // type is read by the selector New
    wordList known({"type", "SOI", "order"});
    known.append(modelKeys);
    dictKeys::warnUnknown(dict, known);

    const word order(dict.getOrDefault<word>("order", "none"));
    if (order != "none" && order != "morton")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown order " << order << " for injector " << name
            << " in dictionary " << dict.name() << nl
            << "    valid orders: 2(none morton)" << exit(FatalIOError);
    }
    morton_ = (order == "morton");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::dpiInjectionModel::checkDiameter
(
    const scalar d,
    const dictionary& dict,
    const string& what
)
{
    if (!(d > 0) || !std::isfinite(d))
    {
        FatalIOErrorInFunction(dict)
            << what.c_str() << " = " << d << " in dictionary " << dict.name()
            << " is out of range: a particle's own diameter must be > 0 [m]"
            << " (leave it out for its type's diameter)"
            << exit(FatalIOError);
    }
}


void Foam::dpiInjectionModel::order
(
    DynamicList<injectionSpec>& particles,
    const label start,
    const scalar cell
) const
{
    if (!morton_ || particles.size() - start < 2)
    {
        return;
    }

    const SubList<injectionSpec> batch(particles, particles.size() - start, start);
    List<point> x(batch.size());
    forAll(batch, i)
    {
        x[i] = batch[i].position;
    }

    const List<injectionSpec> listed(batch);
    const labelList idx(mortonOrder::order(x, cell));
    forAll(idx, i)
    {
        particles[start + i] = listed[idx[i]];
    }
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dpiInjectionModel> Foam::dpiInjectionModel::New
(
    const word& name,
    const dictionary& dict,
    const demMaterials* materials
)
{
    const word modelType(dict.get<word>("type"));

    Info<< "Selecting dpiInjectionModel " << modelType
        << " for injector " << name << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown injection model type " << modelType
            << " in injectors/" << name << nl << nl
            << "Valid types are :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<dpiInjectionModel>(cstrIter()(name, dict, materials));
}


// ************************************************************************* //
