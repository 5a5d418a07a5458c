/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    The stock KinematicCloud sub-models the cloud constructs (they must
    exist even when `none`), registered for basicDPICloud's kinematic base.
    dpiFoam's own models (contact, injection, forces) have their own
    selection tables.

\*---------------------------------------------------------------------------*/

#include "basicDPICloud.H"

#include "makeParcelCloudFunctionObjects.H"
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicDPICloud);
makeParcelForces(basicDPICloud);
makeParcelDispersionModels(basicDPICloud);
makeParcelInjectionModels(basicDPICloud);
makeParcelPatchInteractionModels(basicDPICloud);
makeParcelStochasticCollisionModels(basicDPICloud);
makeParcelSurfaceFilmModels(basicDPICloud);

// ************************************************************************* //
