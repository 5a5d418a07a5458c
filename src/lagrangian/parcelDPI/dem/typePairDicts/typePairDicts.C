/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "typePairDicts.H"
#include "dictKeys.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::typePairDicts::typePairDicts
(
    const dictionary& pairsDict,
    const wordList& typeNames
)
:
    dict_(pairsDict),
    names_(typeNames),
    default_(pairsDict.findDict("default", keyType::LITERAL))
{
    wordHashSet validNames;
    validNames.insert("default");
    forAll(names_, i)
    {
        forAll(names_, j)
        {
            validNames.insert(pairName(i, j));
        }
    }

    for (const word& key : dict_.toc())
    {
        if (!validNames.found(key))
        {
            FatalIOErrorInFunction(dict_)
                << "Unknown pair entry '" << key << "' in dictionary "
                << dict_.name() << nl
                << "Pair entries are named typeA-typeB (either order) or "
                << "default, with types " << names_
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::typePairDicts::pairName(const label i, const label j) const
{
    return names_[i] + "-" + names_[j];
}


const Foam::dictionary* Foam::typePairDicts::find
(
    const label i,
    const label j
) const
{
    const dictionary* pd = dict_.findDict(pairName(i, j), keyType::LITERAL);
    const dictionary* pdji = dict_.findDict(pairName(j, i), keyType::LITERAL);

    if (pd && pdji && i != j)
    {
        FatalIOErrorInFunction(dict_)
            << "Pair " << pairName(i, j) << " is given twice (as "
            << pairName(i, j) << " and " << pairName(j, i)
            << ") in dictionary " << dict_.name() << exit(FatalIOError);
    }

    if (pd)
    {
        return pd;
    }
    if (pdji)
    {
        return pdji;
    }
    return default_;
}


Foam::label Foam::typePairDicts::warnUnknownKeys(const wordList& known) const
{
    label nUnknown = 0;
    for (const entry& e : dict_)
    {
        if (e.isDict())
        {
            nUnknown += dictKeys::warnUnknown(e.dict(), known);
        }
    }
    return nUnknown;
}


const Foam::dictionary& Foam::typePairDicts::lookupDict
(
    const dictionary& pd,
    const word& key
) const
{
    if (!pd.found(key, keyType::LITERAL) && default_)
    {
        return *default_;
    }
    return pd;
}


// ************************************************************************* //
