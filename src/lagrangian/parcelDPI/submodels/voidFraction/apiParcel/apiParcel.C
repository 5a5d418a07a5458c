/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
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
