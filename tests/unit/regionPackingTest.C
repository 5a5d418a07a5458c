/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the regionPacking injection model
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    Region packing in a sphere, box, cylinder, cone and closed surface (an
    STL of a box): achieved solid
    fraction, no overlaps, every particle wholly inside (checked with
    geometry written independently of packingRegion), number and mass
    fractions, reproducibility with a seed, packing around a carrier
    (Case 5, by avoidInjected and by exclude), and a clear error within
    bounded time for a fraction that cannot be reached; bad input.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "regionPacking.H"
#include "demMaterials.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <chrono>
#include <functional>
#include <vector>
#include <sstream>
#include <string>
#include <fstream>
#include <cmath>
#include "OSspecific.H"

using namespace Foam;

namespace
{

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

// carrier 70 um, api 5 um (N 10), mid 10 um of another density, a wall
const std::string materialsText
(
    "types {"
    "  carrier { diameter 70e-6; density 1520; youngsModulus 5e8;"
    "            poissonsRatio 0.35; }"
    "  api { diameter 5e-6; density 1520; youngsModulus 5e8;"
    "        poissonsRatio 0.35; N 10; api true; }"
    "  mid { diameter 10e-6; density 3000; youngsModulus 5e8;"
    "        poissonsRatio 0.35; }"
    "  wall { youngsModulus 5e8; poissonsRatio 0.35; }"
    "}"
    "pairs { default { restitution 0.85; friction 0.45; } }"
    // API parcels packed at their primary radii (the reference scaling);
    // the default's grown radii: coarseGraining.regionPackingKeepsGrownRadiiApart
    "coarseGraining scaledContacts;"
);

// A point as dictionary text, to 17 digits
std::string str(const point& p)
{
    std::ostringstream os;
    os.precision(17);
    os << '(' << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
    return os.str();
}

const demMaterials& materials()
{
    static const demMaterials mat(toDict(materialsText));
    return mat;
}

scalar diameterOf(const word& type)
{
    const demMaterials& mat = materials();
    return mat.size(mat.names().find(type)).minDiameter();
}

scalar volumeOf(const word& type)
{
    return constant::mathematical::pi/6*pow3(diameterOf(type));
}

// Pack with the model, starting from a list that may hold earlier
// injectors' particles; returns only the packed particles
List<injectionSpec> packed
(
    const std::string& text,
    const List<injectionSpec>& before = List<injectionSpec>()
)
{
    autoPtr<dpiInjectionModel> m =
        dpiInjectionModel::New("bed", toDict(text), &materials());
    DynamicList<injectionSpec> out;
    out.append(before);
    m->inject(0, 1, out);
    return List<injectionSpec>
    (
        SubList<injectionSpec>(out, out.size() - before.size(), before.size())
    );
}

// Smallest gap between two packed particles, relative to their radius sum
// (negative: an overlap); O(n^2), fine for a few thousand
scalar minGapRatio(const UList<injectionSpec>& ps)
{
    scalarList r(ps.size());
    forAll(ps, a)
    {
        r[a] = 0.5*diameterOf(ps[a].type);
    }
    scalar worst = GREAT;
    forAll(ps, a)
    {
        for (label b = a + 1; b < ps.size(); ++b)
        {
            const scalar d2 = magSqr(ps[a].position - ps[b].position);
            if (d2 < sqr((1 + worst)*(r[a] + r[b])))
            {
                worst = Foam::sqrt(d2)/(r[a] + r[b]) - 1;
            }
        }
    }
    return worst;
}

scalar solidVolume(const UList<injectionSpec>& ps)
{
    scalar v = 0;
    for (const injectionSpec& p : ps)
    {
        v += volumeOf(p.type);
    }
    return v;
}

label countOf(const UList<injectionSpec>& ps, const word& type)
{
    label n = 0;
    for (const injectionSpec& p : ps)
    {
        n += (p.type == type);
    }
    return n;
}

// Independent containment tests (sphere of radius r wholly inside); a
// relative slack of 1e-12 of the region size for round-off
bool inSphere(const point& p, const scalar r, const point& c, const scalar R)
{
    return mag(p - c) + r <= R*(1 + 1e-12);
}

bool inBox(const point& p, const scalar r, const point& lo, const point& hi)
{
    const scalar eps = 1e-12*mag(hi - lo);
    for (direction i = 0; i < 3; ++i)
    {
        if (p[i] - r < lo[i] - eps || p[i] + r > hi[i] + eps)
        {
            return false;
        }
    }
    return true;
}

// Truncated cone (a cylinder when R1 = R2) from a to b: the sphere is
// inside when it clears both end planes and, at its axial station, the
// lateral surface by r measured normal to the generator
bool inCone
(
    const point& p, const scalar r,
    const point& a, const scalar R1, const point& b, const scalar R2
)
{
    const scalar L = mag(b - a);
    const vector e((b - a)/L);
    const scalar t = (p - a) & e;
    const scalar rho = mag((p - a) - t*e);
    const scalar eps = 1e-12*L;
    if (t - r < -eps || t + r > L + eps)
    {
        return false;
    }
    const scalar Rt = R1 + (R2 - R1)*t/L;
    const scalar cosAlpha = L/Foam::sqrt(sqr(L) + sqr(R2 - R1));
    return (Rt - rho)*cosAlpha >= r - eps;
}

// The box of the surface tests, its corners exact in float32 (an STL
// holds single precision) and in decimal: multiples of 2^-17 m
const point cubeMax(13*std::ldexp(1.0, -17), 16*std::ldexp(1.0, -17), 10*std::ldexp(1.0, -17));

// A closed ASCII STL of the box (0, cubeMax): 12 triangles facing out; its
// absolute path
std::string cubeStl()
{
    const std::string path =
        Foam::getEnv("TMPDIR").size() ? Foam::getEnv("TMPDIR") : "/tmp";
    const std::string file =
        path + "/regionPackingCube" + std::to_string(Foam::pid()) + ".stl";
    const point& m = cubeMax;
    const point v[8] =
    {
        {0, 0, 0}, {m.x(), 0, 0}, {m.x(), m.y(), 0}, {0, m.y(), 0},
        {0, 0, m.z()}, {m.x(), 0, m.z()}, {m.x(), m.y(), m.z()}, {0, m.y(), m.z()}
    };
    // Two triangles per face, counter-clockwise seen from outside
    const int tri[12][3] =
    {
        {0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}
    };
    std::ofstream os(file);
    os.precision(17);
    os << "solid cube\n";
    for (const auto& t : tri)
    {
        const vector n(((v[t[1]] - v[t[0]]) ^ (v[t[2]] - v[t[0]])).normalise());
        os << " facet normal " << n.x() << ' ' << n.y() << ' ' << n.z()
           << "\n  outer loop\n";
        for (const int k : t)
        {
            os << "   vertex " << v[k].x() << ' ' << v[k].y() << ' '
               << v[k].z() << '\n';
        }
        os << "  endloop\n endfacet\n";
    }
    os << "endsolid cube\n";
    return file;
}

struct shapeCase
{
    std::string name;
    std::string region;
    scalar volume;
    std::function<bool(const point&, scalar)> inside;
};

std::vector<shapeCase> shapes()
{
    using constant::mathematical::pi;
    const point a(1e-5, -2e-5, 3e-5);
    const point b(a + vector(40e-6, 60e-6, 90e-6));  // skewed axis
    const scalar L = mag(b - a);

    std::ostringstream cyl, cone;
    cyl.precision(17);
    cone.precision(17);
    cyl << "region { shape cylinder; point1 " << str(a) << "; point2 " << str(b)
        << "; radius 50e-6; }";
    cone << "region { shape cone; point1 " << str(a) << "; radius1 60e-6; point2 "
         << str(b) << "; radius2 20e-6; }";

    return
    {
        {
            "sphere",
            "region { shape sphere; centre (1e-4 2e-4 -3e-4); radius 60e-6; }",
            4.0/3.0*pi*pow3(60e-6),
            [](const point& p, const scalar r)
            { return inSphere(p, r, point(1e-4, 2e-4, -3e-4), 60e-6); }
        },
        {
            "box",
            "region { shape box; min (0 0 0); max (100e-6 120e-6 80e-6); }",
            100e-6*120e-6*80e-6,
            [](const point& p, const scalar r)
            {
                return inBox(p, r, point::zero, point(100e-6, 120e-6, 80e-6));
            }
        },
        {
            "cylinder",
            cyl.str(),
            pi*sqr(50e-6)*L,
            [a, b](const point& p, const scalar r)
            { return inCone(p, r, a, 50e-6, b, 50e-6); }
        },
        {
            "cone",
            cone.str(),
            pi*L/3*(sqr(60e-6) + 60e-6*20e-6 + sqr(20e-6)),
            [a, b](const point& p, const scalar r)
            { return inCone(p, r, a, 60e-6, b, 20e-6); }
        },
        {
            "surface",
            "region { shape surface; file \"" + cubeStl() + "\"; }",
            cmptProduct(cubeMax),
            [](const point& p, const scalar r)
            { return inBox(p, r, point::zero, cubeMax); }
        }
    };
}

std::string bed
(
    const std::string& region,
    const std::string& amount,
    const std::string& fractions,
    const std::string& extra = "",
    const label seed = 11103
)
{
    return "type regionPacking; seed " + std::to_string(seed) + "; "
        + region + " " + amount + " " + fractions + " U (0 0 -1); " + extra;
}

// Pack a 1 mm box of carriers and API with the materials above but the
// API's N set to N (the blend's tests compare N = 1 with N = 10)
List<injectionSpec> packedAtN
(
    const label N,
    const std::string& amount,
    const std::string& fractions
)
{
    std::string text(materialsText);
    text.replace(text.find("N 10;"), 5, "N " + std::to_string(N) + ";");
    const demMaterials mat(toDict(text));
    autoPtr<dpiInjectionModel> m = dpiInjectionModel::New
    (
        "bed",
        toDict
        (
            bed
            (
                "region { shape box; min (0 0 0); max (1e-3 1e-3 1e-3); }",
                amount,
                fractions
            )
        ),
        &mat
    );
    DynamicList<injectionSpec> ps;
    m->inject(0, 1, ps);
    return List<injectionSpec>(std::move(ps));
}

} // End anonymous namespace


