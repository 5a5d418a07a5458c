/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dictKeys.H"
#include "labelList.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "stringOps.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
    //- The dictionaries (dict and those below it) that hold key by name
    static void holders
    (
        const dictionary& dict,
        const word& key,
        DynamicList<fileName>& found
    )
    {
        if (dict.found(key, keyType::LITERAL))
        {
            found.append(dict.name());
        }
        for (const entry& e : dict)
        {
            if (e.isDict())
            {
                holders(e.dict(), key, found);
            }
        }
    }
}

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::label Foam::dictKeys::distance(const word& a, const word& b)
{
    const label n = a.size();
    const label m = b.size();

    // d(i, j): distance between the first i characters of a and the first
    // j of b, row-major (n + 1) x (m + 1)
    labelList d((n + 1)*(m + 1));
    auto at = [&](const label i, const label j) -> label&
    {
        return d[i*(m + 1) + j];
    };

    for (label i = 0; i <= n; ++i)
    {
        at(i, 0) = i;
    }
    for (label j = 0; j <= m; ++j)
    {
        at(0, j) = j;
    }

    for (label i = 1; i <= n; ++i)
    {
        for (label j = 1; j <= m; ++j)
        {
            const label cost = (a[i - 1] == b[j - 1]) ? 0 : 1;

            label best = min(at(i - 1, j) + 1, at(i, j - 1) + 1);
            best = min(best, at(i - 1, j - 1) + cost);

            if
            (
                i > 1 && j > 1
             && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]
            )
            {
                best = min(best, at(i - 2, j - 2) + 1);
            }

            at(i, j) = best;
        }
    }

    return at(n, m);
}


Foam::word Foam::dictKeys::suggest(const word& key, const wordList& known)
{
    word closest;
    label closestDistance = labelMax;

    for (const word& k : known)
    {
        const label dist = distance(key, k);

        // Close enough to be a typo: a short key allows one edit (`Uu` for
        // `U`), a long one two; more and unrelated words start to match
        const label longer = max(label(key.size()), label(k.size()));
        const label allowed = max(label(1), min(label(2), longer/3));

        if (dist <= allowed && dist < closestDistance)
        {
            closest = k;
            closestDistance = dist;
        }
    }

    return closest;
}


Foam::label Foam::dictKeys::warnUnknown
(
    const dictionary& dict,
    const wordList& known
)
{
    label nUnknown = 0;

    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();

        if
        (
            key.isPattern()
         || key.empty()
         || key[0] == '#'
         || key == "FoamFile"
         || known.found(key)
        )
        {
            continue;
        }

        ++nUnknown;

        const word closest(suggest(key, known));

        // One message, built on the stream the warning returns (Snull on
        // the other processors)
        OSstream& os = IOWarningInFunction(dict);

        os  << "Unknown key '" << key.c_str() << "' in dictionary "
            << dict.name().c_str() << " is ignored";

        if (closest.size())
        {
            os  << "; did you mean '" << closest.c_str() << "'?";
        }
        else
        {
            os  << ".";
        }

        os  << " Known keys: (";
        forAll(known, i)
        {
            os  << (i ? " " : "") << known[i].c_str();
        }
        os  << ")" << endl;
    }

    return nUnknown;
}


// ************************************************************************* //


void Foam::dictKeys::refuseDuplicates(const fileName& file)
{
    if (!isFile(file))
    {
        return;     // its reader says what is missing
    }

    // OpenFOAM's own duplicate check, thrown rather than fatal so that the
    // message can say where and what to do
    const entry::inputMode mode = entry::globalInputMode;
    const bool throwing = FatalIOError.throwExceptions();
    entry::globalInputMode = entry::inputMode::ERROR;
    string key;
    label line = -1;
    try
    {
        // (read into an empty dictionary: the top-level constructor
        // resets the input mode to merge)
        IFstream is(file);
        dictionary dict;
        dict.name() = file;
        dict.read(is);
    }
    catch (const IOerror& err)
    {
        const string message(err.message());
        const string tag("duplicate entry: ");
        const auto pos = message.find(tag);
        if (pos != string::npos)
        {
            key = stringOps::trim(message.substr(pos + tag.size()));
            line = err.ioStartLineNumber();
        }
    }
    entry::globalInputMode = mode;
    FatalIOError.throwExceptions(throwing);

    if (key.empty())
    {
        return;
    }

    IFstream is(file);
    const dictionary dict(is);
    DynamicList<fileName> found;
    holders(dict, word(key, false), found);

    FatalIOErrorInFunction(dict)
        << "Key '" << key.c_str() << "' is given twice in dictionary ";
    forAll(found, i)
    {
        FatalIOError<< (i ? " or " : "") << found[i];
    }
    FatalIOError
        << " (the second at line " << line << " of " << file << "):"
        << " OpenFOAM would keep only one of them without a word (a second"
        << " block merged into the first, a second value replacing it)."
        << nl << "    Remove one of them, or give it a name of its own"
        << exit(FatalIOError);
}
