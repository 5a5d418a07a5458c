/*---------------------------------------------------------------------------*\
  dpiFoam: unit test of the DEM state arrays
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demState.H"

using namespace Foam;

// Every array must grow together: a row that is missing in one array would
// silently pair a parcel's position with another's mass.
TEST(demState, appendKeepsRowsAligned)
{
    demState s;
    s.append(point(1, 2, 3), vector(0, 0, -1), Zero, 2.5e-6, 1e-13, 10, 1, 42);
    s.append(point(4, 5, 6), Zero, vector(1, 0, 0), 35e-6, 3e-10, 1, 0, 7);

    ASSERT_EQ(s.size(), 2);
    EXPECT_EQ(s.v.size(), 2);
    EXPECT_EQ(s.fExt.size(), 2);
    EXPECT_EQ(s.torque.size(), 2);
    EXPECT_EQ(s.globalId[0], 42);
    EXPECT_EQ(s.typeId[1], 0);
    EXPECT_DOUBLE_EQ(s.N[0], 10);
    EXPECT_DOUBLE_EQ(s.x[1].y(), 5);
    EXPECT_EQ(s.f[1], vector::zero);

    s.clear();
    EXPECT_EQ(s.size(), 0);
    EXPECT_EQ(s.globalId.size(), 0);
}

// ************************************************************************* //
