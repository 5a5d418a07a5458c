/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "coatingCoverage.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coarseGrainingModels
{
    defineTypeNameAndDebug(coatingCoverage, 0);
    addToRunTimeSelectionTable
    (
        coarseGrainingModel,
        coatingCoverage,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coarseGrainingModels::coatingCoverage::coatingCoverage
(
    const dictionary& dict,
    const scalarUList& N,
    const boolUList& api
)
:
    coarseGrainingModel(dict, typeName, {"knockShare"}, api)
{
    knockShare_ = coeffDict_.getOrDefault<scalar>("knockShare", 1);
    if (!(knockShare_ >= 0 && knockShare_ <= 1))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "knockShare = " << knockShare_ << " in dictionary "
            << coeffDict_.name() << " must be within 0 ... 1 (the share of"
            << " a grown contact's radial push moved to the seat)"
            << exit(FatalIOError);
    }

    forAll(N, t)
    {
        if (api[t] && N[t] > 1)
        {
            factor_[t] = std::sqrt(N[t]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coarseGrainingModels::coatingCoverage::describe
(
    Ostream& os,
    const wordList& names
) const
{
    os  << "coarse-graining coatingCoverage:";
    bool any = false;
    forAll(factor_, t)
    {
        if (factor_[t] > 1)
        {
            os  << ' ' << names[t] << " parcels meet at " << factor_[t]
                << " x their primary radius,";
            any = true;
        }
    }
    if (!any)
    {
        os  << " no API type has N > 1 (primary contacts),";
    }
    os  << " knock share " << knockShare_;
}


// ************************************************************************* //
