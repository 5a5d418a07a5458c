/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the DEM neighbour search and contact history
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    The hierarchical-grid Verlet list must hold every pair a brute-force
    O(n^2) search finds, for a random polydisperse cloud of carriers
    (70 um) and API (5 um), across moves, rebuilds and row reordering; and
    the contact history must survive a reordering of the demState rows
    (trajectories bit-identical to an unshuffled run), with the pairs swept
    in globalId or in Morton order.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "neighbourSearch.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <algorithm>
#include <random>
#include <set>
#include <sstream>
#include <utility>

using namespace Foam;

namespace
{

typedef std::set<std::pair<label, label>> pairSet;

// Pairs of globalIds with |x_i - x_j| < r_i + r_j + extra, by brute force
pairSet bruteForce(const demState& s, const scalar extra)
{
    pairSet result;
    for (label i = 0; i < s.size(); ++i)
    {
        for (label j = i + 1; j < s.size(); ++j)
        {
            if (mag(s.x[i] - s.x[j]) < s.r[i] + s.r[j] + extra)
            {
                result.insert
                (
                    {min(s.globalId[i], s.globalId[j]),
                     max(s.globalId[i], s.globalId[j])}
                );
            }
        }
    }
    return result;
}

// Listed pairs (as globalIds) that are within r_i + r_j + extra
pairSet listed(const neighbourSearch& ns, const demState& s, const scalar extra)
{
    pairSet result;
    for (const labelPair& p : ns.pairs())
    {
        const label i = p.first(), j = p.second();
        // Orientation: the first has the smaller globalId
        EXPECT_LT(s.globalId[i], s.globalId[j]);
        if (mag(s.x[i] - s.x[j]) < s.r[i] + s.r[j] + extra)
        {
            result.insert({s.globalId[i], s.globalId[j]});
        }
    }
    return result;
}

// 150 carriers (r = 35 um) and 1500 API (r = 2.5 um) in a 0.4 mm box:
// dense enough for thousands of carrier-API and many API-API pairs
demState randomCloud(std::mt19937& gen)
{
    std::uniform_real_distribution<scalar> u(0, 4e-4);
    demState s;
    label id = 0;
    for (label k = 0; k < 150; ++k)
    {
        s.append(point(u(gen), u(gen), u(gen)), Zero, Zero, 35e-6, 1, 1, 0,
                 id++);
    }
    for (label k = 0; k < 1500; ++k)
    {
        s.append(point(u(gen), u(gen), u(gen)), Zero, Zero, 2.5e-6, 1, 1, 1,
                 id++);
    }
    return s;
}

} // End anonymous namespace


// The list must equal the brute-force set within the list's own cut-off
// (r_i + r_j + skin: nothing missing, nothing extra), and keep every
// touching pair while all moves stay below skin/2; a larger move or a
// reordering of the rows must ask for a rebuild. Exact set comparisons:
// no tolerance is involved.
TEST(demNeighbourSearch, matchesBruteForcePolydisperse)
{
    std::mt19937 gen(12345);
    demState s(randomCloud(gen));

    const scalar skin = 4e-6;
    neighbourSearch ns(skin);

    EXPECT_TRUE(ns.needsRebuild(s));
    ns.build(s, 0);
    EXPECT_EQ(ns.nLevels(), 2);

    const pairSet bf(bruteForce(s, skin));
    EXPECT_GT(bf.size(), 1000u);
    EXPECT_EQ(listed(ns, s, skin), bf);

    // Moves below skin/2: no rebuild, and every touching pair is listed
    std::uniform_real_distribution<scalar> small(-0.28*skin, 0.28*skin);
    for (point& x : s.x)
    {
        x += vector(small(gen), small(gen), small(gen))/Foam::sqrt(3.0);
    }
    EXPECT_FALSE(ns.needsRebuild(s));
    EXPECT_EQ(listed(ns, s, 0), bruteForce(s, 0));

    // A larger move: rebuild, then equal again
    s.x[7] += vector(0.6*skin, 0, 0);
    EXPECT_TRUE(ns.needsRebuild(s));
    ns.build(s, 0);
    EXPECT_EQ(listed(ns, s, skin), bruteForce(s, skin));

    // Reordered rows: a rebuild is needed and gives the same set of ids
    demState t;
    labelList order(identity(s.size()));
    std::shuffle(order.begin(), order.end(), gen);
    for (const label i : order)
    {
        t.append(s.x[i], s.v[i], s.omega[i], s.r[i], s.m[i], s.N[i],
                 s.typeId[i], s.globalId[i]);
    }
    EXPECT_TRUE(ns.needsRebuild(t));
    ns.build(t, 0);
    EXPECT_EQ(listed(ns, t, skin), bruteForce(s, skin));

    // An interaction range (cohesion) widens the list accordingly
    ns.build(t, 3e-6);
    EXPECT_EQ(listed(ns, t, skin + 3e-6), bruteForce(s, skin + 3e-6));
}


