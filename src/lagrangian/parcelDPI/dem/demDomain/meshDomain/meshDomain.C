/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "meshDomain.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshDomain::meshDomain(demEngine& engine, const polyMesh& mesh)
:
    engine_(engine),
    halo_(nullptr),
    rows_(nullptr),
    vecIn_(nullptr),
    scaIn_(nullptr),
    agglomerateIds_()
{
    if (Pstream::parRun())
    {
        halo_.reset(new processorHalo(mesh));
        engine_.setHalo(halo_.get(), true);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshDomain::begin
(
    demState& meshRows,
    List<vectorField>& vecIn,
    List<scalarField>& scaIn,
    List<labelList>&,
    List<List<vector>>&,
    const scalar range,
    const scalar margin
)
{
    rows_ = &meshRows;
    vecIn_ = &vecIn;
    scaIn_ = &scaIn;

    if (halo_.valid())
    {
        // The owners' contact histories travel with the ghosts at every
        // build: a parcel new to this processor's halo brings the
        // contacts it already has (walls included), so they continue
        // here as they do at its owner
        halo_->build(meshRows, range, margin, &engine_);
        engine_.orderRows(meshRows, meshRows.owned());
    }
}


void Foam::meshDomain::end
(
    demState& meshRows,
    const giveBackFunction& giveBack,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut,
    List<vectorField>& vecBack,
    List<scalarField>& scaBack
)
{
    DynamicList<label> keys;
    DynamicList<vector> xi;
    rowBack row;
    const label n = meshRows.owned();
    for (label i = 0; i < n; ++i)
    {
        row.x = meshRows.x[i];
        row.v = meshRows.v[i];
        row.omega = meshRows.omega[i];
        row.fContact = meshRows.fContact[i];
        row.tContact = meshRows.tContact[i];
        row.agglomerateId = agglomerateIds_[i];
        keys.clear();
        xi.clear();
        engine_.history(meshRows.globalId[i], keys, xi);
        row.keys = keys;
        row.xi = xi;
        giveBack(i, row);
    }

    vecBack.transfer(vecOut);
    scaBack.transfer(scaOut);
}


// ************************************************************************* //
