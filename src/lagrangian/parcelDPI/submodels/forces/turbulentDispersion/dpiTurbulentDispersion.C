/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiTurbulentDispersion.H"
#include "dictKeys.H"
#include "mathematicalConstants.H"
#include "splitmix.H"
#include "Map.H"
#include "PstreamCombineReduceOps.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiTurbulentDispersion, 0);
}

const Foam::Enum<Foam::dpiTurbulentDispersion::closureType>
Foam::dpiTurbulentDispersion::closureNames
({
    { closureType::WALE, "WALE" },
    { closureType::Smagorinsky, "Smagorinsky" },
});

const Foam::Enum<Foam::dpiTurbulentDispersion::sharingType>
Foam::dpiTurbulentDispersion::sharingNames
({
    { sharingType::agglomerate, "agglomerate" },
    { sharingType::parcel, "parcel" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- Uniform in (0, 1) from 53 bits of a hash
    inline double uniform01(const uint64_t h)
    {
        return (double(h >> 11) + 0.5)*(1.0/9007199254740992.0);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiTurbulentDispersion::dpiTurbulentDispersion(const dictionary& dict)
:
    legacyTimeScale_(dict.getOrDefault<bool>("legacyTimeScale", false)),
    // The reference's model whole with legacyTimeScale: its closure, each
    // parcel its own u*
    closure_
    (
        closureNames.getOrDefault
        (
            "closure", dict,
            legacyTimeScale_ ? closureType::Smagorinsky : closureType::WALE
        )
    ),
    sharing_
    (
        sharingNames.getOrDefault
        (
            "sharing", dict,
            legacyTimeScale_ ? sharingType::parcel : sharingType::agglomerate
        )
    ),
    delta_(dict.getOrDefault<scalar>("delta", 0)),
    Cs_(dict.getOrDefault<scalar>("Cs", 0.08)),
    C0_(dict.getOrDefault<scalar>("C0", 2.1)),
    CL_(1/(0.5 + 0.75*C0_)),
    Cw_(dict.getOrDefault<scalar>("Cw", 0.325)),
    Ck_(dict.getOrDefault<scalar>("Ck", 0.094)),
    Ce_(dict.getOrDefault<scalar>("Ce", 1.048)),
    seed_(uint64_t(dict.getOrDefault<label>("seed", 0)))
{
    // The keys read above
    dictKeys::warnUnknown
    (
        dict,
        {
            "legacyTimeScale", "closure", "sharing", "delta", "Cs", "C0",
            "Cw", "Ck", "Ce", "seed"
        }
    );

    if (legacyTimeScale_ && closure_ != closureType::Smagorinsky)
    {
        FatalIOErrorInFunction(dict)
            << "turbulentDispersion: legacyTimeScale yes is the reference's"
            << " Smagorinsky time scale; closure "
            << closureNames[closure_] << " has its own (leave closure out"
            << " or set it to Smagorinsky)" << exit(FatalIOError);
    }
    if (Cw_ <= 0 || Ck_ <= 0 || Ce_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "turbulentDispersion: Cw, Ck and Ce must be > 0"
            << exit(FatalIOError);
    }

    if (dict.found("delta") && delta_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "turbulentDispersion/delta = " << delta_ << " must be > 0"
            << " (or left out: the cube root of the cell volume)"
            << exit(FatalIOError);
    }
    if (Cs_ <= 0 || C0_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "turbulentDispersion: Cs and C0 must be > 0"
            << exit(FatalIOError);
    }

    Info<< "Turbulent dispersion (LES subgrid, Langevin): ";
    if (closure_ == closureType::WALE)
    {
        Info<< "closure WALE (k of the wall-adapting eddy viscosity,"
            << " tau* = C_L Delta/(Ce sqrt(k))), Cw " << Cw_ << ", Ck "
            << Ck_ << ", Ce " << Ce_;
    }
    else
    {
        Info<< "closure Smagorinsky, "
            << (legacyTimeScale_
                ? "legacyTimeScale (the reference: tau* = C_L k/((nu + nu_e)"
                  "|S|), |S| = sqrt(S:S))"
                : "tau* = C_L k/((nu + nu_e)|S|^2), |S| = sqrt(2 S:S)")
            << ", Cs " << Cs_;
    }
    Info<< ", sharing " << sharingNames[sharing_]
        << (sharing_ == sharingType::agglomerate
            ? " (one u* per agglomerate)" : " (one u* per parcel)")
        << ", C0 " << C0_ << ", C_L " << CL_ << ", delta ";
    if (delta_ > 0)
    {
        Info<< delta_ << " m";
    }
    else
    {
        Info<< "cbrt(V_cell)";
    }
    Info<< ", seed " << seed_ << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dpiTurbulentDispersion::delta(const scalar V) const
{
    return delta_ > 0 ? delta_ : Foam::cbrt(V);
}


Foam::scalar Foam::dpiTurbulentDispersion::magS(const tensor& gradU) const
{
    const scalar m = mag(dev(symm(gradU)));     // sqrt(S:S)
    return legacyTimeScale_ ? m : Foam::sqrt(2.0)*m;
}


Foam::dpiTurbulentDispersion::sgs Foam::dpiTurbulentDispersion::closure
(
    const scalar magS,
    const scalar delta,
    const scalar nu
) const
{
    sgs s;
    if (magS <= 0)
    {
        return s;
    }

    const scalar CsD2 = sqr(Cs_*delta);
    const scalar nuE = CsD2*magS;
    s.k = 5*CsD2*sqr(magS);

    const scalar epsilon =
        legacyTimeScale_ ? (nu + nuE)*magS : (nu + nuE)*sqr(magS);

    s.tau = CL_*s.k/epsilon;
    return s;
}


Foam::dpiTurbulentDispersion::sgs Foam::dpiTurbulentDispersion::wale
(
    const tensor& gradU,
    const scalar delta
) const
{
    sgs s;
    const scalar SS = magSqr(symm(gradU));
    const scalar SdSd = magSqr(dev(symm(gradU & gradU)));
    const scalar denom = sqr(Foam::pow(SS, 2.5) + Foam::pow(SdSd, 1.25));
    if (SdSd <= 0 || denom <= 0)
    {
        // Pure shear (the wall's limit) or no gradient: no subgrid energy
        return s;
    }
    s.k = sqr(sqr(Cw_)*delta/Ck_)*pow3(SdSd)/denom;
    if (s.k <= 0)
    {
        s.k = 0;
        return s;
    }
    // epsilon = Ce k^(3/2)/Delta (OpenFOAM's LES dissipation)
    s.tau = CL_*delta/(Ce_*Foam::sqrt(s.k));
    return s;
}


Foam::dpiTurbulentDispersion::sgs Foam::dpiTurbulentDispersion::closure
(
    const tensor& gradU,
    const scalar delta,
    const scalar nu
) const
{
    if (closure_ == closureType::WALE)
    {
        return wale(gradU, delta);
    }
    return closure(magS(gradU), delta, nu);
}


void Foam::dpiTurbulentDispersion::share
(
    const labelUList& aggId,
    const labelUList& globalId,
    const scalarUList& mass,
    UList<vector>& uStar,
    UList<sgs>& s,
    labelUList& key
) const
{
    key.deepCopy(globalId);
    if (sharing_ != sharingType::agglomerate)
    {
        return;
    }

    // The agglomerates of more than one parcel: those with a member that
    // is not their root (the smallest globalId), on any processor
    Map<label> multi;
    forAll(aggId, i)
    {
        if (aggId[i] >= 0 && aggId[i] != globalId[i])
        {
            multi.set(aggId[i], 1);
        }
    }
    Pstream::mapCombineGather(multi, maxEqOp<label>());
    Pstream::mapCombineScatter(multi);
    if (multi.empty())
    {
        return;
    }

    // Their sums over all processors: mass-weighted u* (the subgrid
    // momentum), and (mass, mass k, mass tau)
    Map<vector> momentum(2*multi.size());
    Map<vector> weights(2*multi.size());
    forAll(aggId, i)
    {
        if (aggId[i] >= 0 && multi.found(aggId[i]))
        {
            // (a vector's default construction leaves it undefined)
            momentum.insert(aggId[i], Zero);
            weights.insert(aggId[i], Zero);
            momentum[aggId[i]] += mass[i]*uStar[i];
            weights[aggId[i]] +=
                vector(mass[i], mass[i]*s[i].k, mass[i]*s[i].tau);
        }
    }
    Pstream::mapCombineGather(momentum, plusEqOp<vector>());
    Pstream::mapCombineScatter(momentum);
    Pstream::mapCombineGather(weights, plusEqOp<vector>());
    Pstream::mapCombineScatter(weights);

    forAll(aggId, i)
    {
        const auto iter = weights.cfind(aggId[i]);
        if (aggId[i] < 0 || !iter.found() || iter.val().x() <= 0)
        {
            continue;
        }
        const vector& w = iter.val();
        uStar[i] = momentum[aggId[i]]/w.x();
        s[i].k = w.y()/w.x();
        s[i].tau = w.z()/w.x();
        key[i] = aggId[i];
    }
}


Foam::vector Foam::dpiTurbulentDispersion::gaussian
(
    const uint64_t seed,
    const uint64_t id,
    const uint64_t step,
    const uint64_t sub
)
{
    // Key of the draw: chained bijective mixes of the counters
    const uint64_t key =
        splitmix(splitmix(splitmix(splitmix(seed) ^ id) ^ step) ^ sub);

    // Box-Muller on two pairs of uniforms
    const double u0 = uniform01(splitmix(key ^ UINT64_C(0x1)));
    const double u1 = uniform01(splitmix(key ^ UINT64_C(0x2)));
    const double u2 = uniform01(splitmix(key ^ UINT64_C(0x3)));
    const double u3 = uniform01(splitmix(key ^ UINT64_C(0x4)));

    const double twoPi = constant::mathematical::twoPi;
    const double r0 = std::sqrt(-2*std::log(u0));
    const double r1 = std::sqrt(-2*std::log(u2));

    return vector
    (
        r0*std::cos(twoPi*u1),
        r0*std::sin(twoPi*u1),
        r1*std::cos(twoPi*u3)
    );
}


Foam::vector Foam::dpiTurbulentDispersion::update
(
    const vector& uStar,
    const sgs& s,
    const scalar dt,
    const label id,
    const label step,
    const label sub
) const
{
    if (s.k <= 0 || s.tau <= 0)
    {
        return Zero;
    }

    const scalar a = Foam::exp(-dt/s.tau);
    const scalar b = Foam::sqrt(-std::expm1(-2*dt/s.tau)*2*s.k/3);

    return
        a*uStar
      + b*gaussian(seed_, uint64_t(id), uint64_t(step), uint64_t(sub));
}


// ************************************************************************* //
