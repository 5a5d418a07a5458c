/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of friction and rolling resistance (theory 8.3)
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    A sphere sliding on a plane under gravity (historyParcel) and a sphere
    rolling on a plane (cdt), for a primary (N = 1) and a parcel (N = 100)
    with the rolling torque scaled by S or, as in the reference decks, not.

    The sphere is the guide's Case 4 particle (d = 2 mm, rho = 2400,
    Y = 1e7 Pa, nu = 0.22) so that the rigid-body time scales (ms) need only
    ~1e4 steps of 1e-5 s; it starts at its rest overlap so no bouncing
    disturbs the tangential motion.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

const scalar d = 2e-3;
const scalar rho = 2400;
const scalar Y = 1e7;
const scalar nu = 0.22;
const scalar g = 9.81;

scalar sphereMass()
{
    return rho*constant::mathematical::pi/6*pow3(d);
}

dictionary rollingDeck
(
    const scalar N,
    const scalar mu,
    const scalar muR,
    const bool scaleTorque,
    const bool holdAtRest = true
)
{
    std::ostringstream os;
    os.precision(17);
    os  << "timeStep 1e-5;\n"
        << "types {\n"
        << "  ball { diameter " << d << "; density " << rho
        << "; youngsModulus " << Y << "; poissonsRatio " << nu
        << "; N " << N << "; api true; }\n"
        << "  wall { youngsModulus " << Y << "; poissonsRatio " << nu
        << "; }\n"
        << "}\n"
        << "pairs { default { restitution 0.5; friction " << mu
        << "; rollingFriction " << muR << "; } }\n"
        << "normalModel hertzParcel;\n"
        << "tangentialModel historyParcel;\n"
        << "rollingModel cdt;\n"
        << "cdtCoeffs { scaleTorqueWithN " << (scaleTorque ? "true" : "false")
        << "; holdAtRest " << (holdAtRest ? "true" : "false") << "; }\n"
        << "cohesionModel none;\n"
        << "walls { floor { type plane; point (0 0 0); normal (0 0 1);"
        << " material wall; } }\n"
        << "timeStepCheck { maxImpactVelocity 0.1; }\n";

    IStringStream is(os.str());
    return dictionary(is);
}

// Rest overlap under gravity: (4/3) Y* sqrt(r) delta^1.5 = m g
scalar restOverlap()
{
    const scalar Ystar = Y/(2*(1 - sqr(nu)));
    return Foam::pow(3*sphereMass()*g/(4*Ystar*Foam::sqrt(0.5*d)), 2.0/3.0);
}

struct trace
:
    public demObserver
{
    std::vector<scalar> t, vx, slip;

    virtual void subStep(const scalar time, const demState& s)
    {
        const scalar c = s.r[0] - 0.5*(s.r[0] - s.x[0].z());
        t.push_back(time);
        vx.push_back(s.v[0].x());
        // Contact-point velocity: v - c omega x n, n = +z
        slip.push_back(s.v[0].x() - c*s.omega[0].y());
    }
};

// Least-squares slope of v(t) over [t0, t1]: averages out the tangential
// spring's oscillation (period ~0.7 ms) around the rigid-body motion
scalar slope
(
    const std::vector<scalar>& t,
    const std::vector<scalar>& v,
    const scalar t0,
    const scalar t1
)
{
    scalar n = 0, st = 0, sv = 0, stt = 0, stv = 0;
    for (size_t k = 0; k < t.size(); ++k)
    {
        if (t[k] >= t0 && t[k] <= t1)
        {
            n += 1; st += t[k]; sv += v[k];
            stt += t[k]*t[k]; stv += t[k]*v[k];
        }
    }
    return (n*stv - st*sv)/(n*stt - st*st);
}

// Deceleration of a sphere set rolling without slip at v0
scalar rollingDeceleration
(
    const scalar N,
    const scalar muR,
    const bool scaleTorque,
    const bool holdAtRest = true
)
{
    demEngine engine(rollingDeck(N, 0.45, muR, scaleTorque, holdAtRest));

    const scalar r = 0.5*d;
    const scalar delta = restOverlap();
    const scalar c = r - 0.5*delta;
    const scalar v0 = 0.1;

    demState s;
    s.append(point(0, 0, r - delta), vector(v0, 0, 0),
             vector(0, v0/c, 0), r, sphereMass(), N, 0, 0);

    trace tr;
    engine.evolve(s, 10000*1e-5, vector(0, 0, -g), &tr);

    // Skip the first 10 ms (the spring settles from xi = 0)
    return -slope(tr.t, tr.vx, 0.01, 0.1);
}

} // End anonymous namespace


