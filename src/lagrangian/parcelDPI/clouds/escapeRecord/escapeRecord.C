/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "escapeRecord.H"
#include "PstreamCombineReduceOps.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
    //- Element-wise sum over all processors
    template<class T>
    static List<T> globalSum(const List<T>& local)
    {
        List<T> sum(local);
        Pstream::listCombineGather(sum, plusEqOp<T>());
        Pstream::listCombineScatter(sum);
        return sum;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::escapeRecord::escapeRecord(const polyBoundaryMesh& patches)
:
    patches_(patches),
    parcels_(patches.nNonProcessor(), Zero),
    primaries_(patches.nNonProcessor(), Zero),
    apiPrimaries_(patches.nNonProcessor(), Zero),
    singletPrimaries_(patches.nNonProcessor(), Zero),
    lostParcels_(patches.nNonProcessor(), Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::escapeRecord::escaped
(
    const label patchi,
    const scalar N,
    const bool api,
    const bool singlet
)
{
    ++parcels_[patchi];
    primaries_[patchi] += N;
    if (api)
    {
        apiPrimaries_[patchi] += N;
        if (singlet)
        {
            singletPrimaries_[patchi] += N;
        }
    }
}


void Foam::escapeRecord::lost(const label patchi)
{
    ++lostParcels_[patchi];
}


void Foam::escapeRecord::read(const dictionary& escaped)
{
    // A state written before the API counts existed reads them as zero
    forAll(parcels_, patchi)
    {
        const dictionary d(escaped.subOrEmptyDict(patches_[patchi].name()));
        parcels_[patchi] = d.lookupOrDefault<label>("parcels", 0);
        primaries_[patchi] = d.lookupOrDefault<scalar>("primaries", 0);
        apiPrimaries_[patchi] = d.lookupOrDefault<scalar>("apiPrimaries", 0);
        singletPrimaries_[patchi] =
            d.lookupOrDefault<scalar>("singletPrimaries", 0);
        lostParcels_[patchi] = d.lookupOrDefault<label>("lostParcels", 0);
    }
}


Foam::dictionary Foam::escapeRecord::totals() const
{
    const labelList parcels(globalSum(parcels_));
    const scalarList primaries(globalSum(primaries_));
    const scalarList api(globalSum(apiPrimaries_));
    const scalarList singlets(globalSum(singletPrimaries_));
    const labelList lost(globalSum(lostParcels_));

    dictionary escaped;
    forAll(parcels, patchi)
    {
        if (parcels[patchi] || lost[patchi])
        {
            dictionary d;
            d.add("parcels", parcels[patchi]);
            d.add("primaries", primaries[patchi]);
            d.add("apiPrimaries", api[patchi]);
            d.add("singletPrimaries", singlets[patchi]);
            d.add("lostParcels", lost[patchi]);
            escaped.add(patches_[patchi].name(), d);
        }
    }
    return escaped;
}


Foam::label Foam::escapeRecord::nGone() const
{
    return returnReduce(sum(parcels_) + sum(lostParcels_), sumOp<label>());
}


void Foam::escapeRecord::report(Ostream& os, const dictionary& totals)
{
    for (const word& patchName : totals.sortedToc())
    {
        const dictionary& d = totals.subDict(patchName);
        os  << "    Patch " << patchName
            << ": escaped parcels " << d.get<label>("parcels")
            << " (primaries " << d.get<scalar>("primaries") << ")"
            << ", API primaries " << d.get<scalar>("apiPrimaries")
            << " (as singlets " << d.get<scalar>("singletPrimaries") << ")"
            << ", lost through wall " << d.get<label>("lostParcels") << nl;
    }
}


// ************************************************************************* //
