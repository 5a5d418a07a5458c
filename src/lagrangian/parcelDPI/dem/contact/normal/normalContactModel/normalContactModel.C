/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "normalContactModel.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(normalContactModel, 0);
    defineRunTimeSelectionTable(normalContactModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::normalContactModel::normalContactModel
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

Foam::autoPtr<Foam::normalContactModel>
Foam::normalContactModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("normalModel"));

    Info<< "Selecting normal contact model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "normalModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<normalContactModel>(cstrIter()(dict));
}


// ************************************************************************* //
