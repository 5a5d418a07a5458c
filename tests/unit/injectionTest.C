/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the injection models (what and when to inject)
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "dpiInjectionModel.H"
#include "IStringStream.H"
#include "error.H"
#include "OFstream.H"
#include "OSspecific.H"

using namespace Foam;

namespace
{
    dictionary dictFrom(const char* text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}


// The list is read entry by entry; defaults (U, omega zero, d from type)
// apply per entry, and every particle is injected exactly once, in the fluid
// step whose half-open interval [t0, t1) holds SOI.
TEST(singleParticles, injectsTheListOnceAtSOI)
{
    const dictionary d = dictFrom
    (
        "type singleParticles; SOI 2e-5;"
        "particles ("
        "  { type API; position (1 2 3); U (0 -3 0); }"
        "  { type carrier; position (4 5 6); d 7e-5; omega (0 0 9); }"
        ");"
    );
    autoPtr<dpiInjectionModel> m = dpiInjectionModel::New("impactor", d);

    DynamicList<injectionSpec> out;
    m->inject(0, 1e-5, out);
    EXPECT_EQ(out.size(), 0);
    m->inject(1e-5, 2e-5, out);
    EXPECT_EQ(out.size(), 0) << "SOI at the end of an interval belongs to the next";
    m->inject(2e-5, 3e-5, out);
    ASSERT_EQ(out.size(), 2);
    m->inject(3e-5, 4e-5, out);
    EXPECT_EQ(out.size(), 2) << "injected twice";

    EXPECT_EQ(out[0].type, "API");
    EXPECT_EQ(out[0].position, point(1, 2, 3));
    EXPECT_EQ(out[0].U, vector(0, -3, 0));
    EXPECT_EQ(out[0].omega, vector::zero);
    EXPECT_LT(out[0].d, 0) << "no d: the type's diameter is used";
    EXPECT_DOUBLE_EQ(out[1].d, 7e-5);
    EXPECT_EQ(out[1].omega, vector(0, 0, 9));
}


TEST(singleParticles, badInputIsRefused)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // Unknown model: the error lists the valid types
    try
    {
        dpiInjectionModel::New("x", dictFrom("type singleParticle;"));
        FAIL() << "unknown injection model accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("singleParticles"), std::string::npos)
            << e.message();
    }

    // An entry without a position
    EXPECT_THROW
    (
        dpiInjectionModel::New
        (
            "x",
            dictFrom("type singleParticles; particles ({ type API; });")
        ),
        Foam::error
    );

    // An empty list
    EXPECT_THROW
    (
        dpiInjectionModel::New
        (
            "x", dictFrom("type singleParticles; particles ();")
        ),
        Foam::error
    );
}

// ************************************************************************* //


// particleList reads plain OpenFOAM lists (with or without a FoamFile
// header) and gives the same specs as the equivalent singleParticles
// entries: positions, optional velocities and diameters, one type for all.
// Mismatched lengths and a missing file are refused naming the entry.
TEST(particleList, readsListFilesLikeSingleParticles)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const fileName dir("particleListTest.dir");
    mkDir(dir);
    {
        OFstream os(dir/"x");
        os  << "FoamFile { version 2.0; format ascii; class vectorField;"
            << " object x; }" << nl
            << "2 ( (1 2 3) (4 5 6) )" << nl;
    }
    {
        OFstream os(dir/"U");
        os  << "2 ( (0 -3 0) (0 0 1) )" << nl;
    }
    {
        OFstream os(dir/"d");
        os  << "1 ( 7e-5 )" << nl;
    }

    const std::string path(cwd()/dir);
    const dictionary d = dictFrom
    (
        (
            "type particleList; SOI 0; particleType carrier;"
            "positions \"" + path + "/x\"; velocities \"" + path + "/U\";"
        ).c_str()
    );
    autoPtr<dpiInjectionModel> m = dpiInjectionModel::New("bed", d);

    DynamicList<injectionSpec> out;
    m->inject(0, 1e-5, out);
    ASSERT_EQ(out.size(), 2);
    EXPECT_EQ(out[1].position, point(4, 5, 6));
    EXPECT_EQ(out[0].U, vector(0, -3, 0));
    EXPECT_EQ(out[1].omega, vector::zero);
    EXPECT_EQ(out[0].type, "carrier");
    EXPECT_LT(out[0].d, 0) << "no diameters file: the type's diameter";

    // One diameter for two positions
    try
    {
        dictionary bad(d);
        bad.set("diameters", fileName(path + "/d"));
        dpiInjectionModel::New("bed", bad);
        FAIL() << "1 diameter for 2 positions accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("1 diameters but 2"), std::string::npos)
            << e.message();
    }

    // A missing file
    try
    {
        dictionary bad(d);
        bad.set("positions", fileName(path + "/nothing"));
        dpiInjectionModel::New("bed", bad);
        FAIL() << "missing positions file accepted";
    }
    catch (const Foam::error& e)
    {
        EXPECT_NE(std::string(e.message()).find("Cannot read file"), std::string::npos)
            << e.message();
    }

    rmDir(dir);
}
