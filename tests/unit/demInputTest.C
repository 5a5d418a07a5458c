/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the DEM input: materials table and bad input
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    Effective properties of the guide's material (theory 1.2), the Hertz
    contact time of theory 7.2, and clear errors for bad input: unknown
    model or wall type, N <= 0, mixed N > 1, a time step over the stability
    limit, missing pair properties, out-of-range values, patch walls
    without a mesh, a fluid step that is not a multiple of the DEM step.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "demMaterials.H"
#include "normalContactModel.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <string>

using namespace Foam;

namespace
{

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

const std::string types
(
    "types {"
    "  api { diameter 5e-6; density 1520; youngsModulus 5e8;"
    "        poissonsRatio 0.35; N 100; api true; }"
    "  carrier { diameter 70e-6; density 1520; youngsModulus 5e8;"
    "        poissonsRatio 0.35; }"
    "  wall { youngsModulus 5e8; poissonsRatio 0.35; }"
    "}"
);

const std::string pairs
(
    "pairs { default { restitution 0.85; friction 0.45;"
    " rollingFriction 0.05; }"
    " carrier-api { restitution 0.5; friction 0.3; } }"
);

const std::string models
(
    "normalModel hertzParcel; tangentialModel historyParcel;"
    "rollingModel cdt; cohesionModel none;"
);

const std::string check("timeStepCheck { maxImpactVelocity 30; }");

std::string engineDeck(const std::string& dt = "1e-8")
{
    return "timeStep " + dt + ";" + types + pairs + models
      + "walls { floor { type plane; point (0 0 0); normal (0 0 1);"
        " material wall; } }" + check;
}

} // End anonymous namespace


// Theory 1.2 for Y = 5e8 Pa, nu = 0.35: Y* = 2.849e8 Pa, G* = 5.612e7 Pa,
// beta(0.85) = -0.05166 (4 digits given, so 1e-3 relative); a pair entry
// overrides the default, in either name order, and falls back to the
// default for keys it does not give.
TEST(demInput, materialsEffectiveProperties)
{
    FatalIOError.throwExceptions();

    const demMaterials mat(toDict(types + pairs));
    ASSERT_EQ(mat.size(), 3);

    const label api = 0, carrier = 1, wall = 2;
    EXPECT_TRUE(mat.api(api));
    EXPECT_FALSE(mat.api(carrier));
    EXPECT_FALSE(mat.isParticleType(wall));
    EXPECT_EQ(mat.N(api), 100);
    EXPECT_EQ(mat.parcelN(), 100);

    const demPairProperties& aa = mat.pair(api, api);
    EXPECT_NEAR(aa.Ystar/2.849e8, 1, 1e-3);
    EXPECT_NEAR(aa.Gstar/5.612e7, 1, 1e-3);
    EXPECT_NEAR(aa.beta/-0.05166, 1, 1e-3);
    EXPECT_EQ(aa.muR, 0.05);

    const demPairProperties& ca = mat.pair(api, carrier);
    EXPECT_EQ(mat.pair(carrier, api).e, 0.5);
    EXPECT_EQ(ca.e, 0.5);
    EXPECT_EQ(ca.mu, 0.3);
    EXPECT_EQ(ca.muR, 0.05);     // from default

    // Rayleigh time of the API (theory 7.2: 2.41e-8 s, 3 digits)
    EXPECT_NEAR(mat.rayleighTime(api)/2.41e-8, 1, 5e-3);
}


// Elastic Hertz contact time of theory 7.2 (3 digits given): API-API at
// 1 m/s 8.61e-8 s, API-wall at 3 m/s 7.94e-8 s, carrier-carrier at 30 m/s
// 6.11e-7 s.
TEST(demInput, hertzContactTime)
{
    FatalIOError.throwExceptions();

    const demMaterials mat(toDict(types + pairs));
    autoPtr<normalContactModel> hertz
    (
        normalContactModel::New(toDict(models))
    );

    const scalar rA = 2.5e-6, rC = 35e-6;
    const scalar mA = mat.primaryMass(0), mC = mat.primaryMass(1);

    EXPECT_NEAR
    (
        hertz->contactTime(mat.pair(0, 0), rA/2, mA/2, 1)/8.61e-8, 1, 5e-3
    );
    EXPECT_NEAR
    (
        hertz->contactTime(mat.pair(0, 2), rA, mA, 3)/7.94e-8, 1, 5e-3
    );
    EXPECT_NEAR
    (
        hertz->contactTime(mat.pair(1, 1), rC/2, mC/2, 30)/6.11e-7, 1, 5e-3
    );
}


