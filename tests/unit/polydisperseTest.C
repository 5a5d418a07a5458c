/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the models with polydisperse parcels
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    Parcels of different primary diameters in one material type (the API a
    log-normal, the carrier a table: dem/types sizeDistribution), each model
    family against a closed form with every row's own r, m or d, or an
    invariance:

    - contacts: hertzParcel with historyParcel, pair and wall, the damped
      Hertz force with R* = r1 r2/(r1 + r2) and m* of the two rows' masses,
      the tangential force of the same, each row's torque with its own
      lever arm; the same forces with the rows swapped;
    - coarse-graining: coatingCoverage meets two API parcels at
      sqrt(N)(r1 + r2) with the primaries' R*, and the agglomerate tracker
      links them at the same distance;
    - cohesion: vdwGuParcel, API-API and carrier-API of non-nominal sizes,
      against the exact Hamaker sphere-sphere force of the rows' radii
      (shifted branch, plateau, cut-off at the pair's own R*);
    - drag: wenYuParcel on two parcels of different d in one gas, each the
      Wen-Yu closed form of its own d and Reynolds number, N times;
    - void fraction: divided and apiParcel remove sum (N) pi/6 d^3 of
      parcels of different d from the cells of a mesh, each parcel's 29
      points at its own radius;
    - time-step check: the contact and Rayleigh times are the smallest
      primary's; a step fine for the median is refused;
    - agglomerates: linked by the rows' own radii; a cluster's mass is
      sum rho pi/6 d^3 per copy, N times that in its parcels;
    - emitted dose and impactor: singlets of different d in the stage of
      their own aerodynamic diameter d sqrt(rho/1000), with their own mass;
    - device retention: a parcel is on a wall when its own radius reaches
      it, and counts its own N rho pi/6 d^3.

    The void fraction and retention tests build a two-cell mesh in memory
    (no case files); retention writes its file under a temporary
    directory that the test removes.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "demEngine.H"
#include "guideParticles.H"
#include "guideDecks.H"
#include "vdwGuParcel.H"
#include "dpiFluidForce.H"
#include "dpiVoidFraction.H"
#include "agglomerateTracker.H"
#include "dpiEmittedDose.H"
#include "impactorStages.H"
#include "dpiDeviceRetention.H"
#include "Time.H"
#include "fvMesh.H"
#include "polyMesh.H"
#include "OSspecific.H"
#include "cellModel.H"
#include "mathematicalConstants.H"
#include <cmath>
#include <fstream>
#include <unistd.h>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

using guideDecks::toDict;
using guideDecks::cohesionBlock;
using guideParticles::rho;
using guideParticles::mass;

// Young's modulus and Poisson's ratio of every material here (theory 7.2)
const scalar Y = 5e8;
const scalar nu = 0.35;

// Two API primaries of one type, far from the type's median (a
// log-normal of MMD 2.5 um, GSD 1.8, truncated at 1 and 8 um), and a
// carrier of the table's 40 to 120 um, not its median
const scalar r1 = 0.75e-6;
const scalar r2 = 3e-6;
const scalar rC = 25e-6;

// The types: carrier (table by mass), api (log-normal, coarsening N, api),
// wall; the models as given (coarseGraining, cohesion), a floor z = 0
// when floor
std::string deck
(
    const scalar N,
    const std::string& models,
    const bool floor = false,
    const scalar dt = 1e-10,
    const std::string& apiSize =
        "sizeDistribution { type logNormal; median 2.5e-6; gsd 1.8;"
        " basis mass; min 1e-6; max 8e-6; }"
)
{
    std::ostringstream os;
    os.precision(17);
    os  << "timeStep " << dt << ";\n"
        << "types {\n"
        << "  carrier { sizeDistribution { type table; basis mass;"
        << " diameters (40e-6 55e-6 70e-6 90e-6 120e-6);"
        << " undersize (0 0.1 0.5 0.9 1); }"
        << " density " << rho << "; youngsModulus " << Y
        << "; poissonsRatio " << nu << "; }\n"
        << "  api { " << apiSize << " density " << rho
        << "; youngsModulus " << Y << "; poissonsRatio " << nu
        << "; N " << N << "; api true; }\n"
        << "  wall { youngsModulus " << Y << "; poissonsRatio " << nu
        << "; }\n"
        << "}\n"
        << "pairs { default { restitution 0.85; friction 0.45;"
        << " rollingFriction 0; } }\n"
        << "normalModel hertzParcel; tangentialModel historyParcel;\n"
        << "rollingModel none;\n"
        << models << "\n";
    if (floor)
    {
        os  << "walls { floor { type plane; point (0 0 0); normal (0 0 1);"
            << " material wall; } }\n";
    }
    os  << "neighbourSearch { skin 1e-6; }\n"
        << "timeStepCheck { maxImpactVelocity 1; }\n";
    return os.str();
}

const std::string plain
(
    "cohesionModel none; coarseGraining scaledContacts;"
);

// Type indices in dictionary order
const label carrierType = 0;
const label apiType = 1;

// Y* of two of the materials, 1/((1 - nu^2)/Y + (1 - nu^2)/Y)
scalar Ystar()
{
    return Y/(2*(1 - sqr(nu)));
}

// The damped Hertz law of hertzParcel (theory 1.3) written out: the
// normal force on one primary at overlap delta, normal velocity vn
// (< 0 approaching), reduced radius R and mass M, restitution e
scalar hertzForce
(
    const scalar delta,
    const scalar vn,
    const scalar R,
    const scalar M,
    const scalar e = 0.85
)
{
    const scalar beta = std::log(e)/std::sqrt(sqr(std::log(e)) + sqr(pi));
    const scalar kn = 4.0/3.0*Ystar()*std::sqrt(R*delta);
    const scalar Sn = 2*Ystar()*std::sqrt(R*delta);
    const scalar gammaN = -2*std::sqrt(5.0/6.0)*beta*std::sqrt(Sn*M);
    return kn*delta - gammaN*vn;
}

// Hamaker's attraction of two spheres of radii a, b at surface gap s, from
// the derivative of the sphere-sphere energy
//   U = -A/6 [2ab/(D^2 - (a+b)^2) + 2ab/(D^2 - (a-b)^2)
//             + ln((D^2 - (a+b)^2)/(D^2 - (a-b)^2))],  D = a + b + s,
// as written (not the model's simplified form)
scalar hamaker(const scalar A, const scalar a, const scalar b, const scalar s)
{
    const scalar D = a + b + s;
    const scalar p = sqr(D) - sqr(a + b);
    const scalar q = sqr(D) - sqr(a - b);
    return A*D/3*(2*a*b/sqr(p) + 2*a*b/sqr(q) - 1/p + 1/q);
}

// Two rows i (radius ri, type ti) and j (rj, tj), at the centre distance
// dist along a skew unit vector n (from j to i), with velocities
// vi n + slip and vj n, no spin: the forces and torques on i and j after
// evaluateForces (one sub-step's, from no history). swap: append j
// before i
struct pairScene
{
    vector n = vector(1, 2, 2)/3;
    vector fi = Zero, fj = Zero;
    vector ti = Zero, tj = Zero;
};

pairScene pairForces
(
    demEngine& engine,
    const scalar ri, const label ti,
    const scalar rj, const label tj,
    const scalar dist,
    const scalar vi, const scalar vj,
    const scalar N,
    const bool swap = false,
    const vector& slip = Zero
)
{
    pairScene p;
    const point xj(1e-5, -2e-5, 3e-5);
    const point xi(xj + dist*p.n);
    const scalar Ni = (ti == apiType) ? N : 1;
    const scalar Nj = (tj == apiType) ? N : 1;
    demState s;
    if (!swap)
    {
        s.append(xi, vi*p.n + slip, Zero, ri, mass(ri), Ni, ti, 0);
        s.append(xj, vj*p.n, Zero, rj, mass(rj), Nj, tj, 1);
    }
    else
    {
        s.append(xj, vj*p.n, Zero, rj, mass(rj), Nj, tj, 0);
        s.append(xi, vi*p.n + slip, Zero, ri, mass(ri), Ni, ti, 1);
    }
    engine.evaluateForces(s);
    p.fi = s.f[swap ? 1 : 0];
    p.fj = s.f[swap ? 0 : 1];
    p.ti = s.torque[swap ? 1 : 0];
    p.tj = s.torque[swap ? 0 : 1];
    return p;
}

// A mesh of nx x 1 x 1 hex cells over [x0, x0 + nx h] x [0, h] x [0, h]
autoPtr<polyMesh> boxMesh
(
    const Time& runTime,
    const label nx,
    const scalar x0,
    const scalar h,
    const word& region = polyMesh::defaultRegion
)
{
    pointField pts(4*(nx + 1));
    for (label i = 0; i <= nx; ++i)
    {
        const scalar x = x0 + i*h;
        pts[4*i + 0] = point(x, 0, 0);
        pts[4*i + 1] = point(x, h, 0);
        pts[4*i + 2] = point(x, h, h);
        pts[4*i + 3] = point(x, 0, h);
    }
    const cellModel& hex = cellModel::ref(cellModel::HEX);
    cellShapeList shapes(nx);
    for (label i = 0; i < nx; ++i)
    {
        // OpenFOAM's hex: (0 0 0) (1 0 0) (1 1 0) (0 1 0), then z = 1
        const label a = 4*i, b = 4*(i + 1);
        shapes[i] = cellShape
        (
            hex,
            labelList({a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2})
        );
    }
    return autoPtr<polyMesh>::New
    (
        IOobject
        (
            region,
            runTime.constant(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        std::move(pts),
        shapes,
        faceListList(),
        wordList(),
        PtrList<dictionary>(),
        "walls",
        "wall"
    );
}

// The same box as the finite-volume mesh of region0 (what the function
// objects look up), its boundary one wall patch
autoPtr<fvMesh> fvBoxMesh
(
    const Time& runTime,
    const label nx,
    const scalar x0,
    const scalar h
)
{
    autoPtr<polyMesh> pm(boxMesh(runTime, nx, x0, h, "box"));
    autoPtr<fvMesh> mesh
    (
        autoPtr<fvMesh>::New
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            pointField(pm->points()),
            faceList(pm->faces()),
            labelList(pm->faceOwner()),
            labelList(pm->faceNeighbour())
        )
    );
    List<polyPatch*> patches(pm->boundaryMesh().size());
    forAll(patches, patchi)
    {
        patches[patchi] =
            pm->boundaryMesh()[patchi].clone(mesh->boundaryMesh()).ptr();
    }
    mesh->addFvPatches(patches);
    return mesh;
}

// A cloud that holds given parcel samples, registered where the function
// objects look for the cloud (dpiCloudInterface::find)
class sampleCloud
:
    public regIOobject,
    public dpiCloudInterface
{
    const word name_;
    const parcelSamples samples_;
    const List<escapedParcel> none_;

public:

    sampleCloud
    (
        const objectRegistry& db,
        const word& name,
        const parcelSamples& s
    )
    :
        regIOobject
        (
            IOobject
            (
                name, db.time().timeName(), db,
                IOobject::NO_READ, IOobject::NO_WRITE
            )
        ),
        name_(name),
        samples_(s)
    {}

    virtual bool writeData(Ostream&) const
    {
        return true;
    }

    virtual const word& cloudName() const
    {
        return name_;
    }

    virtual void samples(parcelSamples& s) const
    {
        s = samples_;
    }

    virtual const UList<escapedParcel>& escapedParcels() const
    {
        return none_;
    }
};

} // End anonymous namespace


// Contacts. Two API primaries of radii 0.75 and 3 um (one type) at an
// overlap of 2 nm, approaching at 0.3 m/s, N = 10: the force on each is
// N times the damped Hertz law with their own R* = r1 r2/(r1 + r2) and
// m* = m1 m2/(m1 + m2), and does not depend on the rows' order; sliding,
// the history model's tangential force has the pair's R* and m* too and
// each row's torque its own lever arm; on a floor each row's force is the
// law with R* = r and m* = m of its own. Head-on without spin: the
// tangential force is zero. Tolerance: the
// overlap is the difference of two ~4 um lengths, rounded to ~1e-21 m,
// i.e. 5e-13 of it (F ~ delta^1.5: ~1e-12); 1e-9 holds that with margin,
// while the type's number median for both rows (R* 0.36 um against
// 0.6 um) misses by more than 10 %.
TEST(polydisperse, contactsUseTheRowsRadiiAndMasses)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar N = 10, delta = 2e-9, vi = -0.2, vj = 0.1;
    const scalar R = r1*r2/(r1 + r2);
    const scalar M = mass(r1)*mass(r2)/(mass(r1) + mass(r2));
    const scalar f = N*hertzForce(delta, vi - vj, R, M);

    demEngine engine(toDict(deck(N, plain)));
    const pairScene a =
        pairForces(engine, r1, apiType, r2, apiType, r1 + r2 - delta, vi, vj, N);
    demEngine engine2(toDict(deck(N, plain)));
    const pairScene b = pairForces
    (
        engine2, r1, apiType, r2, apiType, r1 + r2 - delta, vi, vj, N, true
    );

    EXPECT_NEAR((a.fi & a.n)/f, 1, 1e-9);
    EXPECT_LT(mag(a.fi - (a.fi & a.n)*a.n), 1e-9*f) << "tangential";
    EXPECT_LT(mag(a.fi + a.fj), 1e-12*f) << "action and reaction";
    EXPECT_LT(mag(b.fi - a.fi), 1e-9*f) << "rows swapped";
    EXPECT_LT(mag(b.fj - a.fj), 1e-9*f) << "rows swapped";

    // Two rows of the type's number median (1.43 um) would feel another
    // force at that overlap (the check can fail)
    const scalar rMed =
        0.5*engine.materials().size(apiType).numberMedian();
    EXPECT_GT
    (
        mag(N*hertzForce(delta, vi - vj, rMed/2, mass(rMed)/2)/f - 1), 0.1
    );

    // Sliding at 0.1 m/s along t (below the Coulomb cap: the sticking
    // branch, |F_t| ~ 0.15 mu f_n): the history's trial step and dashpot,
    // F_t = -(k_t dt + gamma_t) v_s, k_t = 8 G* sqrt(R* delta),
    // gamma_t = -2 sqrt(5/6) beta sqrt(k_t m*), with the pair's R* and m*,
    // and each row's torque -c (n x F_t) with its own lever arm
    // c = r - delta/2
    {
        const vector t(vector(2, -2, 1)/3);
        const scalar vt = 0.1, dt = 1e-10;
        const scalar Gstar = Y/(4*(2 - nu)*(1 + nu));
        const scalar kt = 8*Gstar*std::sqrt(R*delta);
        const scalar beta =
            std::log(0.85)/std::sqrt(sqr(std::log(0.85)) + sqr(pi));
        const scalar gammaT = -2*std::sqrt(5.0/6.0)*beta*std::sqrt(kt*M);
        const vector Ft(-(kt*dt + gammaT)*vt*t);
        ASSERT_LT(mag(Ft), 0.45*N*hertzForce(delta, vi - vj, R, M));

        demEngine slideEngine(toDict(deck(N, plain)));
        const pairScene p = pairForces
        (
            slideEngine, r1, apiType, r2, apiType, r1 + r2 - delta, vi, vj, N,
            false, vt*t
        );
        const vector fit(p.fi - (p.fi & p.n)*p.n);
        EXPECT_LT(mag(fit - N*Ft), 1e-9*N*mag(Ft));
        EXPECT_NEAR((p.fi & p.n)/f, 1, 1e-9);
        const vector Ti(-N*(r1 - 0.5*delta)*(p.n ^ Ft));
        const vector Tj(-N*(r2 - 0.5*delta)*(p.n ^ Ft));
        EXPECT_LT(mag(p.ti - Ti), 1e-9*mag(Ti)) << "torque on the small";
        EXPECT_LT(mag(p.tj - Tj), 1e-9*mag(Tj)) << "torque on the large";
    }

    // A floor: each row its own R* = r and m* = m (pairScaling: N)
    demEngine floorEngine(toDict(deck(N, plain, true)));
    demState s;
    const scalar vz = -0.3;
    s.append(point(0, 0, r1 - delta), vector(0, 0, vz), Zero, r1, mass(r1), N,
             apiType, 0);
    s.append(point(2e-5, 0, r2 - delta), vector(0, 0, vz), Zero, r2,
             mass(r2), N, apiType, 1);
    floorEngine.evaluateForces(s);
    const scalar rs[2] = {r1, r2};
    for (label k = 0; k < 2; ++k)
    {
        const scalar fw = N*hertzForce(delta, vz, rs[k], mass(rs[k]));
        EXPECT_NEAR(s.f[k].z()/fw, 1, 1e-9) << "row " << k;
        EXPECT_LT(mag(s.f[k] - s.f[k].z()*vector(0, 0, 1)), 1e-9*fw);
    }
}