namespace
{

// A 3 x 3 x 3 lattice of 2 mm spheres, slightly overlapping, with random
// velocities and spins, settling on a floor with friction and rolling
// resistance: many persistent pair and wall contacts with history
dictionary pileDeck
(
    const word& skin = "2e-4",
    const word& order = "globalId"
)
{
    IStringStream is
    (
        "timeStep 1e-5;"
        "types {"
        "  ball { diameter 2e-3; density 2400; youngsModulus 1e7;"
        "         poissonsRatio 0.22; }"
        "  wall { youngsModulus 1e7; poissonsRatio 0.22; }"
        "}"
        "pairs { default { restitution 0.5; friction 0.45;"
        "                  rollingFriction 0.05; } }"
        "normalModel hertzParcel;"
        "tangentialModel historyParcel;"
        "rollingModel cdt;"
        "cohesionModel none;"
        "walls { floor { type plane; point (0 0 0); normal (0 0 1);"
        "                material wall; } }"
        "neighbourSearch { skin " + skin + "; order " + order + "; }"
        "timeStepCheck { maxImpactVelocity 0.2; }"
    );
    return dictionary(is);
}

demState pile()
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(-1, 1);
    const scalar m = 2400*constant::mathematical::pi/6*pow3(2e-3);

    demState s;
    label id = 100;
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            for (label k = 0; k < 3; ++k)
            {
                s.append
                (
                    point(i*1.9999e-3, j*1.9999e-3, 0.9999e-3 + k*1.9999e-3),
                    0.01*vector(u(gen), u(gen), u(gen)),
                    50*vector(u(gen), u(gen), u(gen)),
                    1e-3, m, 1, 0, id
                );
                id += 3;
            }
        }
    }
    return s;
}

// The rows of s in a seeded random order (row k is s's row order[k]);
// forces zero and keys the globalIds, as a fresh copy of the parcels
demState shuffledRows(const demState& s, labelList& order)
{
    std::mt19937 gen(99);
    order = identity(s.size());
    std::shuffle(order.begin(), order.end(), gen);
    demState shuffled;
    for (const label i : order)
    {
        shuffled.append(s.x[i], s.v[i], s.omega[i], s.r[i], s.m[i],
                        s.N[i], s.typeId[i], s.globalId[i]);
    }
    return shuffled;
}

// Row i of sa (engine ea) and row j of sb (engine eb) hold the same
// particle in the same state, to the bit, with the same contact history
void expectSameRow
(
    const demEngine& ea,
    const demState& sa,
    const label i,
    const demEngine& eb,
    const demState& sb,
    const label j
)
{
    ASSERT_EQ(sa.globalId[i], sb.globalId[j]);
    EXPECT_EQ(sa.x[i], sb.x[j]);
    EXPECT_EQ(sa.v[i], sb.v[j]);
    EXPECT_EQ(sa.omega[i], sb.omega[j]);

    DynamicList<label> ka, kb;
    DynamicList<vector> xa, xb;
    ea.history(sa.globalId[i], ka, xa);
    eb.history(sb.globalId[j], kb, xb);
    EXPECT_EQ(ka, kb);
    EXPECT_EQ(xa, xb);
}

} // End anonymous namespace


// Two identical runs; one has its rows shuffled between two evolve() calls.
// Histories are keyed by globalId and the per-particle sums are ordered by
// partner id, so the shuffled run must reproduce the other bit for bit
// (EXPECT_EQ on doubles, no tolerance), and the stored histories must agree.
TEST(demNeighbourSearch, historySurvivesRowReordering)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    demEngine a(pileDeck());
    demEngine b(pileDeck());
    demState sa(pile());
    demState sb(pile());

    const vector g(0, 0, -9.81);
    a.evolve(sa, 200*1e-5, g);
    b.evolve(sb, 200*1e-5, g);

    // Contacts with history exist (pairs and wall)
    EXPECT_GT(a.nHistory(), 20);
    EXPECT_GT(a.diagnostics().nWallContacts, 0);

    // Shuffle b's rows
    labelList order;
    demState shuffled(shuffledRows(sb, order));

    a.evolve(sa, 300*1e-5, g);
    b.evolve(shuffled, 300*1e-5, g);

    for (label i = 0; i < sa.size(); ++i)
    {
        expectSameRow(a, sa, i, b, shuffled, order.find(i));
    }
    EXPECT_EQ(a.nHistory(), b.nHistory());
}