// Every shape at 0.3 with 70 % api and 30 % mid by number (~1000-2000
// particles): the achieved fraction is within 1.5 (v_api + v_mid)/V of the
// target (rounding of the total to an integer, vMean/2, plus of each count
// by largest remainder, < v_k each; ~6e-4 to 1e-3 here); no two particles
// overlap (gap ratio >= 0, the model's own criterion recomputed); every
// particle wholly inside by the independent geometry above; the counts are
// within 1 of N x_k; the velocity and type are as given.
TEST(regionPacking, shapesFractionNoOverlapInside)
{
    FatalIOError.throwExceptions();

    for (const shapeCase& sc : shapes())
    {
        const List<injectionSpec> ps = packed
        (
            bed
            (
                sc.region, "volumeFraction 0.3;",
                "basis number; fractions { api 0.7; mid 0.3; }"
            )
        );

        const scalar phi = solidVolume(ps)/sc.volume;
        const scalar tol = 1.5*(volumeOf("api") + volumeOf("mid"))/sc.volume;
        const label N = ps.size();

        std::cout << "  " << sc.name << ": " << N << " particles, fraction "
                  << phi << " (tolerance " << tol << "), min gap/(r_i + r_j) "
                  << minGapRatio(ps) << std::endl;

        EXPECT_NEAR(phi, 0.3, tol) << sc.name;
        EXPECT_GE(minGapRatio(ps), 0) << sc.name;
        EXPECT_LE(mag(countOf(ps, "api") - 0.7*N), 1) << sc.name;
        EXPECT_LE(mag(countOf(ps, "mid") - 0.3*N), 1) << sc.name;

        label outside = 0;
        for (const injectionSpec& p : ps)
        {
            outside += !sc.inside(p.position, 0.5*diameterOf(p.type));
            EXPECT_EQ(p.U, vector(0, 0, -1));
            EXPECT_LT(p.d, 0) << "the type's diameter";
        }
        EXPECT_EQ(outside, 0) << sc.name;
    }
}