// Coarse-graining. coatingCoverage grows API parcels that meet to
// r_c = sqrt(N) r: two API parcels of N = 10 and radii 0.75 and 3 um
// touch at sqrt(N)(r1 + r2) (coarseGrainingModel::radiusSum; an API and a
// carrier at r1 + rC), and at 2 nm inside that distance, at rest, feel N
// times the primaries' Hertz force with their own R*; 1 nm outside it,
// nothing. The agglomerate tracker links them at the same distance
// (linkGap 0): 0.1 nm inside, not 0.1 nm outside. Tolerances: radiusSum
// is one product and sum (1e-15); the force as in the contacts' test
// (1e-9: the distances are 3.2 times longer, the overlap's rounding ~3
// times coarser).
TEST(polydisperse, grownContactsUseEachParcelsRadius)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar N = 10, G = std::sqrt(N), delta = 2e-9;
    const std::string coverage
    (
        "cohesionModel none; coarseGraining coatingCoverage;"
    );
    const demMaterials mat(toDict(deck(N, coverage)), false);
    const coarseGrainingModel& cg = mat.coarseGraining();
    EXPECT_NEAR(cg.radiusSum(r1, apiType, r2, apiType)/(G*(r1 + r2)), 1, 1e-15);
    EXPECT_EQ(cg.radiusSum(r1, apiType, rC, carrierType), r1 + rC);

    const scalar R = r1*r2/(r1 + r2);
    const scalar f = N*hertzForce(delta, 0, R, 1);
    {
        demEngine engine(toDict(deck(N, coverage)));
        const pairScene p = pairForces
        (
            engine, r1, apiType, r2, apiType, G*(r1 + r2) - delta, 0, 0, N
        );
        EXPECT_NEAR((p.fi & p.n)/f, 1, 1e-9);
        EXPECT_LT(mag(p.fi + p.fj), 1e-12*f);
    }
    {
        demEngine engine(toDict(deck(N, coverage)));
        const pairScene p = pairForces
        (
            engine, r1, apiType, r2, apiType, G*(r1 + r2) + 1e-9, 0, 0, N
        );
        EXPECT_EQ(mag(p.fi), 0) << "outside the grown radii";
    }

    // The tracker's link distance is the engine's contact distance
    const dictionary noKeys;
    agglomerateTracker tracker(noKeys, fileName::null);
    for (const scalar gap : {-1e-10, 1e-10})
    {
        demState s;
        s.append(Zero, Zero, Zero, r1, mass(r1), N, apiType, 0);
        s.append(point(G*(r1 + r2) + gap, 0, 0), Zero, Zero, r2, mass(r2), N,
                 apiType, 1);
        labelList ids;
        tracker.update(s, mat, ids);
        EXPECT_EQ(ids[1] == ids[0], gap < 0) << "gap " << gap;
    }
}


