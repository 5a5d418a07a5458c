/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the injection models (what and when to inject)
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "dpiInjectionModel.H"
#include "mortonOrder.H"
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
    // Once injected the list is released (it is the whole list on every
    // processor): asked again for a window holding SOI, it has nothing left
    m->inject(2e-5, 3e-5, out);
    EXPECT_EQ(out.size(), 2) << "the list was kept after its injection";

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


// `order morton` lists an injector's batch along a Morton (Z-order) curve
// before the ids are given; entries of earlier injectors are left alone,
// points of one cell keep their order, `none` changes nothing, and an
// unknown order is refused naming the valid ones.
TEST(injectionOrder, mortonListsTheBatchAlongTheCurve)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // The eight cells of a 2 x 2 x 2 block (cell 1 m): Z-order takes x
    // fastest, then y, then z
    EXPECT_EQ(mortonOrder::code(0, 0, 0), 0u);
    EXPECT_EQ(mortonOrder::code(1, 0, 0), 1u);
    EXPECT_EQ(mortonOrder::code(0, 1, 0), 2u);
    EXPECT_EQ(mortonOrder::code(0, 0, 1), 4u);
    EXPECT_EQ(mortonOrder::code(2, 0, 0), 8u) << "the next level up";
    EXPECT_EQ(mortonOrder::code(3, 3, 3), 63u);

    // A batch of the block's cell centres listed from the last to the
    // first, and one more point in cell (0 0 0) listed after the others
    std::string text("type singleParticles; order morton; particles (");
    for (int c = 7; c >= 0; --c)
    {
        const int i = c & 1, j = (c >> 1) & 1, k = (c >> 2) & 1;
        text += "{ type carrier; position (" + std::to_string(i + 0.5) + " "
            + std::to_string(j + 0.5) + " " + std::to_string(k + 0.5)
            + "); d " + std::to_string(c + 1) + "; }";
    }
    text += "{ type carrier; position (0.25 0.25 0.25); d 9; });";
    autoPtr<dpiInjectionModel> m =
        dpiInjectionModel::New("bed", dictFrom(text.c_str()));

    DynamicList<injectionSpec> out;
    injectionSpec before;
    before.type = "earlier";
    before.position = point(9, 9, 9);
    out.append(before);
    m->inject(0, 1, out);
    ASSERT_EQ(out.size(), 10);
    m->order(out, 1, 1.0);

    EXPECT_EQ(out[0].type, "earlier") << "an earlier injector's entry moved";
    // Cell c is the (c+1)-th listed cell (d = c + 1); the extra point is in
    // cell 0 and was listed after the cell-0 centre, so it follows it
    // (on cells of 1 m from the batch's box, whose corner is (0.25 ...))
    const scalar expect[9] = {1, 9, 2, 3, 4, 5, 6, 7, 8};
    for (label r = 0; r < 9; ++r)
    {
        EXPECT_EQ(out[1 + r].d, expect[r]) << "row " << r;
    }

    // none (the default): the list as given
    const std::string asListed
    (
        "type singleParticles; particles ("
        "{ type carrier; position (1 1 1); } { type carrier; position (0 0 0); });"
    );
    autoPtr<dpiInjectionModel> plain =
        dpiInjectionModel::New("bed", dictFrom(asListed.c_str()));
    DynamicList<injectionSpec> listed;
    plain->inject(0, 1, listed);
    plain->order(listed, 0, 0.1);
    EXPECT_EQ(listed[0].position, point(1, 1, 1));

    try
    {
        const std::string bad("type singleParticles; order hilbert; particles ("
            "{ type carrier; position (0 0 0); });");
        dpiInjectionModel::New("bed", dictFrom(bad.c_str()));
        FAIL() << "order hilbert accepted";
    }
    catch (const Foam::error& e)
    {
        const std::string msg(e.message());
        EXPECT_NE(msg.find("hilbert"), std::string::npos) << msg;
        EXPECT_NE(msg.find("none morton"), std::string::npos) << msg;
    }
}


// ************************************************************************* //
