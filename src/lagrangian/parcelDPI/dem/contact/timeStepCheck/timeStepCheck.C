/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "timeStepCheck.H"
#include "pairScaling.H"
#include "dictKeys.H"
#include "IOmanip.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::timeStepCheck::timeStepCheck(const dictionary& dict)
:
    maxImpactVelocity_(0),
    allowUnstable_(false)
{
    const dictionary& tsDict = dict.subDict("timeStepCheck");
    dictKeys::warnUnknown(tsDict, {"maxImpactVelocity", "allowUnstable"});
    maxImpactVelocity_ = tsDict.get<scalar>("maxImpactVelocity");
    if (!(maxImpactVelocity_ > 0))
    {
        FatalIOErrorInFunction(tsDict)
            << "Entry 'maxImpactVelocity' = " << maxImpactVelocity_
            << " in dictionary " << tsDict.name() << " must be > 0"
            << exit(FatalIOError);
    }
    allowUnstable_ = tsDict.getOrDefault<bool>("allowUnstable", false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::timeStepCheck::check
(
    const dictionary& dict,
    const scalar dt,
    const demMaterials& mat,
    const normalContactModel& normal,
    const labelUList& wallMaterials
) const
{
    const scalar v = maxImpactVelocity_;

    // A table: 6 digits whatever the case's writePrecision (17 digits
    // would overflow the columns)
    const int oldPrecision = Info().precision(6);

    Info<< nl << "DEM time-step check: timeStep " << dt
        << " s, maxImpactVelocity " << v << " m/s" << nl
        << "    Hertz contact time t_H (elastic, dynamic reduced mass), "
        << "limits: error above t_H/3, warning above t_H/10" << nl
        << "    " << setw(24) << "pair" << setw(13) << "R* [m]"
        << setw(13) << "m_dyn [kg]" << setw(13) << "t_H [s]"
        << setw(13) << "t_H/dt" << setw(13) << "dmax/R*" << nl;

    scalar worstRatio = GREAT;
    word worstPair;
    scalar worstTH = 0;

    // Elastic Hertz impact: t_H = 2.9432 delta_max/v (2 int_0^1
    // dx/sqrt(1 - x^(5/2))), so the peak overlap follows from t_H without
    // the model's stiffness. Beyond a fraction of R* the Hertz law is
    // meaningless and past ~R* particles pass through each other or the
    // wall silently (bench/stability: Y = 5e6 Pa at 30 m/s), which no time
    // step cures: warn above 0.1 R*, refuse above 0.5 R*
    scalar worstOverlap = 0;
    word worstOverlapPair;

    auto row = [&](const word& name, const scalar Rstar, const scalar m,
                   const scalar tH)
    {
        const scalar overlap = v*tH/2.9432/Rstar;

        Info<< "    " << setw(24) << name << setw(13) << Rstar
            << setw(13) << m << setw(13) << tH << setw(13) << tH/dt
            << setw(13) << overlap << nl;

        if (tH/dt < worstRatio)
        {
            worstRatio = tH/dt;
            worstPair = name;
            worstTH = tH;
        }

        if (overlap > worstOverlap)
        {
            worstOverlap = overlap;
            worstOverlapPair = name;
        }

        if (overlap > 0.1 && overlap <= 0.5)
        {
            WarningIn("Foam::timeStepCheck::check")
                << "Contact " << name << " at maxImpactVelocity " << v
                << " m/s reaches an elastic overlap of " << overlap
                << " R*; Hertz contact assumes small overlaps (< 0.1 R*):"
                << " a stiffer (less softened) youngsModulus or a smaller"
                << " maxImpactVelocity is advised" << endl;
        }

        if (dt > tH/10 && dt <= tH/3)
        {
            WarningIn("Foam::timeStepCheck::check")
                << "DEM timeStep " << dt << " s resolves a contact of "
                << name << " with only " << tH/dt << " steps (t_H = " << tH
                << " s at " << v << " m/s); 10 or more are advised"
                << endl;
        }
    };

    // Wall materials in use
    labelList wallTypes(wallMaterials);
    Foam::sort(wallTypes);
    wallTypes.setSize(std::unique(wallTypes.begin(), wallTypes.end())
        - wallTypes.begin());

    for (label i = 0; i < mat.size(); ++i)
    {
        if (!mat.isParticleType(i))
        {
            continue;
        }
        // The smallest primaries of each type: the shortest contact (t_H
        // goes as the radius at a given density and impact speed)
        const scalar ri = 0.5*mat.size(i).minDiameter();
        const scalar mi = mat.primaryMass(i);

        for (label j = i; j < mat.size(); ++j)
        {
            if (!mat.isParticleType(j))
            {
                continue;
            }
            const scalar rj = 0.5*mat.size(j).minDiameter();
            const scalar mj = mat.primaryMass(j);
            const scalar Rstar = ri*rj/(ri + rj);
            const scalar mdyn = pairScaling::dynamicReducedMass
            (
                mi, mat.N(i), mj, mat.N(j)
            );
            const scalar tH =
                normal.contactTime(mat.pair(i, j), Rstar, mdyn, v);

            row(mat.names()[i] + "-" + mat.names()[j], Rstar, mdyn, tH);

            // Theory 7.3: a parcel of N primaries approaching a carrier's
            // mass breaks the "N primaries on one carrier" picture (the
            // largest parcel on the smallest partner)
            const scalar Ni = mat.N(i), Nj = mat.N(j);
            if (Ni != Nj)
            {
                const scalar ratio =
                    (Ni > Nj)
                  ? Ni*mat.primaryMass(i, mat.size(i).maxDiameter())/mj
                  : Nj*mat.primaryMass(j, mat.size(j).maxDiameter())/mi;
                if (ratio > 0.1)
                {
                    WarningInFunction
                        << "Pair " << mat.names()[i] << "-"
                        << mat.names()[j] << ": the parcel mass N m is "
                        << ratio << " of its partner's; the carrier recoil"
                        << " (theory 2.4) is no longer small (> 0.1)"
                        << endl;
                }
            }
        }

        for (const label w : wallTypes)
        {
            const scalar mdyn = pairScaling::dynamicReducedMass(mi, mat.N(i));
            const scalar tH = normal.contactTime(mat.pair(i, w), ri, mdyn, v);
            row
            (
                mat.names()[i] + "-" + mat.names()[w] + "(wall)",
                ri,
                mdyn,
                tH
            );
        }
    }

    Info<< "    Rayleigh time T_R: warning above 0.3 T_R" << nl;
    for (label i = 0; i < mat.size(); ++i)
    {
        if (!mat.isParticleType(i))
        {
            continue;
        }
        const scalar TR = mat.rayleighTime(i);
        Info<< "    " << setw(24) << mat.names()[i] << "  T_R " << TR
            << " s, timeStep/T_R " << dt/TR << nl;

        if (dt > 0.3*TR)
        {
            WarningInFunction
                << "DEM timeStep " << dt << " s is " << dt/TR
                << " of the Rayleigh time of type " << mat.names()[i]
                << " (T_R = " << TR << " s); 0.3 or less is advised"
                << endl;
        }
    }
    Info<< endl;
    Info().precision(oldPrecision);

    if (worstOverlap > 0.5)
    {
        if (allowUnstable_)
        {
            WarningInFunction
                << "Contact " << worstOverlapPair << " reaches an elastic"
                << " overlap of " << worstOverlap << " R* at "
                << "maxImpactVelocity " << v << " m/s (limit 0.5 R*); "
                << "running anyway (allowUnstable true)" << endl;
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Contact " << worstOverlapPair << " reaches an elastic "
                << "overlap of " << worstOverlap << " R* at "
                << "timeStepCheck/maxImpactVelocity " << v << " m/s in "
                << "dictionary " << dict.name() << " (limit 0.5 R*)." << nl
                << "    Particles would pass through each other or the "
                << "walls whatever the time step: raise youngsModulus (less"
                << " softening) or lower maxImpactVelocity if the scene "
                << "cannot reach it, or set timeStepCheck "
                << "{ allowUnstable true; }"
                << exit(FatalIOError);
        }
    }

    if (worstRatio < 3)
    {
        if (allowUnstable_)
        {
            WarningInFunction
                << "DEM timeStep " << dt << " s is above the stability "
                << "limit t_H/3 = " << worstTH/3 << " s of pair "
                << worstPair << "; running anyway (allowUnstable true)"
                << endl;
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "DEM timeStep " << dt << " s in dictionary "
                << dict.name() << " is above the stability limit t_H/3 = "
                << worstTH/3 << " s of pair " << worstPair << nl
                << "    (elastic Hertz contact time t_H = " << worstTH
                << " s at maxImpactVelocity " << v << " m/s; velocity "
                << "Verlet diverges near t_H/2)" << nl
                << "Reduce timeStep to at most " << worstTH/3
                << " s, or set timeStepCheck { allowUnstable true; }"
                << exit(FatalIOError);
        }
    }
}


// ************************************************************************* //