// Cohesion. vdwGuParcel with the guide's block (A_R = 5e-19 J): two API
// of 0.75 and 3 um and a carrier of 25 um with an API of 0.75 um (none of
// the types' medians), N = 10 (pair factor S = max(N_i, N_j) = 10):
// - at a gap of 20 nm (shifted branch): S F(A_R, s - s0), F the exact
//   Hamaker sphere-sphere force of the rows' radii;
// - at 3 nm (below sMins): the plateau S F(A_R/chi, sMin);
// - the cut-off at the pair's own R*: attraction at 0.999 R*, none at
//   1.001 R*.
// Tolerances: the gap is the difference of lengths up to 26 um, rounded
// to ~4e-21 m, 3e-13 of 16 nm (F ~ s^-2: 6e-13); the exact form and the
// model's simplified one agree to round-off (in the exact form the
// leading term 2ab/p^2 is ~R*/s times the others, so their sum cancels
// nothing); 1e-9. Two API of the type's number median (1.43 um) would pull with
// an R* of 0.36 um instead of 0.6 um: 40 % less.
TEST(polydisperse, cohesionUsesTheRowsRadii)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar N = 10, A = 5e-19, chi = 3.177672;
    const std::string models
    (
        "cohesionModel vdwGuParcel; coarseGraining scaledContacts;\n"
      + cohesionBlock(A)
    );

    const demMaterials mat(toDict(deck(N, models)), false);
    const scalar rMed = 0.5*mat.size(apiType).numberMedian();

    struct pairCase
    {
        const char* name;
        scalar ri, rj;
        label tj;
        scalar s0, sMins;
    };
    const pairCase cases[] =
    {
        {"api-api", r1, r2, apiType, 4.295e-9, 6.077e-9},
        {"carrier-api", r1, rC, carrierType, 4.445e-9, 6.227e-9}
    };

    for (const pairCase& c : cases)
    {
        const scalar R = c.ri*c.rj/(c.ri + c.rj);
        auto pull = [&](const scalar gap)
        {
            demEngine engine(toDict(deck(N, models)));
            const pairScene p = pairForces
            (
                engine, c.ri, apiType, c.rj, c.tj, c.ri + c.rj + gap, 0, 0, N
            );
            EXPECT_LT(mag(p.fi + p.fj), 1e-12*mag(p.fi) + VSMALL);
            // Attraction: the force on i points to j (-n)
            return -(p.fi & p.n);
        };

        const scalar s = 20e-9;
        const scalar shifted = N*hamaker(A, c.ri, c.rj, s - c.s0);
        EXPECT_NEAR(pull(s)/shifted, 1, 1e-9) << c.name << " shifted";
        EXPECT_GT(shifted/(N*hamaker(A, rMed, rMed, s - c.s0)), 1.3);

        // The small-gap limit A R*/(6 s^2) of the rows' R*, to O(s/R*)
        EXPECT_NEAR
        (
            shifted/(N*A*R/(6*sqr(s - c.s0))), 1, 2*(s - c.s0)/R
        ) << c.name;

        const scalar plateau = N*hamaker(A/chi, c.ri, c.rj, 1e-9);
        EXPECT_NEAR(pull(3e-9)/plateau, 1, 1e-9) << c.name << " plateau";

        EXPECT_GT(pull(0.999*R), 0) << c.name << " inside R*";
        EXPECT_EQ(pull(1.001*R), 0) << c.name << " beyond R*";
    }
}


