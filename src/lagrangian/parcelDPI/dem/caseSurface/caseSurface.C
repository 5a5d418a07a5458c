/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "caseSurface.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fileName Foam::caseSurface::path(const dictionary& dict)
{
    fileName file(dict.get<fileName>("file"));
    if (!file.isAbsolute() && file[0] != '$')
    {
        file = "$FOAM_CASE/constant/triSurface"/file;
    }
    file.expand();
    return file;
}


Foam::triSurface Foam::caseSurface::read
(
    const dictionary& dict,
    const string& who
)
{
    const fileName file(path(dict));
    if (!isFile(file))
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": no file " << file << nl
            << "    A relative `file` is taken in the case's"
            << " constant/triSurface; any format OpenFOAM's triSurface"
            << " reads (STL, OBJ, VTK, ...)." << exit(FatalIOError);
    }

    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (!(scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": scale " << scale << " must be > 0 (1e-3 for"
            << " a file in mm)" << exit(FatalIOError);
    }

    // Reading merges the vertices an STL repeats per triangle
    triSurface surf(file);
    if (scale != 1)
    {
        surf.scalePoints(scale);
    }
    return surf;
}


// ************************************************************************* //
