/*---------------------------------------------------------------------------*\
  dpiFoam: unit test of the contact-history store
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "contactHistory.H"
#include <map>
#include <random>

using namespace Foam;

namespace
{

// The store's meaning, written the plain way: a map from (owner, partner)
// to xi, where setHistory replaces all of an owner's contacts (the last of
// equal partners wins, a zero xi is no contact) and take removes them.
// Partners are ordered as the store's keys order them: as unsigned 32-bit
// numbers, so the walls' negative keys come after the particles
struct reference
{
    std::map<std::pair<label, std::uint32_t>, vector> m;

    void setHistory
    (
        const label owner,
        const labelUList& keys,
        const UList<vector>& xi
    )
    {
        take(owner);
        forAll(keys, i)
        {
            const std::pair<label, std::uint32_t> k(owner, keys[i]);
            if (xi[i] == vector::zero)
            {
                m.erase(k);
            }
            else
            {
                m[k] = xi[i];
            }
        }
    }

    void history
    (
        const label owner,
        DynamicList<label>& keys,
        DynamicList<vector>& xi
    ) const
    {
        for (const auto& e : m)
        {
            if (e.first.first == owner)
            {
                keys.append(label(std::int32_t(e.first.second)));
                xi.append(e.second);
            }
        }
    }

    void take(const label owner)
    {
        for (auto it = m.begin(); it != m.end();)
        {
            it = (it->first.first == owner) ? m.erase(it) : std::next(it);
        }
    }
};

} // End anonymous namespace


// Random edits and reads against the plain map. The store keeps the
// contacts of a setHistory unsorted until the next read and marks taken
// contacts instead of moving the rest: this checks that no sequence of
// calls tells it apart from the map (an owner given twice before a read,
// given nothing, equal partners in one call, zero xi, takes between sets)
TEST(contactHistory, storeMatchesAPlainMap)
{
    std::mt19937 gen(20261204);
    std::uniform_int_distribution<int> owner(0, 40);
    std::uniform_int_distribution<int> partner(-6, 40);
    std::uniform_int_distribution<int> count(0, 5);
    std::uniform_int_distribution<int> op(0, 9);
    std::uniform_real_distribution<double> value(-1, 1);

    for (int trial = 0; trial < 20; ++trial)
    {
        contactHistory h;
        reference ref;

        for (int step = 0; step < 400; ++step)
        {
            const int o = op(gen);
            const label id = owner(gen);
            if (o < 5)
            {
                const int n = count(gen);
                labelList keys(n);
                List<vector> xi(n);
                forAll(keys, i)
                {
                    keys[i] = partner(gen);
                    // One in five zero: not a contact
                    xi[i] = (count(gen) == 0)
                        ? vector::zero
                        : vector(value(gen), value(gen), value(gen));
                }
                h.setHistory(id, keys, xi);
                ref.setHistory(id, keys, xi);
            }
            else if (o < 7)
            {
                DynamicList<label> k1, k2;
                DynamicList<vector> x1, x2;
                h.take(id, k1, x1);
                ref.history(id, k2, x2);
                ref.take(id);
                ASSERT_EQ(k1, k2)
                    << "take, trial " << trial << " step " << step;
                ASSERT_EQ(x1, x2);
            }
            else if (o < 8)
            {
                DynamicList<label> k1, k2;
                DynamicList<vector> x1, x2;
                h.history(id, k1, x1);
                ref.history(id, k2, x2);
                ASSERT_EQ(k1, k2)
                    << "history, trial " << trial << " step " << step;
                ASSERT_EQ(x1, x2);
            }
            else if (o < 9)
            {
                const label p = partner(gen);
                const auto it =
                    ref.m.find(std::pair<label, std::uint32_t>(id, p));
                ASSERT_EQ
                (
                    h.find(id, p),
                    it == ref.m.end() ? vector::zero : it->second
                ) << "find, trial " << trial << " step " << step;
            }
            else
            {
                ASSERT_EQ(h.size(), label(ref.m.size()))
                    << "size, trial " << trial << " step " << step;
            }
        }

        h.clear();
        EXPECT_EQ(h.size(), 0);
    }
}


// ************************************************************************* //