// Drag. wenYuParcel, two parcels of N = 10 and d = 1.5 and 6 um at rest in
// one gas (air, alpha 0.8, 10 m/s): each force is N times the Wen-Yu
// closed form of its own d, C_D = 24/Re (1 + 0.15 Re^0.687) alpha^-1.65
// with Re = alpha d |u_r|/nu of its own d (0.79 and 3.2 here), F = N pi/8
// d^2 rho C_D |u_r| u_r; the closed form is written as the theory gives
// it, the model without the 1/Re (a few roundings apart): 1e-12.
TEST(polydisperse, dragOfEachParcelIsItsOwnDiameters)
{
    FatalIOError.throwExceptions();

    PtrList<dpiFluidForce> forces(1);
    forces.set(0, dpiFluidForce::New("wenYuParcel", dictionary()));

    dpiFluidForce::fluidState fl;
    fl.rho = 1.2;
    fl.nu = 1.511e-5;
    fl.alpha = 0.8;
    fl.U = vector(10, 0, 0);

    const scalar N = 10;
    const vector v(0, 0, 0.05);
    const vector ur(fl.U - v);
    vector F[2];
    const scalar ds[2] = {2*r1, 2*r2};
    for (label k = 0; k < 2; ++k)
    {
        const scalar d = ds[k];
        vector Fc;
        scalar Spc;
        dpiFluidForce::sum(forces, fl, v, d, N, F[k], Fc, Spc);

        const scalar Re = fl.alpha*d*mag(ur)/fl.nu;
        const scalar CD =
            24/Re*(1 + 0.15*std::pow(Re, 0.687))*std::pow(fl.alpha, -1.65);
        const vector closed(N*pi/8*sqr(d)*fl.rho*CD*mag(ur)*ur);
        EXPECT_LT(mag(F[k] - closed), 1e-12*mag(closed)) << "d " << d;
        EXPECT_LT(mag(Fc - F[k]), 1e-15*mag(F[k])) << "coupled";

        // N times the primary's
        vector F1, Fc1;
        scalar Spc1;
        dpiFluidForce::sum(forces, fl, v, d, 1, F1, Fc1, Spc1);
        EXPECT_LT(mag(F[k]/N - F1), 1e-14*mag(F1));
    }
    // Not Stokes' ratio d2/d1 = 4: the Reynolds numbers differ (the
    // correction 1 + 0.15 Re^0.687 is 1.13 against 1.33)
    EXPECT_GT(mag(F[1])/mag(F[0]), 4*1.1);
}


