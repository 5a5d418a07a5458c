/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the void-fraction models
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    The 29 representative points of theory 5.1 (one centre, 14 per shell
    radius, centroid at the centre, all inside the sphere); divided removes
    one particle volume, apiParcel N; alphaMin outside (0, 1) and an unknown
    model are FatalIOErrors. The split over cells through the solver:
    tests/cases/voidFraction.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "dpiVoidFraction.H"
#include "mathematicalConstants.H"
#include "error.H"

using namespace Foam;

namespace
{
    dictionary vfDict(const word& type, const scalar alphaMin)
    {
        dictionary d;
        d.add("type", type);
        d.add("alphaMin", alphaMin);
        return d;
    }
}


TEST(voidFraction, twentyNinePoints)
{
    const vectorList& pts = dpiVoidFraction::unitPoints();
    ASSERT_EQ(pts.size(), 29);
    EXPECT_EQ(mag(pts[0]), 0);

    label n1 = 0, n2 = 0;
    vector sum(Zero);
    for (const vector& p : pts)
    {
        sum += p;
        if (mag(mag(p) - 0.623926) < 1e-12) ++n1;
        if (mag(mag(p) - 0.917902) < 1e-12) ++n2;
    }
    EXPECT_EQ(n1, 14);
    EXPECT_EQ(n2, 14);
    EXPECT_LT(mag(sum), 1e-14);         // centroid at the centre

    // no two points coincide
    for (label i = 0; i < 29; ++i)
    {
        for (label j = i + 1; j < 29; ++j)
        {
            EXPECT_GT(mag(pts[i] - pts[j]), 0.1) << i << " " << j;
        }
    }
}


TEST(voidFraction, volumesAndN)
{
    using constant::mathematical::pi;
    const scalar d = 5e-6, Vp = pi/6*d*d*d;

    autoPtr<dpiVoidFraction> div(dpiVoidFraction::New(vfDict("divided", 0.3)));
    autoPtr<dpiVoidFraction> api(dpiVoidFraction::New(vfDict("apiParcel", 0.4)));

    EXPECT_NEAR(div->solidVolume(d, 10)/Vp, 1, 1e-14);
    EXPECT_NEAR(api->solidVolume(d, 10)/Vp, 10, 1e-13);
    EXPECT_NEAR(api->solidVolume(d, 1)/Vp, 1, 1e-14);
    EXPECT_EQ(div->alphaMin(), 0.3);
    EXPECT_EQ(api->alphaMin(), 0.4);

    dictionary noMin;
    noMin.add("type", "divided");
    EXPECT_EQ(dpiVoidFraction::New(noMin)->alphaMin(), 0.3);
}


TEST(voidFraction, badInput)
{
    FatalIOError.throwExceptions();
    for (const scalar a : {0.0, 1.0, -0.1, 1.5})
    {
        EXPECT_THROW(dpiVoidFraction::New(vfDict("divided", a)), Foam::error)
            << "alphaMin " << a;
    }
    EXPECT_THROW(dpiVoidFraction::New(vfDict("dividedVoidFraction", 0.3)), Foam::error);
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