// Sliding at v0 without spin: kinetic friction mu m g decelerates the centre
// and spins the sphere up until rolling without slip at
// t = 2 v0/(7 mu g) with speed 5 v0/7 (rigid-body result). The history
// spring adds small oscillations and the step is 1e-5 s = 0.15 % of that
// time, so 2 % (the required tolerance) is ample and fails for a wrong cap, a
// wrong torque sign or a missing lever arm.
TEST(demFriction, slidingSphereReachesRolling)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar mu = 0.45;
    demEngine engine(rollingDeck(1, mu, 0, true));

    const scalar r = 0.5*d;
    const scalar v0 = 0.1;
    demState s;
    s.append(point(0, 0, r - restOverlap()), vector(v0, 0, 0), Zero,
             r, sphereMass(), 1, 0, 0);

    trace tr;
    engine.evolve(s, 1000*1e-5, vector(0, 0, -g), &tr);

    scalar tRoll = -1, vRoll = 0;
    for (size_t k = 0; k < tr.t.size(); ++k)
    {
        if (tr.slip[k] <= 0)
        {
            tRoll = tr.t[k];
            vRoll = tr.vx[k];
            break;
        }
    }

    const scalar tExpected = 2*v0/(7*mu*g);
    std::cout << "  sliding: rolling at t = " << tRoll << " s (expected "
              << tExpected << "), v = " << vRoll/v0 << " v0 (5/7 = "
              << 5.0/7.0 << ")" << std::endl;

    EXPECT_NEAR(tRoll/tExpected, 1, 0.02);
    EXPECT_NEAR(vRoll/(5*v0/7), 1, 0.02);
}


// CDT: rolling without slip, the constant torque mu_r (k_n delta) c with
// k_n delta = m g decelerates the sphere at (5/7) mu_r g (theory 8.3).
// The fit over 90 ms of a 140 ms roll averages the spring oscillation;
// 2 % is the required tolerance.
TEST(demFriction, cdtRollingDeceleration)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar muR = 0.1;
    const scalar expected = 5.0/7.0*muR*g;

    const scalar a1 = rollingDeceleration(1, muR, true);
    const scalar a100 = rollingDeceleration(100, muR, true);

    std::cout << "  cdt: a(N=1) = " << a1 << ", a(N=100, scaled) = " << a100
              << " m/s2, expected " << expected << std::endl;

    EXPECT_NEAR(a1/expected, 1, 0.02);

    // A parcel rolls like a primary when the torque is scaled by S
    EXPECT_NEAR(a100/expected, 1, 0.02);
}


// The reference decks' unscaled torque (scaleTorqueWithN false): a parcel's
// inertia is N times the primary's but its rolling torque is not, so it
// decelerates N times less, (5/7) mu_r g/N (theory 2.3). For N = 1 the
// switch must change nothing.
TEST(demFriction, cdtUnscaledTorqueIsReferenceBehaviour)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar muR = 0.1;
    const scalar expected = 5.0/7.0*muR*g;

    const scalar a1 = rollingDeceleration(1, muR, false);
    const scalar a100 = rollingDeceleration(100, muR, false);

    std::cout << "  cdt unscaled: a(N=1) = " << a1 << ", a(N=100) = " << a100
              << " m/s2 (expected " << expected/100 << ")" << std::endl;

    EXPECT_NEAR(a1/expected, 1, 0.02);
    EXPECT_NEAR(a100/(expected/100), 1, 0.02);
}


// holdAtRest (the default) limits the cdt torque to I* |omega_rel|/dt,
// which only a contact almost at rest reaches (here |omega_rel| < 0.03
// rad/s against the 100 rad/s of the roll): with the reference's torque
// (holdAtRest false) a rolling sphere decelerates alike, to the same 2 %,
// for a primary and a parcel
TEST(demFriction, cdtReferenceTorqueRollsAlike)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar muR = 0.1;
    const scalar expected = 5.0/7.0*muR*g;

    const scalar a1 = rollingDeceleration(1, muR, true, false);
    const scalar a100 = rollingDeceleration(100, muR, true, false);

    std::cout << "  cdt reference torque: a(N=1) = " << a1 << ", a(N=100) = "
              << a100 << " m/s2 (expected " << expected << ")" << std::endl;

    EXPECT_NEAR(a1/expected, 1, 0.02);
    EXPECT_NEAR(a100/expected, 1, 0.02);
}


// ************************************************************************* //