// Void fraction. Four parcels of d 1.5, 6 (API, N = 10), 2, 4 um (N = 1)
// in a mesh of two 20 um cells: the solid volume over the cells is
// sum N pi/6 d^3 (apiParcel) and sum pi/6 d^3 (divided), to round-off
// (1e-14 of it: 29 terms a parcel). Each parcel's 29 points are at its
// own radius: a parcel centred 0.8 R from the face between the cells
// puts exactly one point (the outer shell's, at 0.918 R) across it, 1/29
// of its volume, for R = 0.75 and 3 um alike (1e-14).
TEST(polydisperse, voidFractionRemovesEachParcelsVolume)
{
    FatalIOError.throwExceptions();

    Time runTime
    (
        fileName("/tmp"), fileName("dpiPolydisperseVoidFraction"),
        "system", "constant", false, false
    );
    const scalar h = 20e-6;
    autoPtr<polyMesh> meshPtr(boxMesh(runTime, 2, -h, h));
    const polyMesh& mesh = meshPtr();
    ASSERT_EQ(mesh.nCells(), 2);

    dictionary apiDict;
    apiDict.add("type", "apiParcel");
    dictionary divDict;
    divDict.add("type", "divided");
    autoPtr<dpiVoidFraction> api(dpiVoidFraction::New(apiDict));
    autoPtr<dpiVoidFraction> div(dpiVoidFraction::New(divDict));

    struct parcel { point x; scalar d, N; };
    const parcel parcels[] =
    {
        {point(-0.8*r1, 0.5*h, 0.5*h), 2*r1, 10},
        {point(0.8*r2, 0.3*h, 0.6*h), 2*r2, 10},
        {point(-0.5*h, 0.5*h, 0.4*h), 2e-6, 1},
        {point(0.5*h, 0.6*h, 0.5*h), 4e-6, 1}
    };

    scalarField Vapi(mesh.nCells(), Zero), Vdiv(mesh.nCells(), Zero);
    scalar sumApi = 0, sumDiv = 0;
    for (const parcel& p : parcels)
    {
        const label celli = mesh.findCell(p.x);
        ASSERT_GE(celli, 0);
        dpiVoidFraction::distribute
        (
            mesh, p.x, celli, 0.5*p.d, api->solidVolume(p.d, p.N), Vapi
        );
        dpiVoidFraction::distribute
        (
            mesh, p.x, celli, 0.5*p.d, div->solidVolume(p.d, p.N), Vdiv
        );
        sumApi += p.N*pi/6*pow3(p.d);
        sumDiv += pi/6*pow3(p.d);
    }
    EXPECT_NEAR(sum(Vapi)/sumApi, 1, 1e-14);
    EXPECT_NEAR(sum(Vdiv)/sumDiv, 1, 1e-14);

    // Cell 0 is x < 0: parcel 0 (x = -0.8 r1) puts 1/29 of its volume in
    // cell 1, parcel 1 (x = +0.8 r2) 1/29 of its own in cell 0
    const label c0 = mesh.findCell(point(-0.5*h, 0.5*h, 0.5*h));
    const label c1 = 1 - c0;
    const scalar V0 = pi/6*pow3(2*r1), V1 = pi/6*pow3(2*r2);
    const scalar V2 = pi/6*pow3(2e-6), V3 = pi/6*pow3(4e-6);
    EXPECT_NEAR(Vdiv[c0]/(28.0/29*V0 + V1/29 + V2), 1, 1e-14);
    EXPECT_NEAR(Vdiv[c1]/(V0/29 + 28.0/29*V1 + V3), 1, 1e-14);
}


