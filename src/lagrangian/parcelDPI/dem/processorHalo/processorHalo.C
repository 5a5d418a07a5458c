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

Foam::processorHalo::processorHalo(const polyMesh& mesh)
:
    procBb_(Pstream::nProcs()),
    sendRows_(Pstream::nProcs()),
    recvStart_(Pstream::nProcs(), 0),
    recvSize_(Pstream::nProcs(), 0)
{
    procBb_[Pstream::myProcNo()] = boundBox(mesh.points(), false);
    Pstream::gatherList(procBb_);
    Pstream::scatterList(procBb_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::processorHalo::build
(
    demState& s,
    const scalar reach,
    demEngine* engine
)
{
    const label nOwned = s.size();
    s.nOwned = nOwned;

    forAll(sendRows_, proci)
    {
        DynamicList<label> rows;
        if (proci != Pstream::myProcNo())
        {
            boundBox bb(procBb_[proci]);
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
        os  << (engine != nullptr);
        if (engine)
        {
            List<labelList> allKeys(rows.size());
            List<List<vector>> allXi(rows.size());
            forAll(rows, k)
            {
                keys.clear();
                xi.clear();
                engine->history(s.globalId[rows[k]], keys, xi);
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
        const labelList globalId
        (
            SubList<label>(s.globalId, recvSize_[proci], start)
        );

        bool withHistory = false;
        is  >> withHistory;
        if (withHistory && engine)
        {
            const List<labelList> allKeys(is);
            const List<List<vector>> allXi(is);
            label nXi = 0;
            forAll(allXi, k)
            {
                nXi += allXi[k].size();
            }
            engine->reserveHistory(nXi);
            forAll(globalId, k)
            {
                engine->setHistory(globalId[k], allKeys[k], allXi[k]);
            }
        }
    }
}


void Foam::processorHalo::update(demState& s)
{
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
