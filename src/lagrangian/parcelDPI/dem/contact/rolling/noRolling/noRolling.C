/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "noRolling.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rollingContactModels
{
    defineTypeNameAndDebug(noRolling, 0);
    addToRunTimeSelectionTable(rollingContactModel, noRolling, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rollingContactModels::noRolling::noRolling(const dictionary& dict)
:
    rollingContactModel(dict, typeName, wordList())    // reads no coefficients
{}


// ************************************************************************* //
