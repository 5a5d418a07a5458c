/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "logNormal.H"
#include "dictKeys.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace sizeDistributions
{
    defineTypeNameAndDebug(logNormal, 0);
    addToRunTimeSelectionTable(sizeDistribution, logNormal, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::sizeDistributions::logNormal::Phi(const scalar x)
{
    // erfc keeps the lower tail's precision (1 - Phi(-x) would not)
    return 0.5*std::erfc(-x/std::sqrt(2.0));
}


Foam::scalar Foam::sizeDistributions::logNormal::undersize
(
    const scalar d,
    const scalar shift,
    const scalar PhiLo,
    const scalar PhiHi
) const
{
    if (d <= min_)
    {
        return 0;
    }
    if (d >= max_)
    {
        return 1;
    }
    return (Phi(z(d) - shift) - PhiLo)/(PhiHi - PhiLo);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sizeDistributions::logNormal::logNormal(const dictionary& dict)
:
    dict_(dict),
    mu_(0),
    s_(0),
    min_(0),
    max_(0),
    PhiA_(0),
    PhiB_(1),
    PhiAm_(0),
    PhiBm_(1)
{
    dictKeys::warnUnknown(dict, {"type", "median", "gsd", "basis", "min", "max"});

    const scalar median = readDiameter(dict, "median");
    const scalar gsd = dict.get<scalar>("gsd");
    if (!(gsd > 1) || !std::isfinite(gsd))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'gsd' = " << gsd << " in dictionary " << dict.name()
            << " must be > 1 (the geometric standard deviation; for one"
            << " size give the type a diameter instead)"
            << exit(FatalIOError);
    }
    s_ = std::log(gsd);

    const word basis(dict.get<word>("basis"));
    if (basis == "number")
    {
        mu_ = std::log(median);
    }
    else if (basis == "mass")
    {
        // Hatch-Choate: ln CMD = ln MMD - 3 s^2
        mu_ = std::log(median) - 3*sqr(s_);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown basis '" << basis << "' for entry 'basis' in"
            << " dictionary " << dict.name() << nl
            << "    Valid choices: (number mass): mass when median is the"
            << " mass median diameter (MMD, laser diffraction's d50 by"
            << " volume), number for the count median (CMD)"
            << exit(FatalIOError);
    }

    const scalar cmd = std::exp(mu_);
    min_ = dict.found("min") ? readDiameter(dict, "min") : cmd/pow3(gsd);
    max_ =
        dict.found("max")
      ? readDiameter(dict, "max")
      : cmd*std::exp(3*sqr(s_))*pow3(gsd);

    if (!(min_ < max_))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'min' = " << min_ << " and 'max' = " << max_
            << " in dictionary " << dict.name() << ": min must be below max"
            << exit(FatalIOError);
    }

    PhiA_ = Phi(z(min_));
    PhiB_ = Phi(z(max_));
    PhiAm_ = Phi(z(min_) - 3*s_);
    PhiBm_ = Phi(z(max_) - 3*s_);

    // Bounds both in one tail leave no primary (or no mass) between them
    if (!(PhiB_ - PhiA_ > 1e-12) || !(PhiBm_ - PhiAm_ > 1e-12))
    {
        FatalIOErrorInFunction(dict)
            << "The bounds " << min_ << " to " << max_ << " m in dictionary "
            << dict.name() << " hold no primaries of the log-normal (CMD "
            << cmd << " m, GSD " << gsd << "): put min and max about the"
            << " median" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::sizeDistributions::logNormal::numberUndersize
(
    const scalar d
) const
{
    return undersize(d, 0, PhiA_, PhiB_);
}


Foam::scalar Foam::sizeDistributions::logNormal::massUndersize
(
    const scalar d
) const
{
    // The mass is log-normal with the same s about ln CMD + 3 s^2
    return undersize(d, 3*s_, PhiAm_, PhiBm_);
}


Foam::scalar Foam::sizeDistributions::logNormal::diameter
(
    const scalar u
) const
{
    if (u <= 0)
    {
        return min_;
    }
    if (u >= 1)
    {
        return max_;
    }
    return invert
    (
        [this](const scalar d) { return numberUndersize(d); },
        u,
        min_,
        max_
    );
}


Foam::scalar Foam::sizeDistributions::logNormal::meanCube() const
{
    // E[d^3] of the untruncated number distribution, times the share of
    // the mass (the d^3-weighted distribution) inside the bounds over the
    // share of the number
    return
        std::exp(3*mu_ + 4.5*sqr(s_))*(PhiBm_ - PhiAm_)/(PhiB_ - PhiA_);
}


Foam::string Foam::sizeDistributions::logNormal::description() const
{
    return
        "logNormal: CMD " + Foam::name(numberMedian()) + " m, MMD "
      + Foam::name(massMedian()) + " m, GSD " + Foam::name(std::exp(s_))
      + ", from " + Foam::name(min_) + " to " + Foam::name(max_) + " m";
}


// ************************************************************************* //
