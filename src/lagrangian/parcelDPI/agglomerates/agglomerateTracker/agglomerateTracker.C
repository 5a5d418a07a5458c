/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "agglomerateTracker.H"
#include "demState.H"
#include "demMaterials.H"
#include "HashTable.H"
#include "Map.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "boundBox.H"

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
    DynamicList<labelPair>& pairs
) const
{
    pairs.clear();
    const label n = s.size();
    if (n < 2)
    {
        return;
    }

    scalar rMax = 0;
    boundBox bb(s.x, false);
    forAll(s.r, i)
    {
        rMax = max(rMax, s.r[i]);
    }

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
                    mag(s.x[a] - s.x[b]) - s.r[a] - s.r[b];
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
    labelList& agglomerateId
)
{
    const label n = s.size();

    DynamicList<labelPair> pairs;
    linkedPairs(s, pairs);

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

    // Per root: smallest globalId, size, carrier present, API primaries
    Map<label> minId(2*n);
    Map<label> size(2*n);
    Map<bool> hasCarrier(2*n);
    forAll(s.x, row)
    {
        const label root = findRoot(parent, row);
        const label gid = s.globalId[row];
        auto iter = minId.find(root);
        if (iter.found())
        {
            iter.val() = min(iter.val(), gid);
            ++size[root];
        }
        else
        {
            minId.insert(root, gid);
            size.insert(root, 1);
            hasCarrier.insert(root, false);
        }
        if (!materials.api(s.typeId[row]))
        {
            hasCarrier[root] = true;
        }
    }

    agglomerateId.setSize(n);
    stats_ = statistics();
    forAll(s.x, row)
    {
        const label root = findRoot(parent, row);
        agglomerateId[row] = minId[root];

        if (materials.api(s.typeId[row]))
        {
            stats_.apiPrimaries += s.N[row];
            if (size[root] == 1)
            {
                stats_.singletAPIPrimaries += s.N[row];
            }
            if (hasCarrier[root])
            {
                stats_.attachedAPIPrimaries += s.N[row];
            }
        }
    }

    stats_.nAgglomerates = minId.size();
    forAllConstIters(size, iter)
    {
        const label bin = sizeBin(iter.val());
        if (stats_.sizeHistogram.size() <= bin)
        {
            stats_.sizeHistogram.setSize(bin + 1, 0);
        }
        ++stats_.sizeHistogram[bin];
    }

    // Sums over processors (components are per processor for now)
    reduce(stats_.nAgglomerates, sumOp<label>());
    reduce(stats_.apiPrimaries, sumOp<scalar>());
    reduce(stats_.singletAPIPrimaries, sumOp<scalar>());
    reduce(stats_.attachedAPIPrimaries, sumOp<scalar>());
    label nBins = stats_.sizeHistogram.size();
    reduce(nBins, maxOp<label>());
    stats_.sizeHistogram.setSize(nBins, 0);
    Pstream::listCombineGather(stats_.sizeHistogram, plusEqOp<label>());
    Pstream::listCombineScatter(stats_.sizeHistogram);
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


// ************************************************************************* //
