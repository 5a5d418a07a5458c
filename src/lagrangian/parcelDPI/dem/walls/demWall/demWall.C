/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demWall.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demWall, 0);
    defineRunTimeSelectionTable(demWall, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWall::demWall
(
    const word& name,
    const dictionary& dict,
    const wordList& typeKeys
)
:
    name_(name),
    material_(dict.get<word>("material"))
{
    // type is read by the selector New
    wordList known({"type", "material"});
    known.append(typeKeys);
    dictKeys::warnUnknown(dict, known);
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::demWall> Foam::demWall::New
(
    const word& name,
    const dictionary& dict,
    const polyMesh* mesh
)
{
    const word wallType(dict.get<word>("type"));

    Info<< "Selecting DEM wall " << wallType << " for " << name << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(wallType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "DEM wall type",
            wallType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<demWall>(cstrIter()(name, dict, mesh));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demWall::findCandidates
(
    const point& x,
    const scalar reach,
    DynamicList<label>& elements
) const
{
    DynamicList<demWallContact> contacts;
    findContacts(x, reach, contacts);
    if (contacts.size())
    {
        elements.append(0);
    }
}


void Foam::demWall::findContacts
(
    const point& x,
    const scalar reach,
    const labelUList&,
    DynamicList<demWallContact>& contacts
) const
{
    findContacts(x, reach, contacts);
}


// ************************************************************************* //
