/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "dpiInjectionModel.H"

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
    const dictionary& dict
)
:
    name_(name),
    dict_(dict),
    SOI_(dict.lookupOrDefault<scalar>("SOI", 0))
{}


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
