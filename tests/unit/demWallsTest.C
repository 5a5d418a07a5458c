/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of DEM walls
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    Triangulated walls: contacts at shared edges and vertices are counted
    once on flat and convex surfaces and twice in a concave corner; an
    oblique impact on a tilted wall made of many small triangles (the
    contact crosses shared edges) reflects with the set restitution and
    follows the same trajectory as on the equivalent plane wall.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "triangleWall.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include "transform.H"
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

std::string str(const vector& v)
{
    std::ostringstream os;
    os.precision(17);
    os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
    return os.str();
}

// A square [-L, L]^2 of the plane through the origin with unit normal n,
// split into n x n squares of two triangles each
std::string tiltedTriangles(const vector& n, const scalar L, const label m)
{
    // Two unit vectors in the plane
    vector e1(vector(1, 0, 0) - (n & vector(1, 0, 0))*n);
    e1 /= mag(e1);
    const vector e2(n ^ e1);

    std::ostringstream os;
    os.precision(17);
    os << "points (";
    for (label i = 0; i <= m; ++i)
    {
        for (label j = 0; j <= m; ++j)
        {
            const scalar a = -L + 2*L*i/m, b = -L + 2*L*j/m;
            os << str(a*e1 + b*e2) << " ";
        }
    }
    os << "); triangles (";
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j < m; ++j)
        {
            const label p00 = i*(m + 1) + j, p10 = (i + 1)*(m + 1) + j;
            const label p01 = p00 + 1, p11 = p10 + 1;
            // Alternate the diagonal so vertices join 4 or 8 triangles
            if ((i + j) % 2)
            {
                os << "(" << p00 << " " << p10 << " " << p11 << ") ("
                   << p00 << " " << p11 << " " << p01 << ") ";
            }
            else
            {
                os << "(" << p00 << " " << p10 << " " << p01 << ") ("
                   << p10 << " " << p11 << " " << p01 << ") ";
            }
        }
    }
    os << ");";
    return os.str();
}

std::string deck(const std::string& wall, const scalar mu)
{
    std::ostringstream os;
    os.precision(17);
    os  << "timeStep 1e-10;\n"
        << "types { api { diameter 5e-6; density 1520; youngsModulus 5e8;"
        << " poissonsRatio 0.35; }\n"
        << " wall { youngsModulus 5e8; poissonsRatio 0.35; } }\n"
        << "pairs { default { restitution 0.85; friction " << mu
        << "; rollingFriction 0; } }\n"
        << "normalModel hertzParcel; tangentialModel historyParcel;\n"
        << "rollingModel none; cohesionModel none;\n"
        << "walls { w { " << wall << " material wall; } }\n"
        << "timeStepCheck { maxImpactVelocity 3; }\n";
    return os.str();
}

struct recorder
:
    public demObserver
{
    std::vector<point> x;
    label maxWallContacts = 0;
    const demEngine* engine = nullptr;

    virtual void subStep(const scalar, const demState& s)
    {
        x.push_back(s.x[0]);
        maxWallContacts =
            max(maxWallContacts, engine->diagnostics().nWallContacts);
    }
};

} // End anonymous namespace


