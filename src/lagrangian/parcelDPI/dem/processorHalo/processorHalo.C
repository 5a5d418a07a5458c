/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "demState.H"
#include "demEngine.H"
#include "PstreamBuffers.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::processorHalo::processorHalo()
:
    homeBox_(boundBox::invertedBox),
    sendRows_(Pstream::nProcs()),
    recvStart_(Pstream::nProcs(), 0),
    recvSize_(Pstream::nProcs(), 0),
    range_(0),
    margin_(0),
    engine_(nullptr),
    x0_(),
    stepsLeft_(labelMax),
    nBuilds_(0),
    nRebuilds_(0),
    warned_(false)
{}


Foam::processorHalo::processorHalo(const polyMesh& mesh)
:
    processorHalo()
{
    homeBox_ = boundBox(mesh.points(), false);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::processorHalo::send(demState& s)
{
    const label nOwned = s.size();
    s.nOwned = nOwned;
    x0_ = SubList<point>(s.x, nOwned);
    ++nBuilds_;

    // The box of each processor's owned parcels and home (none: an
    // inverted box, which contains nothing however far it is grown)
    List<boundBox> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = homeBox_;
    boxes[Pstream::myProcNo()].add(x0_);
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);

    // The sub-steps this halo serves: two parcels at 1.5 x the fastest
    // speed now (moderate acceleration, as the margin was chosen) close
    // at most the margin (a fixed count, the same on every processor: no
    // collective at the sub-steps in between)
    scalar v2Max = 0;
    for (label p = 0; p < nOwned; ++p)
    {
        v2Max = max(v2Max, magSqr(s.v[p]));
    }
    reduce(v2Max, maxOp<scalar>());
    stepsLeft_ = labelMax;
    if (engine_ && v2Max > 0)
    {
        // (1e-6: a margin made for the whole fluid step serves all of it,
        // whatever the rounding of the quotient)
        const scalar steps =
            margin_/(3*sqrt(v2Max)*engine_->timeStep()) + 1e-6;
        if (steps < labelMax)
        {
            stepsLeft_ = max(label(1), label(steps));
        }
    }

    const scalar reach = range_ + margin_;
    forAll(sendRows_, proci)
    {
        DynamicList<label> rows;
        if (proci != Pstream::myProcNo())
        {
            boundBox bb(boxes[proci]);
            bb.min() -= vector::uniform(reach);
            bb.max() += vector::uniform(reach);
            for (label p = 0; p < nOwned; ++p)
            {
                if (bb.contains(s.x[p]))
                {
                    rows.append(p);
                }
            }
        }
        sendRows_[proci].transfer(rows);
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    DynamicList<label> keys;
    DynamicList<vector> xi;
    forAll(sendRows_, proci)
    {
        const labelList& rows = sendRows_[proci];
        if (rows.empty())
        {
            continue;
        }
        UOPstream os(proci, pBufs);
        s.writeRows(os, rows);
        // The owner's sweep keys: within a fluid step they are no longer
        // those of the ghosts' positions (demEngine::orderRows)
        os  << List<uint64_t>(UIndirectList<uint64_t>(s.key, rows));
        os  << (engine_ != nullptr);
        if (engine_)
        {
            List<labelList> allKeys(rows.size());
            List<List<vector>> allXi(rows.size());
            forAll(rows, k)
            {
                keys.clear();
                xi.clear();
                engine_->history(s.globalId[rows[k]], keys, xi);
                allKeys[k] = keys;
                allXi[k] = xi;
            }
            os  << allKeys << allXi;
        }
    }

    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    recvStart_ = s.size();
    recvSize_ = 0;
    forAll(recvSizes, proci)
    {
        if (!recvSizes[proci] || proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        // Not integrated here: their forces (zero) are never used
        const label start = s.size();
        recvStart_[proci] = start;
        recvSize_[proci] = s.readRows(is);
        const List<uint64_t> sweepKeys(is);
        forAll(sweepKeys, k)
        {
            s.key[start + k] = sweepKeys[k];
        }
        const labelList globalId
        (
            SubList<label>(s.globalId, recvSize_[proci], start)
        );

        bool withHistory = false;
        is  >> withHistory;
        if (withHistory && engine_)
        {
            const List<labelList> allKeys(is);
            const List<List<vector>> allXi(is);
            label nXi = 0;
            forAll(allXi, k)
            {
                nXi += allXi[k].size();
            }
            engine_->reserveHistory(nXi);
            forAll(globalId, k)
            {
                engine_->setHistory(globalId[k], allKeys[k], allXi[k]);
            }
        }
    }
}


void Foam::processorHalo::rebuild(demState& s)
{
    // The margin assumed no parcel would travel more than half of it
    // before now: checked (a parcel accelerated harder may have missed a
    // contact across a processor boundary, which serial would not)
    const label nOwned = s.owned();
    scalar travel2 = 0;
    for (label p = 0; p < nOwned; ++p)
    {
        travel2 = max(travel2, magSqr(s.x[p] - x0_[p]));
    }
    reduce(travel2, maxOp<scalar>());
    if (travel2 > sqr(0.5*margin_) && !warned_)
    {
        WarningInFunction
            << "A parcel travelled " << sqrt(travel2) << " m since the DEM "
            << "halo was built, more than half its margin " << margin_
            << " m (from 1.5 x the fastest speed then): contacts across "
            << "processor boundaries may have been missed. Not repeated."
            << endl;
        warned_ = true;
    }

    // The ghosts go, their owners send them again at their new positions.
    // The engine's working history is written back first (so the
    // histories sent are current) and its lists rebuilt at the next
    // evaluation (the rows have changed)
    if (engine_)
    {
        engine_->editHistory();
    }
    s.resize(nOwned);
    ++nRebuilds_;
    send(s);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::processorHalo::build
(
    demState& s,
    const scalar range,
    const scalar margin,
    demEngine* engine
)
{
    range_ = range;
    margin_ = margin;
    engine_ = engine;
    send(s);
}


void Foam::processorHalo::update(demState& s)
{
    if (stepsLeft_-- == 0)
    {
        rebuild(s);
        return;
    }

    // Every sub-step: the sizes are known on both sides since the build, so
    // the values go as raw doubles, receives posted first, without the
    // size exchange and stream encoding of PstreamBuffers (a collective
    // all-to-all per call: it was most of the halo's cost)
    const label nProcs = Pstream::nProcs();
    sendBuf_.setSize(nProcs);
    recvBuf_.setSize(nProcs);
    const int tag = UPstream::msgType();
    const label startRequest = UPstream::nRequests();

    forAll(recvSize_, proci)
    {
        if (recvSize_[proci])
        {
            scalarList& buf = recvBuf_[proci];
            buf.setSize(9*recvSize_[proci]);
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking, proci,
                reinterpret_cast<char*>(buf.data()), buf.byteSize(), tag
            );
        }
    }

    forAll(sendRows_, proci)
    {
        const labelList& rows = sendRows_[proci];
        if (rows.empty())
        {
            continue;
        }
        scalarList& buf = sendBuf_[proci];
        buf.setSize(9*rows.size());
        label k = 0;
        for (const label row : rows)
        {
            for (const vector* w : {&s.x[row], &s.v[row], &s.omega[row]})
            {
                buf[k++] = w->x();
                buf[k++] = w->y();
                buf[k++] = w->z();
            }
        }
        UOPstream::write
        (
            UPstream::commsTypes::nonBlocking, proci,
            reinterpret_cast<const char*>(buf.cdata()), buf.byteSize(), tag
        );
    }

    UPstream::waitRequests(startRequest);

    forAll(recvSize_, proci)
    {
        const scalarList& buf = recvBuf_[proci];
        const label start = recvStart_[proci];
        label k = 0;
        for (label row = start; row < start + recvSize_[proci]; ++row)
        {
            for (vector* w : {&s.x[row], &s.v[row], &s.omega[row]})
            {
                w->x() = buf[k++];
                w->y() = buf[k++];
                w->z() = buf[k++];
            }
        }
    }
}


Foam::label Foam::processorHalo::nGhosts() const
{
    label n = 0;
    forAll(recvSize_, proci)
    {
        n += recvSize_[proci];
    }
    return n;
}


// ************************************************************************* //
