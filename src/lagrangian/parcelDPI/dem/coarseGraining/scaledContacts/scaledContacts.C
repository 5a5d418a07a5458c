/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "scaledContacts.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coarseGrainingModels
{
    defineTypeNameAndDebug(scaledContacts, 0);
    addToRunTimeSelectionTable
    (
        coarseGrainingModel,
        scaledContacts,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coarseGrainingModels::scaledContacts::scaledContacts
(
    const dictionary& dict,
    const scalarUList& N,
    const boolUList& api
)
:
    coarseGrainingModel(dict, typeName, wordList(), api)   // no coefficients
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coarseGrainingModels::scaledContacts::describe
(
    Ostream& os,
    const wordList&
) const
{
    os  << "coarse-graining scaledContacts: primary contacts x N";
}


// ************************************************************************* //
