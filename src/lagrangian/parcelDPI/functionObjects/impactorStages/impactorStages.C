/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "impactorStages.H"
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::impactorStages::impactorStages(const dictionary& dict)
:
    type_(dict.get<word>("type")),
    flowRate_(dict.get<scalar>("flowRate")),
    stageNames_(),
    cutOffs_()
{
    if (!(flowRate_ > 0) || !std::isfinite(flowRate_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'flowRate' = " << flowRate_ << " in dictionary "
            << dict.name() << " must be > 0 [L/min] (the flow rate the"
            << " impactor is run at; the pharmacopoeia's test draws 4 L"
            << " at the flow rate of a 4 kPa pressure drop)"
            << exit(FatalIOError);
    }

    // The cut-offs at the reference flow rate and their exponents
    scalar Qn = 0;
    scalarList d50, x;
    if (type_ == "NGI")
    {
        Qn = 60;
        d50 = scalarList({8.06, 4.46, 2.82, 1.66, 0.94, 0.55, 0.34});
        for (scalar& d : d50)
        {
            d *= 1e-6;      // [um] as tabulated, to [m]
        }
        x = scalarList({0.54, 0.52, 0.50, 0.47, 0.53, 0.60, 0.67});
        stageNames_.setSize(d50.size());
        forAll(stageNames_, i)
        {
            stageNames_[i] = "stage" + Foam::name(i + 1);
        }
    }
    else if (type_ == "table")
    {
        Qn = dict.get<scalar>("referenceFlowRate");
        stageNames_ = dict.get<wordList>("stages");
        d50 = dict.get<scalarList>("cutOffs");
        x = dict.get<scalarList>("exponents");
        if
        (
            !(Qn > 0) || stageNames_.empty()
         || d50.size() != stageNames_.size() || x.size() != d50.size()
        )
        {
            FatalIOErrorInFunction(dict)
                << "Impactor table in dictionary " << dict.name() << ":"
                << " referenceFlowRate (" << Qn << ") must be > 0 [L/min],"
                << " and stages (names), cutOffs [m] at referenceFlowRate"
                << " and exponents lists of one length, not empty"
                << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown impactor type '" << type_ << "' in dictionary "
            << dict.name() << nl
            << "Valid choices: NGI (the Next Generation Impactor, Ph. Eur."
            << " apparatus E), table (referenceFlowRate, stages, cutOffs,"
            << " exponents)" << exit(FatalIOError);
    }

    cutOffs_.setSize(d50.size());
    forAll(d50, i)
    {
        cutOffs_[i] = d50[i]*std::pow(Qn/flowRate_, x[i]);
        if
        (
            !(cutOffs_[i] > 0) || cutOffs_[i] >= 1e-3
         || (i && !(cutOffs_[i] < cutOffs_[i-1]))
        )
        {
            FatalIOErrorInFunction(dict)
                << "Impactor " << type_ << " in dictionary " << dict.name()
                << ": the stages' cut-offs must fall from the first to the"
                << " last, each > 0 and below 1 mm [m]; stage "
                << stageNames_[i] << " has " << cutOffs_[i] << " m at "
                << flowRate_ << " L/min" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::impactorStages::names() const
{
    wordList n(size());
    n.first() = "IP+PS";
    forAll(stageNames_, i)
    {
        n[i + 1] = stageNames_[i];
    }
    n.last() = "MOC";
    return n;
}


Foam::string Foam::impactorStages::describe() const
{
    std::ostringstream os;
    os.precision(3);
    os  << type_ << " at " << flowRate_ << " L/min, cut-offs [um]:";
    forAll(cutOffs_, i)
    {
        os  << ' ' << stageNames_[i] << ' ' << 1e6*cutOffs_[i];
    }
    return os.str();
}


Foam::label Foam::impactorStages::bucket
(
    const scalar dae,
    const bool onCarrier
) const
{
    if (onCarrier)
    {
        return 0;
    }
    forAll(cutOffs_, i)
    {
        if (dae >= cutOffs_[i])
        {
            return i + 1;
        }
    }
    return cutOffs_.size() + 1;
}


void Foam::impactorStages::mmadGsd
(
    const scalarUList& mass,
    scalar& mmad,
    scalar& gsd
) const
{
    mmad = 0;
    gsd = 0;

    // The impactor's mass (without IP+PS) and its fraction below each
    // cut-off, from the largest cut-off down (falling)
    scalar total = 0;
    for (label b = 1; b < mass.size(); ++b)
    {
        total += mass[b];
    }
    if (!(total > 0))
    {
        return;
    }
    scalarList below(cutOffs_.size());
    scalar above = 0;
    forAll(cutOffs_, i)
    {
        above += mass[i + 1];
        below[i] = 1 - above/total;
    }

    // The diameter where the undersize fraction is f: linear in log D50
    // between the two cut-offs that bracket f (0 if none does)
    auto at = [&](const scalar f)
    {
        for (label i = 0; i + 1 < below.size(); ++i)
        {
            const scalar f0 = below[i], f1 = below[i + 1];
            if (f0 >= f && f >= f1 && f0 > f1)
            {
                const scalar w = (f - f1)/(f0 - f1);
                return std::exp
                (
                    std::log(cutOffs_[i + 1])
                  + w*(std::log(cutOffs_[i]) - std::log(cutOffs_[i + 1]))
                );
            }
        }
        return scalar(0);
    };

    mmad = at(0.5);
    const scalar d84 = at(0.8413), d16 = at(0.1587);
    gsd = (d84 > 0 && d16 > 0) ? std::sqrt(d84/d16) : 0;
}


// ************************************************************************* //
