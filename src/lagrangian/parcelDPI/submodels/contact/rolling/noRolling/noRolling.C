/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
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
