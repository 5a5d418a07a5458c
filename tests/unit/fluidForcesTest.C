/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the gas-particle force models
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    wenYuParcel against theory 4.1 and 8.5: Stokes limit 3 pi mu d u_r
    alpha^-2.65 (model A), the Wen-Yu correction and the Re >= 1000 branch,
    exact x N scaling; pressureGradient = -N V_p grad(p); the selector's
    error for an unknown force.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wenYuParcel.H"
#include "scalarList.H"
#include "pressureGradient.H"
#include "mathematicalConstants.H"

using namespace Foam;
using constant::mathematical::pi;

namespace
{
    dpiFluidForce::fluidState air(const scalar alpha)
    {
        dpiFluidForce::fluidState f;
        f.rho = 1.2;
        f.nu = 1.511e-5;
        f.alpha = alpha;
        return f;
    }

    vector totalForce
    (
        const dpiFluidForce& m,
        const dpiFluidForce::fluidState& f,
        const vector& v,
        const scalar d,
        const scalar N
    )
    {
        const dpiFluidForce::forceSuSp F = m.parcelForce(f, v, d, N);
        return F.Su + F.Sp*(f.U + f.Uturb - v);
    }
}


TEST(wenYuParcel, StokesLimitModelA)
{
    autoPtr<dpiFluidForce> drag(dpiFluidForce::New("wenYuParcel", dictionary()));
    const scalar d = 5e-6, mu = 1.2*1.511e-5;
    const vector v(0, 0, -1e-9);    // Re ~ 3e-10
    for (const scalar alpha : {1.0, 0.7, 0.4})
    {
        const vector F = totalForce(drag(), air(alpha), v, d, 1);
        const scalar stokes = 3*pi*mu*d*1e-9*Foam::pow(alpha, scalar(-2.65));
        EXPECT_NEAR(F.z()/stokes, 1, 1e-6) << "alpha " << alpha;
        EXPECT_EQ(F.x(), 0);
    }
    EXPECT_TRUE(drag->coupled());
    EXPECT_NEAR(drag->relaxationTime(d, 1520, 1.2, 1.511e-5)/1.164e-4, 1, 1e-3);
}


TEST(wenYuParcel, WenYuCorrectionAndHighRe)
{
    const scalar d = 5e-6, nu = 1.511e-5, rho = 1.2;
    // Re = 1: (1 + 0.15)
    const scalar u1 = nu/d;
    EXPECT_NEAR
    (
        dpiFluidForces::wenYuParcel::primarySp(d, 1, rho, nu, u1)
       /(3*pi*rho*nu*d),
        1.15, 1e-12
    );
    // Re = 2000: C_D = 0.44 alpha^-1.65
    const scalar alpha = 0.8, u2 = 2000*nu/(alpha*d);
    EXPECT_NEAR
    (
        dpiFluidForces::wenYuParcel::primarySp(d, alpha, rho, nu, u2)
       /(pi/8*d*d*rho*0.44*Foam::pow(alpha, scalar(-1.65))*u2),
        1, 1e-12
    );
}


TEST(wenYuParcel, ForceIsNTimesPrimary)
{
    autoPtr<dpiFluidForce> drag(dpiFluidForce::New("wenYuParcel", dictionary()));
    dpiFluidForce::fluidState f = air(0.9);
    f.U = vector(0.3, -0.1, 2);
    const vector v(0.1, 0.2, -0.5);
    const vector F1 = totalForce(drag(), f, v, 5e-6, 1);
    for (const scalar N : {10.0, 100.0})
    {
        const vector FN = totalForce(drag(), f, v, 5e-6, N);
        EXPECT_NEAR(mag(FN/N - F1)/mag(F1), 0, 1e-14) << "N " << N;
    }
}


TEST(wenYuParcel, AlphaRangeIsTheReferencesClamp)
{
    FatalIOError.throwExceptions();

    // The reference clamps the drag's interpolated void fraction to
    // [0.4, 1]: below 0.4 the force is the force at 0.4, inside the range
    // unchanged
    dictionary clampDict;
    clampDict.add("alphaRange", scalarList({0.4, 1}));
    autoPtr<dpiFluidForce> clamped
    (
        dpiFluidForce::New("wenYuParcel", clampDict)
    );
    autoPtr<dpiFluidForce> plain
    (
        dpiFluidForce::New("wenYuParcel", dictionary())
    );
    const vector v(0.1, 0.2, -0.5);
    for (const scalar alpha : {0.3, 0.4, 0.7, 1.0})
    {
        dpiFluidForce::fluidState f = air(alpha);
        f.U = vector(0.3, -0.1, 2);
        dpiFluidForce::fluidState g = air(max(alpha, 0.4));
        g.U = f.U;
        const vector Fc = totalForce(clamped(), f, v, 5e-6, 10);
        const vector Fp = totalForce(plain(), g, v, 5e-6, 10);
        EXPECT_EQ(Fc, Fp) << "alpha " << alpha;
    }
    // At 0.3 the clamp lowers the drag: (0.3/0.4)^-3.65 in Stokes flow
    const vector F03 = totalForce(plain(), air(0.3), v, 5e-6, 10);
    const vector F03c = totalForce(clamped(), air(0.3), v, 5e-6, 10);
    EXPECT_LT(mag(F03c), mag(F03));

    // A range that is not one: refused
    const List<scalarList> bads
    ({
        scalarList({0.5, 0.4}), scalarList({0, 1}), scalarList({0.4, 1.2}),
        scalarList({0.4})
    });
    for (const scalarList& bad : bads)
    {
        dictionary d;
        d.add("alphaRange", bad);
        EXPECT_THROW(dpiFluidForce::New("wenYuParcel", d), Foam::error)
            << "alphaRange of " << bad.size() << " values";
    }
}


TEST(pressureGradient, MinusNVgradP)
{
    autoPtr<dpiFluidForce> gp(dpiFluidForce::New("pressureGradient", dictionary()));
    dpiFluidForce::fluidState f = air(1);
    f.gradp = vector(0, 0, -1.2*9.81);  // hydrostatic: buoyancy upwards
    const scalar d = 5e-6, N = 100;
    const vector F = totalForce(gp(), f, vector(1, 2, 3), d, N);
    EXPECT_NEAR(F.z()/(N*pi/6*pow3(d)*1.2*9.81), 1, 1e-14);
    // Coupled: its reaction turns the gas's -grad(p) into -alpha grad(p)
    // (model A) and balances the momentum (incompressibleGas)
    EXPECT_TRUE(gp->coupled());
}
