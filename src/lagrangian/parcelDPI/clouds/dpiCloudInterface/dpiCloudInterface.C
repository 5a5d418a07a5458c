/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiCloudInterface.H"
#include "cloud.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

const Foam::dpiCloudInterface& Foam::dpiCloudInterface::find
(
    const objectRegistry& registry,
    const word& cloudName,
    const word& who
)
{
    const dpiCloudInterface* c =
        registry.cfindObject<dpiCloudInterface>(cloudName);
    if (!c)
    {
        FatalErrorInFunction
            << "Function object " << who << ": no dpiFoam cloud named "
            << cloudName << " in the mesh (clouds: "
            << registry.sortedNames<cloud>() << ")." << nl
            << "    Set `cloud` to the couplingProperties cloudName."
            << exit(FatalError);
    }
    return *c;
}


// ************************************************************************* //
