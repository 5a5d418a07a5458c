/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of impactorStages (the emitted dose as an impactor
  reads it)
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    The NGI's cut-offs at 60 L/min are the calibration's and scale with the
    flow rate as (60/Q)^x; a diameter falls in the stage whose cut-off it
    reaches; MMAD and GSD of a log-normal aerosol sorted into the stages
    exactly (its mass between two cut-offs from the normal integral)
    come back within the error of the stages' linear-in-log reading.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "impactorStages.H"
#include "IStringStream.H"
#include <cmath>

using namespace Foam;

namespace
{

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

}


TEST(impactorStages, ngiCutOffsScaleWithFlowRate)
{
    const impactorStages at60(toDict("type NGI; flowRate 60;"));
    const scalar d50[] = {8.06, 4.46, 2.82, 1.66, 0.94, 0.55, 0.34};
    const scalar x[] = {0.54, 0.52, 0.50, 0.47, 0.53, 0.60, 0.67};
    ASSERT_EQ(at60.cutOffs().size(), 7);
    EXPECT_EQ(at60.size(), 9);
    EXPECT_EQ(at60.names().first(), "IP+PS");
    EXPECT_EQ(at60.names().last(), "MOC");

    for (const scalar Q : {30.0, 60.0, 90.0})
    {
        const impactorStages ngi
        (
            toDict("type NGI; flowRate " + std::to_string(Q) + ";")
        );
        for (label i = 0; i < 7; ++i)
        {
            EXPECT_NEAR
            (
                ngi.cutOffs()[i], 1e-6*d50[i]*std::pow(60/Q, x[i]),
                1e-12*d50[i]
            ) << "stage " << i + 1 << " at " << Q << " L/min";
        }
    }

    // Buckets: on a carrier IP+PS; at and above a cut-off its stage; below
    // the last the MOC
    EXPECT_EQ(at60.bucket(1e-6, true), 0);
    EXPECT_EQ(at60.bucket(20e-6, false), 1);
    EXPECT_EQ(at60.bucket(8.06e-6, false), 1);
    EXPECT_EQ(at60.bucket(8.05e-6, false), 2);
    EXPECT_EQ(at60.bucket(0.3e-6, false), 8);
}


TEST(impactorStages, logNormalMmadAndGsdComeBack)
{
    const impactorStages ngi(toDict("type NGI; flowRate 60;"));
    const scalarList& cut = ngi.cutOffs();

    for (const scalar mmad0 : {1.5e-6, 3e-6})
    {
        for (const scalar gsd0 : {1.6, 2.2})
        {
            // Mass fraction below d of the log-normal
            const auto F = [&](const scalar d)
            {
                return 0.5*std::erfc
                (
                    -std::log(d/mmad0)/(std::sqrt(2.0)*std::log(gsd0))
                );
            };
            scalarList mass(ngi.size(), Zero);
            mass[0] = 0.3;      // IP+PS: not in MMAD or GSD
            mass[1] = 1 - F(cut[0]);
            for (label i = 1; i < cut.size(); ++i)
            {
                mass[i + 1] = F(cut[i - 1]) - F(cut[i]);
            }
            mass.last() = F(cut.last());

            scalar mmad, gsd;
            ngi.mmadGsd(mass, mmad, gsd);
            std::cout << "  log-normal MMAD " << 1e6*mmad0 << " um, GSD "
                      << gsd0 << ": stages give " << 1e6*mmad << " um, "
                      << gsd << std::endl;

            // Linear in log between cut-offs a factor 1.6-1.9 apart: the
            // median within a few % (measured under 2 %), the GSD within
            // 10 % (its tails lie in the wider, coarser intervals)
            EXPECT_NEAR(mmad/mmad0, 1, 0.04);
            EXPECT_NEAR(gsd/gsd0, 1, 0.10);
        }
    }

    // All the mass in one stage: the median is bracketed, the 84 %
    // point too; nothing in the impactor: 0
    scalarList one(ngi.size(), Zero);
    one[3] = 1;
    scalar mmad, gsd;
    ngi.mmadGsd(one, mmad, gsd);
    EXPECT_NEAR(mmad, std::sqrt(cut[1]*cut[2]), 1e-15);
    scalarList none(ngi.size(), Zero);
    none[0] = 1;
    ngi.mmadGsd(none, mmad, gsd);
    EXPECT_EQ(mmad, 0);
    EXPECT_EQ(gsd, 0);
}


TEST(impactorStages, badInputIsRejected)
{
    FatalIOError.throwExceptions();
    EXPECT_THROW(impactorStages(toDict("type ACJ; flowRate 60;")), Foam::error);
    EXPECT_THROW(impactorStages(toDict("type NGI; flowRate -30;")), Foam::error);
    EXPECT_THROW(impactorStages(toDict("type NGI;")), Foam::error);
    EXPECT_THROW
    (
        impactorStages
        (
            toDict
            (
                "type table; flowRate 28.3; referenceFlowRate 28.3;"
                " stages (s0 s1); cutOffs (4e-6 9e-6); exponents (0.5 0.5);"
            )
        ),
        Foam::error
    );
    // A table of its own (the Andersen impactor's top stages at 28.3 L/min)
    const impactorStages aci
    (
        toDict
        (
            "type table; flowRate 28.3; referenceFlowRate 28.3;"
            " stages (s0 s1 s2); cutOffs (9e-6 5.8e-6 4.7e-6);"
            " exponents (0.5 0.5 0.5);"
        )
    );
    EXPECT_EQ(aci.size(), 5);
    EXPECT_NEAR(aci.cutOffs()[1], 5.8e-6, 1e-18);
}


// ************************************************************************* //
