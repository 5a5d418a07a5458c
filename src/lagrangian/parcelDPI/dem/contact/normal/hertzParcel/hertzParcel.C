/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "hertzParcel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace normalContactModels
{
    defineTypeNameAndDebug(hertzParcel, 0);
    addToRunTimeSelectionTable(normalContactModel, hertzParcel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

const Foam::wordList Foam::normalContactModels::hertzParcel::coeffKeys
({
    "limitForce",
    "tangentialDamping"
});


Foam::normalContactModels::hertzParcel::hertzParcel(const dictionary& dict)
:
    normalContactModel(dict, typeName, coeffKeys),
    limitForce_(coeffDict_.getOrDefault<bool>("limitForce", false)),
    tangentialDamping_
    (
        coeffDict_.getOrDefault<bool>("tangentialDamping", true)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


Foam::scalar Foam::normalContactModels::hertzParcel::contactTime
(
    const demPairProperties& props,
    const scalar Rstar,
    const scalar mass,
    const scalar v
) const
{
    // 2.9433*(15/16)^(2/5) = 2.8683 (theory 7.1)
    return 2.8683*pow(sqr(mass)/(Rstar*sqr(props.Ystar)*v), 0.2);
}


// ************************************************************************* //
