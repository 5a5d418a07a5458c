/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the size distributions and of packing them
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    logNormal against its closed forms (Hatch-Choate, the normal CDF, the
    mean cube) and, truncated, against numerical integration; table meets
    its rows in its basis and its number and mass agree with integration;
    every quantile inverts its cumulative; a bed packed from distributions
    has the typed distribution (within the stratified draw's bound), no
    overlaps at the drawn sizes, and the same drug load at N = 1 and 10;
    one-size types pack as before; bad input is refused.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "sizeDistribution.H"
#include "regionPacking.H"
#include "demMaterials.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <algorithm>
#include <cmath>
#include <functional>
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

autoPtr<sizeDistribution> sizes(const std::string& entry)
{
    return sizeDistribution::New(toDict(entry));
}

// Standard normal CDF, written here from erfc
scalar normalCdf(const scalar x)
{
    return 0.5*std::erfc(-x/std::sqrt(2.0));
}

// Integral of f(ln d) over [ln a, ln b] by Simpson's rule, 20000 panels:
// for the smooth integrands here (d^3 times a Gaussian in ln d) the error
// is below 1e-10 of the integral
scalar integrateLn
(
    const std::function<scalar(scalar)>& f,
    const scalar a,
    const scalar b
)
{
    const label n = 20000;
    const scalar la = std::log(a), h = (std::log(b) - la)/n;
    scalar s = f(a) + f(b);
    for (label i = 1; i < n; ++i)
    {
        s += (i % 2 ? 4 : 2)*f(std::exp(la + i*h));
    }
    return s*h/3;
}

// Number density in ln d of the log-normal by number (CMD, GSD), untruncated
scalar lnDensity(const scalar d, const scalar cmd, const scalar gsd)
{
    const scalar s = std::log(gsd), z = std::log(d/cmd)/s;
    return std::exp(-0.5*z*z)/(s*std::sqrt(2*constant::mathematical::pi));
}

void expectQuantileInverts(const sizeDistribution& sd)
{
    for (label i = 1; i < 100; ++i)
    {
        const scalar u = i/100.0;
        // The bisection stops at a relative width of 4e-15 in d; the CDF's
        // slope in ln d is at most about 1/(s sqrt(2 pi)) < 1 here
        EXPECT_NEAR(sd.numberUndersize(sd.diameter(u)), u, 1e-12) << u;
    }
    EXPECT_EQ(sd.diameter(0), sd.minDiameter());
    EXPECT_EQ(sd.diameter(1), sd.maxDiameter());
}

const std::string apiLogNormal
(
    "sizeDistribution { type logNormal; median 2.5e-6; gsd 1.8;"
    " basis mass; min 0.5e-6; max 10e-6; }"
);

const std::string materialsText
(
    "types {"
    "  carrier { sizeDistribution { type table; basis mass;"
    "            diameters (40e-6 55e-6 70e-6 90e-6 120e-6);"
    "            undersize (0 0.1 0.5 0.9 1); }"
    "            density 1520; youngsModulus 5e8; poissonsRatio 0.35; }"
    "  api { " + apiLogNormal + " density 1520; youngsModulus 5e8;"
    "        poissonsRatio 0.35; N NAPI; api true; }"
    "  wall { youngsModulus 5e8; poissonsRatio 0.35; }"
    "}"
    "pairs { default { restitution 0.85; friction 0.45; } }"
    "coarseGraining scaledContacts;"
);

std::string withN(const std::string& text, const std::string& N)
{
    std::string s(text);
    s.replace(s.find("NAPI"), 4, N);
    return s;
}

List<injectionSpec> pack
(
    const demMaterials& mat,
    const std::string& text
)
{
    autoPtr<dpiInjectionModel> m =
        dpiInjectionModel::New("bed", toDict(text), &mat);
    DynamicList<injectionSpec> out;
    m->inject(0, 1, out);
    return List<injectionSpec>(out);
}

} // End anonymous namespace


