/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "tangentialContactModel.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(tangentialContactModel, 0);
    defineRunTimeSelectionTable(tangentialContactModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::tangentialContactModel::tangentialContactModel
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

Foam::autoPtr<Foam::tangentialContactModel>
Foam::tangentialContactModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("tangentialModel"));

    Info<< "Selecting tangential contact model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "tangentialModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<tangentialContactModel>(cstrIter()(dict));
}


// ************************************************************************* //
