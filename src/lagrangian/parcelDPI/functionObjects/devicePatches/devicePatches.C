/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "devicePatches.H"
#include "polyBoundaryMesh.H"
#include "wordRes.H"
#include "SubList.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::labelHashSet Foam::devicePatches::select
(
    const polyBoundaryMesh& pbm,
    const dictionary& dict,
    const word& key,
    const word& who
)
{
    const wordRes names(dict.get<wordRes>(key));
    const wordList allPatches(pbm.names());     // a copy: SubList refers to it
    const SubList<word> meshPatches(allPatches, pbm.nNonProcessor());

    // Each entry must select a patch: a misspelt name among right ones
    // would otherwise drop that patch's parcels from the counts silently
    std::string unmatched;
    label nUnmatched = 0;
    for (const wordRe& name : names)
    {
        bool matched = false;
        for (const word& patch : meshPatches)
        {
            matched = matched || name.match(patch);
        }
        if (!matched)
        {
            unmatched += (nUnmatched++ ? " " : "") + name;
        }
    }
    if (names.empty() || nUnmatched)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << who << ": `" << key << "` " << names
            << (
                   names.empty()
                 ? std::string(" is empty")
                 : ": " + unmatched + (nUnmatched > 1 ? " name" : " names")
                 + " no patch of the mesh"
               ).c_str()
            << " (patches: " << meshPatches << ")." << nl
            << "    Name each patch as in constant/polyMesh/boundary, or a"
            << " regular expression in quotes (\"inlet.*\") that matches at"
            << " least one" << exit(FatalIOError);
    }
    return pbm.patchSet(names, false, true);
}


// ************************************************************************* //
