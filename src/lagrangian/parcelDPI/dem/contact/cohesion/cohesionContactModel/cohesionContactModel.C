/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "cohesionContactModel.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(cohesionContactModel, 0);
    defineRunTimeSelectionTable(cohesionContactModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cohesionContactModel::cohesionContactModel
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

Foam::autoPtr<Foam::cohesionContactModel>
Foam::cohesionContactModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("cohesionModel"));

    Info<< "Selecting cohesion model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "cohesionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<cohesionContactModel>(cstrIter()(dict));
}


// ************************************************************************* //