// Time-step check. An API of MMD 2.5 um, GSD 1.8, truncated at 0.5 and
// 8 um (number median 1.0 um), N = 10, at 1 m/s: its
// shortest contact is that of two of its smallest primaries, t_H =
// 2.8683 (m*^2/(R* Y*^2 v))^(1/5) with R* = r_min/2, m* = m_min/2. A DEM
// step 5 % below t_H/3 runs; 5 % above it is refused, with that t_H/3 in
// the message (printed with 6 digits: 1e-5); the same step runs for a
// type of one size, the number median's. The Rayleigh time is the
// smallest primary's, pi r_min sqrt(rho/G)/(0.1631 nu + 0.8766) (1e-12).
TEST(polydisperse, timeStepCheckTakesTheSmallestPrimary)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const std::string logNormal
    (
        "sizeDistribution { type logNormal; median 2.5e-6; gsd 1.8;"
        " basis mass; min 0.5e-6; max 8e-6; }"
    );
    const scalar N = 10;
    const scalar rMin = 0.25e-6;
    const scalar tH = 2.8683*std::pow
    (
        sqr(mass(rMin)/2)/(rMin/2*sqr(Ystar())*1), 0.2
    );

    auto message = [&](const scalar dt, const std::string& size)
    {
        try
        {
            demEngine engine(toDict(deck(N, plain, false, dt, size)));
        }
        catch (const Foam::error& e)
        {
            return std::string(e.message());
        }
        return std::string();
    };

    EXPECT_EQ(message(0.95*tH/3, logNormal), "");
    const std::string refused = message(1.05*tH/3, logNormal);
    ASSERT_NE(refused.find("t_H/3 = "), std::string::npos) << refused;
    EXPECT_NE(refused.find("api-api"), std::string::npos) << refused;
    const scalar reported =
        std::stod(refused.substr(refused.find("t_H/3 = ") + 8));
    EXPECT_NEAR(reported/(tH/3), 1, 1e-5) << refused;

    // A one-size type of the number median runs at that step
    const demMaterials mat(toDict(deck(N, plain, false, 1e-10, logNormal)), false);
    EXPECT_NEAR
    (
        mat.rayleighTime(apiType)
       /(pi*rMin*std::sqrt(rho*2*(1 + nu)/Y)/(0.1631*nu + 0.8766)),
        1, 1e-12
    );
    const scalar cmd = mat.size(apiType).numberMedian();
    EXPECT_GT(cmd, 1.5*2*rMin) << "the median's t_H is 1.5 x longer";
    std::ostringstream fixed;
    fixed.precision(17);
    fixed << "diameter " << cmd << ";";
    EXPECT_EQ(message(1.05*tH/3, fixed.str()), "");
}


