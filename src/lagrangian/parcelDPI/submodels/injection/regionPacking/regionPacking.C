/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "regionPacking.H"
#include "demMaterials.H"
#include "dictKeys.H"
#include "mathematicalConstants.H"
#include "splitmix.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dpiInjectionModels
{
    defineTypeNameAndDebug(regionPacking, 0);
    addToRunTimeSelectionTable(dpiInjectionModel, regionPacking, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Volume of a sphere of diameter d
inline Foam::scalar sphereVolume(const Foam::scalar d)
{
    return Foam::constant::mathematical::pi/6*Foam::pow3(d);
}

//- Densest packing of equal spheres, pi/sqrt(18)
const Foam::scalar maxFraction = 0.74048;


//- Uniform hash grid of spheres for the overlap test
class sphereGrid
{
    Foam::point origin_;
    Foam::scalar h_;
    std::unordered_map<std::int64_t, std::vector<Foam::label>> cells_;
    std::vector<Foam::point> x_;
    std::vector<Foam::scalar> r_;
    std::vector<Foam::scalar> grown_;

    std::int64_t key(const std::int64_t i, const std::int64_t j,
                     const std::int64_t k) const
    {
        // Cells are within 2^20 of the origin in every direction
        const std::int64_t o = 1 << 20;
        return ((i + o) << 42) | ((j + o) << 21) | (k + o);
    }

    std::int64_t index(const Foam::scalar x) const
    {
        return static_cast<std::int64_t>(std::floor(x/h_));
    }

public:

    sphereGrid(const Foam::point& origin, const Foam::scalar h)
    :
        origin_(origin),
        h_(h)
    {}

    //- Insert a sphere of radius <= h/2 and its grown radius <= h/2 among
    //  growing parcels (0: it does not grow)
    void insert
    (
        const Foam::point& x,
        const Foam::scalar r,
        const Foam::scalar grown
    )
    {
        grown_.push_back(grown);
        const Foam::vector d(x - origin_);
        cells_[key(index(d.x()), index(d.y()), index(d.z()))]
            .push_back(Foam::label(x_.size()));
        x_.push_back(x);
        r_.push_back(r);
    }

    //- Move sphere q to x
    void move(const Foam::label q, const Foam::point& x)
    {
        const Foam::vector d0(x_[q] - origin_), d1(x - origin_);
        const std::int64_t k0 = key(index(d0.x()), index(d0.y()), index(d0.z()));
        const std::int64_t k1 = key(index(d1.x()), index(d1.y()), index(d1.z()));
        if (k0 != k1)
        {
            std::vector<Foam::label>& from = cells_[k0];
            from.erase(std::find(from.begin(), from.end(), q));
            cells_[k1].push_back(q);
        }
        x_[q] = x;
    }

    //- Number of spheres
    Foam::label size() const
    {
        return Foam::label(x_.size());
    }

    //- Centre of sphere q
    const Foam::point& centre(const Foam::label q) const
    {
        return x_[q];
    }

    //- Whether a sphere of radius <= h/2 (grown radius among growing
    //  parcels <= h/2, 0 if it does not grow) at x overlaps one in the grid
    //  other than sphere skip
    bool overlaps
    (
        const Foam::point& x,
        const Foam::scalar r,
        const Foam::scalar grown,
        const Foam::label skip = -1
    ) const
    {
        const Foam::vector d(x - origin_);
        const std::int64_t i0 = index(d.x()), j0 = index(d.y()),
            k0 = index(d.z());
        for (std::int64_t i = i0 - 1; i <= i0 + 1; ++i)
        {
            for (std::int64_t j = j0 - 1; j <= j0 + 1; ++j)
            {
                for (std::int64_t k = k0 - 1; k <= k0 + 1; ++k)
                {
                    const auto iter = cells_.find(key(i, j, k));
                    if (iter == cells_.end())
                    {
                        continue;
                    }
                    for (const Foam::label q : iter->second)
                    {
                        if
                        (
                            q != skip
                         && Foam::magSqr(x - x_[q])
                          < Foam::sqr
                            (
                                grown > 0 && grown_[q] > 0
                              ? grown + grown_[q]
                              : r + r_[q]
                            )
                        )
                        {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpiInjectionModels::regionPacking::readFractions
(
    const demMaterials& mat
)
{
    const dictionary& fd = dict_.subDict("fractions");
    const wordList names(fd.toc());

    if (names.empty())
    {
        FatalIOErrorInFunction(fd)
            << "Dictionary " << fd.name() << " is empty: give a fraction per"
            << " type, e.g. fractions { api 1; }; types: " << mat.names()
            << exit(FatalIOError);
    }

    types_.setSize(names.size());
    sizes_.setSize(names.size());
    scalar sum = 0;
    forAll(names, k)
    {
        const label ti = mat.typeIndex(names[k], fd, names[k]);
        if (!mat.isParticleType(ti))
        {
            FatalIOErrorInFunction(fd)
                << "Type '" << names[k] << "' in dictionary " << fd.name()
                << " has no diameter: it is a wall material" << nl
                << "Particle types: " << mat.names() << exit(FatalIOError);
        }

        packedType& t = types_[k];
        t.name = names[k];
        sizes_.set(k, mat.size(ti).clone());
        t.size = &sizes_[k];
        t.rho = mat.density(ti);
        t.meanVolume = constant::mathematical::pi/6*t.size->meanCube();
        t.factor = mat.coarseGraining().factor(ti);
        t.N = mat.N(ti);
        t.api = mat.api(ti);
        t.fraction = fd.get<scalar>(names[k]);
        if (!(t.fraction >= 0))
        {
            FatalIOErrorInFunction(fd)
                << "Entry '" << names[k] << "' = " << t.fraction
                << " in dictionary " << fd.name() << " must be >= 0"
                << exit(FatalIOError);
        }
        sum += t.fraction;
    }

    if (mag(sum - 1) > 1e-6)
    {
        FatalIOErrorInFunction(fd)
            << "The fractions in dictionary " << fd.name() << " sum to "
            << sum << "; they must sum to 1 (basis "
            << dict_.get<word>("basis") << ")"
            << exit(FatalIOError);
    }

    // Number fractions
    scalar norm = 0;
    for (packedType& t : types_)
    {
        const scalar parcelMass = t.rho*t.meanVolume;
        t.x =
            basis_ == fractionBasis::number ? t.fraction
          : basis_ == fractionBasis::mass ? t.fraction/parcelMass
          : t.fraction/(t.N*parcelMass);
        norm += t.x;
    }
    for (packedType& t : types_)
    {
        t.x /= norm;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiInjectionModels::regionPacking::regionPacking
(
    const word& name,
    const dictionary& dict,
    const demMaterials* materials
)
:
    dpiInjectionModel
    (
        name,
        dict,
        {
            "region", "fractions", "basis", "volumeFraction", "nParticles",
            "seed", "U", "omega", "exclude", "avoidInjected",
            "countObstacles", "maxAttempts", "maxShakes", "fillMass"
        }
    ),
    region_(packingRegion::New(dict.subDict("region"))),
    types_(),
    sizes_(),
    basis_(fractionBasis::number),
    volumeFraction_(-1),
    nParticles_(-1),
    fillMass_(-1),
    seed_(dict.get<label>("seed")),
    U_(dict.getOrDefault<vector>("U", Zero)),
    omega_(dict.getOrDefault<vector>("omega", Zero)),
    exclude_(),
    avoidInjected_(dict.getOrDefault<bool>("avoidInjected", true)),
    countObstacles_(dict.getOrDefault<bool>("countObstacles", true)),
    maxAttempts_(dict.getOrDefault<label>("maxAttempts", 10000)),
    maxShakes_(dict.getOrDefault<label>("maxShakes", 20)),
    typeDiameter_()
{
    if (!materials)
    {
        FatalIOErrorInFunction(dict)
            << "Injector " << name << " (regionPacking) needs the material "
            << "table (dem/types) for the types' diameters and densities; "
            << "construct it with the engine's materials"
            << exit(FatalIOError);
    }

    const word basis(dict.get<word>("basis"));
    if (basis == "mass")
    {
        basis_ = fractionBasis::mass;
    }
    else if (basis == "primaryMass")
    {
        basis_ = fractionBasis::primaryMass;
    }
    else if (basis != "number")
    {
        FatalIOErrorInFunction(dict)
            << "Unknown basis '" << basis << "' for entry 'basis' in "
            << "dictionary " << dict.name() << nl
            << "Valid choices: (number mass primaryMass): primaryMass for"
            << " a blend in % w/w (the fractions of all primaries' mass, N"
            << " counted), mass for the fractions of parcel masses"
            << exit(FatalIOError);
    }

    readFractions(*materials);

    for (label i = 0; i < materials->size(); ++i)
    {
        if (materials->isParticleType(i))
        {
            typeDiameter_.insert
            (
                materials->names()[i],
                materials->size(i).maxDiameter()
            );
            typeFactor_.insert
            (
                materials->names()[i],
                materials->coarseGraining().factor(i)
            );
        }
    }

    const bool hasFraction = dict.found("volumeFraction");
    const bool hasNumber = dict.found("nParticles");
    const bool hasMass = dict.found("fillMass");
    if (hasFraction + hasNumber + hasMass != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Injector " << name << " needs exactly one of the entries "
            << "'volumeFraction', 'nParticles' and 'fillMass' (the fill's"
            << " primary mass [kg], N counted) in dictionary "
            << dict.name() << exit(FatalIOError);
    }
    if (hasFraction)
    {
        volumeFraction_ = dict.get<scalar>("volumeFraction");
        if (!(volumeFraction_ > 0) || volumeFraction_ > maxFraction)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'volumeFraction' = " << volumeFraction_
                << " in dictionary " << dict.name() << " cannot be reached: "
                << "it must be > 0 and at most pi/sqrt(18) = " << maxFraction
                << " (the densest packing of equal spheres; random "
                << "sequential packing reaches about 0.38)"
                << exit(FatalIOError);
        }
    }
    else if (hasMass)
    {
        fillMass_ = dict.get<scalar>("fillMass");
        if (!(fillMass_ > 0) || !std::isfinite(fillMass_))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'fillMass' = " << fillMass_ << " in dictionary "
                << dict.name() << " must be > 0 [kg] (a 10 mg fill is"
                << " 1e-5)" << exit(FatalIOError);
        }
    }
    else
    {
        nParticles_ = dict.get<label>("nParticles");
        if (nParticles_ < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'nParticles' = " << nParticles_ << " in dictionary "
                << dict.name() << " must be >= 0" << exit(FatalIOError);
        }
    }

    if (maxAttempts_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxAttempts' = " << maxAttempts_ << " in dictionary "
            << dict.name() << " must be >= 1" << exit(FatalIOError);
    }

    if (maxShakes_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxShakes' = " << maxShakes_ << " in dictionary "
            << dict.name() << " must be >= 0 (0: random sequential addition"
            << " alone)" << exit(FatalIOError);
    }

    if (dict.found("exclude"))
    {
        List<dictionary> ex(dict.get<List<dictionary>>("exclude"));
        exclude_.setSize(ex.size());
        forAll(ex, k)
        {
            // Named after its place, for the warning
            ex[k].name() = dict.name() + ".exclude[" + Foam::name(k) + "]";
            dictKeys::warnUnknown(ex[k], {"centre", "radius"});

            exclude_[k].centre = ex[k].get<point>("centre");
            exclude_[k].radius = ex[k].get<scalar>("radius");
            if (!(exclude_[k].radius > 0))
            {
                FatalIOErrorInFunction(dict)
                    << "Sphere " << k << " of entry 'exclude' in dictionary "
                    << dict.name() << " has radius " << exclude_[k].radius
                    << "; it must be > 0" << exit(FatalIOError);
            }
        }
    }

    for (const packedType& t : types_)
    {
        const scalar dMax = t.size->maxDiameter();
        if (t.x > 0 && !region_->fits(0.5*dMax))
        {
            FatalIOErrorInFunction(dict)
                << "A particle of type " << t.name << " (d = " << dMax
                << " m) does not fit in the " << region_->shapeName()
                << " of dictionary " << dict.subDict("region").name()
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::dpiInjectionModels::regionPacking::counts
(
    const scalar obstacleVolume
) const
{
    label N = nParticles_;

    if (fillMass_ > 0)
    {
        // The mean primary mass a parcel carries, N counted
        scalar mMean = 0;
        for (const packedType& t : types_)
        {
            mMean += t.x*t.N*t.rho*t.meanVolume;
        }
        const scalar n = fillMass_/mMean;
        if (!(n < labelMax))
        {
            FatalIOErrorInFunction(dict_)
                << "Injector " << name_ << ": fillMass " << fillMass_
                << " kg is " << n << " parcels, more than can be counted;"
                << " is it in kg?" << exit(FatalIOError);
        }
        N = label(std::round(n));
    }
    else if (N < 0)
    {
        const scalar target =
            volumeFraction_*region_->volume()
          - (countObstacles_ ? obstacleVolume : 0);

        if (!(target > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "Injector " << name_ << ": the obstacles in the "
                << region_->shapeName() << " already occupy "
                << obstacleVolume/region_->volume() << " of it, at least the"
                << " target volumeFraction " << volumeFraction_
                << " in dictionary " << dict_.name() << "; nothing to pack"
                << " (raise volumeFraction or set countObstacles false)"
                << exit(FatalIOError);
        }

        scalar vMean = 0;
        for (const packedType& t : types_)
        {
            vMean += t.x*t.meanVolume;
        }
        N = label(std::round(target/vMean));
    }

    // Largest remainder: counts sum to N, each within 1 of N x_k
    labelList n(types_.size());
    scalarList rem(types_.size());
    label assigned = 0;
    forAll(types_, k)
    {
        const scalar exact = N*types_[k].x;
        n[k] = label(std::floor(exact));
        rem[k] = exact - n[k];
        assigned += n[k];
    }
    labelList order(identity(types_.size()));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&](const label a, const label b) { return rem[a] > rem[b]; }
    );
    for (label k = 0; assigned < N; ++k)
    {
        ++n[order[k % order.size()]];
        ++assigned;
    }

    return n;
}


void Foam::dpiInjectionModels::regionPacking::pack
(
    const UList<injectionSpec>& previous,
    DynamicList<injectionSpec>& particles
) const
{
    Random rnd(seed_);

    // Largest packed diameter: the grid cell (the grown diameter of
    // growing parcels if larger)
    scalar dMax = 0;
    for (const packedType& t : types_)
    {
        dMax = max(dMax, t.factor*t.size->maxDiameter());
    }
    // The grown radius of a particle of radius r and contact radius
    // factor f, 0 if it does not grow
    const auto grownRadius = [](const scalar r, const scalar f)
    {
        return f > 1 ? f*r : 0;
    };

    // Obstacles near the region: small ones into the grid, larger ones in
    // a list
    const boundBox near(region_->bounds());
    const point origin(near.min() - vector::uniform(dMax));
    sphereGrid grid(origin, dMax);
    List<sphere> large;
    scalar obstacleVolume = 0;
    label nObstacles = 0;

    auto addObstacle = [&](const point& c, const scalar r, const scalar f)
    {
        for (direction cmpt = 0; cmpt < 3; ++cmpt)
        {
            if
            (
                c[cmpt] < near.min()[cmpt] - r - dMax
             || c[cmpt] > near.max()[cmpt] + r + dMax
            )
            {
                return;
            }
        }
        ++nObstacles;
        if (region_->contains(c, 0))
        {
            obstacleVolume += sphereVolume(2*r);
        }
        if (max(r, grownRadius(r, f)) <= 0.5*dMax)
        {
            grid.insert(c, r, grownRadius(r, f));
        }
        else
        {
            large.append(sphere{c, r});
        }
    };

    for (const sphere& s : exclude_)
    {
        addObstacle(s.centre, s.radius, 1);
    }
    if (avoidInjected_)
    {
        for (const injectionSpec& s : previous)
        {
            const scalar d = s.d > 0 ? s.d : typeDiameter_.lookup(s.type, -1);
            if (d > 0)
            {
                addObstacle
                (
                    s.position, 0.5*d, typeFactor_.lookup(s.type, 1)
                );
            }
        }
    }

    const labelList n(counts(obstacleVolume));

    // Each particle's type and diameter, drawn by number from its type's
    // distribution, stratified: the m-th of n draws is the quantile of
    // (m + v)/n, v uniform in [0, 1). So the drawn sizes' distribution
    // is within 1/n of the typed one at every size, and their mean d^3
    // (the fill's mass) within (dmax^3 - dmin^3)/n of its mean, where
    // independent draws would miss the mass by several times d^3's
    // spread over sqrt(n) (a GSD of 1.8: 20 % for 600 parcels). The v come
    // from counter-based numbers of (seed, type, m), so the placement's
    // draws (rnd) are those of one-size types alone
    struct particle { label type; scalar d; };
    std::vector<particle> all;
    forAll(types_, k)
    {
        const sizeDistribution& size = *types_[k].size;
        const uint64_t stream =
            splitmix(splitmix(uint64_t(seed_)) ^ uint64_t(k + 1));
        for (label m = 0; m < n[k]; ++m)
        {
            // 53 random bits: v in [0, 1)
            const scalar v =
                scalar(splitmix(stream + uint64_t(m)) >> 11)
               /9007199254740992.0;    // 2^53
            all.push_back(particle{k, size.diameter((m + v)/n[k])});
        }
    }

    // Larger particles first (a large particle finds no room among small
    // ones); of equal size, in type then draw order
    std::stable_sort
    (
        all.begin(),
        all.end(),
        [](const particle& a, const particle& b) { return a.d > b.d; }
    );

    const label nTotal = label(all.size());

    const scalar V = region_->volume();
    scalar placedVolume = 0;
    label nPlaced = 0;
    scalar nDraws = 0;

    // The particles placed so far: their grid index, their entry in
    // particles, radius and grown radius (for the shaking below)
    struct placedSphere { label grid, spec; scalar r, grown; };
    std::vector<placedSphere> placedSpheres;
    auto hitsLarge = [&](const point& p, const scalar r)
    {
        for (const sphere& s : large)
        {
            if (magSqr(p - s.centre) < sqr(r + s.radius))
            {
                return true;
            }
        }
        return false;
    };

    // Random sequential addition: maxAttempts draws of a free centre
    auto tryPlace = [&](const packedType& t, const scalar r)
    {
        const scalar grown = grownRadius(r, t.factor);
        for (label attempt = 0; attempt < maxAttempts_; ++attempt)
        {
            ++nDraws;
            point p;
            if
            (
                !region_->sample(rnd, r, p)
             || grid.overlaps(p, r, grown)
             || hitsLarge(p, r)
            )
            {
                continue;
            }

            placedSpheres.push_back
            (
                placedSphere{grid.size(), particles.size(), r, grown}
            );
            grid.insert(p, r, grown);
            injectionSpec spec;
            spec.position = p;
            spec.U = U_;
            spec.omega = omega_;
            spec.type = t.name;
            spec.d = t.size->fixed() ? -1 : 2*r;
            particles.append(spec);
            return true;
        }
        return false;
    };

    // When addition jams (no free centre in maxAttempts draws), the placed
    // particles are shaken: sweeps of random moves of up to a quarter
    // radius, each kept if the particle stays wholly inside and overlaps
    // nothing (hard-sphere Monte Carlo). Sequential addition leaves the
    // placed particles where they first fitted, a jammed arrangement well
    // below what the region holds (the quick inhaler's cone, its top
    // narrower than a carrier, jammed at 0.286-0.293 for most seeds); the
    // shaken arrangement relaxes and opens room. A packing that needed no
    // shaking is unchanged (same draws)
    const label nSweeps = 10;
    auto shake = [&]()
    {
        for (label sweep = 0; sweep < nSweeps; ++sweep)
        {
            for (const placedSphere& ps : placedSpheres)
            {
                const scalar step = 0.5*ps.r;
                const point p
                (
                    grid.centre(ps.grid)
                  + step*(rnd.sample01<vector>() - vector::uniform(0.5))
                );
                if
                (
                    region_->contains(p, ps.r)
                 && !grid.overlaps(p, ps.r, ps.grown, ps.grid)
                 && !hitsLarge(p, ps.r)
                )
                {
                    grid.move(ps.grid, p);
                    particles[ps.spec].position = p;
                }
            }
        }
    };

    label nShakes = 0;
    // The primaries' mass of each type, N counted, as drawn
    scalarList typeMass(types_.size(), Zero);
    for (const particle& a : all)
    {
        const packedType& t = types_[a.type];
        const scalar r = 0.5*a.d;

        {
            bool placed = tryPlace(t, r);
            for (label round = 0; !placed && round < maxShakes_; ++round)
            {
                shake();
                ++nShakes;
                placed = tryPlace(t, r);
            }

            if (!placed)
            {
                FatalIOErrorInFunction(dict_)
                    << "Injector " << name_ << " (regionPacking, seed "
                    << seed_ << "): could not place particle " << nPlaced + 1
                    << " of " << nTotal << " (type " << t.name << ", d "
                    << a.d << " m) without overlap after " << maxAttempts_
                    << " attempts (maxAttempts), each of " << maxShakes_
                    << " times after shaking the placed particles"
                    << " (maxShakes)." << nl
                    << "    Reached solid fraction "
                    << (placedVolume + (countObstacles_ ? obstacleVolume : 0))/V
                    << " of the " << region_->shapeName() << " (target "
                    << (volumeFraction_ > 0 ? "volumeFraction " : "parcels ")
                    << (volumeFraction_ > 0 ? volumeFraction_ : scalar(nTotal))
                    << ", obstacles " << obstacleVolume/V << ")." << nl
                    << "    Shaken random packing of equal spheres reaches"
                    << " about 0.5 in bulk, less near walls: lower"
                    << " volumeFraction or nParticles, enlarge the region, or"
                    << " raise maxAttempts or maxShakes in dictionary "
                    << dict_.name() << exit(FatalIOError);
            }

            placedVolume += sphereVolume(a.d);
            typeMass[a.type] += t.N*t.rho*sphereVolume(a.d);
            ++nPlaced;
        }
    }

    Info<< "    regionPacking " << name_ << ": " << nPlaced << " particles (";
    forAll(types_, k)
    {
        Info<< (k ? " " : "") << types_[k].name << " " << n[k];
    }
    Info<< ") in " << region_->shapeName() << " of volume " << V
        << " m^3, solid fraction "
        << (placedVolume + (countObstacles_ ? obstacleVolume : 0))/V;
    if (volumeFraction_ > 0)
    {
        Info<< " (target " << volumeFraction_ << ")";
    }
    Info<< ", " << nObstacles << " obstacles (" << obstacleVolume/V
        << " of the region), seed " << seed_ << ", " << nDraws << " draws, "
        << nShakes << " shakes" << endl;

    // The blend as a formulator reads it: each type's parcels, primaries
    // (N counted) and mass in mg and % w/w, and the API per carrier. With
    // basis mass at N > 1 the API's w/w is N times what the fractions say
    scalar totalMass = 0, apiPrimaries = 0, carriers = 0;
    forAll(types_, k)
    {
        const packedType& t = types_[k];
        totalMass += typeMass[k];
        (t.api ? apiPrimaries : carriers) += n[k]*t.N;
    }
    Info<< "    regionPacking " << name_ << ": the blend";
    forAll(types_, k)
    {
        const packedType& t = types_[k];
        const scalar m = typeMass[k];
        char text[160];
        std::snprintf
        (
            text, sizeof text,
            "%s %s %ld parcels = %.6g primaries, %.4g mg (%.4g %% w/w)",
            k ? ";" : ":", t.name.c_str(), long(n[k]), n[k]*t.N, 1e6*m,
            totalMass > 0 ? 100*m/totalMass : 0.0
        );
        Info<< text;
    }
    if (carriers > 0)
    {
        char text[64];
        std::snprintf(text, sizeof text, "%.4g", apiPrimaries/carriers);
        Info<< "; " << text << " API primaries per carrier";
    }
    Info<< endl;

    // The drawn sizes of each polydisperse type beside its distribution:
    // the medians by number and by mass of the parcels' primaries (a
    // parcel's N primaries have its diameter, so parcels weigh alike)
    forAll(types_, k)
    {
        const sizeDistribution& size = *types_[k].size;
        if (size.fixed() || !n[k])
        {
            continue;
        }
        std::vector<scalar> d;
        scalar cubes = 0;
        for (const particle& a : all)
        {
            if (a.type == k)
            {
                d.push_back(a.d);
                cubes += pow3(a.d);
            }
        }
        std::sort(d.begin(), d.end());
        scalar below = 0;
        std::size_t massMedian = 0;
        while
        (
            massMedian + 1 < d.size()
         && below + pow3(d[massMedian]) < 0.5*cubes
        )
        {
            below += pow3(d[massMedian++]);
        }
        Info<< "    regionPacking " << name_ << ": " << types_[k].name
            << " sizes drawn: CMD " << d[d.size()/2] << " m, MMD "
            << d[massMedian] << " m, from " << d.front() << " to "
            << d.back() << " m (" << size.description().c_str() << ")"
            << endl;
    }
}


void Foam::dpiInjectionModels::regionPacking::inject
(
    const scalar t0,
    const scalar t1,
    DynamicList<injectionSpec>& particles
)
{
    if (SOI_ >= t0 && SOI_ < t1)
    {
        // The earlier injectors' particles of this step are obstacles
        const List<injectionSpec> previous(particles);
        pack(previous, particles);
    }
}


// ************************************************************************* //
