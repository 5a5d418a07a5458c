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
    sumRatio_(Zero),
    maxRatio_(Zero)
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

    List<FixedList<label, nCounts>> counts(Pstream::nProcs());
    FixedList<label, nCounts>& mine = counts[Pstream::myProcNo()];
    mine[parcels] = nOwned;
    mine[rows] = nRows;
    mine[contacts] = nContacts;
    Pstream::gatherList(counts);
    Pstream::scatterList(counts);

    // Per count: its value on every processor and its max/mean
    FixedList<labelField, nCounts> perProc;
    FixedList<scalar, nCounts> ratio;
    ++nSamples_;
    forAll(perProc, c)
    {
        perProc[c].setSize(counts.size());
        forAll(counts, proci)
        {
            perProc[c][proci] = counts[proci][c];
        }
        ratio[c] = maxOverMean(perProc[c]);
        sumRatio_[c] += ratio[c];
        maxRatio_[c] = max(maxRatio_[c], ratio[c]);
    }

    if (file_.valid())
    {
        file_() << t;
        forAll(perProc, c)
        {
            const labelField& n = perProc[c];
            file_()
                << ' ' << min(n) << ' ' << max(n)
                << ' ' << scalar(sum(n))/n.size()
                << ' ' << ratio[c];
        }
        file_() << endl;
    }

    Info<< "    DEM load: parcels per processor " << min(perProc[parcels])
        << " to " << max(perProc[parcels]) << ", max/mean " << ratio[parcels]
        << "; with halo copies max/mean " << ratio[rows]
        << "; pair contacts " << min(perProc[contacts]) << " to "
        << max(perProc[contacts]) << ", max/mean " << ratio[contacts] << nl;

    return ratio[parcels];
}


void Foam::parcelBalance::summary(Ostream& os) const
{
    if (!Pstream::parRun() || nSamples_ == 0)
    {
        return;
    }
    os  << "DEM load balance over " << nSamples_ << " fluid steps on "
        << Pstream::nProcs() << " processors: parcels max/mean "
        << sumRatio_[parcels]/nSamples_ << " on average, "
        << maxRatio_[parcels] << " at worst; with halo copies "
        << sumRatio_[rows]/nSamples_ << " on average, " << maxRatio_[rows]
        << " at worst; pair contacts " << sumRatio_[contacts]/nSamples_
        << " on average, " << maxRatio_[contacts] << " at worst" << endl;
}


// ************************************************************************* //