// The untruncated log-normal's closed forms: medians (Hatch-Choate), the
// CDF one GSD above the median, the mean cube exp(3 mu + 9 s^2/2)
TEST(sizeDistribution, logNormalClosedForms)
{
    const scalar mmd = 2.5e-6, gsd = 1.8, s = std::log(gsd);
    const scalar cmd = mmd*std::exp(-3*s*s);

    // Bounds 12 deviations out: the truncation changes nothing at 1e-15
    const std::string bounds(" min 1e-9; max 1e-2; }");
    autoPtr<sizeDistribution> byMass = sizes
    (
        "sizeDistribution { type logNormal; median 2.5e-6; gsd 1.8;"
        " basis mass;" + bounds
    );
    std::ostringstream median;
    median.precision(17);
    median << cmd;
    autoPtr<sizeDistribution> byNumber = sizes
    (
        "sizeDistribution { type logNormal; median "
      + median.str() + "; gsd 1.8; basis number;" + bounds
    );

    for (const sizeDistribution* sd : {byMass.get(), byNumber.get()})
    {
        EXPECT_NEAR(sd->numberMedian()/cmd, 1, 1e-9);
        EXPECT_NEAR(sd->massMedian()/mmd, 1, 1e-9);
        EXPECT_NEAR(sd->numberUndersize(cmd*gsd), normalCdf(1), 1e-12);
        EXPECT_NEAR(sd->massUndersize(mmd/gsd), normalCdf(-1), 1e-12);
        EXPECT_NEAR
        (
            sd->meanCube()/std::exp(3*std::log(cmd) + 4.5*s*s), 1, 1e-9
        );
        EXPECT_FALSE(sd->fixed());
        expectQuantileInverts(*sd);
    }
}


// Truncated: the number and mass cumulatives and the mean cube against
// numerical integration of the untruncated density over [min, max]
TEST(sizeDistribution, logNormalTruncatedAgainstIntegration)
{
    autoPtr<sizeDistribution> sd = sizes(apiLogNormal);
    const scalar gsd = 1.8, s = std::log(gsd);
    const scalar cmd = 2.5e-6*std::exp(-3*s*s);
    const scalar a = 0.5e-6, b = 10e-6;

    auto number = [&](const scalar d) { return lnDensity(d, cmd, gsd); };
    auto mass = [&](const scalar d) { return pow3(d)*lnDensity(d, cmd, gsd); };
    const scalar n = integrateLn(number, a, b), m = integrateLn(mass, a, b);

    for (const scalar d : {0.7e-6, 1.3e-6, 2.5e-6, 4e-6, 8e-6})
    {
        EXPECT_NEAR(sd->numberUndersize(d), integrateLn(number, a, d)/n, 1e-9);
        EXPECT_NEAR(sd->massUndersize(d), integrateLn(mass, a, d)/m, 1e-9);
    }
    EXPECT_NEAR(sd->meanCube()/(m/n), 1, 1e-9);
    EXPECT_EQ(sd->numberUndersize(a), 0);
    EXPECT_EQ(sd->massUndersize(b), 1);
    expectQuantileInverts(*sd);

    // Default bounds: CMD/GSD^3 and MMD GSD^3
    autoPtr<sizeDistribution> dflt = sizes
    (
        "sizeDistribution { type logNormal; median 2.5e-6; gsd 1.8;"
        " basis mass; }"
    );
    EXPECT_NEAR(dflt->minDiameter()/(cmd/pow3(gsd)), 1, 1e-12);
    EXPECT_NEAR(dflt->maxDiameter()/(2.5e-6*pow3(gsd)), 1, 1e-12);
}


