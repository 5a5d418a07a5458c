/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the coarse-graining models
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    coatingCoverage (doc/theory.md 2.5): a parcel's wall impact is the
    primary's at any N; two parcels meet at sqrt(N) x their primary radii
    with the primaries' contact law (their impact is the N = 1 impact
    displaced by the growth); a knock of two parcels on one carrier moves
    the radial part of its normal force to the carrier (closed form) and
    keeps momentum; parcels that overlap at their grown radii are refused
    at the start and regionPacking keeps them apart; bad input.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "guideParticles.H"
#include "regionPacking.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

// Guide particles: carrier type 0, API type 1
using namespace guideParticles;
const auto massOf = guideParticles::mass;

// The engine dictionary: API parcels of N, no cohesion, a floor z = 0 when
// floor, the given coarse-graining entries
std::string engineText
(
    const scalar N,
    const std::string& coarseGraining,
    const bool floor = false,
    const scalar dt = 1e-10
)
{
    std::ostringstream os;
    os.precision(17);
    os  << "timeStep " << dt << ";\n"
        << "types {\n"
        << "  carrier { diameter " << 2*rCarrier << "; density " << rho
        << "; youngsModulus 5e8; poissonsRatio 0.35; }\n"
        << "  API { diameter " << 2*rApi << "; density " << rho
        << "; youngsModulus 5e8; poissonsRatio 0.35; N " << N
        << "; api true; }\n"
        << "}\n"
        << "pairs { default { restitution 0.85; friction 0.45; } }\n"
        << "normalModel hertzParcel; tangentialModel historyParcel;\n"
        << "rollingModel none; cohesionModel none;\n"
        << coarseGraining << "\n";
    if (floor)
    {
        os  << "walls { floor { type plane; point (0 0 0); normal (0 0 1);"
            << " material carrier; } }\n";
    }
    os  << "neighbourSearch { skin 1e-6; }\n"
        << "timeStepCheck { maxImpactVelocity 2; }\n";
    return os.str();
}

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

const std::string coverage("coarseGraining coatingCoverage;");

// Every sub-step's state of all rows
struct history
:
    public demObserver
{
    std::vector<List<point>> x;
    std::vector<List<vector>> v, f;

    virtual void subStep(const scalar, const demState& s)
    {
        x.push_back(s.x);
        v.push_back(s.v);
        f.push_back(s.f);
    }
};

// Total momentum of the rows (a parcel weighs N primaries)
vector momentum(const demState& s)
{
    vector p(Zero);
    forAll(s.x, i)
    {
        p += s.N[i]*s.m[i]*s.v[i];
    }
    return p;
}

// The forces of one sub-step of 1e-12 s (the parcels barely move: the
// forces are those at rest) on a carrier at the origin and two
// API parcels of N = 10 on it, at +-theta from its top in the x-z plane,
// touching it by 1e-12 m and each other's grown radii by deltaGrown
struct knockScene
{
    scalar theta;
    vector fCarrier, fi, fj;
};

knockScene knock(const scalar share, const scalar deltaGrown)
{
    const scalar N = 10;
    const scalar G = std::sqrt(N);
    const dictionary dict
    (
        toDict
        (
            engineText
            (
                N,
                coverage + " coatingCoverageCoeffs { knockShare "
              + std::to_string(share) + "; }",
                false,
                1e-12
            )
        )
    );
    demEngine engine(dict);

    knockScene k;
    const scalar rho0 = rCarrier + rApi - 1e-12;
    k.theta = std::asin((2*G*rApi - deltaGrown)/(2*rho0));
    const vector ei(std::sin(k.theta), 0, std::cos(k.theta));
    const vector ej(-std::sin(k.theta), 0, std::cos(k.theta));

    demState s;
    s.append(Zero, Zero, Zero, rCarrier, massOf(rCarrier), 1, 0, 0);
    s.append(rho0*ei, Zero, Zero, rApi, massOf(rApi), N, 1, 1);
    s.append(rho0*ej, Zero, Zero, rApi, massOf(rApi), N, 1, 2);

    history h;
    engine.evolve(s, 1e-12, Zero, &h);
    k.fCarrier = h.f[0][0];
    k.fi = h.f[0][1];
    k.fj = h.f[0][2];
    return k;
}

} // End anonymous namespace


// A parcel of N = 100 dropped on a wall at 1 m/s follows the primary's
// trajectory under coatingCoverage too (walls meet the primary radius).
// Tolerances as demImpact.wallImpactNInvariance: the runs differ only in
// the rounding of N f/(N m) against f/m.
TEST(coarseGraining, wallImpactNInvariance)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    std::vector<history> runs(2);
    const scalar Ns[2] = {1, 100};
    for (label k = 0; k < 2; ++k)
    {
        demEngine engine(toDict(engineText(Ns[k], coverage, true)));
        demState s;
        s.append(point(0, 0, rApi + 1e-9), vector(0, 0, -1), Zero, rApi,
                 massOf(rApi), Ns[k], 1, 0);
        engine.evolve(s, 3e-7, Zero, &runs[k]);
    }
    ASSERT_EQ(runs[0].x.size(), runs[1].x.size());
    for (size_t t = 0; t < runs[0].x.size(); ++t)
    {
        EXPECT_NEAR(runs[1].x[t][0].z()/runs[0].x[t][0].z(), 1, 1e-12);
        EXPECT_NEAR(runs[1].v[t][0].z(), runs[0].v[t][0].z(), 1e-12);
    }
    // It bounced (the test saw a contact)
    EXPECT_GT(runs[0].v.back()[0].z(), 0.8);
}


