/*---------------------------------------------------------------------------*\
  dpiFoam: unit test of the DEM engine's force cache
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
-------------------------------------------------------------------------------
    The cache lets the next fluid step's first half kick reuse the last
    sub-step's forces when the rows come back unchanged. It keeps a hash
    of each row's position, velocity and spin: a change in any bit of any
    component must refuse the reuse (stale forces would be kicked in
    silently), while the same state, in any row order, must reuse them and
    move the forces with their particles.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "forceCache.H"
#include <cmath>

using namespace Foam;

namespace
{

demState rows()
{
    demState s;
    for (label k = 0; k < 5; ++k)
    {
        s.append
        (
            point(1e-4*k, -2e-5*k, 3e-3), vector(0.1*k, 0, -0.2),
            vector(0, 10.0*k, 1), 2.5e-6, 1e-13, 10, 1, 40 + k
        );
    }
    return s;
}

List<vector> forces(const label n, const scalar scale)
{
    List<vector> f(n);
    forAll(f, k)
    {
        f[k] = scale*vector(k, 2*k, -k);
    }
    return f;
}

//- Whether c reuses for s, with forces f0, t0 of the stored rows
bool reuses(const forceCache& c, const demState& s)
{
    List<vector> f(forces(s.size(), 1)), t(forces(s.size(), 2));
    return c.reuse(s, f, t);
}

} // End anonymous namespace


TEST(forceCache, sameStateReusesInAnyRowOrder)
{
    const demState s(rows());
    forceCache c;
    EXPECT_FALSE(reuses(c, s));      // nothing stored yet
    c.store(s);
    EXPECT_TRUE(reuses(c, s));

    // The rows reversed: reused, each force moved to its particle's row
    demState r(s);
    r.reorder(labelList({4, 3, 2, 1, 0}));
    List<vector> f(forces(5, 1)), t(forces(5, 2));
    ASSERT_TRUE(c.reuse(r, f, t));
    forAll(f, k)
    {
        EXPECT_EQ(f[k], forces(5, 1)[4 - k]);
        EXPECT_EQ(t[k], forces(5, 2)[4 - k]);
    }

    c.invalidate();
    EXPECT_FALSE(reuses(c, s));
}


// One bit of one component of one row, in each of the three vectors: the
// smallest change a caller can make, refused every time
TEST(forceCache, anyChangedBitRefusesReuse)
{
    const demState s(rows());
    forceCache c;
    c.store(s);

    for (label row = 0; row < s.size(); ++row)
    {
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            for (label which = 0; which < 3; ++which)
            {
                demState t(s);
                vector& w =
                    which == 0 ? t.x[row] : which == 1 ? t.v[row] : t.omega[row];
                w.component(cmpt) =
                    std::nextafter(w.component(cmpt), GREAT);
                EXPECT_FALSE(reuses(c, t))
                    << "row " << row << " component " << int(cmpt)
                    << " of " << (which == 0 ? "x" : which == 1 ? "v" : "omega");
            }
        }
    }

    // Another particle in a row, or a row more: refused
    demState other(s);
    other.globalId[2] = 99;
    EXPECT_FALSE(reuses(c, other));
    demState more(s);
    more.append(point::zero, Zero, Zero, 2.5e-6, 1e-13, 10, 1, 45);
    EXPECT_FALSE(reuses(c, more));
}


// -0 and +0 are the same value (the exact comparison the hash replaced
// took them so): a parcel at rest handed back with -0 keeps its forces
TEST(forceCache, signedZerosAreEqual)
{
    demState s(rows());
    forceCache c;
    c.store(s);
    demState t(s);
    t.v[0] = vector(-0.0, 0.0, -0.2);
    t.omega[3].x() = -0.0;
    EXPECT_TRUE(std::signbit(t.v[0].x()));
    EXPECT_TRUE(reuses(c, t));
}


// ************************************************************************* //
