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
#include "FixedList.H"
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
    maxRowRatio_(0),
    sumContactRatio_(0),
    maxContactRatio_(0)
{
    if (Pstream::parRun() && Pstream::master())
    {
        mkDir(dir);
        file_.reset(new OFstream(dir/"parcelBalance.dat"));
        file_() << "# DEM load per processor at the end of every fluid step"
            << " (" << Pstream::nProcs() << " processors)" << nl
            << "# time parcels:min max mean max/mean"
            << " rowsWithHalo:min max mean max/mean"
            << " pairContacts:min max mean max/mean" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::parcelBalance::sample
(
    const scalar t,
    const label nOwned,
    const label nRows,
    const label nContacts
)
{
    if (!Pstream::parRun())
    {
        return 1;
    }

    List<FixedList<label, 3>> counts(Pstream::nProcs());
    FixedList<label, 3>& mine = counts[Pstream::myProcNo()];
    mine[0] = nOwned;
    mine[1] = nRows;
    mine[2] = nContacts;
    Pstream::gatherList(counts);
    Pstream::scatterList(counts);

    labelField parcels(counts.size());
    labelField rows(counts.size());
    labelField contacts(counts.size());
    forAll(counts, proci)
    {
        parcels[proci] = counts[proci][0];
        rows[proci] = counts[proci][1];
        contacts[proci] = counts[proci][2];
    }
    const scalar parcelRatio = maxOverMean(parcels);
    const scalar rowRatio = maxOverMean(rows);
    const scalar contactRatio = maxOverMean(contacts);

    ++nSamples_;
    sumParcelRatio_ += parcelRatio;
    maxParcelRatio_ = max(maxParcelRatio_, parcelRatio);
    sumRowRatio_ += rowRatio;
    maxRowRatio_ = max(maxRowRatio_, rowRatio);
    sumContactRatio_ += contactRatio;
    maxContactRatio_ = max(maxContactRatio_, contactRatio);

    if (file_.valid())
    {
        file_() << t
            << ' ' << min(parcels) << ' ' << max(parcels)
            << ' ' << scalar(sum(parcels))/parcels.size()
            << ' ' << parcelRatio
            << ' ' << min(rows) << ' ' << max(rows)
            << ' ' << scalar(sum(rows))/rows.size()
            << ' ' << rowRatio
            << ' ' << min(contacts) << ' ' << max(contacts)
            << ' ' << scalar(sum(contacts))/contacts.size()
            << ' ' << contactRatio << endl;
    }

    Info<< "    DEM load: parcels per processor " << min(parcels) << " to "
        << max(parcels) << ", max/mean " << parcelRatio
        << "; with halo copies max/mean " << rowRatio
        << "; pair contacts " << min(contacts) << " to " << max(contacts)
        << ", max/mean " << contactRatio << nl;

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
        << " at worst; pair contacts " << sumContactRatio_/nSamples_
        << " on average, " << maxContactRatio_ << " at worst" << endl;
}


// ************************************************************************* //
