/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "tabulatedSize.H"
#include "dictKeys.H"
#include "addToRunTimeSelectionTable.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace sizeDistributions
{
    defineTypeNameAndDebug(tabulatedSize, 0);
    addToRunTimeSelectionTable(sizeDistribution, tabulatedSize, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::sizeDistributions::tabulatedSize::integral
(
    const scalar p,
    const scalar a,
    const scalar b
)
{
    return p == 0 ? std::log(b/a) : (std::pow(b, p) - std::pow(a, p))/p;
}


Foam::label Foam::sizeDistributions::tabulatedSize::interval
(
    const scalar d
) const
{
    // The last row at or below d, at most the second last
    const label k =
        label(std::upper_bound(d_.begin(), d_.end(), d) - d_.begin()) - 1;
    return max(label(0), min(k, d_.size() - 2));
}


Foam::scalar Foam::sizeDistributions::tabulatedSize::undersize
(
    const scalar d,
    const scalarList& F,
    const scalar p,
    const scalar scale
) const
{
    if (d <= d_.first())
    {
        return 0;
    }
    if (d >= d_.last())
    {
        return 1;
    }
    const label k = interval(d);
    return F[k] + scale*c_[k]*integral(p, d_[k], d);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sizeDistributions::tabulatedSize::tabulatedSize(const dictionary& dict)
:
    dict_(dict),
    d_(dict.get<scalarList>("diameters")),
    q_(0),
    c_(),
    FN_(),
    FM_(),
    meanCube_(0)
{
    dictKeys::warnUnknown(dict, {"type", "basis", "diameters", "undersize"});

    const scalarList F(dict.get<scalarList>("undersize"));
    const label n = d_.size();

    const word basis(dict.get<word>("basis"));
    if (basis == "mass")
    {
        q_ = -3;
    }
    else if (basis != "number")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown basis '" << basis << "' for entry 'basis' in"
            << " dictionary " << dict.name() << nl
            << "    Valid choices: (number mass): mass for a laser"
            << " diffraction (volume) or sieve table, number for counts"
            << exit(FatalIOError);
    }

    if (n < 2 || F.size() != n)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'diameters' (" << n << " values) and 'undersize' ("
            << F.size() << ") in dictionary " << dict.name() << " must have"
            << " the same length, at least 2: the smallest size (undersize"
            << " 0), ..., the largest (undersize 1)" << exit(FatalIOError);
    }

    forAll(d_, k)
    {
        if (!(d_[k] > 0 && d_[k] < cbrt(VGREAT)) || (k && !(d_[k] > d_[k-1])))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'diameters' in dictionary " << dict.name()
                << " must increase and be > 0 [m]: " << d_
                << exit(FatalIOError);
        }
        if (!(F[k] >= 0 && F[k] <= 1) || (k && F[k] < F[k-1]))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'undersize' in dictionary " << dict.name()
                << " must not decrease and lie in [0, 1]: " << F
                << exit(FatalIOError);
        }
    }
    if (F.first() != 0 || F.last() != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'undersize' in dictionary " << dict.name() << " must"
            << " start at 0 and end at 1 (the smallest and the largest"
            << " size: a d10/d50/d90 needs a first and a last row), not "
            << F << exit(FatalIOError);
    }

    // The basis' density c_k d^(q + 3 [mass]) is uniform in ln d, so
    // c_k = dF_k/ln(d_k+1/d_k) in both bases; the number in an interval
    // is c_k times the integral of d^q, its mass of d^(q + 3)
    c_.setSize(n - 1);
    FN_.setSize(n, 0);
    FM_.setSize(n, 0);
    for (label k = 0; k < n - 1; ++k)
    {
        c_[k] = (F[k+1] - F[k])/std::log(d_[k+1]/d_[k]);
        FN_[k+1] = FN_[k] + c_[k]*integral(q_, d_[k], d_[k+1]);
        FM_[k+1] = FM_[k] + c_[k]*integral(q_ + 3, d_[k], d_[k+1]);
    }
    meanCube_ = FM_.last()/FN_.last();

    const scalar nTotal = FN_.last(), mTotal = FM_.last();
    for (label k = 0; k < n; ++k)
    {
        FN_[k] /= nTotal;
        FM_[k] /= mTotal;
    }
    for (scalar& c : c_)
    {
        c /= nTotal;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::sizeDistributions::tabulatedSize::numberUndersize
(
    const scalar d
) const
{
    return undersize(d, FN_, q_, 1);
}


Foam::scalar Foam::sizeDistributions::tabulatedSize::massUndersize
(
    const scalar d
) const
{
    // c_ is normalised by number: the mass integral by the mean cube
    return undersize(d, FM_, q_ + 3, 1/meanCube_);
}


Foam::scalar Foam::sizeDistributions::tabulatedSize::diameter
(
    const scalar u
) const
{
    if (u <= 0)
    {
        return d_.first();
    }
    if (u >= 1)
    {
        return d_.last();
    }

    // The interval whose cumulative number holds u (one with no primaries
    // is never chosen: its FN_ equals the next)
    label k =
        label(std::upper_bound(FN_.begin(), FN_.end(), u) - FN_.begin()) - 1;
    k = max(label(0), min(k, d_.size() - 2));
    while (k < d_.size() - 2 && !(c_[k] > 0))
    {
        ++k;
    }

    // Invert FN_k + c_k integral(q, d_k, d) = u in closed form
    const scalar w = (u - FN_[k])/c_[k];
    const scalar d =
        q_ == 0
      ? d_[k]*std::exp(w)
      : std::pow(std::pow(d_[k], q_) + q_*w, 1/q_);

    return min(max(d, d_[k]), d_[k+1]);
}


Foam::string Foam::sizeDistributions::tabulatedSize::description() const
{
    return
        "table (" + Foam::name(d_.size()) + " rows, by "
      + word(q_ == 0 ? "number" : "mass") + "): CMD "
      + Foam::name(numberMedian()) + " m, MMD " + Foam::name(massMedian())
      + " m, from " + Foam::name(d_.first()) + " to "
      + Foam::name(d_.last()) + " m";
}


// ************************************************************************* //
