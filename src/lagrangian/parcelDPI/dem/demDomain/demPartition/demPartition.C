/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demPartition.H"
#include "dictKeys.H"
#include "PstreamBuffers.H"
#include "PstreamCombineReduceOps.H"
#include "ListOps.H"
#include "SortableList.H"
#include "demDiagnostics.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //



// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //













// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::label Foam::demPartition::readRowsPerMessage(const dictionary& demDict)
{
    const dictionary lbDict(demDict.subOrEmptyDict("loadBalance"));
    label rowsPerMessage;
    rowsPerMessage = lbDict.getOrDefault<label>("rowsPerMessage", 256);
    if (rowsPerMessage < 1)
    {
        FatalIOErrorInFunction(demDict)
            << "loadBalance/rowsPerMessage " << rowsPerMessage
            << " in dictionary " << demDict.name() << " must be >= 1"
            << " (parcels per processor pair in one round of the"
            << " hand-over; default 256)"
            << exit(FatalIOError);
    }
    return rowsPerMessage;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demPartition::demPartition
(
    const dictionary& dict,
    demEngine& engine,
    const polyMesh& mesh
)
:
    engine_(engine),
    rowsPerMessage_(readRowsPerMessage(dict)),
    rcb_(dict, engine),
    dem_(),
    agglomerateIds_(),
    fromProc_(),
    fromRow_(),
    nMesh_(0),
    nDemOwned_(0),
    nDemRows_(0),
    halo_(),
    keys_(nullptr),
    xi_(nullptr),
    range_(0),
    margin_(0),
    vecCols_(),
    scaCols_()
{
    // The engine's history store is emptied after every fluid step
    // (collect): pairs of two halo copies need not be evaluated
    engine_.setHalo(&halo_, false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::demPartition::selected(const dictionary& demDict)
{
    const dictionary lbDict(demDict.subOrEmptyDict("loadBalance"));

    // Called once per run on every processor, in serial too: the keys of
    // loadBalance read here and by the constructor, their values checked
    // here so that bad input stops a serial run as well
    dictKeys::warnUnknown
    (
        lbDict, {"type", "maxImbalance", "contactWeight", "rowsPerMessage"}
    );
    readRowsPerMessage(demDict);
    scalar maxImbalance, contactWeight;
    bool autoWeight;
    rcbCut::readSettings(demDict, maxImbalance, contactWeight, autoWeight);

    const word type(lbDict.getOrDefault<word>("type", "rcb"));
    if (type != "rcb" && type != "none")
    {
        FatalIOErrorInFunction(demDict)
            << "Unknown loadBalance type " << type << " in dictionary "
            << demDict.name() << nl
            << "    valid types: 2(rcb none)" << exit(FatalIOError);
    }
    return Pstream::parRun() && type == "rcb";
}


void Foam::demPartition::copyRow(const label from, const label to)
{
    dem_.copyRow(from, to);
    fromProc_[to] = fromProc_[from];
    fromRow_[to] = fromRow_[from];
    for (vectorField& col : vecCols_)
    {
        col[to] = col[from];
    }
    for (scalarField& col : scaCols_)
    {
        col[to] = col[from];
    }
}


void Foam::demPartition::resizeRows(const label n)
{
    dem_.resize(n);
    fromProc_.setSize(n);
    fromRow_.setSize(n);
    for (vectorField& col : vecCols_)
    {
        col.setSize(n);
    }
    for (scalarField& col : scaCols_)
    {
        col.setSize(n);
    }
}


template<class Send, class Receive>
void Foam::demPartition::inRounds
(
    const UList<DynamicList<label>>& rowsTo,
    const Send& send,
    const Receive& receive
) const
{
    // Every processor takes part in every round (PstreamBuffers exchange
    // sizes collectively), as many as the longest list anywhere needs
    const label myProc = Pstream::myProcNo();
    label nMax = 0;
    forAll(rowsTo, proci)
    {
        if (proci != myProc)
        {
            nMax = max(nMax, rowsTo[proci].size());
        }
    }
    reduce(nMax, maxOp<label>());

    for (label start = 0; start < nMax; start += rowsPerMessage_)
    {
        PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
        forAll(rowsTo, proci)
        {
            if (proci == myProc || start >= rowsTo[proci].size())
            {
                continue;
            }
            UOPstream os(proci, pBufs);
            send
            (
                SubList<label>
                (
                    rowsTo[proci],
                    min(rowsPerMessage_, rowsTo[proci].size() - start),
                    start
                ),
                os
            );
        }
        labelList recvSizes;
        pBufs.finishedSends(recvSizes);

        forAll(recvSizes, proci)
        {
            if (recvSizes[proci])
            {
                UIPstream is(proci, pBufs);
                receive(proci, start, is);
            }
        }
    }
}


void Foam::demPartition::begin
(
    demState& meshRows,
    List<vectorField>& vecIn,
    List<scalarField>& scaIn,
    List<labelList>& keys,
    List<List<vector>>& xi,
    const scalar range,
    const scalar margin
)
{
    keys_ = &keys;
    xi_ = &xi;
    range_ = range;
    margin_ = margin;
    distribute(meshRows, vecIn, scaIn);
}


void Foam::demPartition::distribute
(
    demState& meshRows,
    List<vectorField>& vecIn,
    List<scalarField>& scaIn
)
{
    const scalarList load(rcb_.start(meshRows, *keys_, nDemOwned_));

    const label nProcs = Pstream::nProcs();
    const label nMesh = meshRows.owned();
    List<labelList>& keys = *keys_;
    List<List<vector>>& xi = *xi_;

    // The DEM owner of every row; too uneven over all processors (the
    // parcels or their contacts moved since the last cut): cut again now,
    // so no fluid step runs above maxImbalance
    List<DynamicList<label>> rowsTo(nProcs);
    for (label pass = 0; pass < 2; ++pass)
    {
        scalarList loadTo(nProcs, Zero);
        forAll(rowsTo, proci)
        {
            rowsTo[proci].clear();
        }
        for (label i = 0; i < nMesh; ++i)
        {
            const label proci = rcb_.owner(meshRows.x[i]);
            rowsTo[proci].append(i);
            loadTo[proci] += load[i];
        }
        Pstream::listCombineGather(loadTo, plusEqOp<scalar>());
        Pstream::listCombineScatter(loadTo);
        const scalar loadAll = sum(loadTo);
        if
        (
            pass > 0
         || loadAll == 0
         || max(loadTo)*nProcs/loadAll <= rcb_.maxImbalance()
        )
        {
            break;
        }
        rcb_.partition(meshRows, load);
    }

    // The DEM rows take the mesh rows' storage over: the rows that stay on
    // this processor (most of them when the regions and the mesh
    // decomposition agree) keep their places, a row that leaves is
    // streamed and its place takes a row that arrives; rows are added
    // only where more arrive than leave. So the rows are held once, plus
    // one round's streams (a second copy was ~0.2 kB per particle on 2
    // processes, and re-making it every step left holes in the heap). The
    // order does not matter here: the rows are sorted by globalId below
    const label myProc = Pstream::myProcNo();
    nMesh_ = nMesh;
    dem_.transfer(meshRows);
    fromProc_.setSize(nMesh);
    fromProc_ = myProc;
    fromRow_ = identity(nMesh);
    vecCols_.transfer(vecIn);
    scaCols_.transfer(scaIn);

    // The contacts every processor will give this one's history store,
    // counted first, so that the store is allocated once at its size
    // (grown by doubling it held its old array and one of twice the room
    // at once: 2,000 carriers on 2 processes, ~0.1 MB a process at the
    // peak)
    {
        labelList nGive(nProcs, Zero);
        forAll(rowsTo, proci)
        {
            for (const label i : rowsTo[proci])
            {
                nGive[proci] += keys[i].size();
            }
        }
        labelList nTake(nProcs, Zero);
        UPstream::allToAll(nGive, nTake);
        engine_.reserveHistory(sum(nTake));
    }

    // A row's running contacts (its previous DEM owner wrote them to the
    // mesh owner's copy) go to the engine where the row is
    for (const label i : rowsTo[myProc])
    {
        engine_.setHistory(dem_.globalId[i], keys[i], xi[i]);
        keys[i].clear();
        xi[i].clear();
    }

    // The others in rounds (inRounds), streamed straight from the rows (an
    // indirect list is written as the list of its elements); a sent row's
    // contacts are dropped at once (the stream is their copy) and its
    // place is free for the rows that arrive
    DynamicList<label> freeRows;
    label nextFree = 0;
    inRounds
    (
        rowsTo,
        [&](const labelUList& rows, UOPstream& os)
        {
            os  << rows;
            dem_.writeRows(os, rows);
            os  << UIndirectList<vector>(dem_.fExt, rows)
                << UIndirectList<vector>(dem_.fContact, rows)
                << UIndirectList<vector>(dem_.tContact, rows)
                << UIndirectList<labelList>(keys, rows)
                << UIndirectList<List<vector>>(xi, rows);
            for (const vectorField& col : vecCols_)
            {
                os << UIndirectList<vector>(col, rows);
            }
            for (const scalarField& col : scaCols_)
            {
                os << UIndirectList<scalar>(col, rows);
            }
            for (const label i : rows)
            {
                keys[i].clear();
                xi[i].clear();
                freeRows.append(i);
            }
        },
        [&](const label proci, const label, UIPstream& is)
        {
            // The places: free ones first, then new rows at the end (a
            // row not yet sent is never overwritten)
            const labelList from(is);
            labelList rows(from.size());
            const label nNew =
                max(from.size() - (freeRows.size() - nextFree), 0);
            const label row0 = dem_.size();
            if (nNew)
            {
                resizeRows(row0 + nNew);
            }
            forAll(rows, k)
            {
                rows[k] =
                    (nextFree < freeRows.size())
                  ? freeRows[nextFree++]
                  : row0 + k - (rows.size() - nNew);
            }

            dem_.readRows(is, rows);
            const List<vector> fExt(is);
            const List<vector> fContact(is);
            const List<vector> tContact(is);
            const List<labelList> rowKeys(is);
            const List<List<vector>> rowXi(is);
            for (vectorField& col : vecCols_)
            {
                const vectorField vals(is);
                UIndirectList<vector>(col, rows) = vals;
            }
            for (scalarField& col : scaCols_)
            {
                const scalarField vals(is);
                UIndirectList<scalar>(col, rows) = vals;
            }
            forAll(rows, k)
            {
                const label row = rows[k];
                dem_.fExt[row] = fExt[k];
                dem_.fContact[row] = fContact[k];
                dem_.tContact[row] = tContact[k];
                fromProc_[row] = proci;
                fromRow_[row] = from[k];
                engine_.setHistory(dem_.globalId[row], rowKeys[k], rowXi[k]);
            }
        }
    );

    // More rows left than arrived: the last rows fill the free places
    {
        labelList holes
        (
            SubList<label>(freeRows, freeRows.size() - nextFree, nextFree)
        );
        sort(holes);
        label end = dem_.size();
        label lo = 0;
        label hi = holes.size() - 1;
        while (lo <= hi)
        {
            if (holes[hi] == end - 1)
            {
                // The last row is free itself
                --hi;
            }
            else
            {
                copyRow(end - 1, holes[lo++]);
            }
            --end;
        }
        resizeRows(end);
    }
    const label nOwned = dem_.size();

    // The histories are the engine's now (setHistory); collect hands them
    // back
    keys.clear();
    xi.clear();

    // The rows in increasing key (demEngine::orderRows: the globalId, or
    // with neighbourSearch/order morton a Morton code of the position).
    // The pair sweep visits the pairs in the key order of their first row
    // (for sums in a fixed order), so rows in that order are read one after
    // the other, and rows along a space-filling curve (order morton, or a
    // bed numbered along one at injection) have their partners near them
    // in memory. The rows above are in their mesh order, with the arrivals
    // in the places of the rows sent away, which parcels crossing
    // processors leave unsorted. (Results do not depend on the row order.)
    engine_.orderRows(dem_);
    {
        // Often already in order (a settled bed whose rows stayed with
        // their processors): one pass decides, the sort only if not
        const SubList<uint64_t> keys(dem_.key, nOwned);
        bool sorted = true;
        for (label k = 1; k < nOwned && sorted; ++k)
        {
            sorted = keys[k - 1] < keys[k];
        }
        if (!sorted)
        {
            labelList order;
            sortedOrder(keys, order);
            dem_.reorder(order);
            fromProc_ = labelList(UIndirectList<label>(fromProc_, order));
            fromRow_ = labelList(UIndirectList<label>(fromRow_, order));
            for (vectorField& col : vecCols_)
            {
                col = vectorField(UIndirectList<vector>(col, order));
            }
            for (scalarField& col : scaCols_)
            {
                col = scalarField(UIndirectList<scalar>(col, order));
            }
        }
    }

    halo_.build(dem_, range_, margin_, &engine_);
    engine_.orderRows(dem_, nOwned);
}


void Foam::demPartition::collect
(
    demState& meshRows,
    const giveBackFunction& giveBack,
    const List<vectorField>& vecOut,
    const List<scalarField>& scaOut,
    List<vectorField>& vecBack,
    List<scalarField>& scaBack
)
{
    const label nProcs = Pstream::nProcs();
    const label nOwned = dem_.owned();

    List<DynamicList<label>> rowsTo(nProcs);
    for (label k = 0; k < nOwned; ++k)
    {
        rowsTo[fromProc_[k]].append(k);
    }

    const label myProc = Pstream::myProcNo();
    vecBack.setSize(vecOut.size());
    for (vectorField& col : vecBack)
    {
        col.setSize(nMesh_);
    }
    scaBack.setSize(scaOut.size());
    for (scalarField& col : scaBack)
    {
        col.setSize(nMesh_);
    }

    // The contacts leave the engine's store as they are handed back (it is
    // freed after the return: releaseHistory below)
    DynamicList<label> takenKeys;
    DynamicList<vector> takenXi;
    const auto take = [&](const label k, labelList& rowKeys, List<vector>& rowXi)
    {
        takenKeys.clear();
        takenXi.clear();
        engine_.takeHistory(dem_.globalId[k], takenKeys, takenXi);
        rowKeys = takenKeys;
        rowXi = takenXi;
    };

    // Rows whose mesh owner is this processor go straight back
    label nBack = rowsTo[myProc].size();
    rowBack row;
    for (const label k : rowsTo[myProc])
    {
        const label i = fromRow_[k];
        row.x = dem_.x[k];
        row.v = dem_.v[k];
        row.omega = dem_.omega[k];
        row.fContact = dem_.fContact[k];
        row.tContact = dem_.tContact[k];
        row.agglomerateId = agglomerateIds_[k];
        take(k, row.keys, row.xi);
        giveBack(i, row);
        forAll(vecBack, col)
        {
            vecBack[col][i] = vecOut[col][k];
        }
        forAll(scaBack, col)
        {
            scaBack[col][i] = scaOut[col][k];
        }
    }

    // The others in rounds, as distribute sends them
    inRounds
    (
        rowsTo,
        [&](const labelUList& rows, UOPstream& os)
        {
            List<labelList> allKeys(rows.size());
            List<List<vector>> allXi(rows.size());
            forAll(rows, j)
            {
                take(rows[j], allKeys[j], allXi[j]);
            }
            os  << UIndirectList<label>(fromRow_, rows)
                << UIndirectList<point>(dem_.x, rows)
                << UIndirectList<vector>(dem_.v, rows)
                << UIndirectList<vector>(dem_.omega, rows)
                << UIndirectList<vector>(dem_.fContact, rows)
                << UIndirectList<vector>(dem_.tContact, rows)
                << UIndirectList<label>(agglomerateIds_, rows)
                << allKeys << allXi;
            for (const vectorField& col : vecOut)
            {
                os << UIndirectList<vector>(col, rows);
            }
            for (const scalarField& col : scaOut)
            {
                os << UIndirectList<scalar>(col, rows);
            }
        },
        [&](const label, const label, UIPstream& is)
        {
            const labelList rows(is);
            const List<point> x(is);
            const List<vector> v(is);
            const List<vector> omega(is);
            const List<vector> fContact(is);
            const List<vector> tContact(is);
            const labelList aggIds(is);
            List<labelList> allKeys(is);
            List<List<vector>> allXi(is);
            forAll(vecBack, col)
            {
                const vectorField vals(is);
                UIndirectList<vector>(vecBack[col], rows) = vals;
            }
            forAll(scaBack, col)
            {
                const scalarField vals(is);
                UIndirectList<scalar>(scaBack[col], rows) = vals;
            }
            forAll(rows, j)
            {
                row.x = x[j];
                row.v = v[j];
                row.omega = omega[j];
                row.fContact = fContact[j];
                row.tContact = tContact[j];
                row.agglomerateId = aggIds[j];
                row.keys.transfer(allKeys[j]);
                row.xi.transfer(allXi[j]);
                giveBack(rows[j], row);
            }
            nBack += rows.size();
        }
    );

    if (nBack != nMesh_)
    {
        FatalErrorInFunction
            << nMesh_ << " parcels on this processor went to the DEM, "
            << nBack << " came back" << exit(FatalError);
    }

    // The histories are the mesh side's until the next distribute gives
    // them to the engine again; the rows are the parcels' again, and their
    // storage goes back to the mesh side, empty, for the next fluid step's
    // mesh rows (the same blocks every step: re-made blocks of different
    // sizes would leave free holes in the heap that stay resident)
    engine_.releaseHistory();
    nDemOwned_ = nOwned;
    nDemRows_ = dem_.size();
    meshRows.transfer(dem_);
    meshRows.clear();
}


// ************************************************************************* //
