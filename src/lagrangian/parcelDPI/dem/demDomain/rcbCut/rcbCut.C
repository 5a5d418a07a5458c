/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "rcbCut.H"
#include "PstreamCombineReduceOps.H"
#include "ListOps.H"
#include "SortableList.H"
#include "demDiagnostics.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rcbCut::maxContactWeight = 10;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::rcbCut::bisect
(
    const UList<point>& x,
    const UList<scalar>& w,
    labelList& pts,
    const label begin,
    const label end,
    const label p0,
    const label n,
    const boundBox& bb,
    DynamicList<label>& dir,
    DynamicList<scalar>& cut,
    DynamicList<label>& lower,
    DynamicList<label>& upper,
    DynamicList<label>& leafProc
)
{
    const label node = dir.size();
    dir.append(-1);
    cut.append(0);
    lower.append(-1);
    upper.append(-1);
    leafProc.append(p0);

    if (n == 1)
    {
        regions_[p0] = bb;
        return node;
    }

    // Across the longest extent of the points (of the box if none)
    boundBox ptsBb;
    for (label k = begin; k < end; ++k)
    {
        ptsBb.add(x[pts[k]]);
    }
    const vector span = (end > begin) ? ptsBb.span() : vector::one;
    direction d = 0;
    for (direction c = 1; c < 3; ++c)
    {
        if (span[c] > span[d])
        {
            d = c;
        }
    }

    // The points in order along d (ties by index: the same on every
    // processor, the tree is computed on the master only anyway)
    const label nA = n/2;
    const label count = end - begin;
    SortableList<scalar> coord(count);
    for (label k = 0; k < count; ++k)
    {
        coord[k] = x[pts[begin + k]][d];
    }
    coord.sort();   // sortedOrder: a stable sort
    labelList sorted(count);
    for (label k = 0; k < count; ++k)
    {
        sorted[k] = pts[begin + coord.indices()[k]];
    }
    for (label k = 0; k < count; ++k)
    {
        pts[begin + k] = sorted[k];
    }

    // The a/n quantile of the load: the lower part is the first kA points,
    // kA the count whose load sum is nearest a/n of the total (ties go up;
    // with unit loads kA = count a/n rounded, the parcel-count cut); the
    // cut halfway between the last point of the lower part and the first
    // of the upper one
    scalar total = 0;
    for (label k = 0; k < count; ++k)
    {
        total += w[pts[begin + k]];
    }
    const scalar target = total*nA/n;
    label kA = 0;
    scalar below = 0;
    while (kA < count)
    {
        const scalar next = below + w[pts[begin + kA]];
        if (next - target > target - below)
        {
            break;
        }
        below = next;
        ++kA;
    }
    scalar c;
    if (count == 0)
    {
        c = 0.5*(max(bb.min()[d], -1) + min(bb.max()[d], 1));
    }
    else if (kA <= 0)
    {
        c = coord[0] - SMALL;
    }
    else if (kA >= count)
    {
        c = coord[count - 1] + SMALL;
    }
    else
    {
        c = 0.5*(coord[kA - 1] + coord[kA]);
    }

    boundBox bbA(bb);
    boundBox bbB(bb);
    bbA.max()[d] = c;
    bbB.min()[d] = c;

    dir[node] = d;
    cut[node] = c;

    // Points exactly on the cut go up (owner() does the same)
    label kSplit = begin;
    while (kSplit < end && x[pts[kSplit]][d] < c)
    {
        ++kSplit;
    }

    const label a = bisect
    (
        x, w, pts, begin, kSplit, p0, nA, bbA, dir, cut, lower, upper, leafProc
    );
    const label b = bisect
    (
        x, w, pts, kSplit, end, p0 + nA, n - nA, bbB, dir, cut, lower, upper,
        leafProc
    );
    lower[node] = a;
    upper[node] = b;

    return node;
}


void Foam::rcbCut::updateWeight(const label nOwned)
{
    const scalar tContacts = engine_.timePair() + engine_.timeWall();
    const scalar tRows =
        engine_.timeNeighbour() + engine_.timeIntegrate()
      + engine_.timeExternal();
    const demDiagnostics& d = engine_.diagnostics();

    // This processor's last fluid step: its time in contacts and in rows,
    // its contacts and rows at the end of the step
    scalarList step(4);
    step[0] = tContacts - timeContacts0_;
    step[1] = tRows - timeRows0_;
    step[2] = d.nPairContacts + d.nWallContacts;
    step[3] = nOwned;
    timeContacts0_ = tContacts;
    timeRows0_ = tRows;
    // (gathered and scattered: every processor gets the same sums)
    Pstream::listCombineGather(step, plusEqOp<scalar>());
    Pstream::listCombineScatter(step);

    // Measured only with at least one contact per ten rows: the contact
    // time also holds the near pairs' checks, which with few contacts
    // would make the time per contact (and w) huge (237 in the first
    // steps of the full-size inhaler's bed)
    if (step[0] > 0 && step[1] > 0 && step[3] > 0 && step[2] >= 0.1*step[3])
    {
        // Time per contact over time per row, at most maxContactWeight;
        // smoothed, so that the timers' noise does not move the cut every
        // step
        const scalar w =
            min((step[0]/step[2])/(step[1]/step[3]), maxContactWeight);
        contactWeight_ =
            nWeightSamples_ ? 0.8*contactWeight_ + 0.2*w : w;
        ++nWeightSamples_;
    }
}


