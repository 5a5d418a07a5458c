/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "wenYuParcel.H"
#include "mathematicalConstants.H"
#include "scalarList.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiFluidForces
{
    defineTypeNameAndDebug(wenYuParcel, 0);
    addToRunTimeSelectionTable(dpiFluidForce, wenYuParcel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiFluidForces::wenYuParcel::wenYuParcel
(
    const word& name,
    const dictionary& coeffs
)
:
    dpiFluidForce(name, coeffs, wordList({"alphaRange"})),
    alphaLow_(0),
    alphaHigh_(1)
{
    if (coeffs.found("alphaRange"))
    {
        const scalarList range(coeffs.get<scalarList>("alphaRange"));
        if
        (
            range.size() != 2 || range[0] <= 0 || range[0] >= range[1]
         || range[1] > 1
        )
        {
            FatalIOErrorInFunction(coeffs)
                << "wenYuParcel/alphaRange " << range << " in "
                << coeffs.name() << ": give (low high) with 0 < low < high"
                << " <= 1, e.g. (0.4 1) as the reference"
                << exit(FatalIOError);
        }
        alphaLow_ = range[0];
        alphaHigh_ = range[1];
        Info<< "    wenYuParcel: the drag's void fraction clamped to ["
            << alphaLow_ << ", " << alphaHigh_ << "]" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dpiFluidForces::wenYuParcel::primarySp
(
    const scalar d,
    const scalar alpha,
    const scalar rhof,
    const scalar nuf,
    const scalar magUr
)
{
    using constant::mathematical::pi;

    const scalar Re = alpha*d*magUr/nuf;
    const scalar alphaPow = pow(alpha, -1.65);

    if (Re < 1000)
    {
        // (pi/8) d^2 rho C_D |u_r| with C_D = 24/Re (...): written without
        // 1/Re so that u_r = 0 is regular
        return
            3*pi*rhof*nuf*d/alpha*alphaPow*(1 + 0.15*pow(Re, 0.687));
    }

    return (pi/8)*sqr(d)*rhof*0.44*alphaPow*magUr;
}


Foam::scalar Foam::dpiFluidForces::wenYuParcel::relaxationTime
(
    const scalar d,
    const scalar rhop,
    const scalar rhof,
    const scalar nuf
) const
{
    return rhop*sqr(d)/(18*rhof*nuf);
}


Foam::dpiFluidForce::forceSuSp Foam::dpiFluidForces::wenYuParcel::force
(
    const fluidState& fluid,
    const vector& v,
    const scalar d
) const
{
    const vector Ur(fluid.U + fluid.Uturb - v);

    forceSuSp F;
    const scalar alpha = min(max(fluid.alpha, alphaLow_), alphaHigh_);
    F.Sp = primarySp(d, alpha, fluid.rho, fluid.nu, mag(Ur));
    return F;
}


// ************************************************************************* //
