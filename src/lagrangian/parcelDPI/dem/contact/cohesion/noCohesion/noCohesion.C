/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
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