TEST(demInput, badInputIsRejected)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // The reference deck is accepted
    EXPECT_NO_THROW(demEngine(toDict(engineDeck())));

    // Unknown model names
    std::string d(engineDeck());
    EXPECT_THROW
    (
        demEngine(toDict(d + "normalModel hooke;")), Foam::error
    );
    EXPECT_THROW
    (
        demEngine(toDict(d + "rollingModel epsd;")), Foam::error
    );
    EXPECT_THROW
    (
        demEngine(toDict(d + "cohesionModel vdw;")), Foam::error
    );

    // N <= 0, and two coarse-grained types with different N
    auto withTypes = [&](const std::string& t)
    {
        return "timeStep 1e-8;" + t + pairs + models + check;
    };
    EXPECT_THROW
    (
        demMaterials(toDict
        (
            "types { api { diameter 5e-6; density 1520; youngsModulus 5e8;"
            " poissonsRatio 0.35; N 0; } }" + pairs
        )),
        Foam::error
    );
    EXPECT_THROW
    (
        demEngine(toDict(withTypes
        (
            "types { api { diameter 5e-6; density 1520; youngsModulus 5e8;"
            " poissonsRatio 0.35; N 100; api true; }"
            " api2 { diameter 5e-6; density 1520; youngsModulus 5e8;"
            " poissonsRatio 0.35; N 10; api true; } }"
        ))),
        Foam::error
    );

    // A coarse-grained type must be API: a carrier of N 10 would be
    // counted as API in every statistic (no 'api', or api false)
    EXPECT_THROW
    (
        demMaterials(toDict
        (
            "types { carrier { diameter 70e-6; density 1520;"
            " youngsModulus 5e8; poissonsRatio 0.35; N 10; } }" + pairs
        )),
        Foam::error
    );
    EXPECT_THROW
    (
        demMaterials(toDict
        (
            "types { carrier { diameter 70e-6; density 1520;"
            " youngsModulus 5e8; poissonsRatio 0.35; N 10; api false; } }"
          + pairs
        )),
        Foam::error
    );

    // Out-of-range material values
    EXPECT_THROW
    (
        demMaterials(toDict
        (
            "types { a { diameter 5e-6; density 1520; youngsModulus 5e8;"
            " poissonsRatio 0.6; } }" + pairs
        )),
        Foam::error
    );
    EXPECT_THROW
    (
        demMaterials(toDict(types +
            "pairs { default { restitution 0.01; friction 0.45; } }")),
        Foam::error
    );

    // Missing pair without default; unknown pair entry name
    EXPECT_THROW
    (
        demMaterials(toDict(types +
            "pairs { api-api { restitution 0.85; friction 0.45; } }")),
        Foam::error
    );
    EXPECT_THROW
    (
        demMaterials(toDict(types +
            "pairs { default { restitution 0.85; friction 0.45; }"
            " api-carier { restitution 0.85; friction 0.45; } }")),
        Foam::error
    );

    // Time step over t_H/3 (API-API at 30 m/s: t_H = 4.36e-8 s), and the
    // explicit override
    EXPECT_THROW(demEngine(toDict(engineDeck("2e-8"))), Foam::error);
    EXPECT_NO_THROW
    (
        demEngine(toDict(engineDeck("2e-8")
          + "timeStepCheck { maxImpactVelocity 30; allowUnstable true; }"))
    );

    // Walls: unknown type, unknown material, patch wall without a mesh
    const std::string base("timeStep 1e-8;" + types + pairs + models + check);
    EXPECT_THROW
    (
        demEngine(toDict(base + "walls { w { type cylinder; material wall; } }")),
        Foam::error
    );
    EXPECT_THROW
    (
        demEngine(toDict(base + "walls { w { type plane; point (0 0 0);"
            " normal (0 0 1); material steel; } }")),
        Foam::error
    );
    EXPECT_THROW
    (
        demEngine(toDict(base + "walls { w { type patch; patches (walls);"
            " material wall; } }")),
        Foam::error
    );

    // State: mixed N > 1 among parcels, N <= 0, non-multiple fluid step
    demEngine engine(toDict(engineDeck()));
    const scalar m = 1520*constant::mathematical::pi/6*pow3(5e-6);
    {
        demState s;
        s.append(point(0, 0, 1e-5), Zero, Zero, 2.5e-6, m, 100, 0, 0);
        s.append(point(0, 0, 2e-5), Zero, Zero, 2.5e-6, m, 10, 0, 1);
        EXPECT_THROW(engine.evolve(s, 1e-8, Zero), Foam::error);
    }
    {
        demState s;
        s.append(point(0, 0, 1e-5), Zero, Zero, 2.5e-6, m, 0, 0, 0);
        EXPECT_THROW(engine.evolve(s, 1e-8, Zero), Foam::error);
    }
    {
        demState s;
        s.append(point(0, 0, 1e-5), Zero, Zero, 2.5e-6, m, 1, 0, 0);
        EXPECT_THROW(engine.evolve(s, 1.5e-8, Zero), Foam::error);
        EXPECT_NO_THROW(engine.evolve(s, 1e-6, Zero));
    }
}


// ************************************************************************* //
