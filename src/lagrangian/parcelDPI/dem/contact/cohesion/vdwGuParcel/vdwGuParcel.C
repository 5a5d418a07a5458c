/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "vdwGuParcel.H"
#include "typePairDicts.H"
#include "demMaterials.H"
#include "HashSet.H"
#include "IOmanip.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace cohesionContactModels
{
    defineTypeNameAndDebug(vdwGuParcel, 0);
    addToRunTimeSelectionTable(cohesionContactModel, vdwGuParcel, dictionary);
}
}

const Foam::scalar
Foam::cohesionContactModels::vdwGuParcel::continuityTolerance = 0.01;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The dictionary that holds key for a pair entry: the entry itself, else
//  the default entry; FatalIOError naming both when neither has it
const Foam::dictionary& holder
(
    const Foam::word& key,
    const Foam::word& pairName,
    const Foam::dictionary& entry,
    const Foam::dictionary* defaultDict
)
{
    using namespace Foam;

    if (entry.found(key, keyType::LITERAL))
    {
        return entry;
    }
    if (defaultDict && defaultDict->found(key, keyType::LITERAL))
    {
        return *defaultDict;
    }

    FatalIOErrorInFunction(entry)
        << "Missing entry '" << key << "' for the cohesion of pair "
        << pairName << " in dictionary " << entry.name()
        << (defaultDict ? " and in its 'default' entry" : "") << nl
        << "A cohesive pair needs hamakerConstant, sMin, sMins and s0"
        << " (hamakerConstant 0 switches the pair off)"
        << exit(FatalIOError);

    return entry;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::cohesionContactModels::vdwGuParcel::continuityJump
(
    const pairCoeffs& p,
    const scalar ri,
    const scalar rj
)
{
    if (rj <= 0)
    {
        const scalar F0 = wallForce(p.AS, ri, p.sMin);
        return mag(wallForce(p.A, ri, p.sMins - p.s0) - F0)/F0;
    }

    const scalar F0 = sphereForce(p.AS, ri, rj, p.sMin);
    return mag(sphereForce(p.A, ri, rj, p.sMins - p.s0) - F0)/F0;
}


Foam::scalar Foam::cohesionContactModels::vdwGuParcel::continuousShift
(
    const pairCoeffs& p,
    const scalar ri,
    const scalar rj
)
{
    if (rj <= 0)
    {
        // A_R/x^2 = A_S/sMin^2
        return p.sMins - p.sMin*sqrt(p.A/p.AS);
    }

    // F(A_R, x) = F(A_S, sMin) with F decreasing in x: since A_R >= A_S
    // the root is above sMin; bisection in log(x)
    const scalar target = sphereForce(p.AS, ri, rj, p.sMin);
    scalar lo = p.sMin;
    scalar hi = 2*p.sMin;
    for (label k = 0; k < 200 && sphereForce(p.A, ri, rj, hi) > target; ++k)
    {
        lo = hi;
        hi *= 2;
    }
    for (label k = 0; k < 200; ++k)
    {
        const scalar mid = sqrt(lo*hi);
        if (sphereForce(p.A, ri, rj, mid) > target)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return p.sMins - sqrt(lo*hi);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::cohesionContactModels::vdwGuParcel::pairCoeffs
Foam::cohesionContactModels::vdwGuParcel::readPair
(
    const word& name,
    const dictionary& entry,
    const dictionary* defaultDict
) const
{
    pairCoeffs p;
    p.name = name;

    auto read = [&](const word& key)
    {
        return holder(key, name, entry, defaultDict).get<scalar>(key);
    };

    p.A = read("hamakerConstant");
    if (p.A < 0)
    {
        const dictionary& d =
            holder("hamakerConstant", name, entry, defaultDict);
        FatalIOErrorInFunction(d)
            << "Entry 'hamakerConstant' = " << p.A << " for pair " << name
            << " in dictionary " << d.name()
            << " must be >= 0 (0 switches the pair off)"
            << exit(FatalIOError);
    }
    if (p.A == 0)
    {
        return p;
    }

    p.AS = p.A/chi_;
    p.sMin = read("sMin");
    p.sMins = read("sMins");
    p.s0 = read("s0");

    if (!(p.sMin > 0))
    {
        FatalIOErrorInFunction(holder("sMin", name, entry, defaultDict))
            << "Entry 'sMin' = " << p.sMin << " for pair " << name
            << " in dictionary "
            << holder("sMin", name, entry, defaultDict).name()
            << " must be > 0" << exit(FatalIOError);
    }

    if (!(p.sMins > p.sMin))
    {
        FatalIOErrorInFunction(holder("sMins", name, entry, defaultDict))
            << "Entry 'sMins' = " << p.sMins << " for pair " << name
            << " in dictionary "
            << holder("sMins", name, entry, defaultDict).name()
            << " must be > sMin = " << p.sMin << nl
            << "sMins is the end of the softened plateau F(A/chi, sMin),"
            << " which starts at contact (theory 3.3); the guide uses"
            << " sMin 1e-9, sMins 6.077e-9 to 6.276e-9 m"
            << exit(FatalIOError);
    }

    if (!(p.s0 < p.sMins))
    {
        FatalIOErrorInFunction(holder("s0", name, entry, defaultDict))
            << "Entry 's0' = " << p.s0 << " for pair " << name
            << " in dictionary "
            << holder("s0", name, entry, defaultDict).name()
            << " must be < sMins = " << p.sMins
            << " (the tail F(A, s - s0) is singular at s = s0)"
            << exit(FatalIOError);
    }

    return p;
}


void Foam::cohesionContactModels::vdwGuParcel::checkContinuity
(
    const wordList& names,
    const scalarList& radius,
    const boolList& isWall
)
{
    discontinuous_.clear();

    Info<< "    vdwGuParcel: chi " << chi_ << ", wall cohesion "
        << (wallCohesion_ ? "on" : "off") << nl
        << "    " << setw(26) << "pair" << setw(13) << "A_R [J]"
        << setw(13) << "sMin [m]" << setw(13) << "sMins [m]"
        << setw(13) << "s0 [m]" << setw(13) << "F_S [N]"
        << setw(13) << "smax [m]" << setw(13) << "jump [%]" << nl;

    auto check = [&](const pairCoeffs& p, const word& name, const scalar ri,
                     const scalar rj)
    {
        const scalar jump = continuityJump(p, ri, rj);
        const bool wall = rj <= 0;
        const scalar FS =
            wall
          ? wallForce(p.AS, ri, p.sMin)
          : sphereForce(p.AS, ri, rj, p.sMin);
        const scalar smax = wall ? ri : ri*rj/(ri + rj);

        Info<< "    " << setw(26) << name << setw(13) << p.A
            << setw(13) << p.sMin << setw(13) << p.sMins << setw(13) << p.s0
            << setw(13) << FS << setw(13) << smax << setw(13) << 100*jump
            << nl;

        if (jump > continuityTolerance)
        {
            discontinuous_.append(name);

            WarningIn
            (
                "Foam::cohesionContactModels::vdwGuParcel::checkContinuity"
            )
                << "Cohesion of pair " << name << " is discontinuous at "
                << "sMins = " << p.sMins << " m: F(A_R, sMins - s0) differs "
                << "from the plateau F(A_R/chi, sMin) by " << 100*jump
                << " % (more than " << 100*continuityTolerance << " %)."
                << nl << "    Continuity (theory 3.3) with these sMin, sMins"
                << " and chi " << chi_ << " needs s0 = "
                << continuousShift(p, ri, rj) << " m (given " << p.s0
                << " m)" << endl;
        }
        return jump;
    };

    const label n = names.size();
    for (label i = 0; i < n; ++i)
    {
        for (label j = i; j < n; ++j)
        {
            pairCoeffs& p = pairs_[i*n + j];
            if (!p.active())
            {
                continue;
            }
            if (radius[i] > 0 && radius[j] > 0)
            {
                p.jump = check(p, p.name, radius[i], radius[j]);
                pairs_[j*n + i].jump = p.jump;
            }
            if (wallCohesion_)
            {
                if (radius[i] > 0 && isWall[j])
                {
                    check
                    (
                        p, names[i] + "-" + names[j] + "(wall)", radius[i], 0
                    );
                }
                if (j != i && radius[j] > 0 && isWall[i])
                {
                    check
                    (
                        p, names[j] + "-" + names[i] + "(wall)", radius[j], 0
                    );
                }
            }
        }
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

const Foam::wordList Foam::cohesionContactModels::vdwGuParcel::coeffKeys
({
    "chi",
    "wallCohesion",
    "pairs"
});


const Foam::wordList Foam::cohesionContactModels::vdwGuParcel::pairKeys
({
    "hamakerConstant",
    "sMin",
    "sMins",
    "s0"
});


Foam::cohesionContactModels::vdwGuParcel::vdwGuParcel(const dictionary& dict)
:
    cohesionContactModel(dict, typeName, coeffKeys),
    chi_(1),
    nTypes_(0),
    pairs_(),
    wallCohesion_(true),
    pairActive_(false),
    wallActive_(false),
    discontinuous_()
{
    const word coeffsName(typeName + "Coeffs");

    if (!dict.isDict(coeffsName))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary '" << coeffsName << "' in dictionary "
            << dict.name() << " for cohesionModel " << typeName << nl
            << "It holds chi and the per-pair entries: " << coeffsName
            << " { chi 3.177672; pairs { default { hamakerConstant 5e-19;"
            << " sMin 1e-9; sMins 6.227e-9; s0 4.445e-9; } } }"
            << exit(FatalIOError);
    }

    chi_ = coeffDict_.get<scalar>("chi");
    if (!(chi_ >= 1))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Entry 'chi' = " << chi_ << " in dictionary "
            << coeffDict_.name() << " must be >= 1" << nl
            << "chi = (Y_real/Y_sim)^0.4 is the stiffness scaling of the "
            << "softened modulus (1: no softening; the guide uses 3.177672"
            << " for 5e8 Pa against 9e9 Pa)" << exit(FatalIOError);
    }

    wallCohesion_ = coeffDict_.getOrDefault<bool>("wallCohesion", true);

    // Types as the engine reads them (same dictionary, same order); the
    // engine's own table has warned about unknown keys already
    const demMaterials mat(dict, false);
    const wordList& names = mat.names();
    const label n = names.size();
    nTypes_ = n;

    scalarList radius(n);
    forAll(radius, i)
    {
        // The report's radius: the number median (a polydisperse type's
        // continuity hardly depends on it, s << r)
        radius[i] =
            mat.isParticleType(i) ? 0.5*mat.size(i).numberMedian() : -1;
    }

    // Materials of the walls in use
    boolList isWall(n, false);
    if (const dictionary* wallsDict = dict.findDict("walls"))
    {
        for (const word& w : wallsDict->toc())
        {
            const dictionary& wd = wallsDict->subDict(w);
            isWall[mat.typeIndex(wd.get<word>("material"), wd, "material")] =
                true;
        }
    }

    const dictionary* pairsDictPtr = coeffDict_.findDict("pairs");
    if (!pairsDictPtr)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Missing sub-dictionary 'pairs' in dictionary "
            << coeffDict_.name() << nl
            << "Give per-type-pair cohesion entries, e.g. pairs { default "
            << "{ hamakerConstant 5e-19; sMin 1e-9; sMins 6.227e-9; "
            << "s0 4.445e-9; } }; types: " << names << exit(FatalIOError);
    }
    const dictionary& pairsDict = *pairsDictPtr;
    const typePairDicts pairDicts(pairsDict, names);
    pairDicts.warnUnknownKeys(pairKeys);
    const dictionary* defaultDict = pairDicts.defaultDict();

    pairs_.setSize(n*n);

    for (label i = 0; i < n; ++i)
    {
        for (label j = i; j < n; ++j)
        {
            const bool particles = radius[i] > 0 && radius[j] > 0;
            const bool wall =
                wallCohesion_
             && ((radius[i] > 0 && isWall[j]) || (radius[j] > 0 && isWall[i]));

            const word ij(pairDicts.pairName(i, j));
            const dictionary* pd = pairDicts.find(i, j);

            pairCoeffs p;
            p.name = ij;

            if (pd && (particles || wall))
            {
                p = readPair(ij, *pd, defaultDict);
            }
            else if (particles || wall)
            {
                FatalIOErrorInFunction(pairsDict)
                    << "No cohesion parameters for the type pair " << ij
                    << " in dictionary " << pairsDict.name()
                    << (particles ? "" : " (a particle type against a wall"
                        " material; or set wallCohesion false)") << nl
                    << "Add an entry " << ij << " { hamakerConstant ..; "
                    << "sMin ..; sMins ..; s0 ..; } (hamakerConstant 0 "
                    << "switches the pair off) or a 'default' entry;"
                    << " valid pair names: typeA-typeB with types " << names
                    << exit(FatalIOError);
            }

            if (p.active())
            {
                pairActive_ = pairActive_ || particles;
                wallActive_ = wallActive_ || wall;
            }

            pairs_[i*n + j] = p;
            pairs_[j*n + i] = p;
        }
    }

    checkContinuity(names, radius, isWall);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// ************************************************************************* //
