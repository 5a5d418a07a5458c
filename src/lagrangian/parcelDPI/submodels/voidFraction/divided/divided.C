/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "divided.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiVoidFractions
{
    defineTypeNameAndDebug(divided, 0);
    addToRunTimeSelectionTable(dpiVoidFraction, divided, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiVoidFractions::divided::divided(const dictionary& dict)
:
    dpiVoidFraction(dict, wordList())    // reads no other keys
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dpiVoidFractions::divided::solidVolume
(
    const scalar d,
    const scalar  // N: ignored (one particle per parcel)
) const
{
    return constant::mathematical::pi/6*d*d*d;
}


// ************************************************************************* //