// Agglomerates. A carrier of 25 um carrying API parcels of 0.75 and 3 um,
// a 1.5 um one on the 3 um one; apart, a doublet of 2 and 0.6 um; a
// 1 um singlet 0.1 nm beyond the 2 um one's surface (not linked by the
// two rows' own radii). All API N = 10. The components follow
// the rows' radii; one copy of an agglomerate (compose) has the solid
// volume sum pi/6 d^3 and mass sum rho pi/6 d^3 of its members (the
// carrier once), and N copies the mass of its API parcels,
// sum N rho pi/6 d^3. Sums of a few terms: 1e-14.
TEST(polydisperse, agglomerateMassIsItsParcelsMass)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const scalar N = 10, touch = 1e-9;
    const demMaterials mat(toDict(deck(N, plain)), false);

    struct row { point x; scalar r; label type; };
    const scalar ra = r1, rb = r2, rc = 1.5e-6, rd = 2e-6, re = 0.6e-6;
    const scalar rf = 1e-6;
    const point far(200e-6, 0, 0);
    const std::vector<row> rows =
    {
        {point::zero, rC, carrierType},
        {point(rC + ra - touch, 0, 0), ra, apiType},
        {point(0, rC + rb - touch, 0), rb, apiType},
        {point(0, rC + 2*rb + rc - 2*touch, 0), rc, apiType},
        {far, rd, apiType},
        {far + vector(0, 0, rd + re - touch), re, apiType},
        {far - vector(rd + rf + 1e-10, 0, 0), rf, apiType}
    };

    demState s;
    scalarList d(rows.size()), rhos(rows.size(), rho);
    boolList carrier(rows.size(), false);
    for (label k = 0; k < label(rows.size()); ++k)
    {
        const row& w = rows[k];
        s.append(w.x, Zero, Zero, w.r, mass(w.r),
                 w.type == apiType ? N : 1, w.type, 10 + k);
        d[k] = 2*w.r;
        carrier[k] = (w.type == carrierType);
    }

    const dictionary noKeys;
    agglomerateTracker tracker(noKeys, fileName::null);
    labelList ids;
    tracker.update(s, mat, ids);
    const labelList expected({10, 10, 10, 10, 14, 14, 16});
    EXPECT_EQ(ids, expected);
    EXPECT_EQ(tracker.stats().nAgglomerates, 3);
    EXPECT_EQ(tracker.stats().apiPrimaries, 6*N);
    EXPECT_EQ(tracker.stats().singletAPIPrimaries, N);
    EXPECT_EQ(tracker.stats().attachedAPIPrimaries, 3*N);

    const agglomerateTracker::composition c =
        agglomerateTracker::compose(ids, d, rhos, carrier);

    auto cube = [](const scalar r) { return pow3(2*r); };
    const scalar V10 = pi/6*(cube(rC) + cube(ra) + cube(rb) + cube(rc));
    const scalar V14 = pi/6*(cube(rd) + cube(re));
    EXPECT_NEAR(c.volume[10]/V10, 1, 1e-14);
    EXPECT_NEAR(c.mass[10]/(rho*V10), 1, 1e-14);
    EXPECT_EQ(c.parcels[10], 4);
    EXPECT_EQ(c.carriers[10], 1);
    EXPECT_NEAR(c.volume[14]/V14, 1, 1e-14);
    EXPECT_EQ(c.carriers[14], 0);
    EXPECT_NEAR(c.mass[16]/(rho*pi/6*cube(rf)), 1, 1e-14);

    // N copies of the API doublet: the mass its API parcels carry
    scalar parcelMass = 0;
    forAll(s.x, k)
    {
        if (ids[k] == 14)
        {
            parcelMass += s.N[k]*s.m[k];
        }
    }
    EXPECT_NEAR(N*c.mass[14]/parcelMass, 1, 1e-14);
}


