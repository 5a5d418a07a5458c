/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "noCohesion.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace cohesionContactModels
{
    defineTypeNameAndDebug(noCohesion, 0);
    addToRunTimeSelectionTable(cohesionContactModel, noCohesion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cohesionContactModels::noCohesion::noCohesion(const dictionary& dict)
:
    cohesionContactModel(dict, typeName, wordList())    // reads no coefficients
{}


// ************************************************************************* //
