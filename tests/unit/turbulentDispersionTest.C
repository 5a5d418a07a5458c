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
      to 2k/3, the autocorrelation tends to exp(-s/tau);
    - closure WALE: no subgrid energy in pure shear, k ~ y^6 (nu_e ~ y^3)
      approaching a no-slip wall, k ~ Delta^2 |grad u|^2, the closed form in
      plane strain and rotation, tau* = C_L Delta/(Ce sqrt(k));
    - sharing agglomerate: a carrier and its API take the mass-weighted
      mean u* (the subgrid momentum kept) and then one path to the bit, a
      singlet its own; the shared u* has the OU law of the shared k and
      tau*; legacyTimeScale selects the reference's whole model.
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


TEST(turbulentDispersion, waleClosure)
{
    const dpiTurbulentDispersion td(dispersionDict(false, 2e-4));
    ASSERT_TRUE
    (
        td.closureModel() == dpiTurbulentDispersion::closureType::WALE
    );
    const scalar Delta = 2e-4, nu = 1.511e-5;
    const scalar Cw = 0.325, Ck = 0.094, Ce = 1.048;
    const scalar C = sqr(sqr(Cw)*Delta/Ck);

    // Pure shear (grad u = G e_y e_x: the wall's limit): none, where
    // Smagorinsky's is largest
    const tensor shear(0, 0, 0, 1e4, 0, 0, 0, 0, 0);
    EXPECT_EQ(td.closure(shear, Delta, nu).k, 0);
    EXPECT_GT(td.closure(td.magS(shear), Delta, nu).k, 0);

    // Plane strain S = diag(a, -a, 0): S:S = 2a^2, dev(S.S) has
    // Sd:Sd = 2a^4/3 (by hand)
    const scalar a = 1e4;
    const tensor strain(a, 0, 0, 0, -a, 0, 0, 0, 0);
    const scalar SS = 2*sqr(a), SdSd = 2*pow4(a)/3;
    const scalar kStrain =
        C*pow3(SdSd)/sqr(Foam::pow(SS, 2.5) + Foam::pow(SdSd, 1.25));
    const dpiTurbulentDispersion::sgs sStrain =
        td.closure(strain, Delta, nu);
    EXPECT_NEAR(sStrain.k/kStrain, 1, 1e-12);
    EXPECT_NEAR(sStrain.tau/(td.CL()*Delta/(Ce*Foam::sqrt(kStrain))), 1, 1e-12);

    // Solid rotation at rate w about z: S = 0, g.g = -w^2 (e_x e_x + e_y
    // e_y), Sd:Sd = 2w^4/3 (by hand), so k = C sqrt(Sd:Sd)
    const scalar w = 1e4;
    const tensor rotation(0, w, 0, -w, 0, 0, 0, 0, 0);
    EXPECT_NEAR
    (
        td.closure(rotation, Delta, nu).k/(C*Foam::sqrt(2*pow4(w)/3)),
        1, 1e-12
    );

    // k ~ Delta^2 |grad u|^2
    const tensor g(3e3, -1e3, 2e3, 5e2, -4e3, 1e3, -2e3, 7e2, 1e3);
    const scalar k1 = td.closure(g, Delta, nu).k;
    EXPECT_GT(k1, 0);
    EXPECT_NEAR(td.closure(2*g, Delta, nu).k/k1, 4, 1e-10);
    EXPECT_NEAR(td.closure(g, 2*Delta, nu).k/k1, 4, 1e-10);

    // Towards a no-slip wall y = 0 (Nicoud & Ducros): u = a y - 2 b x y,
    // v = b y^2, w = c y (divergence-free); at x = 0 the gradient d_i u_j
    // has d_y u = a, d_y w = c, d_x u = -2 b y, d_y v = 2 b y. Then
    // k ~ y^6, so nu_e = Ck Delta sqrt(k) ~ y^3: the local slope of
    // log k against log y tends to 6
    auto kWall = [&](const scalar y)
    {
        const scalar A = 1e4, B = 1e6, Cc = 5e3;
        const tensor gw(-2*B*y, 0, 0, A, 2*B*y, Cc, 0, 0, 0);
        return td.closure(gw, Delta, nu).k;
    };
    const scalar slope =
        Foam::log(kWall(2e-6)/kWall(1e-6))/Foam::log(2.0);
    EXPECT_NEAR(slope, 6, 0.01) << "k(y) ~ y^" << slope;

    // No gradient: no subgrid motion
    EXPECT_EQ(td.closure(tensor::zero, Delta, nu).k, 0);
    std::cout
        << "    [ info ] WALE: plane strain 1e4 1/s k " << sStrain.k
        << " m2/s2, tau* " << sStrain.tau << " s; near the wall k ~ y^"
        << slope << std::endl;
}


