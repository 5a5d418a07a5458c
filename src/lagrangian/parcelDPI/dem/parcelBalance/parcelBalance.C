/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "parcelBalance.H"
#include "Pstream.H"
#include "ListOps.H"
#include "labelField.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{
    //- max/mean of one count per processor (1 when there is nothing)
    static scalar maxOverMean(const labelList& n)
    {
        label total = 0;
        label most = 0;
        for (const label ni : n)
        {
            total += ni;
            most = max(most, ni);
        }
        return total > 0 ? scalar(most)*n.size()/total : 1;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parcelBalance::parcelBalance(const fileName& dir)
:
    file_(nullptr),
    nSamples_(0),
    sumParcelRatio_(0),
    maxParcelRatio_(0),
    sumRowRatio_(0),
    maxRowRatio_(0)
{
    if (Pstream::parRun() && Pstream::master())
    {
        mkDir(dir);
        file_.reset(new OFstream(dir/"parcelBalance.dat"));
        file_() << "# DEM load per processor at the end of every fluid step"
            << " (" << Pstream::nProcs() << " processors)" << nl
            << "# time parcels:min max mean max/mean"
            << " rowsWithHalo:min max mean max/mean" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parcelBalance::sample
(
    const scalar t,
    const label nOwned,
    const label nRows
)
{
    if (!Pstream::parRun())
    {
        return 1;
    }

    List<labelPair> counts(Pstream::nProcs());
    counts[Pstream::myProcNo()] = labelPair(nOwned, nRows);
    Pstream::gatherList(counts);
    Pstream::scatterList(counts);

    labelField parcels(counts.size());
    labelField rows(counts.size());
    forAll(counts, proci)
    {
        parcels[proci] = counts[proci].first();
        rows[proci] = counts[proci].second();
    }
    const scalar parcelRatio = maxOverMean(parcels);
    const scalar rowRatio = maxOverMean(rows);

    ++nSamples_;
    sumParcelRatio_ += parcelRatio;
    maxParcelRatio_ = max(maxParcelRatio_, parcelRatio);
    sumRowRatio_ += rowRatio;
    maxRowRatio_ = max(maxRowRatio_, rowRatio);

    if (file_.valid())
    {
        file_() << t
            << ' ' << min(parcels) << ' ' << max(parcels)
            << ' ' << scalar(sum(parcels))/parcels.size()
            << ' ' << parcelRatio
            << ' ' << min(rows) << ' ' << max(rows)
            << ' ' << scalar(sum(rows))/rows.size()
            << ' ' << rowRatio << endl;
    }

    Info<< "    DEM load: parcels per processor " << min(parcels) << " to "
        << max(parcels) << ", max/mean " << parcelRatio
        << "; with halo copies max/mean " << rowRatio << nl;

    return parcelRatio;
}


void Foam::parcelBalance::summary(Ostream& os) const
{
    if (!Pstream::parRun() || nSamples_ == 0)
    {
        return;
    }
    os  << "DEM load balance over " << nSamples_ << " fluid steps on "
        << Pstream::nProcs() << " processors: parcels max/mean "
        << sumParcelRatio_/nSamples_ << " on average, "
        << maxParcelRatio_ << " at worst; with halo copies "
        << sumRowRatio_/nSamples_ << " on average, " << maxRowRatio_
        << " at worst" << endl;
}


// ************************************************************************* //