// Two parcels of N = 10 meet at sqrt(10) x (r_i + r_j) and then follow the
// primaries' law (their R* and m*): their impact at +-0.5 m/s, started
// 2.05 nm outside the grown radii, has the velocities of the N = 1 impact
// started as far outside the primary radii, step by step (not 2 nm: the
// contact would then begin on a step boundary, where rounding decides the
// step). The overlaps are the
// differences of distances 3.2 times larger, so they round ~3 times
// coarser: 1e-9 of the speed holds that with a wide margin, while a
// contact at the primary radius (no contact at all here) or a grown R*
// fails by orders.
TEST(coarseGraining, grownPairImpactIsThePrimaryImpact)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar v = 0.5;
    std::vector<history> runs(2);
    const scalar Ns[2] = {1, 10};
    for (label k = 0; k < 2; ++k)
    {
        demEngine engine(toDict(engineText(Ns[k], coverage)));
        const scalar rSum = std::sqrt(Ns[k])*2*rApi;
        demState s;
        s.append(Zero, vector(0, 0, v), Zero, rApi, massOf(rApi), Ns[k], 1, 0);
        s.append(point(0, 0, rSum + 2.05e-9), vector(0, 0, -v), Zero, rApi,
                 massOf(rApi), Ns[k], 1, 1);
        engine.evolve(s, 3e-7, Zero, &runs[k]);
    }
    ASSERT_EQ(runs[0].v.size(), runs[1].v.size());
    for (size_t t = 0; t < runs[0].v.size(); ++t)
    {
        EXPECT_NEAR(runs[1].v[t][1].z(), runs[0].v[t][1].z(), 1e-9*v)
            << " at step " << t;
    }
    // Both rebounded with the law's restitution
    const scalar e = runs[1].v.back()[1].z()/v;
    EXPECT_NEAR(e, 0.85, 0.002);
}


// The knock moves the radial parts of the normal force to the carrier.
// At rest, with the grown radii 50 nm into each other: the pair's normal
// force is the Hertz force of the primaries' R* at that overlap times N;
// with knockShare 1 each parcel is pushed along the carrier's surface
// only (no radial component: what is left is the carrier contact's, at
// 1e-12 m overlap ~1e-7 of the knock); the difference from knockShare 0
// is, on each parcel, fn (n.e) e, and the carrier takes its opposite; the
// forces sum to zero in both (momentum). Tolerances: relative 1e-6, above
// the carrier contact's share and the step's motion (~1e-7).
TEST(coarseGraining, knockMovesRadialPushToCarrier)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar deltaG = 5e-8;
    const knockScene off = knock(0, deltaG);
    const knockScene on = knock(1, deltaG);

    const scalar th = on.theta;
    const vector n(1, 0, 0);
    const vector ei(std::sin(th), 0, std::cos(th));
    const vector ej(-std::sin(th), 0, std::cos(th));

    // Hertz: F = N 4/3 E* sqrt(R* delta) delta, E* = Y/(2(1 - nu^2))
    const scalar Estar = 5e8/(2*(1 - sqr(0.35)));
    const scalar fHertz =
        10*4.0/3.0*Estar*std::sqrt(0.5*rApi*deltaG)*deltaG;
    const scalar fn = off.fi & n;
    EXPECT_NEAR(fn/fHertz, 1, 1e-5);

    const scalar tol = 1e-5*fn;
    EXPECT_NEAR(on.fi & ei, 0, tol);
    EXPECT_NEAR(on.fj & ej, 0, tol);
    EXPECT_GT(on.fi & n, 0.5*fn);   // still pushed apart, along the surface

    const vector moved(fn*(n & ei)*ei);
    EXPECT_LT(mag(off.fi - on.fi - moved), tol);
    EXPECT_LT(mag((on.fCarrier - off.fCarrier) - 2*fn*std::sin(th)*std::cos(th)*vector(0, 0, 1)), 2*tol);
    EXPECT_LT(mag(on.fi + on.fj + on.fCarrier), 1e-9*fn);
    EXPECT_LT(mag(off.fi + off.fj + off.fCarrier), 1e-9*fn);
}


