/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "historyParcel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace tangentialContactModels
{
    defineTypeNameAndDebug(historyParcel, 0);
    addToRunTimeSelectionTable
    (
        tangentialContactModel,
        historyParcel,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::tangentialContactModels::historyParcel::historyParcel
(
    const dictionary& dict
)
:
    tangentialContactModel(dict, typeName, wordList())    // reads no coefficients
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::tangentialContactModels::historyParcel::force
(
    const demContact& c,
    const scalar fn,
    const bool damping,
    vector& xi
) const
{
    // Accumulate the slip, then keep only the part in the tangent plane
    // (the contact normal rotates while the particles roll over each other)
    xi += c.vs*c.dt;
    xi -= (xi & c.n)*c.n;

    const scalar kt = 8*c.props->Gstar*sqrt(c.Rstar*c.delta);

    const scalar magXi = mag(xi);
    const scalar fCap = c.props->mu*mag(fn);

    if (kt*magXi > fCap)
    {
        // Sliding: the elastic part alone decides, as in the reference
        if (magXi > 0)
        {
            const vector t(xi/magXi);
            xi = (fCap/kt)*t;
            return -fCap*t;
        }
        return Zero;
    }

    vector Ft(-kt*xi);

    if (damping)
    {
        const scalar gammaT =
            -2*sqrt(5.0/6.0)*c.props->beta*sqrt(kt*c.mstar);
        Ft -= gammaT*c.vs;
    }

    return Ft;
}


// ************************************************************************* //
