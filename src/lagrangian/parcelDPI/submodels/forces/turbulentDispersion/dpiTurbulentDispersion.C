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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiTurbulentDispersion, 0);
}


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
    delta_(dict.getOrDefault<scalar>("delta", 0)),
    Cs_(dict.getOrDefault<scalar>("Cs", 0.08)),
    C0_(dict.getOrDefault<scalar>("C0", 2.1)),
    CL_(1/(0.5 + 0.75*C0_)),
    seed_(uint64_t(dict.getOrDefault<label>("seed", 0)))
{
    // The keys read above
    dictKeys::warnUnknown
    (
        dict,
        {"legacyTimeScale", "delta", "Cs", "C0", "seed"}
    );

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

    Info<< "Turbulent dispersion (LES subgrid, Langevin): "
        << (legacyTimeScale_
            ? "legacyTimeScale (the reference: tau* = C_L k/((nu + nu_e)|S|)"
              ", |S| = sqrt(S:S))"
            : "tau* = C_L k/((nu + nu_e)|S|^2), |S| = sqrt(2 S:S)")
        << ", Cs " << Cs_ << ", C0 " << C0_ << ", C_L " << CL_
        << ", delta ";
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
