/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "pressureGradient.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiFluidForces
{
    defineTypeNameAndDebug(pressureGradient, 0);
    addToRunTimeSelectionTable(dpiFluidForce, pressureGradient, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiFluidForces::pressureGradient::pressureGradient
(
    const word& name,
    const dictionary& coeffs
)
:
    dpiFluidForce(name, coeffs, wordList())    // reads no coefficients
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::dpiFluidForce::forceSuSp
Foam::dpiFluidForces::pressureGradient::force
(
    const fluidState& fluid,
    const vector& v,
    const scalar d
) const
{
    using constant::mathematical::pi;

    forceSuSp F;
    F.Su = -(pi/6*pow3(d))*fluid.gradp;
    return F;
}


// ************************************************************************* //
