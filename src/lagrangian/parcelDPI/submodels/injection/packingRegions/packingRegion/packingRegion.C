/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "packingRegion.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(packingRegion, 0);
    defineRunTimeSelectionTable(packingRegion, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::packingRegion::readLength
(
    const dictionary& dict,
    const word& key,
    const bool allowZero
)
{
    const scalar x = dict.get<scalar>(key);
    if (allowZero ? !(x >= 0) : !(x > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << x << " in dictionary "
            << dict.name() << " must be " << (allowZero ? ">= 0" : "> 0")
            << exit(FatalIOError);
    }
    return x;
}


const Foam::dictionary& Foam::packingRegion::checked
(
    const dictionary& dict,
    const wordList& keys
)
{
    wordList known({"shape"});
    known.append(keys);
    dictKeys::warnUnknown(dict, known);
    return dict;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::packingRegion> Foam::packingRegion::New
(
    const dictionary& dict
)
{
    const word shape(dict.get<word>("shape"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shape);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown shape '" << shape << "' for entry 'shape' in "
            << "dictionary " << dict.name() << nl
            << "Valid shapes: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }
    return cstrIter()(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::packingRegion::sample
(
    Random& rnd,
    const scalar r,
    point& p,
    const label maxTries
) const
{
    for (label k = 0; k < maxTries; ++k)
    {
        const point q(candidate(rnd, r));
        if (contains(q, r))
        {
            p = q;
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
