/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
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