// Static contact queries on a V made of two strips of triangles: a sphere
// in the valley touches both faces (2 contacts), a sphere over the ridge of
// the inverted V touches the shared edge once, a sphere over a vertex
// shared by 8 triangles of a flat fan touches once.
TEST(demWalls, sharedEdgesAndVerticesCountOnce)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // Valley along y: faces z = |x| for -1 <= x <= 1, -1 <= y <= 1
    const dictionary valley(toDict
    (
        "type triangles; material wall;"
        "points ((-1 -1 1) (0 -1 0) (1 -1 1) (-1 1 1) (0 1 0) (1 1 1));"
        "triangles ((0 1 4) (0 4 3) (1 2 5) (1 5 4));"
    ));
    demWalls::triangleWall v("valley", valley, nullptr);
    v.prepare(0.5);

    DynamicList<demWallContact> c;
    // Centre on the axis at height 0.3: distance 0.3/sqrt(2) to each face
    v.findContacts(point(0, 0.1, 0.3), 0.5, c);
    EXPECT_EQ(c.size(), 2);

    // Ridge: the same surface upside down, sphere above the ridge line
    const dictionary ridge(toDict
    (
        "type triangles; material wall;"
        "points ((-1 -1 -1) (0 -1 0) (1 -1 -1) (-1 1 -1) (0 1 0) (1 1 -1));"
        "triangles ((0 1 4) (0 4 3) (1 2 5) (1 5 4));"
    ));
    demWalls::triangleWall r("ridge", ridge, nullptr);
    r.prepare(0.5);
    c.clear();
    r.findContacts(point(0, 0.1, 0.3), 0.5, c);
    ASSERT_EQ(c.size(), 1);
    EXPECT_NEAR(c[0].distance, 0.3, 1e-12);
    EXPECT_NEAR(c[0].n.z(), 1, 1e-12);

    // Slightly off the ridge, over one face: still one contact, that face
    c.clear();
    r.findContacts(point(0.05, 0.1, 0.3), 0.5, c);
    EXPECT_EQ(c.size(), 1);

    // Flat fan: sphere right above a vertex shared by 8 triangles and
    // above a shared edge
    const dictionary flat(toDict
    (
        "type triangles; material wall; " + tiltedTriangles(vector(0, 0, 1), 1, 4)
    ));
    demWalls::triangleWall f("flat", flat, nullptr);
    f.prepare(0.5);
    for (const point& x : {point(0, 0, 0.2), point(0.25, 0.1, 0.2),
                           point(0.1, 0.1, 0.2), point(0.5, 0.5, 0.2)})
    {
        c.clear();
        f.findContacts(x, 0.5, c);
        ASSERT_EQ(c.size(), 1) << " at " << str(x);
        EXPECT_NEAR(c[0].distance, 0.2, 1e-12);
    }
}


// Oblique impact at 3 m/s, 40 degrees off the normal, on a wall tilted
// about two axes and built of 0.5 um squares (the contact patch slides
// ~0.2 um during the 80 ns contact, crossing shared edges). Frictionless:
// the normal velocity must come back at e = 0.85 +- 0.001 (as for Case 1,
// dt = 1e-10 s) and the tangential velocity unchanged; with friction the
// trajectory must match the plane wall's to 1e-9 of the radius (the
// tangential history is handed over between triangles). In both runs at
// most one wall contact is ever counted.
TEST(demWalls, obliqueImpactOnTiltedTriangulatedWall)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    vector n(0.3, -0.2, 1);
    n /= mag(n);
    const scalar r = 2.5e-6;

    vector t(vector(1, 0.5, 0) - (n & vector(1, 0.5, 0))*n);
    t /= mag(t);
    const scalar angle = 40*constant::mathematical::pi/180;
    const vector v0(3*(-Foam::cos(angle)*n + Foam::sin(angle)*t));

    const scalar m = 1520*constant::mathematical::pi/6*pow3(5e-6);

    for (const scalar mu : {0.0, 0.45})
    {
        std::vector<point> xPlane, xTri;
        vector vPlane(Zero), vTri(Zero);

        for (const bool tri : {false, true})
        {
            const std::string wall = tri
              ? "type triangles; " + tiltedTriangles(n, 10e-6, 40)
              : "type plane; point (0 0 0); normal " + str(n) + ";";

            demEngine engine(toDict(deck(wall, mu)));
            demState s;
            s.append((r + 1e-9)*n - 0.1e-6*t, v0, Zero, r, m, 1, 0, 0);

            recorder rec;
            rec.engine = &engine;
            engine.evolve(s, 3000*1e-10, Zero, &rec);

            EXPECT_LE(rec.maxWallContacts, 1);
            EXPECT_EQ(rec.maxWallContacts, 1);

            (tri ? xTri : xPlane) = rec.x;
            (tri ? vTri : vPlane) = s.v[0];
        }

        const scalar vn0 = v0 & n;
        std::cout << "  tilted wall, mu = " << mu << ": e = "
                  << -(vTri & n)/vn0 << " (plane " << -(vPlane & n)/vn0
                  << ")" << std::endl;

        ASSERT_EQ(xPlane.size(), xTri.size());
        for (size_t k = 0; k < xPlane.size(); ++k)
        {
            EXPECT_LT(mag(xPlane[k] - xTri[k]), 1e-9*r) << " step " << k;
        }

        if (mu == 0)
        {
            EXPECT_NEAR(-(vTri & n)/vn0, 0.85, 0.001);
            const vector vt0(v0 - vn0*n);
            EXPECT_LT(mag((vTri - (vTri & n)*n) - vt0), 1e-9*mag(vt0));
        }
    }
}


// ************************************************************************* //