// With neighbourSearch/order morton the pairs are swept, and summed, in
// the order of the rows' keys (a Morton code of the position above the
// globalId, set at each fluid step's start: demEngine::orderRows), so the
// result still does not depend on the row order (EXPECT_EQ on doubles).
// The keys put some pairs' first row at the larger globalId (checked, or
// the test would not differ from the one above): their springs are the
// opposite of the stored ones, and must come back so after the rebuild
// that the shuffle causes.
TEST(demNeighbourSearch, mortonSweepIndependentOfRowOrder)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    demEngine a(pileDeck("2e-4", "morton"));
    demEngine b(pileDeck("2e-4", "morton"));
    ASSERT_TRUE(a.alongCurve());
    // The pile numbered against its curve (ids falling along x, y, z)
    demState sa(pile());
    for (label& id : sa.globalId)
    {
        id = 226 - id;
    }
    demState sb(sa);

    const vector g(0, 0, -9.81);
    a.orderRows(sa);
    b.orderRows(sb);
    a.evolve(sa, 200*1e-5, g);
    b.evolve(sb, 200*1e-5, g);
    EXPECT_GT(a.nHistory(), 20);

    // Keys: unique, the globalId in the lower 31 bits
    std::set<uint64_t> keys(sa.key.begin(), sa.key.end());
    EXPECT_EQ(label(keys.size()), sa.size());
    forAll(sa.key, i)
    {
        EXPECT_EQ(label(sa.key[i] & ((uint64_t(1) << 31) - 1)), sa.globalId[i]);
    }
    // Touching pairs whose keys and globalIds disagree on the first row
    label reversed = 0;
    for (label i = 0; i < sa.size(); ++i)
    {
        for (label j = i + 1; j < sa.size(); ++j)
        {
            reversed +=
                mag(sa.x[i] - sa.x[j]) < sa.r[i] + sa.r[j]
             && (sa.key[i] < sa.key[j]) != (sa.globalId[i] < sa.globalId[j]);
        }
    }
    EXPECT_GT(reversed, 0) << "no touching pair swept from its larger id";
    labelList order;
    demState shuffled(shuffledRows(sb, order));

    // The next fluid step's keys, from the positions it starts from
    a.orderRows(sa);
    b.orderRows(shuffled);
    a.evolve(sa, 300*1e-5, g);
    b.evolve(shuffled, 300*1e-5, g);

    for (label i = 0; i < sa.size(); ++i)
    {
        expectSameRow(a, sa, i, b, shuffled, order.find(i));
    }
    EXPECT_EQ(a.nHistory(), b.nHistory());

    // The same pile swept in globalId order: the sums come in another
    // order, so the two differ by round-off only, which 500 steps of a
    // settling pile leave far below 1e-12 of a ball's diameter (measured:
    // ~1e-19 m); a spring of the wrong sign would move the balls by
    // micrometres
    demEngine c(pileDeck());
    demState sc(pile());
    for (label& id : sc.globalId)
    {
        id = 226 - id;
    }
    c.evolve(sc, 200*1e-5, g);
    c.evolve(sc, 300*1e-5, g);
    scalar maxDiff = 0;
    forAll(sc.x, i)
    {
        maxDiff = max(maxDiff, mag(sc.x[i] - sa.x[i]));
    }
    EXPECT_LT(maxDiff, 1e-12*2e-3);
}


// The history can be taken out and put back (restart): a fresh engine
// given the stored histories continues exactly like the original.
TEST(demNeighbourSearch, historyRestartRoundTrip)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    demEngine a(pileDeck());
    demState sa(pile());
    const vector g(0, 0, -9.81);
    a.evolve(sa, 200*1e-5, g);

    demEngine b(pileDeck());
    demState sb(sa);
    for (const label id : sa.globalId)
    {
        DynamicList<label> keys;
        DynamicList<vector> xi;
        a.history(id, keys, xi);
        b.setHistory(id, keys, xi);
    }
    EXPECT_EQ(a.nHistory(), b.nHistory());

    // b re-evaluates the starting forces (it has no cached forces); the
    // trial step of a re-evaluation equals the stored step for contacts in
    // the sliding branch only, so compare with a tolerance: the two runs
    // must agree to ~1e-9 of the particle size after 100 steps
    a.evolve(sa, 100*1e-5, g);
    b.evolve(sb, 100*1e-5, g);
    for (label i = 0; i < sa.size(); ++i)
    {
        EXPECT_LT(mag(sa.x[i] - sb.x[i]), 1e-3*1e-6);
    }
}


