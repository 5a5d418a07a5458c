/*---------------------------------------------------------------------------*\
  dpiFoam: unit test of the DEM state arrays
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demState.H"
#include "OStringStream.H"
#include "IStringStream.H"

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

// reorder moves every column's row together (the DEM partition orders its
// rows by globalId with it); rows after the permuted ones stay as they are
TEST(demState, reorderMovesWholeRows)
{
    demState s;
    for (label k = 0; k < 4; ++k)
    {
        s.append
        (
            point(k, 0, 0), vector(0, k, 0), vector(0, 0, k), 1e-6*(k + 1),
            1e-12*(k + 1), k + 1, k % 2, 100 - k
        );
        s.fExt[k] = vector(k, k, 0);
        s.f[k] = vector(0, k, k);
        s.torque[k] = vector(k, 0, k);
        s.fContact[k] = vector(-k, 0, 0);
        s.tContact[k] = vector(0, -k, 0);
    }

    // the first three rows by increasing globalId: 98, 99, 100
    const labelList order({2, 1, 0});
    s.reorder(order);

    ASSERT_EQ(s.size(), 4);
    forAll(order, k)
    {
        const label was = order[k];
        EXPECT_EQ(s.globalId[k], 100 - was);
        EXPECT_EQ(s.x[k], point(was, 0, 0));
        EXPECT_EQ(s.v[k], vector(0, was, 0));
        EXPECT_EQ(s.omega[k], vector(0, 0, was));
        EXPECT_DOUBLE_EQ(s.r[k], 1e-6*(was + 1));
        EXPECT_DOUBLE_EQ(s.m[k], 1e-12*(was + 1));
        EXPECT_DOUBLE_EQ(s.N[k], was + 1);
        EXPECT_EQ(s.typeId[k], was % 2);
        EXPECT_EQ(s.fExt[k], vector(was, was, 0));
        EXPECT_EQ(s.f[k], vector(0, was, was));
        EXPECT_EQ(s.torque[k], vector(was, 0, was));
        EXPECT_EQ(s.fContact[k], vector(-was, 0, 0));
        EXPECT_EQ(s.tContact[k], vector(0, -was, 0));
    }
    EXPECT_EQ(s.globalId[3], 97);
    EXPECT_EQ(s.x[3], point(3, 0, 0));
}

// The DEM partition takes the mesh rows over without a copy (transfer),
// moves rows into the places of rows sent away (copyRow) and reads the
// rows that arrive into given places (readRows): every column must follow
namespace
{
    demState fourRows()
    {
        demState s;
        for (label k = 0; k < 4; ++k)
        {
            s.append
            (
                point(k, 0, 0), vector(0, k, 0), vector(0, 0, k),
                1e-6*(k + 1), 1e-12*(k + 1), k + 1, k % 2, 100 - k
            );
            s.fExt[k] = vector(k, k, 0);
            s.fContact[k] = vector(-k, 0, 0);
            s.tContact[k] = vector(0, -k, 0);
        }
        s.contactForcesValid = true;
        return s;
    }
}


TEST(demState, transferTakesRowsAndLeavesSourceEmpty)
{
    demState mesh(fourRows());
    const point* data = mesh.x.cdata();
    demState dem;
    dem.transfer(mesh);

    EXPECT_EQ(mesh.size(), 0);
    EXPECT_EQ(mesh.fContact.size(), 0);
    EXPECT_EQ(mesh.x.capacity(), 0);
    EXPECT_FALSE(mesh.contactForcesValid);
    ASSERT_EQ(dem.size(), 4);
    EXPECT_EQ(dem.x.cdata(), data);     // the same storage: no copy
    EXPECT_TRUE(dem.contactForcesValid);
    EXPECT_EQ(dem.globalId[3], 97);
    EXPECT_EQ(dem.tContact[2], vector(0, -2, 0));
}


TEST(demState, copyRowAndScatteredReadMoveWholeRows)
{
    demState s(fourRows());
    s.copyRow(3, 1);
    EXPECT_EQ(s.globalId[1], 97);
    EXPECT_EQ(s.x[1], point(3, 0, 0));
    EXPECT_EQ(s.fExt[1], vector(3, 3, 0));
    EXPECT_EQ(s.tContact[1], vector(0, -3, 0));
    EXPECT_DOUBLE_EQ(s.m[1], 4e-12);

    // rows 0 and 2 written, read back into places 3 and 0
    OStringStream os;
    s.writeRows(os, labelList({0, 2}));
    IStringStream is(os.str());
    s.readRows(is, labelList({3, 0}));
    EXPECT_EQ(s.globalId[3], 100);
    EXPECT_EQ(s.x[3], point(0, 0, 0));
    EXPECT_EQ(s.globalId[0], 98);
    EXPECT_EQ(s.v[0], vector(0, 2, 0));
    EXPECT_DOUBLE_EQ(s.N[0], 3);
    // readRows sets the parcels' state; their forces start at zero
    EXPECT_EQ(s.fContact[0], vector::zero);
    EXPECT_EQ(s.size(), 4);
}

// ************************************************************************* //
