/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "agglomerateTracker.H"
#include "dictKeys.H"
#include "demState.H"
#include "demMaterials.H"
#include "HashTable.H"
#include "Map.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "boundBox.H"
#include "processorHalo.H"
#include "PstreamCombineReduceOps.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- Root of a union-find forest with path halving
    Foam::label findRoot(Foam::labelList& parent, Foam::label i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }

    //- Histogram bin of a component of n parcels: 1, 2, 3-4, 5-8, ...
    Foam::label sizeBin(const Foam::label n)
    {
        Foam::label bin = 0;
        Foam::label upper = 1;
        while (n > upper)
        {
            upper *= 2;
            ++bin;
        }
        return bin;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::agglomerateTracker::linkedPairs
(
    const demState& s,
    const demMaterials& materials,
    DynamicList<labelPair>& pairs
) const
{
    pairs.clear();
    const label n = s.size();
    if (n < 2)
    {
        return;
    }

    // The contact radii: API parcels that meet each other at grown radii
    // (coarseGrainingModel) are linked where their grown radii touch, as
    // in the engine
    const coarseGrainingModel& cg = materials.coarseGraining();
    const scalar rMax = cg.maxRadius(s.r, s.typeId);
    boundBox bb(s.x, false);

    // Any linked pair has centres closer than 2 rMax + linkGap: with cells
    // at least that size, partners are in the 27 surrounding cells
    const scalar h = max(2*rMax + linkGap_, VSMALL);
    const vector span(bb.span());
    const label nx = max(1, label(span.x()/h) + 1);
    const label ny = max(1, label(span.y()/h) + 1);
    const label nz = max(1, label(span.z()/h) + 1);

    auto cellOf = [&](const point& x, label& i, label& j, label& k)
    {
        i = min(nx - 1, label((x.x() - bb.min().x())/h));
        j = min(ny - 1, label((x.y() - bb.min().y())/h));
        k = min(nz - 1, label((x.z() - bb.min().z())/h));
    };

    // Sparse grid: cell key -> rows (the box can be large and mostly empty)
    Map<DynamicList<label>> cells(2*n);
    forAll(s.x, row)
    {
        label i, j, k;
        cellOf(s.x[row], i, j, k);
        cells(i + nx*(j + ny*k)).append(row);
    }

    forAll(s.x, a)
    {
        label i, j, k;
        cellOf(s.x[a], i, j, k);
        for (label dk = -1; dk <= 1; ++dk)
        for (label dj = -1; dj <= 1; ++dj)
        for (label di = -1; di <= 1; ++di)
        {
            const label ci = i + di, cj = j + dj, ck = k + dk;
            if
            (
                ci < 0 || cj < 0 || ck < 0
             || ci >= nx || cj >= ny || ck >= nz
            )
            {
                continue;
            }
            const auto iter = cells.cfind(ci + nx*(cj + ny*ck));
            if (!iter.found())
            {
                continue;
            }
            for (const label b : iter.val())
            {
                if (b <= a)
                {
                    continue;
                }
                const scalar gap =
                    mag(s.x[a] - s.x[b])
                  - cg.radiusSum(s.r[a], s.typeId[a], s.r[b], s.typeId[b]);
                if (gap < linkGap_)
                {
                    pairs.append(labelPair(a, b));
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::agglomerateTracker::agglomerateTracker
(
    const dictionary& dict,
    const fileName& dir
)
:
    linkGap_(dict.lookupOrDefault<scalar>("linkGap", 0)),
    file_(nullptr),
    stats_()
{
    // The one key read above
    dictKeys::warnUnknown(dict, {"linkGap"});

    if (!dir.empty() && Pstream::master())
    {
        mkDir(dir);
        file_.reset(new OFstream(dir/"agglomerates.dat"));
        file_().precision(10);
        file_()
            << "# Agglomerates (connected components, link gap "
            << linkGap_ << " m), API counted in primaries (sum of N)" << nl
            << "# time nAgglomerates apiPrimaries singletAPIPrimaries"
            << " attachedAPIPrimaries histogram(1 2 3-4 5-8 ... parcels)"
            << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::agglomerateTracker::update
(
    const demState& s,
    const demMaterials& materials,
    labelList& agglomerateId,
    const processorHalo* halo
)
{
    const label n = s.size();
    const label nOwned = s.owned();

    DynamicList<labelPair> pairs;
    linkedPairs(s, materials, pairs);

    labelList parent(identity(n));
    for (const labelPair& pr : pairs)
    {
        const label ra = findRoot(parent, pr.first());
        const label rb = findRoot(parent, pr.second());
        if (ra != rb)
        {
            parent[max(ra, rb)] = min(ra, rb);
        }
    }

    labelList root(n);
    labelList localSize(n, 0);
    forAll(root, row)
    {
        root[row] = findRoot(parent, row);
        ++localSize[root[row]];
    }

    // Labels per row: smallest globalId, and 1 if a carrier is in the
    // component. Locally: min/max over the component's rows; in parallel
    // the ghosts' labels come from their owners, which may know more
    agglomerateId = s.globalId;
    labelList carrier(n, 0);
    forAll(carrier, row)
    {
        carrier[row] = materials.api(s.typeId[row]) ? 0 : 1;
    }

    while (true)
    {
        labelList minId(n, labelMax);
        labelList anyCarrier(n, 0);
        forAll(root, row)
        {
            minId[root[row]] = min(minId[root[row]], agglomerateId[row]);
            anyCarrier[root[row]] = max(anyCarrier[root[row]], carrier[row]);
        }

        bool changed = false;
        forAll(root, row)
        {
            const label r = root[row];
            if (agglomerateId[row] != minId[r] || carrier[row] != anyCarrier[r])
            {
                changed = true;
            }
            agglomerateId[row] = minId[r];
            carrier[row] = anyCarrier[r];
        }

        if (!halo)
        {
            break;
        }

        // Owners' labels to the ghosts; stop when no processor changed
        halo->exchange(agglomerateId);
        halo->exchange(carrier);
        if (!returnReduce(changed, orOp<bool>()))
        {
            break;
        }
    }

    stats_ = statistics();

    // Size of each component over all processors: owned rows per id
    Map<label> size;
    for (label row = 0; row < nOwned; ++row)
    {
        size(agglomerateId[row]) += 1;

        if (materials.api(s.typeId[row]))
        {
            stats_.apiPrimaries += s.N[row];
            // Alone in its component: no link to any row, ghosts included
            if (localSize[root[row]] == 1)
            {
                stats_.singletAPIPrimaries += s.N[row];
            }
            if (carrier[row])
            {
                stats_.attachedAPIPrimaries += s.N[row];
            }
        }
    }
    Pstream::mapCombineGather(size, plusEqOp<label>());

    stats_.nAgglomerates = size.size();
    forAllConstIters(size, iter)
    {
        const label bin = sizeBin(iter.val());
        if (stats_.sizeHistogram.size() <= bin)
        {
            stats_.sizeHistogram.setSize(bin + 1, 0);
        }
        ++stats_.sizeHistogram[bin];
    }

    // The counts and the histogram are on the master; sums of the rest
    Pstream::scatter(stats_.nAgglomerates);
    Pstream::scatter(stats_.sizeHistogram);
    reduce(stats_.apiPrimaries, sumOp<scalar>());
    reduce(stats_.singletAPIPrimaries, sumOp<scalar>());
    reduce(stats_.attachedAPIPrimaries, sumOp<scalar>());
}


void Foam::agglomerateTracker::write(const scalar t)
{
    if (file_.valid())
    {
        OFstream& os = file_();
        os  << t << ' ' << stats_.nAgglomerates
            << ' ' << stats_.apiPrimaries
            << ' ' << stats_.singletAPIPrimaries
            << ' ' << stats_.attachedAPIPrimaries;
        forAll(stats_.sizeHistogram, bin)
        {
            os  << ' ' << stats_.sizeHistogram[bin];
        }
        os  << endl;
    }
}


Foam::Map<Foam::label> Foam::agglomerateTracker::members
(
    const labelUList& agglomerateId
)
{
    Map<label> n(2*agglomerateId.size() + 1);
    for (const label id : agglomerateId)
    {
        ++n(id, 0);
    }
    Pstream::mapCombineGather(n, plusEqOp<label>());
    Pstream::mapCombineScatter(n);
    return n;
}


Foam::agglomerateTracker::composition Foam::agglomerateTracker::compose
(
    const labelUList& agglomerateId,
    const scalarUList& d,
    const scalarUList& rho,
    const boolUList& carrier
)
{
    composition c;
    c.parcels = members(agglomerateId);
    forAll(agglomerateId, i)
    {
        const label id = agglomerateId[i];
        const scalar v = constant::mathematical::pi/6*pow3(d[i]);
        c.volume(id, 0) += v;
        c.mass(id, 0) += rho[i]*v;
        c.carriers(id, 0) += carrier[i] ? 1 : 0;
    }
    Pstream::mapCombineGather(c.volume, plusEqOp<scalar>());
    Pstream::mapCombineScatter(c.volume);
    Pstream::mapCombineGather(c.mass, plusEqOp<scalar>());
    Pstream::mapCombineScatter(c.mass);
    Pstream::mapCombineGather(c.carriers, plusEqOp<label>());
    Pstream::mapCombineScatter(c.carriers);
    return c;
}


// ************************************************************************* //
