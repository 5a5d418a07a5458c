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


// ************************************************************************* //
