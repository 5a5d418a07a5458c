/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demMaterials.H"
#include "typePairDicts.H"
#include "dictKeys.H"
#include "mathematicalConstants.H"
#include "HashSet.H"

#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Read a scalar and check a range; the message names dictionary, key,
//  value and the allowed range so the user can fix the deck directly
template<class Predicate>
Foam::scalar readInRange
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Predicate& inRange,
    const char* rangeText
)
{
    const Foam::scalar value = dict.get<Foam::scalar>(key);

    if (!inRange(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value << " in dictionary "
            << dict.name() << " is out of range: must be " << rangeText
            << Foam::exit(Foam::FatalIOError);
    }

    return value;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::demMaterials::typeKeys
({
    "diameter",
    "sizeDistribution",
    "density",
    "youngsModulus",
    "poissonsRatio",
    "N",
    "api"
});


const Foam::wordList Foam::demMaterials::pairKeys
({
    "restitution",
    "friction",
    "rollingFriction"
});


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demMaterials::readType(const label typei, const dictionary& d)
{
    // Finite too: a value beyond the double range is read as inf, and
    // 1e300 overflows every volume and mass made of it
    auto positive = [](const scalar x)
    {
        return x > 0 && x < std::numeric_limits<scalar>::max();
    };

    // Neither diameter nor sizeDistribution: a wall-only material, whose
    // diameter and density are not needed (walls have infinite mass)
    sizes_.set(typei, sizeDistribution::New(d));
    if (sizes_.set(typei))
    {
        density_[typei] =
            readInRange(d, "density", positive, "finite and > 0");
    }
    else
    {
        density_[typei] = d.getOrDefault<scalar>("density", -1);
    }

    youngsModulus_[typei] =
        readInRange(d, "youngsModulus", positive, "finite and > 0");

    poissonsRatio_[typei] = readInRange
    (
        d,
        "poissonsRatio",
        [](const scalar x) { return x >= 0 && x <= 0.5; },
        "0 <= poissonsRatio <= 0.5"
    );

    N_[typei] = 1;
    if (d.found("N"))
    {
        // A parcel stands for N >= 1 primaries: below 1 it would stand for
        // a fraction of a particle (nParticle < 1 in every statistic)
        N_[typei] = readInRange
        (
            d,
            "N",
            [](const scalar x) { return x >= 1; },
            ">= 1 (the primaries a parcel stands for; carriers 1)"
        );
    }

    // Representative parcels stand for N primary API particles; carriers
    // are tracked one by one. A type with N > 1 must say it is API: a
    // carrier of N 10 would otherwise be counted as API in every statistic
    api_[typei] = d.getOrDefault<bool>("api", false);
    if (N_[typei] > 1 && !api_[typei])
    {
        FatalIOErrorInFunction(d)
            << "Type " << names_[typei] << " has N " << N_[typei]
            << (d.found("api") ? " and api false" : " and no 'api true'")
            << " in dictionary " << d.name() << nl
            << "    Only API types may be coarse-grained (carriers are"
            << " tracked one by one, N 1): set N 1 for a carrier, or"
            << " api true; if this type is API" << exit(FatalIOError);
    }
}


void Foam::demMaterials::readPairs
(
    const dictionary& pairsDict,
    const bool warnKeys
)
{
    const label n = names_.size();
    const typePairDicts pairDicts(pairsDict, names_);

    if (warnKeys)
    {
        pairDicts.warnUnknownKeys(pairKeys);
    }

    pairs_.setSize(n*n);

    for (label i = 0; i < n; ++i)
    {
        for (label j = i; j < n; ++j)
        {
            const word ij(pairDicts.pairName(i, j));
            const dictionary* pd = pairDicts.find(i, j);
            if (!pd)
            {
                FatalIOErrorInFunction(pairsDict)
                    << "No properties for the pair " << ij
                    << " and no 'default' entry in dictionary "
                    << pairsDict.name() << nl
                    << "Add an entry " << ij << " { restitution ..; "
                    << "friction ..; rollingFriction ..; } or a default;"
                    << " valid type names: " << names_
                    << exit(FatalIOError);
            }

            // Keys missing from a specific entry fall back to the default
            auto from = [&](const word& key) -> const dictionary&
            {
                return pairDicts.lookupDict(*pd, key);
            };

            demPairProperties p;
            p.name = ij;

            p.e = readInRange
            (
                from("restitution"),
                "restitution",
                [](const scalar x) { return x > 0.05 && x <= 1; },
                "0.05 < restitution <= 1"
            );

            p.mu = readInRange
            (
                from("friction"),
                "friction",
                [](const scalar x) { return x >= 0; },
                ">= 0"
            );

            p.muR = 0;
            if (from("rollingFriction").found("rollingFriction"))
            {
                p.muR = readInRange
                (
                    from("rollingFriction"),
                    "rollingFriction",
                    [](const scalar x) { return x >= 0; },
                    ">= 0"
                );
            }

            // Theory 1.2 (the code's G*, not the Theory Guide's Eq. 14)
            const scalar Yi = youngsModulus_[i], Yj = youngsModulus_[j];
            const scalar nui = poissonsRatio_[i], nuj = poissonsRatio_[j];

            p.Ystar = 1/((1 - sqr(nui))/Yi + (1 - sqr(nuj))/Yj);
            p.Gstar = 1/
            (
                2*(2 - nui)*(1 + nui)/Yi
              + 2*(2 - nuj)*(1 + nuj)/Yj
            );

            const scalar lne = log(p.e);
            p.beta = lne/sqrt(sqr(lne) + sqr(constant::mathematical::pi));

            pairs_[i*n + j] = p;
            pairs_[j*n + i] = p;
        }
    }
}


void Foam::demMaterials::checkCoarsening(const dictionary& typesDict) const
{
    label firstCoarse = -1;

    forAll(names_, i)
    {
        if (N_[i] > 1)
        {
            if (firstCoarse < 0)
            {
                firstCoarse = i;
            }
            else if (N_[i] != N_[firstCoarse])
            {
                FatalIOErrorInFunction(typesDict)
                    << "Types " << names_[firstCoarse] << " (N "
                    << N_[firstCoarse] << ") and " << names_[i] << " (N "
                    << N_[i] << ") in dictionary " << typesDict.name()
                    << " are both coarse-grained with different N." << nl
                    << "The pair factor max(N_i, N_j) gives the smaller "
                    << "parcel the wrong acceleration and cannot conserve "
                    << "momentum (theory 2.4): use one N for all parcels "
                    << "with N > 1."
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demMaterials::demMaterials
(
    const dictionary& dict,
    const bool warnUnknownKeys
)
{
    const dictionary& typesDict = dict.subDict("types");

    names_ = typesDict.toc();

    if (names_.empty())
    {
        FatalIOErrorInFunction(typesDict)
            << "No material types in dictionary " << typesDict.name()
            << exit(FatalIOError);
    }

    const label n = names_.size();
    sizes_.setSize(n);
    density_.setSize(n);
    youngsModulus_.setSize(n);
    poissonsRatio_.setSize(n);
    N_.setSize(n);
    api_.setSize(n);

    forAll(names_, i)
    {
        if (!typesDict.isDict(names_[i]))
        {
            FatalIOErrorInFunction(typesDict)
                << "Entry '" << names_[i] << "' in dictionary "
                << typesDict.name() << " is not a dictionary of material"
                << " properties" << exit(FatalIOError);
        }
        if (warnUnknownKeys)
        {
            dictKeys::warnUnknown(typesDict.subDict(names_[i]), typeKeys);
        }
        readType(i, typesDict.subDict(names_[i]));
    }

    checkCoarsening(typesDict);

    readPairs(dict.subDict("pairs"), warnUnknownKeys);

    coarseGraining_ = coarseGrainingModel::New(dict, N_, api_, warnUnknownKeys);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::demMaterials::typeIndex
(
    const word& name,
    const dictionary& context,
    const word& keyword
) const
{
    const label i = names_.find(name);

    if (i < 0)
    {
        FatalIOErrorInFunction(context)
            << "Unknown material type '" << name << "' for entry '"
            << keyword << "' in dictionary " << context.name() << nl
            << "Valid types: " << names_ << exit(FatalIOError);
    }

    return i;
}


Foam::scalar Foam::demMaterials::primaryMass
(
    const label i,
    const scalar d
) const
{
    return density_[i]*constant::mathematical::pi/6*pow3(d);
}


Foam::scalar Foam::demMaterials::rayleighTime(const label i) const
{
    const scalar nu = poissonsRatio_[i];
    const scalar G = youngsModulus_[i]/(2*(1 + nu));

    return
        constant::mathematical::pi*0.5*size(i).minDiameter()
       *sqrt(density_[i]/G)
       /(0.1631*nu + 0.8766);
}


Foam::scalar Foam::demMaterials::parcelN() const
{
    scalar result = 1;
    for (const scalar n : N_)
    {
        result = max(result, n);
    }
    return result;
}


Foam::scalar Foam::demMaterials::maxDiameter() const
{
    scalar d = 0;
    forAll(sizes_, i)
    {
        if (isParticleType(i))
        {
            d = max(d, size(i).maxDiameter());
        }
    }
    return d;
}


Foam::scalar Foam::demMaterials::minMedianDiameter() const
{
    // No sentinel value: any diameter the types hold is a candidate (was
    // GREAT, so a type of diameter above 1e15 m counted as none)
    bool any = false;
    scalar d = 0;
    forAll(sizes_, i)
    {
        if (isParticleType(i))
        {
            const scalar di = size(i).numberMedian();
            d = any ? min(d, di) : di;
            any = true;
        }
    }
    return d;
}


// ************************************************************************* //
