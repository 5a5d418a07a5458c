/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "particleList.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "clockTime.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiInjectionModels
{
    defineTypeNameAndDebug(particleList, 0);
    addToRunTimeSelectionTable(dpiInjectionModel, particleList, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::List<Type> Foam::dpiInjectionModels::particleList::readList
(
    const dictionary& dict,
    const word& key,
    const bool required
)
{
    if (!required && !dict.found(key))
    {
        return List<Type>();
    }

    fileName file(dict.get<fileName>(key));
    file.expand();
    if (!file.isAbsolute())
    {
        file = fileName(getEnv("FOAM_CASE"))/file;
    }

    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Cannot read file " << file << " (entry '" << key
            << "' in dictionary " << dict.name() << ")"
            << exit(FatalIOError);
    }

    // An optional FoamFile header, as in a lagrangian field
    token first(is);
    if (first.isWord() && first.wordToken() == "FoamFile")
    {
        dictionary header(is);
    }
    else
    {
        is.putBack(first);
    }

    List<Type> values(is);
    return values;
}


Foam::List<Foam::injectionSpec>
Foam::dpiInjectionModels::particleList::readParticles
(
    const word& name,
    const dictionary& dict
)
{
    // Timed for the log: with the injection's line it is the whole cost
    // of a particle list (the set-up figure of a run holds it among the
    // mesh, the fields and the first fluid step)
    const clockTime timer;

    const word type(dict.get<word>("particleType"));
    const List<point> x(readList<point>(dict, "positions", true));
    const List<vector> U(readList<vector>(dict, "velocities", false));
    const List<vector> omega(readList<vector>(dict, "spins", false));
    const List<scalar> d(readList<scalar>(dict, "diameters", false));

    if (x.empty())
    {
        FatalIOErrorInFunction(dict)
            << "injectors/" << name << ": the positions file is empty"
            << exit(FatalIOError);
    }

    const auto checkSize = [&](const label n, const word& key)
    {
        if (n && n != x.size())
        {
            FatalIOErrorInFunction(dict)
                << "injectors/" << name << ": " << n << " " << key
                << " but " << x.size() << " positions; the files must list"
                << " the particles in the same order" << exit(FatalIOError);
        }
    };
    checkSize(U.size(), "velocities");
    checkSize(omega.size(), "spins");
    checkSize(d.size(), "diameters");

    forAll(d, i)
    {
        checkDiameter
        (
            d[i], dict, "diameters[" + Foam::name(i) + "] (file "
          + dict.get<fileName>("diameters") + ")"
        );
    }

    List<injectionSpec> particles(x.size());
    forAll(x, i)
    {
        injectionSpec& p = particles[i];
        p.position = x[i];
        p.U = U.size() ? U[i] : vector::zero;
        p.omega = omega.size() ? omega[i] : vector::zero;
        p.type = type;
        p.d = d.size() ? d[i] : -1;
    }

    Info<< "    injectors/" << name << ": read " << x.size()
        << " particles in " << timer.elapsedTime() << " s" << endl;

    return particles;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiInjectionModels::particleList::particleList
(
    const word& name,
    const dictionary& dict,
    const demMaterials*
)
:
    singleParticles
    (
        name,
        dict,
        {"particleType", "positions", "velocities", "spins", "diameters"},
        readParticles(name, dict)
    )
{}


// ************************************************************************* //
