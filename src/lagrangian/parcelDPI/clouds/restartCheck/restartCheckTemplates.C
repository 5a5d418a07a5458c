/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "restartCheck.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

template<class CloudType>
void Foam::restartCheck::checkCloud
(
    CloudType& parcels,
    const dictionary& dpiDict,
    const dictionary& demDict,
    const demMaterials& mat,
    const label nWalls,
    const dictionary& context
)
{
    typedef typename CloudType::particleType parcelType;

    const word timeName(parcels.db().time().timeName());

    labelList typeIds(parcels.size());
    labelList ids(parcels.size());
    scalarList ds(parcels.size()), Ns(parcels.size()), rhos(parcels.size());
    label i = 0;
    for (const parcelType& p : parcels)
    {
        typeIds[i] = p.typeId();
        ids[i] = p.globalId();
        ds[i] = p.d();
        Ns[i] = p.N();
        rhos[i] = p.rho();
        ++i;
    }

    // Types by name; what the parcels were made with unchanged
    const labelList newIndex
    (
        mapTypes(dpiDict, demDict, mat, timeName, typeIds, ids, ds, Ns, rhos)
    );
    if (newIndex.size())
    {
        for (parcelType& p : parcels)
        {
            p.typeId() = newIndex[p.typeId()];
        }
    }

    // Unique ids, and contact histories that name parcels and walls that
    // exist. A partner that was issued but is gone (it left through an
    // outlet in the step the time was written) is a finished contact:
    // dropped. One never issued, or a wall not in dem/walls, is refused.
    const labelHashSet all(globalIds(ids, timeName));
    const label nIssued = dpiDict.lookupOrDefault<label>("nextGlobalId", 0);
    label nDropped = 0;
    string reason;
    for (parcelType& p : parcels)
    {
        checkHistory
        (
            p.globalId(), p.contactKeys(), p.contactXi(), all, nIssued,
            nWalls, timeName, reason, nDropped
        );
    }

    refuseIfAny(reason, context);

    reduce(nDropped, sumOp<label>());
    if (nDropped)
    {
        Info<< "    Dropped " << nDropped << " contact histories with parcels"
            << " that left the domain before time " << timeName << endl;
    }
}


// ************************************************************************* //
