/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "overlapLimits.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::overlapLimits::overlapLimits(const dictionary& dict)
:
    startWarn_(0.01),
    startRefuse_(0.1),
    runWarn_(0.1),
    runRefuse_(0.5)
{
    const dictionary soDict(dict.subOrEmptyDict("startOverlap"));
    dictKeys::warnUnknown(soDict, {"warn", "refuse"});
    startWarn_ = soDict.getOrDefault<scalar>("warn", startWarn_);
    startRefuse_ =
        soDict.getOrDefault<scalar>("refuse", startRefuse_);
    if (!(startWarn_ > 0) || !(startRefuse_ >= startWarn_))
    {
        FatalIOErrorInFunction(dict)
            << "startOverlap { warn " << startWarn_ << "; refuse "
            << startRefuse_ << "; } in dictionary " << dict.name()
            << ": need 0 < warn <= refuse (overlap / R*; defaults 0.01 and"
            << " 0.1)" << exit(FatalIOError);
    }

    const dictionary ocDict(dict.subOrEmptyDict("overlapCheck"));
    dictKeys::warnUnknown(ocDict, {"warn", "refuse"});
    runWarn_ = ocDict.getOrDefault<scalar>("warn", runWarn_);
    runRefuse_ =
        ocDict.getOrDefault<scalar>("refuse", runRefuse_);
    if (!(runWarn_ > 0) || !(runRefuse_ >= runWarn_))
    {
        FatalIOErrorInFunction(dict)
            << "overlapCheck { warn " << runWarn_ << "; refuse "
            << runRefuse_ << "; } in dictionary " << dict.name()
            << ": need 0 < warn <= refuse (overlap / R*; defaults 0.1 and"
            << " 0.5)" << exit(FatalIOError);
    }
}


// ************************************************************************* //