// A table meets its rows exactly in its basis; its other basis and mean
// cube agree with integrating the piecewise density (uniform in ln d in
// the basis given)
TEST(sizeDistribution, tableMeetsItsRows)
{
    const scalarList d({1e-6, 1.5e-6, 2.5e-6, 4.5e-6, 10e-6});
    const scalarList F({0, 0.1, 0.5, 0.9, 1});
    const std::string rows
    (
        "diameters (1e-6 1.5e-6 2.5e-6 4.5e-6 10e-6);"
        " undersize (0 0.1 0.5 0.9 1); }"
    );

    for (const word basis : {"mass", "number"})
    {
        autoPtr<sizeDistribution> sd = sizes
        (
            "sizeDistribution { type table; basis " + basis + "; " + rows
        );
        const bool byMass = basis == "mass";

        // The density in ln d, by number, written here from the rows, in
        // the interval k being integrated (it jumps at the rows)
        label k = 0;
        auto number = [&](const scalar x)
        {
            const scalar c = (F[k+1] - F[k])/std::log(d[k+1]/d[k]);
            return byMass ? c/pow3(x) : c;
        };
        auto mass = [&](const scalar x) { return pow3(x)*number(x); };

        auto integral = [&](const std::function<scalar(scalar)>& f, scalar hi)
        {
            scalar sum = 0;
            for (k = 0; k < 4 && d[k] < hi; ++k)
            {
                sum += integrateLn(f, d[k], min(hi, d[k+1]));
            }
            return sum;
        };
        const scalar n = integral(number, d.last());
        const scalar m = integral(mass, d.last());

        forAll(d, k)
        {
            const scalar given =
                byMass ? sd->massUndersize(d[k]) : sd->numberUndersize(d[k]);
            EXPECT_NEAR(given, F[k], 1e-14) << basis << ' ' << k;
        }
        for (const scalar x : {1.2e-6, 2e-6, 3e-6, 7e-6})
        {
            EXPECT_NEAR(sd->numberUndersize(x), integral(number, x)/n, 1e-9);
            EXPECT_NEAR(sd->massUndersize(x), integral(mass, x)/m, 1e-9);
        }
        EXPECT_NEAR(sd->meanCube()/(m/n), 1, 1e-9);
        EXPECT_NEAR(byMass ? sd->massMedian() : sd->numberMedian(), 2.5e-6, 1e-15);
        expectQuantileInverts(*sd);
    }
}


// A diameter is a fixed size: no draws, the same numbers as before
TEST(sizeDistribution, diameterIsFixed)
{
    autoPtr<sizeDistribution> sd = sizes("diameter 70e-6;");
    EXPECT_TRUE(sd->fixed());
    EXPECT_EQ(sd->diameter(0.3), 70e-6);
    EXPECT_EQ(sd->meanCube(), pow3(70e-6));
    EXPECT_EQ(sd->massMedian(), 70e-6);

    // A wall material has neither
    EXPECT_FALSE(sizeDistribution::New(toDict("youngsModulus 5e8;")).valid());
}


// The packed bed has the typed distribution: stratified draws put the
// drawn cumulative within 1/n of the typed one at every size (a
// Kolmogorov-Smirnov distance of at most 1/n) and the drawn mean cube
// within (dmax^3 - dmin^3)/n of the mean cube; no two parcels overlap at
// their drawn sizes, and each is inside the box
TEST(sizeDistribution, packedBedHasTheTypedDistribution)
{
    const demMaterials mat(toDict(withN(materialsText, "1")));
    const List<injectionSpec> ps = pack
    (
        mat,
        "type regionPacking; seed 7; region { shape box; min (0 0 0);"
        " max (5e-4 5e-4 5e-4); } volumeFraction 0.2; basis primaryMass;"
        " fractions { carrier 0.998; api 0.002; }"
    );

    for (const word type : {"carrier", "api"})
    {
        const sizeDistribution& sd = mat.size(mat.names().find(type));
        std::vector<scalar> d;
        for (const injectionSpec& p : ps)
        {
            if (p.type == type)
            {
                ASSERT_GT(p.d, 0);
                d.push_back(p.d);
            }
        }
        std::sort(d.begin(), d.end());
        const label n = d.size();
        ASSERT_GT(n, 100) << type;

        scalar ks = 0, cubes = 0;
        for (label i = 0; i < n; ++i)
        {
            const scalar F = sd.numberUndersize(d[i]);
            ks = max(ks, max(F - scalar(i)/n, scalar(i + 1)/n - F));
            cubes += pow3(d[i]);
        }
        EXPECT_LE(ks, 1.0/n + 1e-12) << type;
        EXPECT_NEAR
        (
            cubes/n, sd.meanCube(),
            (pow3(sd.maxDiameter()) - pow3(sd.minDiameter()))/n
        ) << type;
        EXPECT_GE(d.front(), sd.minDiameter());
        EXPECT_LE(d.back(), sd.maxDiameter());
    }

    // No overlaps at the drawn radii, wholly inside the box
    forAll(ps, a)
    {
        const scalar ra = 0.5*ps[a].d;
        for (direction c = 0; c < 3; ++c)
        {
            EXPECT_GE(ps[a].position[c] - ra, -1e-18);
            EXPECT_LE(ps[a].position[c] + ra, 6e-4 + 1e-18);
        }
        for (label b = a + 1; b < ps.size(); ++b)
        {
            ASSERT_GE
            (
                mag(ps[a].position - ps[b].position), ra + 0.5*ps[b].d
            ) << a << ' ' << b;
        }
    }
}