// Mass basis, carriers and API of equal density at 0.2 in a 600 um box:
// the counts are N x_k rounded (x_k ~ w_k/v_k, computed here directly), so
// within 1 of N x_k, and the API mass fraction is within
// 1.5 (m_c + m_a)/M of 0.005 (one particle of each type, as above).
TEST(regionPacking, massFractions)
{
    FatalIOError.throwExceptions();

    const List<injectionSpec> ps = packed
    (
        bed
        (
            "region { shape box; min (0 0 0); max (600e-6 600e-6 600e-6); }",
            "volumeFraction 0.2;",
            "basis mass; fractions { carrier 0.995; api 0.005; }"
        )
    );

    const scalar vc = volumeOf("carrier"), va = volumeOf("api");
    const label nc = countOf(ps, "carrier"), na = countOf(ps, "api");
    const label N = nc + na;
    ASSERT_EQ(N, ps.size());

    const scalar xa = (0.005/va)/(0.005/va + 0.995/vc);
    const scalar massApi = na*va, massTotal = na*va + nc*vc;   // rho equal

    std::cout << "  mass basis: " << nc << " carriers, " << na << " api, api "
              << "mass fraction " << massApi/massTotal << ", fraction "
              << massTotal/pow3(600e-6) << ", min gap ratio "
              << minGapRatio(ps) << std::endl;

    EXPECT_LE(mag(na - xa*N), 1);
    EXPECT_NEAR(massApi/massTotal, 0.005, 1.5*(vc + va)/massTotal);
    EXPECT_NEAR(massTotal/pow3(600e-6), 0.2, 1.5*(vc + va)/pow3(600e-6));
    EXPECT_GE(minGapRatio(ps), 0);

    // Carriers are placed first (larger types first)
    EXPECT_EQ(ps[0].type, "carrier");
    EXPECT_EQ(ps[nc].type, "api");
}


