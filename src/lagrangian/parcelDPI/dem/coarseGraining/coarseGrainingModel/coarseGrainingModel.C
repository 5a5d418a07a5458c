/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "coarseGrainingModel.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(coarseGrainingModel, 0);
    defineRunTimeSelectionTable(coarseGrainingModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coarseGrainingModel::coarseGrainingModel
(
    const dictionary& dict,
    const word& type,
    const wordList& coeffKeys,
    const boolUList& api
)
:
    coeffDict_(dict.subOrEmptyDict(type + "Coeffs")),
    factor_(api.size(), scalar(1)),
    seat_(api.size()),
    knockShare_(0)
{
    dictKeys::warnUnknown(coeffDict_, coeffKeys);
    forAll(api, t)
    {
        seat_[t] = !api[t];
    }
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coarseGrainingModel> Foam::coarseGrainingModel::New
(
    const dictionary& dict,
    const scalarUList& N,
    const boolUList& api,
    const bool report
)
{
    const word modelType
    (
        dict.getOrDefault<word>("coarseGraining", "scaledContacts")
    );

    if (report)
    {
        Info<< "Selecting coarse-graining model " << modelType
            << (dict.found("coarseGraining") ? "" : " (default)") << endl;
    }

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "coarseGraining",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // The coefficients of a model not selected would be ignored: say so
    for (const word& other : dictionaryConstructorTablePtr_->sortedToc())
    {
        if (report && other != modelType && dict.found(other + "Coeffs"))
        {
            WarningInFunction
                << "Dictionary " << dict.name() << " has " << other
                << "Coeffs but coarseGraining is " << modelType
                << ": its entries are not used" << endl;
        }
    }

    return autoPtr<coarseGrainingModel>(cstrIter()(dict, N, api));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coarseGrainingModel::grows() const
{
    return maxFactor() > 1;
}


Foam::scalar Foam::coarseGrainingModel::maxRadius
(
    const UList<scalar>& r,
    const labelUList& typeId
) const
{
    scalar rMax = 0;
    forAll(r, p)
    {
        rMax = max(rMax, factor_[typeId[p]]*r[p]);
    }
    return rMax;
}


Foam::scalar Foam::coarseGrainingModel::maxFactor() const
{
    scalar f = 1;
    for (const scalar ft : factor_)
    {
        f = max(f, ft);
    }
    return f;
}


// ************************************************************************* //
