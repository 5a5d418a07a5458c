/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "singleParticles.H"
#include "dictKeys.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiInjectionModels
{
    defineTypeNameAndDebug(singleParticles, 0);
    addToRunTimeSelectionTable(dpiInjectionModel, singleParticles, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiInjectionModels::singleParticles::singleParticles
(
    const word& name,
    const dictionary& dict,
    const demMaterials*
)
:
    dpiInjectionModel(name, dict, {"particles"}),
    particles_()
{
    List<dictionary> entries(dict.get<List<dictionary>>("particles"));

    if (entries.empty())
    {
        FatalIOErrorInFunction(dict)
            << "injectors/" << name << "/particles is empty"
            << exit(FatalIOError);
    }

    particles_.setSize(entries.size());
    forAll(entries, i)
    {
        // Named after its place, for this warning and the errors below
        dictionary& e = entries[i];
        e.name() = dict.name() + ".particles[" + Foam::name(i) + "]";
        dictKeys::warnUnknown(e, {"position", "U", "omega", "type", "d"});

        injectionSpec& p = particles_[i];
        p.position = e.get<point>("position");
        p.U = e.lookupOrDefault<vector>("U", Zero);
        p.omega = e.lookupOrDefault<vector>("omega", Zero);
        p.type = e.get<word>("type");
        p.d = -1;
        if (e.found("d"))
        {
            p.d = e.get<scalar>("d");
            checkDiameter(p.d, e, "Entry 'd'");
        }
    }
}


Foam::dpiInjectionModels::singleParticles::singleParticles
(
    const word& name,
    const dictionary& dict,
    const wordList& modelKeys,
    List<injectionSpec>&& particles
)
:
    dpiInjectionModel(name, dict, modelKeys),
    particles_(std::move(particles))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::dpiInjectionModels::singleParticles::bounds() const
{
    boundBox bb(boundBox::invertedBox);
    for (const injectionSpec& p : particles_)
    {
        bb.add(p.position);
    }
    return bb;
}


void Foam::dpiInjectionModels::singleParticles::inject
(
    const scalar t0,
    const scalar t1,
    DynamicList<injectionSpec>& particles
)
{
    if (SOI_ >= t0 && SOI_ < t1)
    {
        particles.append(particles_);
        particles_.clear();
    }
}


// ************************************************************************* //
