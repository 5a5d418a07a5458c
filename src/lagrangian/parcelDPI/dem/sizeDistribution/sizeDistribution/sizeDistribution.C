/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "sizeDistribution.H"
#include "fixedSize.H"

#include <limits>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(sizeDistribution, 0);
    defineRunTimeSelectionTable(sizeDistribution, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions * * * * * * * * * * * //

Foam::scalar Foam::sizeDistribution::readDiameter
(
    const dictionary& dict,
    const word& key
)
{
    const scalar d = dict.get<scalar>(key);

    // Finite too: a value beyond the double range is read as inf
    if (!(d > 0 && d < std::numeric_limits<scalar>::max()))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << d << " in dictionary "
            << dict.name() << " is out of range: must be finite and > 0"
            << exit(FatalIOError);
    }

    // (compared without cubing: the overflow itself traps, sigFpe)
    if (!(d < Foam::cbrt(VGREAT)))
    {
        // Its volume, mass and every sum over it overflow. The mesh check
        // (demEngine) refuses any diameter larger than the mesh
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << d << " in dictionary "
            << dict.name() << " is out of range: a particle's volume"
            << " overflows (diameters are in metres: 5e-6 for 5 um)"
            << exit(FatalIOError);
    }

    return d;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::sizeDistribution> Foam::sizeDistribution::New
(
    const dictionary& typeDict
)
{
    const bool hasDiameter = typeDict.found("diameter");
    const bool hasDistribution = typeDict.found("sizeDistribution");

    if (hasDiameter && hasDistribution)
    {
        FatalIOErrorInFunction(typeDict)
            << "Dictionary " << typeDict.name() << " has both 'diameter'"
            << " and 'sizeDistribution': give one (diameter for one size,"
            << " sizeDistribution { type logNormal; ... } for many)"
            << exit(FatalIOError);
    }

    if (hasDiameter)
    {
        return autoPtr<sizeDistribution>(new fixedSize(typeDict));
    }

    if (!hasDistribution)
    {
        // A wall material
        return nullptr;
    }

    if (!typeDict.isDict("sizeDistribution"))
    {
        FatalIOErrorInFunction(typeDict)
            << "Entry 'sizeDistribution' in dictionary " << typeDict.name()
            << " is not a dictionary: sizeDistribution { type logNormal;"
            << " median 2.5e-6; gsd 1.8; basis mass; min 5e-7; max 1e-5; }"
            << nl << "    Valid types: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    const dictionary& dict = typeDict.subDict("sizeDistribution");
    const word type(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(type);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown size distribution '" << type << "' for entry 'type'"
            << " in dictionary " << dict.name() << nl
            << "    Valid types: "
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::sizeDistribution::massMedian() const
{
    if (fixed())
    {
        return minDiameter();
    }
    return invert
    (
        [this](const scalar d) { return massUndersize(d); },
        0.5,
        minDiameter(),
        maxDiameter()
    );
}


// ************************************************************************* //