// The inhaler's powder bed (theory 8.7, guide deck): a cone on the z axis
// at x = 3.9 cm, radius 0.08 cm at z = -0.34 cm to 0.01 cm at z = -0.235 cm,
// 30 % solids split 99.5357 % carrier / 0.4643 % API by mass (N = 10 on the
// API type does not enter: primary geometry). Expected counts, from the
// cone volume 8.03e-10 m^3: 1334 carriers and 17083 API (the guide's
// sample run has 17,100 API parcels). Achieved fraction within
// 1.5 (v_c + v_a)/V, no overlaps, all inside. Measured 0.15 s.
TEST(regionPacking, inhalerPowderBed)
{
    FatalIOError.throwExceptions();

    const point a(0.039, 0, -0.0034), b(0.039, 0, -0.00235);
    const List<injectionSpec> ps = packed
    (
        bed
        (
            "region { shape cone; point1 " + str(a) + "; radius1 8e-4;"
            " point2 " + str(b) + "; radius2 1e-4; }",
            "volumeFraction 0.3;",
            "basis mass; fractions { carrier 0.995357; api 0.004643; }",
            "",
            86
        )
    );

    using constant::mathematical::pi;
    const scalar V = pi*0.00105/3*(sqr(8e-4) + 8e-4*1e-4 + sqr(1e-4));
    const label nc = countOf(ps, "carrier"), na = countOf(ps, "api");

    std::cout << "  inhaler bed: " << nc << " carriers, " << na << " api, "
              << "fraction " << solidVolume(ps)/V << std::endl;

    EXPECT_NEAR(nc, 1334, 1);
    EXPECT_NEAR(na, 17083, 1);
    EXPECT_NEAR
    (
        solidVolume(ps)/V, 0.3, 1.5*(volumeOf("carrier") + volumeOf("api"))/V
    );
    EXPECT_GE(minGapRatio(ps), 0);

    label outside = 0;
    for (const injectionSpec& p : ps)
    {
        outside +=
            !inCone(p.position, 0.5*diameterOf(p.type), a, 8e-4, b, 1e-4);
    }
    EXPECT_EQ(outside, 0);
}


// The box the start check holds against the mesh's: the hull of a cone's
// end discs, no larger. The inhaler's full cone (base radius 0.8 mm at
// z = -3.33 mm, axis z) reaches z = -3.33 mm, not z = -3.33 - 0.8 mm,
// which would lie below its mesh (z >= -4 mm) and refuse a valid bed.
// A tilted cylinder: each end disc reaches r sqrt(1 - a_i^2) along axis i.
TEST(regionPacking, boundsAreTheEndDiscsHull)
{
    FatalIOError.throwExceptions();

    const point a(0.039, 0, -0.00333), b(0.039, 0, -0.00235);
    autoPtr<dpiInjectionModel> cone = dpiInjectionModel::New
    (
        "bed",
        toDict
        (
            bed
            (
                "region { shape cone; point1 " + str(a) + "; radius1 8e-4;"
                " point2 " + str(b) + "; radius2 1e-4; }",
                "volumeFraction 0.3;",
                "basis mass; fractions { carrier 0.995357; api 0.004643; }",
                "",
                86
            )
        ),
        &materials()
    );
    const boundBox bb(cone->bounds());
    EXPECT_NEAR(bb.min().z(), -0.00333, 1e-15);
    EXPECT_NEAR(bb.max().z(), -0.00235, 1e-15);
    EXPECT_NEAR(bb.min().x(), 0.039 - 8e-4, 1e-15);
    EXPECT_NEAR(bb.max().y(), 8e-4, 1e-15);

    // axis along (1 0 1)/sqrt(2): the discs reach r/sqrt(2) in x and z, r in y
    const point c(0, 0, 0), d(1e-3, 0, 1e-3);
    autoPtr<dpiInjectionModel> cyl = dpiInjectionModel::New
    (
        "bed",
        toDict
        (
            bed
            (
                "region { shape cylinder; point1 " + str(c) + "; point2 "
              + str(d) + "; radius 2e-4; }",
                "volumeFraction 0.1;",
                "basis mass; fractions { carrier 1; }",
                "",
                86
            )
        ),
        &materials()
    );
    const boundBox cb(cyl->bounds());
    const scalar h = 2e-4/Foam::sqrt(2.0);
    EXPECT_NEAR(cb.min().x(), -h, 1e-15);
    EXPECT_NEAR(cb.max().x(), 1e-3 + h, 1e-15);
    EXPECT_NEAR(cb.min().y(), -2e-4, 1e-15);
    EXPECT_NEAR(cb.max().z(), 1e-3 + h, 1e-15);
}