TEST(turbulentDispersion, agglomerateSharesOneVelocity)
{
    const dpiTurbulentDispersion td(dispersionDict(false, 2e-4));
    ASSERT_TRUE
    (
        td.sharing() == dpiTurbulentDispersion::sharingType::agglomerate
    );

    // A carrier (id 4) with three API parcels (ids 7, 9, 12) in cells of
    // different k, and a singlet API (id 5)
    const labelList gid({7, 4, 9, 12, 5});
    const labelList agg({4, 4, 4, 4, 5});
    const scalarList mass({3e-12, 2.7e-10, 1e-12, 2e-12, 1e-12});
    List<vector> u
    ({
        vector(0.3, -0.1, 0.2), vector(0.01, 0, -0.02),
        vector(-0.5, 0.4, 0), vector(0, 0, 0.6), vector(0.2, 0.2, 0.2)
    });
    List<dpiTurbulentDispersion::sgs> s(5);
    const scalarList k({0.2, 0.05, 0.4, 0.1, 0.3});
    const scalarList tau({1e-4, 3e-4, 8e-5, 2e-4, 9e-5});
    forAll(s, i)
    {
        s[i].k = k[i];
        s[i].tau = tau[i];
    }
    vector momentum(Zero);
    scalar m = 0, mk = 0, mtau = 0;
    for (label i = 0; i < 4; ++i)
    {
        momentum += mass[i]*u[i];
        m += mass[i];
        mk += mass[i]*k[i];
        mtau += mass[i]*tau[i];
    }
    const vector single(u[4]);

    labelList key(5, -1);
    td.share(agg, gid, mass, u, s, key);

    // The agglomerate's subgrid momentum is kept, the means are shared
    vector after(Zero);
    for (label i = 0; i < 4; ++i)
    {
        after += mass[i]*u[i];
        EXPECT_EQ(key[i], 4);
        EXPECT_EQ(u[i], u[0]);
        EXPECT_NEAR(s[i].k, mk/m, 1e-15);
        EXPECT_NEAR(s[i].tau, mtau/m, 1e-19);
    }
    EXPECT_LT(mag(after - momentum), 1e-14*mag(momentum));
    EXPECT_EQ(key[4], 5);
    EXPECT_EQ(u[4], single);
    EXPECT_EQ(s[4].k, k[4]);

    // One path to the bit for the agglomerate, another for the singlet
    for (label step = 0; step < 200; ++step)
    {
        forAll(u, i)
        {
            u[i] = td.update(u[i], s[i], 1e-5, key[i], step, 0);
        }
    }
    for (label i = 1; i < 4; ++i)
    {
        EXPECT_EQ(u[i], u[0]);
    }
    EXPECT_GT(mag(u[4] - u[0]), 0);

    // sharing parcel: each its own key and u*
    dictionary d(dispersionDict(false, 2e-4));
    d.add("sharing", "parcel");
    const dpiTurbulentDispersion own(d);
    List<vector> u2(5, vector(1, 2, 3));
    List<dpiTurbulentDispersion::sgs> s2(s);
    own.share(agg, gid, mass, u2, s2, key);
    EXPECT_EQ(key, gid);
    EXPECT_EQ(u2[2], vector(1, 2, 3));

    // The shared u* over many two-parcel agglomerates of unequal k has the
    // OU law of the shared k: stationary variance 2 k_mean/3
    const label n = 50000;
    labelList g2(2*n), a2(2*n), key2(2*n);
    scalarList m2(2*n, 1e-12);
    List<vector> u3(2*n, Zero);
    List<dpiTurbulentDispersion::sgs> s3(2*n);
    for (label i = 0; i < n; ++i)
    {
        g2[2*i] = 2*i;
        g2[2*i+1] = 2*i + 1;
        a2[2*i] = a2[2*i+1] = 2*i;
        s3[2*i].k = 0.1;
        s3[2*i+1].k = 0.3;
        s3[2*i].tau = s3[2*i+1].tau = 1e-4;
    }
    td.share(a2, g2, m2, u3, s3, key2);
    for (label step = 0; step < 100; ++step)
    {
        forAll(u3, i)
        {
            u3[i] = td.update(u3[i], s3[i], 1e-5, key2[i], step, 0);
        }
    }
    scalar v = 0;
    for (label i = 0; i < n; ++i)
    {
        EXPECT_EQ(u3[2*i], u3[2*i+1]);
        v += magSqr(u3[2*i]);
    }
    v /= 3*n;
    EXPECT_NEAR(v/(2*0.2/3), 1, 4*Foam::sqrt(2.0/(3*n - 1)));
}


TEST(turbulentDispersion, legacyIsTheGuidesModel)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const dpiTurbulentDispersion legacy(dispersionDict(true, 2e-4));
    EXPECT_TRUE
    (
        legacy.closureModel()
     == dpiTurbulentDispersion::closureType::Smagorinsky
    );
    EXPECT_TRUE
    (
        legacy.sharing() == dpiTurbulentDispersion::sharingType::parcel
    );

    // The reference's time scale with another closure: refused
    dictionary d(dispersionDict(true, 2e-4));
    d.add("closure", "WALE");
    EXPECT_THROW(dpiTurbulentDispersion bad(d), Foam::error);

    // A misspelt choice: refused with the valid ones
    dictionary e(dispersionDict(false, 2e-4));
    e.add("sharing", "agglomerates");
    try
    {
        dpiTurbulentDispersion bad(e);
        ADD_FAILURE() << "sharing agglomerates accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("agglomerate"), std::string::npos) << msg;
        EXPECT_NE(msg.find("parcel"), std::string::npos) << msg;
    }
}


// ************************************************************************* //
