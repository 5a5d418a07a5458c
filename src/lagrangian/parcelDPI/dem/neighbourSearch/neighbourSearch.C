/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "neighbourSearch.H"
#include "SortableList.H"
#include <algorithm>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// 21 bits per direction: 2 million cells across a level's grid
const Foam::label maxCellsPerDir = 2097151;

inline std::uint64_t cellKey
(
    const Foam::label i,
    const Foam::label j,
    const Foam::label k
)
{
    return
        (std::uint64_t(i) << 42) | (std::uint64_t(j) << 21)
      | std::uint64_t(k);
}

//- One size level: its cell size and its rows by cell
struct level
{
    Foam::scalar h = 0;
    Foam::scalar rMax = 0;

    // (cell key, row), sorted: a cell's rows are contiguous, and so are
    // the cells of one (i, j) column, k being the key's lowest bits
    std::vector<std::pair<std::uint64_t, Foam::label>> entries;
    // The entries' keys alone, searched
    std::vector<std::uint64_t> keys;
};


//- The first of the n sorted keys not below key. Without a branch on the
//  comparisons: in a sparse spray every particle's cell is new and these
//  searches were most of a build, their branches mispredicted half the time
inline Foam::label firstNotBelow
(
    const std::vector<std::uint64_t>& keys,
    const std::uint64_t key
)
{
    const std::uint64_t* base = keys.data();
    std::size_t n = keys.size();
    if (n == 0)
    {
        return 0;
    }
    while (n > 1)
    {
        const std::size_t half = n/2;
        base = (base[half] < key) ? base + half : base;
        n -= half;
    }
    return Foam::label(base - keys.data()) + (*base < key);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::neighbourSearch::neighbourSearch(const scalar skin)
:
    skin_(skin),
    nReleased_(0),
    nLevels_(0),
    nBuilds_(0),
    valid_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::neighbourSearch::needsRebuild
(
    const demState& s,
    const label firstRow
) const
{
    if (!valid_ || s.size() != x0_.size())
    {
        return true;
    }

    const scalar maxMove2 = sqr(0.5*skin_);

    for (label i = firstRow; i < x0_.size(); ++i)
    {
        if
        (
            s.key[i] != key0_[i]
         || magSqr(s.x[i] - x0_[i]) > maxMove2
        )
        {
            return true;
        }
    }

    return false;
}


void Foam::neighbourSearch::clear()
{
    valid_ = false;
    pairs_.clear();
}


void Foam::neighbourSearch::build(const demState& s, const scalar range)
{
    build(s, [range](const scalar, const scalar) { return range; });
}


void Foam::neighbourSearch::build
(
    const demState& s,
    const std::function<scalar(scalar, scalar)>& range
)
{
    build(s, s.r, range);
}


void Foam::neighbourSearch::build
(
    const demState& s,
    const UList<scalar>& radii,
    const std::function<scalar(scalar, scalar)>& range
)
{
    const label n = s.size();

    x0_ = s.x;
    key0_ = s.key;
    pairs_.clear();
    pairs_.reserve(nReleased_ + nReleased_/8);
    valid_ = true;
    ++nBuilds_;
    nLevels_ = 0;

    if (n < 2)
    {
        return;
    }

    // Size levels: a level spans radii up to twice its smallest radius
    SortableList<scalar> sortedR(radii);
    labelList levelOf(n);
    std::vector<level> levels;
    {
        scalar r0 = sortedR[0];
        levels.push_back(level());
        forAll(sortedR, k)
        {
            if (sortedR[k] > 2*r0)
            {
                r0 = sortedR[k];
                levels.push_back(level());
            }
            levelOf[sortedR.indices()[k]] = label(levels.size()) - 1;
            levels.back().rMax = sortedR[k];
        }
    }
    nLevels_ = label(levels.size());

    // Grid box from the particles themselves
    point lo(s.x[0]);
    for (const point& p : s.x)
    {
        lo = min(lo, p);
    }

    // A pair within reach has its smaller particle in this level or a finer
    // one, so its reach is at most that of two of this level's largest
    for (level& lev : levels)
    {
        lev.h = 2*lev.rMax + range(lev.rMax, lev.rMax) + skin_;
    }

    auto cellOf = [&](const point& p, const scalar h, label ijk[3])
    {
        for (direction d = 0; d < 3; ++d)
        {
            ijk[d] = label((p[d] - lo[d])/h);
            if (ijk[d] >= maxCellsPerDir - 1)
            {
                FatalErrorInFunction
                    << "The particles span " << (p[d] - lo[d])
                    << " m in direction " << label(d) << ", more than "
                    << maxCellsPerDir - 1 << " neighbour-search cells of "
                    << h << " m" << nl << "A particle far from the others "
                    << "(lost or diverging?) at " << p
                    << exit(FatalError);
            }
        }
    };

    for (label i = 0; i < n; ++i)
    {
        level& lev = levels[levelOf[i]];
        label ijk[3];
        cellOf(s.x[i], lev.h, ijk);
        lev.entries.push_back({cellKey(ijk[0], ijk[1], ijk[2]), i});
    }

    for (level& lev : levels)
    {
        std::sort(lev.entries.begin(), lev.entries.end());
        lev.keys.resize(lev.entries.size());
        for (std::size_t e = 0; e < lev.entries.size(); ++e)
        {
            lev.keys[e] = lev.entries[e].first;
        }
    }

    // Each particle looks into its own level (larger rows only, so each
    // pair once) and into every coarser level (all particles there).
    //
    // The three cells k - 1 .. k + 1 of each (i, j) column are one run of
    // the sorted entries: one search per column (9, not 27 hash lookups,
    // and no map to allocate per build). The particles are taken level by
    // level in the order of their cells, and a level's 9 runs are searched
    // again only when a particle's cell in it differs from the last one's:
    // rows in one cell share them, and so do the fine particles in one
    // coarse cell (the API coating a carrier), most of the searches. The
    // pairs found are the same (the half list orders them by key).
    struct column
    {
        std::vector<std::pair<std::uint64_t, label>>::const_iterator first;
        std::uint64_t hi;
    };
    struct runs
    {
        std::uint64_t cell = ~std::uint64_t(0);
        label n = 0;
        column c[9];
    };
    std::vector<runs> cache(nLevels_);

    for (label lp = 0; lp < nLevels_; ++lp)
    {
        for (runs& r : cache)
        {
            r.cell = ~std::uint64_t(0);
        }

        for (const auto& entry : levels[lp].entries)
        {
            const label p = entry.second;
            const point& xp = s.x[p];
            const scalar rp = radii[p];

            for (label L = lp; L < nLevels_; ++L)
            {
                const level& lev = levels[L];
                label ijk[3];
                cellOf(xp, lev.h, ijk);

                runs& r = cache[L];
                const std::uint64_t cell = cellKey(ijk[0], ijk[1], ijk[2]);
                if (cell != r.cell)
                {
                    r.cell = cell;
                    r.n = 0;
                    const label kLo = max(ijk[2] - 1, label(0));
                    const label kHi = ijk[2] + 1;
                    for (label i = ijk[0] - 1; i <= ijk[0] + 1; ++i)
                    {
                        if (i < 0) continue;
                        for (label j = ijk[1] - 1; j <= ijk[1] + 1; ++j)
                        {
                            if (j < 0) continue;
                            column& c = r.c[r.n++];
                            c.first =
                                lev.entries.begin()
                              + firstNotBelow(lev.keys, cellKey(i, j, kLo));
                            c.hi = cellKey(i, j, kHi);
                        }
                    }
                }

                for (label ci = 0; ci < r.n; ++ci)
                {
                    const column& c = r.c[ci];
                    for
                    (
                        auto e = c.first;
                        e != lev.entries.end() && e->first <= c.hi;
                        ++e
                    )
                    {
                        const label q = e->second;
                        if (L == lp && q <= p)
                        {
                            continue;
                        }

                        const scalar cut =
                            rp + radii[q] + range(rp, radii[q]) + skin_;
                        if (magSqr(xp - s.x[q]) < sqr(cut))
                        {
                            if (s.key[p] < s.key[q])
                            {
                                pairs_.append(labelPair(p, q));
                            }
                            else
                            {
                                pairs_.append(labelPair(q, p));
                            }
                        }
                    }
                }
            }
        }
    }
}


// ************************************************************************* //
