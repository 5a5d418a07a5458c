/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the LES subgrid turbulent dispersion
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    dpiTurbulentDispersion against theory 4.2 and 8.6:
    - closures: k = 5 Cs^2 Delta^2 |S|^2 and tau* = C_L k/((nu + nu_e)|S|^2)
      (3.5e-5 s for |S| = 1e4 1/s, Delta = 0.2 mm, air); legacyTimeScale:
      tau* |S| times longer (the reference's 0.35 s), |S| = sqrt(S:S);
    - the counter-based generator: reproducible per key, standard normal
      moments, independent components and keys;
    - with a frozen strain rate, over many parcels: the per-component
      variance of u* from u* = 0 follows 2k/3 (1 - exp(-2t/tau)) and tends
      to 2k/3, the autocorrelation tends to exp(-s/tau).
    Tolerances are 4 standard errors of the estimators for the sample size
    (sample variance: sqrt(2/(n - 1)) relative; sample correlation:
    (1 - rho^2)/sqrt(n)); the draws are deterministic (fixed keys), so a
    pass is reproducible.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "dpiTurbulentDispersion.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary dispersionDict(const bool legacy, const scalar delta)
    {
        dictionary d;
        d.add("legacyTimeScale", legacy);
        d.add("delta", delta);
        return d;
    }
}


TEST(turbulentDispersion, closuresTheory42)
{
    const dpiTurbulentDispersion td(dispersionDict(false, 2e-4));
    const dpiTurbulentDispersion legacy(dispersionDict(true, 2e-4));

    const scalar Cs = 0.08, Delta = 2e-4, S = 1e4, nu = 1.511e-5;
    const dpiTurbulentDispersion::sgs s = td.closure(S, Delta, nu);

    EXPECT_NEAR(td.CL(), 1/(0.5 + 0.75*2.1), 1e-15);
    EXPECT_NEAR(s.k/(5*Cs*Cs*Delta*Delta*S*S), 1, 1e-14);
    const scalar nuE = Cs*Cs*Delta*Delta*S;
    EXPECT_NEAR(s.tau/(td.CL()*s.k/((nu + nuE)*S*S)), 1, 1e-14);
    EXPECT_NEAR(s.tau/3.5e-5, 1, 0.01);        // theory 4.2: 3.5e-5 s

    // The reference's formula, |S| times longer (0.35 s)
    const dpiTurbulentDispersion::sgs l = legacy.closure(S, Delta, nu);
    EXPECT_NEAR
    (
        l.tau/(5*td.CL()*Cs*Cs*Delta*Delta*S/(nu + Cs*Cs*Delta*Delta*S)),
        1, 1e-14
    );
    EXPECT_NEAR(l.tau/s.tau, S, 1e-9*S);
    EXPECT_NEAR(l.tau/0.35, 1, 0.01);

    // |S| conventions: sqrt(2 S:S) by default, sqrt(S:S) in legacy mode
    const tensor gradU(0, 100, 0, 0, 0, 0, 0, 0, 0);     // simple shear
    EXPECT_NEAR(td.magS(gradU), 100, 1e-12);
    EXPECT_NEAR(legacy.magS(gradU), 100/Foam::sqrt(2.0), 1e-12);

    // No strain: no subgrid motion
    EXPECT_EQ(td.closure(0, Delta, nu).k, 0);
    EXPECT_EQ(mag(td.update(vector(1, 2, 3), td.closure(0, Delta, nu), 1e-5, 7, 1, 0)), 0);

    // Default filter width: cube root of the cell volume
    const dpiTurbulentDispersion cellDelta(dictionary::null);
    EXPECT_NEAR(cellDelta.delta(8e-12), 2e-4, 1e-16);
}