// Same seed: the identical list (bit for bit, which is what makes every
// processor build the same one); another seed: a different list.
TEST(regionPacking, reproducibleWithSeed)
{
    FatalIOError.throwExceptions();

    const std::string region =
        "region { shape sphere; centre (0 0 0); radius 40e-6; }";
    const std::string fr = "basis number; fractions { api 0.5; mid 0.5; }";

    const List<injectionSpec> a = packed(bed(region, "volumeFraction 0.25;", fr));
    const List<injectionSpec> b = packed(bed(region, "volumeFraction 0.25;", fr));
    const List<injectionSpec> c =
        packed(bed(region, "volumeFraction 0.25;", fr, "", 4711));

    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    ASSERT_GT(a.size(), 100);

    label nSame = 0, nDiff = 0;
    forAll(a, k)
    {
        nSame += (a[k].position == b[k].position && a[k].type == b[k].type);
        nDiff += (a[k].position != c[k].position);
    }
    EXPECT_EQ(nSame, a.size());
    EXPECT_EQ(nDiff, a.size());
}


// nParticles instead of a fraction; SOI: injected once, in the interval
// that holds SOI.
TEST(regionPacking, nParticlesAndSOI)
{
    FatalIOError.throwExceptions();

    autoPtr<dpiInjectionModel> m = dpiInjectionModel::New
    (
        "bed",
        toDict
        (
            bed
            (
                "region { shape box; min (0 0 0); max (50e-6 50e-6 50e-6); }",
                "nParticles 66; SOI 2e-5;",
                "basis number; fractions { api 1; }"
            )
        ),
        &materials()
    );
    DynamicList<injectionSpec> out;
    m->inject(0, 2e-5, out);
    EXPECT_EQ(out.size(), 0);
    m->inject(2e-5, 3e-5, out);
    EXPECT_EQ(out.size(), 66);
    m->inject(3e-5, 4e-5, out);
    EXPECT_EQ(out.size(), 66);
}


// Case 5: a carrier (singleParticles, listed first) at the centre of the
// 42 um sphere, API packed around it to a total solid fraction of 0.6
// (the carrier counts, countObstacles true): N = round((0.6 V - V_c)/v_a)
// = 101. No API overlaps the carrier or another API, all inside; the
// explicit `exclude` sphere gives the identical list; without the carrier
// counted the target (2844 API in the 2 um shell) is unreachable.
TEST(regionPacking, case5AroundCarrier)
{
    FatalIOError.throwExceptions();
    using constant::mathematical::pi;

    const point c(5e-4, 5e-4, 2e-4);
    const scalar R = 42e-6, rc = 35e-6, ra = 2.5e-6;

    std::ostringstream region;
    region.precision(17);
    region << "region { shape sphere; centre " << str(c) << "; radius " << R << "; }";
    const std::string fr = "basis number; fractions { api 1; }";

    injectionSpec carrier;
    carrier.position = c;
    carrier.U = Zero;
    carrier.omega = Zero;
    carrier.type = "carrier";
    carrier.d = -1;

    const List<injectionSpec> ps = packed
    (
        bed(region.str(), "volumeFraction 0.6;", fr),
        List<injectionSpec>(1, carrier)
    );

    const scalar V = 4.0/3.0*pi*pow3(R);
    const label expected =
        label(std::round((0.6*V - 4.0/3.0*pi*pow3(rc))/volumeOf("api")));
    EXPECT_EQ(expected, 101);
    EXPECT_EQ(ps.size(), expected);

    scalar minCarrierGap = GREAT;
    for (const injectionSpec& p : ps)
    {
        EXPECT_TRUE(inSphere(p.position, ra, c, R));
        minCarrierGap = min(minCarrierGap, mag(p.position - c) - rc - ra);
    }
    std::cout << "  Case 5: " << ps.size() << " API around the carrier, "
              << "smallest gap to it " << minCarrierGap << " m, total "
              << "fraction " << (solidVolume(ps) + 4.0/3.0*pi*pow3(rc))/V
              << std::endl;
    EXPECT_GE(minCarrierGap, 0);
    EXPECT_GE(minGapRatio(ps), 0);
    EXPECT_NEAR
    (
        (solidVolume(ps) + 4.0/3.0*pi*pow3(rc))/V, 0.6, volumeOf("api")/V
    );

    // The same obstacle given as an exclude sphere
    std::ostringstream ex;
    ex.precision(17);
    ex << "avoidInjected false; exclude ( { centre " << str(c) << "; radius " << rc
       << "; } );";
    const List<injectionSpec> ps2 =
        packed(bed(region.str(), "volumeFraction 0.6;", fr, ex.str()));
    ASSERT_EQ(ps2.size(), ps.size());
    forAll(ps, k)
    {
        EXPECT_EQ(ps2[k].position, ps[k].position);
    }

    // Not counting the carrier: 0.6 of the sphere in API cannot fit
    EXPECT_THROW
    (
        packed
        (
            bed(region.str(), "volumeFraction 0.6;", fr, "countObstacles false;"),
            List<injectionSpec>(1, carrier)
        ),
        Foam::error
    );
}