// Six parcels of N = 10 slide towards each other in pairs over a free
// carrier (knocks) and leave it: the total momentum (N m v summed) stays
// at its start to round-off (1e-12 of the largest parcel momentum), with
// knockShare 1 as with 0; with 1 the carrier's own momentum changes by
// more than 1 % of a parcel's (the knocks' radial pushes reached it).
TEST(coarseGraining, knocksKeepMomentum)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar N = 10;
    const scalar G = std::sqrt(N);
    const scalar rho0 = rCarrier + rApi - 1e-10;
    // 10 nm apart (the knock within 25 ns, before the parcels' straight
    // paths have left the carrier's surface by its 0.1 nm overlap)
    const scalar half = std::asin((G*rApi + 5e-9)/rho0);
    for (const scalar share : {0.0, 1.0})
    {
        demEngine engine
        (
            toDict
            (
                engineText
                (
                    N,
                    coverage + " coatingCoverageCoeffs { knockShare "
                  + std::to_string(share) + "; }"
                )
            )
        );
        demState s;
        s.append(Zero, Zero, Zero, rCarrier, massOf(rCarrier), 1, 0, 0);
        label id = 1;
        // Three pairs at longitudes 0, 120, 240 degrees, each pair at
        // +-half about latitude 30 degrees, moving towards each other
        for (label k = 0; k < 3; ++k)
        {
            const scalar phi = k*2*constant::mathematical::pi/3;
            for (const scalar sgn : {1.0, -1.0})
            {
                const scalar lat = constant::mathematical::pi/6 + sgn*half;
                const vector e
                (
                    std::cos(lat)*std::cos(phi),
                    std::cos(lat)*std::sin(phi),
                    std::sin(lat)
                );
                const vector t
                (
                    std::sin(lat)*std::cos(phi),
                    std::sin(lat)*std::sin(phi),
                    -std::cos(lat)
                );
                s.append(rho0*e, 0.2*sgn*t, Zero, rApi, massOf(rApi), N, 1,
                         id++);
            }
        }
        const vector p0(momentum(s));
        const vector pCarrier0(s.m[0]*s.v[0]);
        scalar pMax = 0;
        forAll(s.x, i)
        {
            pMax = max(pMax, mag(s.N[i]*s.m[i]*s.v[i]));
        }
        engine.evolve(s, 1e-6, Zero);

        EXPECT_LT(mag(momentum(s) - p0), 1e-12*pMax) << "share " << share;
        if (share > 0)
        {
            EXPECT_GT(mag(s.m[0]*s.v[0] - pCarrier0), 1e-2*pMax);
        }
    }
}


// Parcels whose grown radii overlap at the start are refused (their grown
// overlap would release at once), with the engine's start check; the same
// places are accepted by the reference (primary radii 2 um apart).
TEST(coarseGraining, grownOverlapRefusedAtStart)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    for (const bool grown : {false, true})
    {
        demEngine engine(toDict(engineText(10, grown ? coverage : "coarseGraining scaledContacts;")));
        demState s;
        s.append(Zero, Zero, Zero, rApi, massOf(rApi), 10, 1, 0);
        s.append(point(2*rApi + 2e-6, 0, 0), Zero, Zero, rApi, massOf(rApi),
                 10, 1, 1);
        if (grown)
        {
            EXPECT_THROW(engine.checkStartState(s, "at the start"),
                         Foam::error);
        }
        else
        {
            EXPECT_NO_THROW(engine.checkStartState(s, "at the start"));
        }
    }
}


// regionPacking keeps API parcels at their grown radii apart under
// coatingCoverage (200 parcels of N = 10 in a 150 um box, 12 % of it
// grown); the reference packing of the same seed has pairs closer than
// that (so the check can fail), none closer than the primary radii.
TEST(coarseGraining, regionPackingKeepsGrownRadiiApart)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar G = std::sqrt(10.0);
    for (const bool grown : {false, true})
    {
        const demMaterials mat
        (
            toDict(engineText(10, grown ? coverage : "coarseGraining scaledContacts;")), false
        );
        autoPtr<dpiInjectionModel> m = dpiInjectionModel::New
        (
            "bed",
            toDict
            (
                "type regionPacking; seed 11103; region { shape box;"
                " min (0 0 0); max (150e-6 150e-6 150e-6); }"
                " nParticles 200; basis number; fractions { API 1; }"
                " U (0 0 0);"
            ),
            &mat
        );
        DynamicList<injectionSpec> ps;
        m->inject(0, 1, ps);
        ASSERT_EQ(ps.size(), 200);
        scalar dMin = GREAT;
        forAll(ps, a)
        {
            for (label b = a + 1; b < ps.size(); ++b)
            {
                dMin = min(dMin, mag(ps[a].position - ps[b].position));
            }
        }
        if (grown)
        {
            EXPECT_GE(dMin, 2*G*rApi);
        }
        else
        {
            EXPECT_LT(dMin, 2*G*rApi);
            EXPECT_GE(dMin, 2*rApi);
        }
    }
}


// Bad input: an unknown model names the valid ones; knockShare outside
// 0 ... 1 is refused
TEST(coarseGraining, badInput)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    EXPECT_THROW
    (
        demEngine(toDict(engineText(10, "coarseGraining coverage;"))),
        Foam::IOerror
    );
    EXPECT_THROW
    (
        demEngine
        (
            toDict
            (
                engineText
                (
                    10,
                    coverage + " coatingCoverageCoeffs { knockShare 1.5; }"
                )
            )
        ),
        Foam::IOerror
    );
}


// ************************************************************************* //