TEST(turbulentDispersion, counterBasedGenerator)
{
    // Same key, same numbers (no state): serial = parallel = restart
    EXPECT_EQ
    (
        dpiTurbulentDispersion::gaussian(0, 12345, 678, 0),
        dpiTurbulentDispersion::gaussian(0, 12345, 678, 0)
    );
    EXPECT_NE
    (
        dpiTurbulentDispersion::gaussian(0, 12345, 678, 0).x(),
        dpiTurbulentDispersion::gaussian(0, 12346, 678, 0).x()
    );
    EXPECT_NE
    (
        dpiTurbulentDispersion::gaussian(0, 12345, 678, 0).x(),
        dpiTurbulentDispersion::gaussian(0, 12345, 679, 0).x()
    );
    EXPECT_NE
    (
        dpiTurbulentDispersion::gaussian(0, 12345, 678, 0).x(),
        dpiTurbulentDispersion::gaussian(1, 12345, 678, 0).x()
    );

    // Moments over ids x steps: mean 0, variance 1, no correlation between
    // components, nor between consecutive steps of one id
    const label nId = 2000, nStep = 200;
    const scalar n = nId*nStep;
    vector sum(Zero), sum2(Zero);
    scalar xy = 0, yz = 0, lag = 0, sum4 = 0;
    for (label id = 0; id < nId; ++id)
    {
        vector prev(Zero);
        for (label step = 0; step < nStep; ++step)
        {
            const vector z = dpiTurbulentDispersion::gaussian(3, id, step, 0);
            sum += z;
            sum2 += cmptMultiply(z, z);
            sum4 += Foam::pow4(z.x());
            xy += z.x()*z.y();
            yz += z.y()*z.z();
            lag += z.x()*prev.x();
            prev = z;
        }
    }
    const scalar se = 4/Foam::sqrt(n);
    for (direction c = 0; c < 3; ++c)
    {
        EXPECT_NEAR(sum[c]/n, 0, se) << "component " << label(c);
        EXPECT_NEAR(sum2[c]/n, 1, 4*Foam::sqrt(2/n)) << "component " << label(c);
    }
    EXPECT_NEAR(sum4/n, 3, 4*Foam::sqrt(96/n));     // Gaussian kurtosis
    EXPECT_NEAR(xy/n, 0, se);
    EXPECT_NEAR(yz/n, 0, se);
    EXPECT_NEAR(lag/n, 0, se);
}


TEST(turbulentDispersion, frozenStrainVarianceAndAutocorrelation)
{
    const dpiTurbulentDispersion td(dispersionDict(false, 2e-4));
    const dpiTurbulentDispersion::sgs s = td.closure(1e4, 2e-4, 1.511e-5);
    const scalar var = 2*s.k/3;
    const scalar tau = s.tau;
    const scalar dt = tau/10;

    const label n = 100000;                  // parcels
    const scalar nS = 3*n;                   // samples (3 components)
    List<vector> u(n, Zero);

    auto advance = [&](const label step)
    {
        for (label i = 0; i < n; ++i)
        {
            u[i] = td.update(u[i], s, dt, i, step, 0);
        }
    };
    auto variance = [&]()
    {
        scalar v = 0;
        for (const vector& x : u)
        {
            v += magSqr(x);
        }
        return v/nS;
    };

    label step = 0;
    // Transient from u* = 0: 2k/3 (1 - exp(-2t/tau)) at t = tau
    for (; step < 10; ++step)
    {
        advance(step);
    }
    const scalar v1 = variance();
    const scalar v1Ref = var*(1 - Foam::exp(-2.0));
    EXPECT_NEAR(v1/v1Ref, 1, 4*Foam::sqrt(2/(nS - 1)));

    // Stationary after 10 tau
    for (; step < 100; ++step)
    {
        advance(step);
    }
    const scalar vInf = variance();
    EXPECT_NEAR(vInf/var, 1, 4*Foam::sqrt(2/(nS - 1)))
        << "variance " << vInf << ", 2k/3 = " << var;

    // Autocorrelation at lags tau/2, tau, 2 tau
    const List<vector> u0(u);
    const scalar v0 = variance();
    label lag = 0;
    for (const label lagTarget : {5, 10, 20})
    {
        for (; lag < lagTarget; ++lag, ++step)
        {
            advance(step);
        }
        scalar c = 0;
        forAll(u, i)
        {
            c += u0[i] & u[i];
        }
        const scalar rho = c/nS/Foam::sqrt(v0*variance());
        const scalar rhoRef = Foam::exp(-lag*dt/tau);
        EXPECT_NEAR(rho, rhoRef, 4*(1 - sqr(rhoRef))/Foam::sqrt(nS))
            << "lag " << lag*dt/tau << " tau";
        std::cout
            << "    [ info ] lag " << lag*dt/tau << " tau: rho " << rho
            << " (exp " << rhoRef << ")" << std::endl;
    }
    std::cout
        << "    [ info ] variance/(2k/3): at t = tau " << v1/v1Ref
        << " of (1 - e^-2), stationary " << vInf/var << "; k = " << s.k
        << " m2/s2, tau* = " << tau << " s, " << n << " parcels"
        << std::endl;
}


// ************************************************************************* //