Foam::scalarList Foam::rcbCut::loads
(
    const demState& meshRows,
    const List<labelList>& keys
) const
{
    scalarList load(meshRows.owned(), scalar(1));
    forAll(load, i)
    {
        if (i < keys.size())
        {
            load[i] += contactWeight_*keys[i].size();
        }
    }
    return load;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rcbCut::rcbCut(const dictionary& demDict, const demEngine& engine)
:
    engine_(engine),
    // Set by readSettings below (its defaults: one place)
    maxImbalance_(0),
    contactWeight_(0),
    autoWeight_(false),
    timeContacts0_(0),
    timeRows0_(0),
    nWeightSamples_(0),
    dir_(),
    cut_(),
    lower_(),
    upper_(),
    leafProc_(),
    regions_(),
    repartition_(true),
    nPartitions_(0)
{
    readSettings(demDict, maxImbalance_, contactWeight_, autoWeight_);

    Info<< "DEM load balance: the DEM's own partition of the parcels (rcb),"
        << " a parcel's load 1 + w x its contacts, w = ";
    if (autoWeight_)
    {
        Info<< "the time per contact over the time per row (auto)";
    }
    else
    {
        Info<< contactWeight_;
    }
    Info<< ", re-partitioned when max/mean > " << maxImbalance_ << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rcbCut::readSettings
(
    const dictionary& demDict,
    scalar& maxImbalance,
    scalar& contactWeight,
    bool& autoWeight
)
{
    const dictionary lbDict(demDict.subOrEmptyDict("loadBalance"));


    maxImbalance = lbDict.getOrDefault<scalar>("maxImbalance", 1.1);
    if (!(maxImbalance >= 1))
    {
        FatalIOErrorInFunction(demDict)
            << "loadBalance/maxImbalance " << maxImbalance
            << " in dictionary " << demDict.name() << " must be >= 1"
            << " (max/mean of the load per processor; default 1.1)"
            << exit(FatalIOError);
    }

    // auto (measured; the parcel counts until the first measurement), or
    // a number >= 0
    autoWeight = true;
    contactWeight = 0;
    if (lbDict.found("contactWeight"))
    {
        ITstream& is = lbDict.lookup("contactWeight");
        const token t(is);
        if (t.isWord() && t.wordToken() == "auto")
        {
            autoWeight = true;
        }
        else if (t.isNumber() && t.number() >= 0)
        {
            autoWeight = false;
            contactWeight = t.number();
        }
        else
        {
            FatalIOErrorInFunction(demDict)
                << "loadBalance/contactWeight " << t
                << " in dictionary " << demDict.name() << " must be auto"
                << " or a number >= 0 (a parcel's load is 1 + w x its"
                << " contacts: auto takes w from the timers, 0 balances the"
                << " parcel counts; default auto)"
                << exit(FatalIOError);
        }
    }
}


Foam::scalarList Foam::rcbCut::start
(
    const demState& meshRows,
    const List<labelList>& keys,
    const label nOwned
)
{
    if (autoWeight_ && nPartitions_ > 0)
    {
        updateWeight(nOwned);
    }
    const scalarList load(loads(meshRows, keys));
    if (repartition_)
    {
        partition(meshRows, load);
    }
    return load;
}


void Foam::rcbCut::partition
(
    const demState& meshRows,
    const scalarList& load
)
{
    // All positions and loads to the master, which cuts; the tree to
    // everyone
    List<pointField> allX(Pstream::nProcs());
    allX[Pstream::myProcNo()] =
        pointField(SubList<point>(meshRows.x, meshRows.owned()));
    Pstream::gatherList(allX);
    List<scalarField> allW(Pstream::nProcs());
    allW[Pstream::myProcNo()] = load;
    Pstream::gatherList(allW);

    regions_.setSize(Pstream::nProcs());
    if (Pstream::master())
    {
        const pointField x(ListListOps::combine<pointField>
        (
            allX, accessOp<pointField>()
        ));
        const scalarField w(ListListOps::combine<scalarField>
        (
            allW, accessOp<scalarField>()
        ));
        labelList pts(identity(x.size()));

        DynamicList<label> dir, lower, upper, leafProc;
        DynamicList<scalar> cut;
        const scalar big = 0.1*GREAT;
        bisect
        (
            x, w, pts, 0, x.size(), 0, Pstream::nProcs(),
            boundBox(point::uniform(-big), point::uniform(big)),
            dir, cut, lower, upper, leafProc
        );
        dir_.transfer(dir);
        cut_.transfer(cut);
        lower_.transfer(lower);
        upper_.transfer(upper);
        leafProc_.transfer(leafProc);
    }
    Pstream::scatter(dir_);
    Pstream::scatter(cut_);
    Pstream::scatter(lower_);
    Pstream::scatter(upper_);
    Pstream::scatter(leafProc_);
    Pstream::scatter(regions_);

    repartition_ = false;
    ++nPartitions_;

    Info<< "    DEM partition " << nPartitions_ << ": "
        << returnReduce(meshRows.owned(), sumOp<label>())
        << " parcels cut into " << Pstream::nProcs() << " regions, a"
        << " parcel's load 1 + " << contactWeight_ << " x its contacts"
        << nl;
}


Foam::label Foam::rcbCut::owner(const point& x) const
{
    label node = 0;
    while (dir_[node] >= 0)
    {
        node = (x[dir_[node]] < cut_[node]) ? lower_[node] : upper_[node];
    }
    return leafProc_[node];
}


// ************************************************************************* //