// A fraction the packing cannot reach (0.5 of equal spheres in a box of 12
// diameters: random sequential addition saturates near 0.38, shaking takes
// it to about 0.4 with the walls): a FatalIOError naming maxAttempts and
// the fraction reached, after at most N x maxAttempts draws and maxShakes
// x 10 sweeps of moves per particle. Measured 2.6 s; 30 s is a bound that
// only a hang (or a quadratic search) breaks.
// Above pi/sqrt(18) the error comes at construction.
TEST(regionPacking, unreachableFractionFailsInBoundedTime)
{
    FatalIOError.throwExceptions();

    const auto t0 = std::chrono::steady_clock::now();
    std::string msg;
    try
    {
        packed
        (
            bed
            (
                "region { shape box; min (0 0 0); max (60e-6 60e-6 60e-6); }",
                "volumeFraction 0.5;",
                "basis number; fractions { api 1; }"
            )
        );
    }
    catch (const Foam::error& e)
    {
        msg = e.message();
    }
    const double seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();

    std::cout << "  unreachable 0.5: failed after " << seconds << " s: "
              << msg.substr(0, msg.find('\n')) << std::endl;

    EXPECT_NE(msg.find("could not place particle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("maxAttempts"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Reached solid fraction"), std::string::npos) << msg;
    EXPECT_LT(seconds, 30);

    EXPECT_THROW
    (
        packed
        (
            bed
            (
                "region { shape box; min (0 0 0); max (100e-6 100e-6 100e-6); }",
                "volumeFraction 0.75;",
                "basis number; fractions { api 1; }"
            )
        ),
        Foam::error
    );
}


// Bad input: clear FatalIOErrors naming the key and the valid choices
TEST(regionPacking, badInputIsRejected)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    auto message = [](const std::string& text, const bool withMaterials = true)
        -> std::string
    {
        try
        {
            dpiInjectionModel::New
            (
                "bed", toDict(text), withMaterials ? &materials() : nullptr
            );
        }
        catch (const Foam::error& e)
        {
            return e.message();
        }
        return "";
    };
    auto has = [](const std::string& s, const std::string& what)
    {
        return s.find(what) != std::string::npos;
    };

    const std::string box =
        "region { shape box; min (0 0 0); max (1e-4 1e-4 1e-4); }";
    const std::string amount = "volumeFraction 0.2;";
    const std::string fr = "basis number; fractions { api 1; }";

    EXPECT_EQ(message(bed(box, amount, fr)), "");

    std::string m = message
    (
        bed("region { shape ball; radius 1e-4; }", amount, fr)
    );
    EXPECT_TRUE
    (
        has(m, "ball") && has(m, "sphere") && has(m, "box")
     && has(m, "cylinder") && has(m, "cone") && has(m, "surface")
    ) << m;

    m = message(bed(box, amount, "basis number; fractions { API 1; }"));
    EXPECT_TRUE(has(m, "API") && has(m, "carrier")) << m;

    m = message(bed(box, amount, "basis number; fractions { wall 1; }"));
    EXPECT_TRUE(has(m, "wall material")) << m;

    m = message(bed(box, amount, "basis number; fractions { api 0.5; mid 0.4; }"));
    EXPECT_TRUE(has(m, "sum to")) << m;

    m = message(bed(box, amount, "basis volume; fractions { api 1; }"));
    EXPECT_TRUE(has(m, "basis") && has(m, "number mass")) << m;

    m = message(bed(box, "volumeFraction 0.2; nParticles 5;", fr));
    EXPECT_TRUE(has(m, "volumeFraction") && has(m, "nParticles")) << m;

    m = message(bed(box, amount, fr), false);
    EXPECT_TRUE(has(m, "material")) << m;

    m = message
    (
        bed
        (
            "region { shape box; min (0 0 0); max (5e-5 1e-4 1e-4); }",
            amount, "basis number; fractions { carrier 1; }"
        )
    );
    EXPECT_TRUE(has(m, "does not fit")) << m;

    m = message
    (
        bed
        (
            "region { shape cone; point1 (0 0 0); radius1 1e-4;"
            " point2 (0 0 0); radius2 0; }",
            amount, fr
        )
    );
    EXPECT_TRUE(has(m, "point1") && has(m, "coincide")) << m;
}

// ************************************************************************* //


