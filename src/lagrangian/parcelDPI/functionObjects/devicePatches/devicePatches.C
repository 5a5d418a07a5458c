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
    const labelHashSet ids(pbm.patchSet(names, false, true));
    if (ids.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << who << ": `" << key << "` " << names
            << " names no patch of the mesh (patches: "
            << SubList<word>(pbm.names(), pbm.nNonProcessor()) << ")."
            << exit(FatalIOError);
    }
    return ids;
}


// ************************************************************************* //