// The drug load in % w/w is the same at N = 1 and N = 10 with a
// polydisperse API: the packed API's mass (N counted, at the drawn sizes)
// over the bed's is the typed 0.2 % within the draws' bound on each mean
// cube (their two bounds added) and one parcel's rounding
TEST(sizeDistribution, drugLoadIsTheSameAtAnyN)
{
    scalarList load(2);
    scalarList bound(2);
    const char* Ns[2] = {"1", "10"};
    for (label k = 0; k < 2; ++k)
    {
        const demMaterials mat(toDict(withN(materialsText, Ns[k])));
        const List<injectionSpec> ps = pack
        (
            mat,
            "type regionPacking; seed 3; region { shape box; min (0 0 0);"
            " max (4e-4 4e-4 4e-4); } volumeFraction 0.2;"
            " basis primaryMass; fractions { carrier 0.998; api 0.002; }"
        );
        scalar api = 0, all = 0;
        label nApi = 0, nCarrier = 0;
        for (const injectionSpec& p : ps)
        {
            const bool isApi = p.type == "api";
            const scalar m = (isApi ? mat.N(mat.names().find("api")) : 1)*pow3(p.d);
            (isApi ? api : all) += m;
            (isApi ? nApi : nCarrier) += 1;
        }
        load[k] = api/(api + all);
        // Each type's total within n (dmax^3 - dmin^3)/n of its mean:
        // relative to the total, the sum of the two types' bounds
        const sizeDistribution& a = mat.size(mat.names().find("api"));
        const sizeDistribution& c = mat.size(mat.names().find("carrier"));
        bound[k] =
            (pow3(a.maxDiameter()) - pow3(a.minDiameter()))
           /(nApi*a.meanCube())
          + (pow3(c.maxDiameter()) - pow3(c.minDiameter()))
           /(nCarrier*c.meanCube());
        // The counts are rounded to whole parcels: one parcel of each
        // type, of the mean size (API: N primaries)
        bound[k] +=
            mat.N(mat.names().find("api"))*a.meanCube()/api
          + c.meanCube()/all;
        EXPECT_NEAR(load[k], 0.002, 0.002*bound[k])
            << "N " << Ns[k] << ": load " << load[k] << ", bound " << bound[k];
    }
}


// Bad input is refused, naming the dictionary and the key
TEST(sizeDistribution, badInputIsRejected)
{
    FatalIOError.throwExceptions();
    FatalError.throwExceptions();
    const std::vector<std::string> bad
    {
        "diameter 5e-6; sizeDistribution { type logNormal; median 2e-6;"
        " gsd 1.5; basis mass; }",
        "sizeDistribution { type logNormal; median 2e-6; gsd 1; basis mass; }",
        "sizeDistribution { type logNormal; median 2e-6; gsd 1.5;"
        " basis volume; }",
        "sizeDistribution { type logNormal; median 2e-6; gsd 1.5; basis mass;"
        " min 5e-6; max 1e-6; }",
        "sizeDistribution { type logNormal; median 2e-6; gsd 1.5; basis mass;"
        " min 1e-3; max 2e-3; }",
        "sizeDistribution { type logNormal; median -2e-6; gsd 1.5;"
        " basis mass; }",
        "sizeDistribution { type rosinRammler; }",
        "sizeDistribution 5e-6;",
        "sizeDistribution { type table; basis mass; diameters (1e-6 2e-6);"
        " undersize (0 0.9); }",
        "sizeDistribution { type table; basis mass; diameters (2e-6 1e-6);"
        " undersize (0 1); }",
        "sizeDistribution { type table; basis mass;"
        " diameters (1e-6 2e-6 3e-6); undersize (0 0.6 0.5 1); }",
        "sizeDistribution { type table; basis mass;"
        " diameters (1e-6 2e-6 3e-6); undersize (0 0.6 0.5); }",
    };
    for (const std::string& entry : bad)
    {
        EXPECT_THROW(sizes(entry), Foam::error) << entry;
    }
    try
    {
        sizes("sizeDistribution { type rosinRammler; }");
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("logNormal"), std::string::npos) << msg;
        EXPECT_NE(msg.find("table"), std::string::npos) << msg;
    }
    FatalIOError.dontThrowExceptions();
    FatalError.dontThrowExceptions();
}


// ************************************************************************* //