// A row in no listed pair and beyond its reach plus the skin of every wall
// cannot touch anything before the next search, so the near list does not
// follow it (pairContacts::tracked_): a fast ball far from the pile must
// neither size the near skin nor trigger near builds, and must leave the
// pile's trajectories as they are to the bit. Balls falling onto the floor
// from out of the walls' skin must still meet it: the search that sees them
// within reach puts them back under the near list, so their bounce is that
// of a run whose skin holds everything (EXPECT_EQ on doubles).
TEST(demNeighbourSearch, isolatedFastRowSetsNoNearPace)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar m = 2400*constant::mathematical::pi/6*pow3(2e-3);
    const vector g(0, 0, -9.81);
    const scalar Dt = 500*1e-5;

    // The pile alone, and with a ball 50 mm away crossing at 0.8 m/s
    // (4 mm in the run: below half the 10 mm skin, so no new search)
    demEngine a(pileDeck("1e-2"));
    demEngine b(pileDeck("1e-2"));
    demState sa(pile());
    demState sb(pile());
    sb.append(point(0.05, 0.05, 0.02), vector(0.8, 0, 0), Zero, 1e-3, m, 1, 0,
              1000);
    a.evolve(sa, Dt, g);
    b.evolve(sb, Dt, g);

    EXPECT_EQ(a.neighbours().nBuilds(), b.neighbours().nBuilds());
    EXPECT_EQ(a.nNearBuilds(), b.nNearBuilds());
    for (label i = 0; i < sa.size(); ++i)
    {
        EXPECT_EQ(sa.x[i], sb.x[i]);
        EXPECT_EQ(sa.v[i], sb.v[i]);
        EXPECT_EQ(sa.omega[i], sb.omega[i]);
    }

    // Balls far from the pile falling onto the floor at 2.5 m/s: one
    // within the walls' reach plus skin at the start (centre 7 mm up), one
    // beyond it (12 mm up; the search after it has fallen half the skin
    // finds the floor). With skin 0.1 m every ball is followed throughout.
    demEngine c(pileDeck("1e-2"));
    demEngine d(pileDeck("1e-1"));
    demState sc(pile());
    sc.append(point(0.05, 0.0, 0.007), vector(0, 0, -2.5), Zero, 1e-3, m, 1, 0,
              1001);
    sc.append(point(0.0, 0.05, 0.012), vector(0, 0, -2.5), Zero, 1e-3, m, 1, 0,
              1002);
    demState sd(sc);
    c.evolve(sc, Dt, g);
    d.evolve(sd, Dt, g);

    for (label i = sc.size() - 2; i < sc.size(); ++i)
    {
        // Bounced: the floor was met
        EXPECT_GT(sc.v[i].z(), 0) << "ball " << sc.globalId[i];
        EXPECT_EQ(sc.x[i], sd.x[i]);
        EXPECT_EQ(sc.v[i], sd.v[i]);
        EXPECT_EQ(sc.omega[i], sd.omega[i]);
    }
}


// ************************************************************************* //


// Which pairs and wall elements are visited must not change a bit: a pair
// out of range adds nothing and its history is cleared when it separates
// (theory 1.6). The skin decides the Verlet list, the near skin derived
// from it (pairContacts::buildNear), the wall candidates and how often all
// are rebuilt; three skins from a hundredth of a radius (rebuilds every
// few steps) to more than the pile (never) must give the same states and
// histories, compared with EXPECT_EQ on doubles (no tolerance).
TEST(demNeighbourSearch, resultIndependentOfSkin)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const wordList skins({"1e-5", "2e-4", "1e-2"});
    List<demState> states(skins.size(), pile());
    PtrList<demEngine> engines(skins.size());
    const vector g(0, 0, -9.81);

    forAll(skins, e)
    {
        engines.set(e, new demEngine(pileDeck(skins[e])));
        engines[e].evolve(states[e], 500*1e-5, g);
    }

    // Contacts with history exist, and the small skin rebuilt its list
    EXPECT_GT(engines[0].nHistory(), 20);
    EXPECT_GT(engines[0].diagnostics().nWallContacts, 0);
    EXPECT_GT(engines[0].neighbours().nBuilds(), engines[2].neighbours().nBuilds());

    for (label e = 1; e < skins.size(); ++e)
    {
        const demState& a = states[0];
        const demState& b = states[e];
        SCOPED_TRACE("skin " + skins[e]);
        for (label i = 0; i < a.size(); ++i)
        {
            expectSameRow(engines[0], a, i, engines[e], b, i);
        }
        EXPECT_EQ(engines[0].nHistory(), engines[e].nHistory());
    }
}