// A closed surface (an STL of a box) is the box: the same volume (exact: the
// corners are exact in float32), the same bounds, and the same answer to
// "does a sphere of radius r centred at p fit" at 20,000 random points and
// radii (inside a box the nearest triangle is the nearest face, so the
// surface's test, inside and no triangle within r, is the box's per-axis
// inset); a surface that is not closed, or a missing file, is refused.
TEST(regionPacking, surfaceRegionIsTheBoxItEncloses)
{
    FatalIOError.throwExceptions();

    const std::string stl = cubeStl();
    std::ostringstream boxText;
    boxText.precision(17);
    boxText << "shape box; min (0 0 0); max (" << cubeMax.x() << ' '
            << cubeMax.y() << ' ' << cubeMax.z() << ");";
    const autoPtr<packingRegion> box(packingRegion::New(toDict(boxText.str())));
    const autoPtr<packingRegion> surf
    (
        packingRegion::New(toDict("shape surface; file \"" + stl + "\";"))
    );

    EXPECT_EQ(surf->shapeName(), "surface");
    EXPECT_NEAR(surf->volume(), box->volume(), 1e-14*box->volume());
    EXPECT_EQ(surf->bounds().min(), box->bounds().min());
    EXPECT_EQ(surf->bounds().max(), box->bounds().max());

    Random rnd(7);
    label differ = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p
        (
            cmptMultiply(1.2*cubeMax, rnd.sample01<vector>()) - 0.1*cubeMax
        );
        const scalar r = 0.3*cmptMin(cubeMax)*rnd.sample01<scalar>();
        differ += surf->contains(p, r) != box->contains(p, r);
    }
    EXPECT_EQ(differ, 0);
    EXPECT_TRUE(surf->fits(0.49*cmptMin(cubeMax)));
    EXPECT_FALSE(surf->fits(0.51*cmptMin(cubeMax)));

    // Not closed: the cube without its last two triangles
    {
        std::ifstream is(stl);
        std::string text((std::istreambuf_iterator<char>(is)), {});
        for (int k = 0; k < 2; ++k)
        {
            const auto at = text.rfind(" facet normal");
            text.erase(at, text.find("endfacet", at) + 9 - at);
        }
        std::ofstream(stl) << text;
    }
    std::string m;
    try
    {
        packingRegion::New(toDict("shape surface; file \"" + stl + "\";"));
    }
    catch (const Foam::error& e)
    {
        m = e.message();
    }
    EXPECT_NE(m.find("must be a closed surface"), std::string::npos) << m;

    m.clear();
    try
    {
        packingRegion::New(toDict("shape surface; file \"/no/such.stl\";"));
    }
    catch (const Foam::error& e)
    {
        m = e.message();
    }
    EXPECT_NE(m.find("no file"), std::string::npos) << m;

    Foam::rm(stl);
}



// The quick inhaler's bed (tutorials/inhaler system/sizes/quick: the
// guide's cone scaled by 0.33, 48 carriers of 70 um and API of 5 um at 30 %
// solids by the guide's mass fractions) packs for any seed. Random
// sequential addition alone jams here for most seeds: the 48th carrier
// found no room after 1e5 draws at 0.286-0.293 (seeds 87, 88, 90, 4711;
// 5e6 draws did not help), since the cone's top is narrower than a
// carrier and its walls exclude most of the volume. Each seed must reach
// the target within the rounding of the counts, without overlap and wholly
// inside, in a few seconds.
TEST(regionPacking, quickInhalerBedPacksForAnySeed)
{
    FatalIOError.throwExceptions();

    const point a(0.039, 0, -3.4e-3), b(0.039, 0, -3.0535e-3);
    const scalar ra = 2.64e-4, rb = 3.3e-5;
    using constant::mathematical::pi;
    const scalar V = pi*(b.z() - a.z())/3*(sqr(ra) + ra*rb + sqr(rb));

    for (const label seed : {86, 87, 88, 90, 4711, 1, 2, 3, 4, 5, 6, 7, 8, 9})
    {
        const auto t0 = std::chrono::steady_clock::now();
        List<injectionSpec> ps;
        std::string msg;
        try
        {
            ps = packed
            (
                bed
                (
                    "region { shape cone; point1 " + str(a) + "; radius1 "
                  + std::to_string(ra) + "; point2 " + str(b) + "; radius2 "
                  + std::to_string(rb) + "; }",
                    "volumeFraction 0.3;",
                    "basis mass; fractions { carrier 0.995357; api 0.004643; }",
                    "maxAttempts 100000;",
                    seed
                )
            );
        }
        catch (const Foam::error& e)
        {
            msg = e.message();
        }
        const double seconds = std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - t0
        ).count();
        ASSERT_TRUE(msg.empty()) << "seed " << seed << ": " << msg;

        label outside = 0;
        for (const injectionSpec& p : ps)
        {
            outside +=
                !inCone(p.position, 0.5*diameterOf(p.type), a, ra, b, rb);
        }
        std::cout << "  seed " << seed << ": " << countOf(ps, "carrier")
                  << " carriers, " << countOf(ps, "api") << " api, fraction "
                  << solidVolume(ps)/V << " in " << seconds << " s"
                  << std::endl;
        EXPECT_EQ(countOf(ps, "carrier"), 48) << "seed " << seed;
        EXPECT_NEAR
        (
            solidVolume(ps)/V, 0.3,
            1.5*(volumeOf("carrier") + volumeOf("api"))/V
        ) << "seed " << seed;
        EXPECT_GE(minGapRatio(ps), 0) << "seed " << seed;
        EXPECT_EQ(outside, 0) << "seed " << seed;
        EXPECT_LT(seconds, 20) << "seed " << seed;
    }
}


