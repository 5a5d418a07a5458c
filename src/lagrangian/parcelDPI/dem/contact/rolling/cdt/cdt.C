/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "cdt.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rollingContactModels
{
    defineTypeNameAndDebug(cdt, 0);
    addToRunTimeSelectionTable(rollingContactModel, cdt, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

const Foam::wordList Foam::rollingContactModels::cdt::coeffKeys
({
    "scaleTorqueWithN",
    "holdAtRest"
});


Foam::rollingContactModels::cdt::cdt(const dictionary& dict)
:
    rollingContactModel(dict, typeName, coeffKeys),
    scaleTorqueWithN_(coeffDict_.getOrDefault<bool>("scaleTorqueWithN", true)),
    holdAtRest_(coeffDict_.getOrDefault<bool>("holdAtRest", true)),
    invDt_(1/dict.get<scalar>("timeStep"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //


// ************************************************************************* //
