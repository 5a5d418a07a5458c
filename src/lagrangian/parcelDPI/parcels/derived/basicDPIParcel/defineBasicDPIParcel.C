/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "basicDPIParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebug(basicDPIParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicDPIParcel>, 0);
}

// ************************************************************************* //