// Emitted dose and impactor. API singlets of N = 10 and d = 1 ... 6 um
// leave the device: each weighs N rho pi/6 d^3 of its own d, has the
// aerodynamic diameter d sqrt(rho/1000) of its own d, and the NGI at
// 60 L/min puts it in the stage whose cut-off that reaches (found here by
// its own search over the cut-offs); the stages' masses add up to the
// emitted mass, the fine one (d_ae < 5 um) is that of d = 1 ... 4 um. An
// agglomerate of 2 and 0.6 um leaves as the sphere of its solid volume,
// d_v = (d1^3 + d2^3)^(1/3), d_ae = d_v sqrt(rho/(chi 1000)). Closed forms
// of one or two operations: 1e-14.
TEST(polydisperse, doseBinsSingletsByTheirOwnDiameter)
{
    FatalIOError.throwExceptions();
    using functionObjects::dpiEmittedDose;

    const impactorStages ngi(toDict("type NGI; flowRate 60;"));
    const scalarList& cut = ngi.cutOffs();
    const scalar N = 10;

    dpiEmittedDose::dose total;
    scalarList byStage(ngi.size(), Zero);
    scalar emitted = 0, fine = 0;
    labelList stages;
    for (const scalar d : {1e-6, 2e-6, 3e-6, 4e-6, 6e-6})
    {
        dpiCloudInterface::escapedParcel e;
        e.patchi = 0;
        e.N = N;
        e.api = true;
        e.d = d;
        e.rho = rho;
        e.agglomerateParcels = 1;
        e.agglomerateVolume = pi/6*pow3(d);
        e.agglomerateMass = rho*e.agglomerateVolume;

        const scalar m = N*rho*pi/6*pow3(d);
        EXPECT_NEAR(dpiEmittedDose::apiMass(e)/m, 1, 1e-14);

        const scalar dae = dpiEmittedDose::aerodynamicDiameter(e, 1.15);
        EXPECT_NEAR(dae/(d*std::sqrt(rho/1000)), 1, 1e-14) << "d " << d;

        label stage = ngi.size() - 1;
        forAll(cut, k)
        {
            if (dae >= cut[k])
            {
                stage = k + 1;
                break;
            }
        }
        EXPECT_EQ(ngi.bucket(dae, false), stage) << "d " << d;
        stages.append(stage);

        byStage[ngi.bucket(dae, false)] += dpiEmittedDose::apiMass(e);
        total.add(m, N, false, 1, dae < 5e-6);
        emitted += m;
        fine += (d < 4.1e-6) ? m : 0;
    }
    // Five sizes in four stages (4 and 6 um share stage 2, 4.46 um and up)
    EXPECT_EQ(stages, labelList({5, 4, 3, 2, 2}));
    EXPECT_NEAR(sum(byStage)/emitted, 1, 1e-14);
    EXPECT_NEAR(total.emitted/emitted, 1, 1e-14);
    EXPECT_NEAR(total.singlets/emitted, 1, 1e-14);
    EXPECT_NEAR(total.fine/fine, 1, 1e-14);
    EXPECT_EQ(total.primaries, 5*N);

    // An agglomerate of two API primaries of 2 and 0.6 um
    dpiCloudInterface::escapedParcel e;
    e.N = N;
    e.api = true;
    e.d = 2e-6;
    e.rho = rho;
    e.agglomerateParcels = 2;
    e.agglomerateVolume = pi/6*(pow3(2e-6) + pow3(0.6e-6));
    e.agglomerateMass = rho*e.agglomerateVolume;
    const scalar dv = std::cbrt(pow3(2e-6) + pow3(0.6e-6));
    EXPECT_NEAR
    (
        dpiEmittedDose::aerodynamicDiameter(e, 1.15)
       /(dv*std::sqrt(rho/(1.15*1000))),
        1, 1e-14
    );
}


// Device retention. In a 40 x 20 x 20 um box whose walls are one patch,
// API parcels (N = 10) not on carriers: one of 6 um with its centre 2.9 um
// from a wall (touching it by its own radius), one of 1.5 um as far from
// the walls (not touching: 2.9 um > 0.75 um), one of 1 um 0.4 um from a
// wall (touching); a 2 um one on a carrier's agglomerate near a wall
// (on carriers, wherever it is). The retained masses are each parcel's
// own N rho pi/6 d^3: in the device all four, on carriers the 2 um one,
// on the walls the 6 and 1 um ones, neither the 1.5 um one. Written with
// 17 digits, sums of up to four terms: 1e-14.
TEST(polydisperse, retentionDepositsByEachParcelsRadius)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const fileName root
    (
        "/tmp/dpiPolydisperseRetention." + std::to_string(::getpid())
    );
    {
        Time runTime(root, "case", "system", "constant", false, false);
        const scalar h = 20e-6;
        autoPtr<fvMesh> mesh(fvBoxMesh(runTime, 2, -h, h));

        struct parcel { point x; scalar d; bool api; label agg; };
        const std::vector<parcel> ps =
        {
            {point(-10e-6, 2.9e-6, 10e-6), 6e-6, true, 0},
            {point(10e-6, 2.9e-6, 10e-6), 1.5e-6, true, 1},
            {point(5e-6, 10e-6, 19.6e-6), 1e-6, true, 2},
            {point(-15e-6, 10e-6, 10e-6), 2e-6, true, 3},
            {point(-5e-6, 10e-6, 10e-6), 8e-6, false, 3}
        };
        const scalar N = 10;
        dpiCloudInterface::parcelSamples s;
        const label n = ps.size();
        s.setSize(n);
        for (label k = 0; k < n; ++k)
        {
            s.position[k] = ps[k].x;
            s.N[k] = ps[k].api ? N : 1;
            s.api[k] = ps[k].api;
            s.globalId[k] = k;
            s.agglomerateId[k] = ps[k].agg;
            s.d[k] = ps[k].d;
            s.rho[k] = rho;
            s.cell[k] = mesh->findCell(ps[k].x);
            ASSERT_GE(s.cell[k], 0);
        }
        sampleCloud cloud(mesh(), "dpiCloud", s);

        functionObjects::dpiDeviceRetention retention
        (
            "retention", runTime, toDict("writePrecision 17;")
        );
        retention.execute();
        retention.file().flush();

        std::ifstream is(retention.file().name());
        std::string line, last;
        while (std::getline(is, line))
        {
            if (line.size() && line[0] != '#')
            {
                last = line;
            }
        }
        std::istringstream cols(last);
        scalar t, inDevice, onCarriers, neither, onWalls;
        cols >> t >> inDevice >> onCarriers >> neither >> onWalls;
        ASSERT_FALSE(cols.fail()) << last;

        auto m = [&](const scalar d) { return N*rho*pi/6*pow3(d); };
        EXPECT_NEAR(inDevice/(m(6e-6) + m(1.5e-6) + m(1e-6) + m(2e-6)), 1, 1e-14);
        EXPECT_NEAR(onCarriers/m(2e-6), 1, 1e-14);
        EXPECT_NEAR(onWalls/(m(6e-6) + m(1e-6)), 1, 1e-14);
        EXPECT_NEAR(neither/m(1.5e-6), 1, 1e-14);
    }
    rmDir(root);
}


// ************************************************************************* //
