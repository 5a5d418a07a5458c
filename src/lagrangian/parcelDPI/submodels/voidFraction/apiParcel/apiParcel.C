/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "apiParcel.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiVoidFractions
{
    defineTypeNameAndDebug(apiParcel, 0);
    addToRunTimeSelectionTable(dpiVoidFraction, apiParcel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiVoidFractions::apiParcel::apiParcel(const dictionary& dict)
:
    dpiVoidFraction(dict, wordList())    // reads no other keys
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dpiVoidFractions::apiParcel::solidVolume
(
    const scalar d,
    const scalar N
) const
{
    return N*constant::mathematical::pi/6*d*d*d;
}


// ************************************************************************* //
