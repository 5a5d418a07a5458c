/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "parcelRows.H"
#include "ListOps.H"
#include "mortonOrder.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class ParcelType>
Foam::List<ParcelType*> Foam::parcelRows<ParcelType>::inOrder
(
    Cloud<ParcelType>& parcels
)
{
    List<ParcelType*> ptrs(parcels.size());
    label i = 0;
    for (ParcelType& p : parcels)
    {
        ptrs[i++] = &p;
    }
    return ptrs;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
void Foam::parcelRows<ParcelType>::copy
(
    Cloud<ParcelType>& parcels,
    demEngine& engine,
    const demDomain& domain,
    const bool contactForcesValid
)
{
    state_.clear();
    state_.reserve(parcels.size());

    for (const ParcelType& p : parcels)
    {
        const label row = state_.append
        (
            p.xDEM(),
            p.U(),
            p.omega(),
            0.5*p.d(),
            p.primaryMass(),
            p.N(),
            p.typeId(),
            p.globalId()
        );
        state_.fContact[row] = p.f();
        state_.tContact[row] = p.torque();
    }
    state_.contactForcesValid = contactForcesValid;

    // With the DEM's own partition the histories travel with the rows
    // every fluid step: the parcels' lists are moved, not copied, to the
    // partition (which gives them to the engine), and come back with
    // the rows (end), so a history is held once while the DEM runs
    if (domain.historiesTravel())
    {
        keys_.setSize(state_.size());
        xi_.setSize(state_.size());
        label i = 0;
        for (ParcelType& p : parcels)
        {
            keys_[i].transfer(p.contactKeys());
            xi_[i].transfer(p.contactXi());
            ++i;
        }
        return;
    }

    // The engine keeps the histories between steps; the parcels' copies
    // are loaded once, at the first step (a restart)
    if (!historyLoaded_)
    {
        // The store sized once (it would otherwise grow by doubling,
        // copying itself at each growth; measured on a 50,000 restart this
        // does not move the run's peak memory)
        label nContacts = 0;
        for (const ParcelType& p : parcels)
        {
            nContacts += p.contactKeys().size();
        }
        engine.reserveHistory(nContacts);

        for (const ParcelType& p : parcels)
        {
            engine.setHistory(p.globalId(), p.contactKeys(), p.contactXi());
        }
        historyLoaded_ = true;
    }
}


template<class ParcelType>
void Foam::parcelRows<ParcelType>::order
(
    Cloud<ParcelType>& parcels,
    demEngine& engine
)
{
    engine.orderRows(state_);
    if (!engine.alongCurve())
    {
        return;
    }

    // The pairs are swept in key order, so rows in that order are read one
    // after the other and a row's partners lie near it in memory. The keys
    // move only as parcels cross cells, and a reorder costs a neighbour
    // build (the search sees new rows): a few rows out of place are left
    const UList<uint64_t>& keys = state_.key;
    if (mortonOrder::nDescents(keys) <= keys.size()/100)
    {
        return;
    }

    labelList order;
    sortedOrder(keys, order);
    state_.reorder(order);

    // The parcels to the same order (relinked, not copied: each in turn to
    // the list's end), so that the rows come in it at the next steps
    const List<ParcelType*> ptrs(inOrder(parcels));
    for (const label k : order)
    {
        parcels.append(parcels.remove(ptrs[k]));
    }
}


template<class ParcelType>
void Foam::parcelRows<ParcelType>::end
(
    Cloud<ParcelType>& parcels,
    demDomain& domain,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut,
    List<vectorField>& vecBack,
    List<scalarField>& scaBack
)
{
    const List<ParcelType*> ptrs(inOrder(parcels));

    // A parcel's state after the DEM sub-steps, its history taken over
    auto giveBack = [&ptrs](const label i, demDomain::rowBack& row)
    {
        ParcelType& p = *ptrs[i];
        p.xDEM() = row.x;
        p.U() = row.v;
        p.omega() = row.omega;
        p.f() = row.fContact;
        p.torque() = row.tContact;
        p.agglomerateId() = row.agglomerateId;
        p.contactKeys().transfer(row.keys);
        p.contactXi().transfer(row.xi);
    };

    domain.end(state_, giveBack, vecOut, scaOut, vecBack, scaBack);
}


// ************************************************************************* //
