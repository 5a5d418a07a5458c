/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "rollingContactModel.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(rollingContactModel, 0);
    defineRunTimeSelectionTable(rollingContactModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rollingContactModel::rollingContactModel
(
    const dictionary& dict,
    const word& type,
    const wordList& coeffKeys
)
:
    coeffDict_(dict.subOrEmptyDict(type + "Coeffs"))
{
    dictKeys::warnUnknown(coeffDict_, coeffKeys);
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::rollingContactModel>
Foam::rollingContactModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("rollingModel"));

    Info<< "Selecting rolling contact model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "rollingModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<rollingContactModel>(cstrIter()(dict));
}


// ************************************************************************* //