// A blend in % w/w (basis primaryMass: the fractions of all primaries'
// mass, N counted) is the same blend at N = 1 and N = 10: 2 % w/w of API
// in a box of carriers gives API primaries of 2 % of the mass whatever N,
// to the rounding of the parcel counts (one API parcel of N primaries,
// N v_api/(n_c v_c) of the mass). basis mass (the fractions of parcel
// masses) at N = 10 gives a blend ten times richer in API than typed:
// API to carrier mass 10 x 0.02/0.98, so 2 % typed is 0.2/1.18 = 17 % w/w.
TEST(regionPacking, drugLoadIsTheSameBlendAtAnyN)
{
    FatalIOError.throwExceptions();

    const auto apiShare = [](const label N, const std::string& basis)
    {
        const List<injectionSpec> ps
        (
            packedAtN
            (
                N, "volumeFraction 0.2;",
                "basis " + basis + "; fractions { carrier 0.98; api 0.02; }"
            )
        );
        const scalar nc = countOf(ps, "carrier"), na = countOf(ps, "api");
        const scalar mc = nc*pow3(70e-6), ma = na*N*pow3(5e-6);
        std::cout << "  N " << N << ", basis " << basis << ": " << nc
                  << " carriers, " << na << " API parcels, API "
                  << 100*ma/(ma + mc) << " % w/w" << std::endl;
        return std::make_pair(ma/(ma + mc), N*pow3(5e-6)/(ma + mc));
    };

    for (const label N : {1, 10})
    {
        const auto share = apiShare(N, "primaryMass");
        // the counts' rounding: one API parcel (share.second), and one
        // carrier of ~1100 moves the share by 0.02/1100 < 1e-4
        EXPECT_NEAR(share.first, 0.02, share.second + 1e-4) << "N " << N;
    }
    const auto one = apiShare(1, "primaryMass"), ten = apiShare(10, "primaryMass");
    EXPECT_NEAR(one.first, ten.first, one.second + ten.second + 2e-4);

    // The parcel-mass basis at N = 10: 10 x 0.02/0.98 API to carrier mass
    const auto parcelMass = apiShare(10, "mass");
    EXPECT_NEAR(parcelMass.first, 0.2/(0.98 + 0.2), 2e-3);
}


// A fill given by its mass (fillMass, the primaries' mass, N counted): the
// packed primaries weigh the fill at N = 1 and N = 10, to the rounding of
// the parcel count (half a mean parcel: the counts sum to round(M/m_mean))
// and of the per-type counts (within one parcel of each type)
TEST(regionPacking, fillMassIsTheSameFillAtAnyN)
{
    FatalIOError.throwExceptions();

    const scalar fill = 2e-7;      // 0.2 mg: ~720 carriers of 70 um
    for (const label N : {1, 10})
    {
        const List<injectionSpec> ps
        (
            packedAtN
            (
                N, "fillMass 2e-7;",
                "basis primaryMass; fractions { carrier 0.98; api 0.02; }"
            )
        );
        using constant::mathematical::pi;
        const scalar mc = 1520*pi/6*pow3(70e-6), ma = N*1520*pi/6*pow3(5e-6);
        const scalar nc = countOf(ps, "carrier"), na = countOf(ps, "api");
        const scalar mass = nc*mc + na*ma;
        std::cout << "  fillMass 2e-7 kg at N " << N << ": " << nc
                  << " carriers, " << na << " API parcels, " << mass
                  << " kg, API " << 100*na*ma/mass << " % w/w" << std::endl;
        EXPECT_NEAR(mass, fill, mc + ma) << "N " << N;
        EXPECT_NEAR(na*ma/mass, 0.02, ma/mass + mc/mass*0.02 + 1e-4) << "N " << N;
    }

    // Exactly one amount
    const std::string region
    (
        "region { shape box; min (0 0 0); max (1e-3 1e-3 1e-3); }"
    );
    const std::string fractions
    (
        "basis primaryMass; fractions { carrier 0.98; api 0.02; }"
    );
    EXPECT_THROW(packed(bed(region, "fillMass 2e-9; nParticles 10;", fractions)), Foam::error);
    EXPECT_THROW(packed(bed(region, "fillMass -1;", fractions)), Foam::error);
}
