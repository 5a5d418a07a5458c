#!/usr/bin/python3
"""A carrier-API powder for bench/costVsN: a dpiFoam DEM-only case.

nCarriers lactose carriers (70 um) at random without overlaps in a box of
six plane walls, each coated with `primaries` API primaries (5 um), i.e.
round(primaries/N) API parcels of N primaries, placed at random on its
surface without API-API overlaps, touching it at the adhesive equilibrium
overlap; each carrier and its API move with the carrier's random velocity
(isotropic Gaussian, rms vrms, capped at 2.5 vrms): a stirred, coated powder.
Materials and cohesion as tutorials/case6AgglomerateWallCollision (Y 5e8 Pa,
nu 0.35, e 0.85, mu 0.45, vdwGuParcel A = 1e-19 J, chi 3.177672, no wall
cohesion), gravity -z, DEM step 1e-8 s.

    powder.py DIR --N 10 [--carriers 100] [--primaries 100] [--steps 3000]
              [--fluid-every 1000] [--phi 0.15] [--vrms 0.5] [--seed 20240]
              [--coarse-graining scaledContacts|coatingCoverage]

With --coarse-graining coatingCoverage (written to dem/coarseGraining) the
API parcels meet each other at sqrt(N) x their primary radius, so they are
placed that far apart, on their own carrier and from the parcels of the
carriers placed before (the engine refuses a start with them overlapping).
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import settlingScene as ss  # noqa: E402

DC, DA = 70e-6, 5e-6
RHO, Y, NU = 1520.0, 5e8, 0.35
DELTA_EQ = 7.632e-10          # carrier-API equilibrium overlap, A = 1e-19 J


def coat(rng, nParcels, xc, placed, grow=1.0):
    """nParcels positions on the carrier at xc whose API (at distance
    rc + ra from it) are at least grow x DA apart from each other and from
    the API in placed (an array of positions, grow > 1 only)."""
    rc, ra = DC/2, DA/2
    dist = rc + ra - DELTA_EQ
    dmin = grow*DA*(1 + 1e-3)
    out = []
    tries = 0
    while len(out) < nParcels:
        tries += 1
        if tries > 100000:
            sys.exit("powder.py: cannot place %d API on a carrier" % nParcels)
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        p = dist*u
        if not all(np.linalg.norm(p - q) >= dmin for q in out):
            continue
        if grow > 1 and len(placed) and \
                np.min(np.linalg.norm(placed - (xc + p), axis=1)) < dmin:
            continue
        out.append(p)
    return [xc + p for p in out]


def coatAll(rng, centres, counts, N, coarseGraining):
    """The API of every carrier (centres, counts parcels each, in order):
    coat's positions, with coatingCoverage sqrt(N) x DA apart also from
    the API of the carriers coated before."""
    grow = math.sqrt(N) if coarseGraining == "coatingCoverage" else 1.0
    placed = np.zeros((0, 3))
    out = []
    for c, k in zip(centres, counts):
        api = coat(rng, int(k), np.asarray(c), placed, grow)
        out.append(api)
        if grow > 1:
            placed = np.vstack([placed] + [p[None, :] for p in api])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--N", type=int, required=True)
    ap.add_argument("--carriers", type=int, default=100)
    ap.add_argument("--primaries", type=int, default=100,
                    help="API primaries per carrier")
    ap.add_argument("--steps", type=int, default=3000)
    ap.add_argument("--fluid-every", type=int, default=1000)
    ap.add_argument("--phi", type=float, default=0.15,
                    help="solids fraction of the coated carriers' "
                    "bounding spheres (80 um)")
    ap.add_argument("--vrms", type=float, default=0.5)
    ap.add_argument("--seed", type=int, default=20240)
    ap.add_argument("--coarse-graining", default="scaledContacts",
                    choices=["scaledContacts", "coatingCoverage"])
    a = ap.parse_args()
    if a.steps % a.fluid_every:
        sys.exit("powder.py: --steps must be a multiple of --fluid-every")

    # Carriers: the settling scene's packing with the coated diameter
    ss.DIAMETER = DC + 2*DA
    x, v, L = ss.generate(a.carriers, a.phi, a.vrms, a.seed)
    nPer = max(1, int(round(a.primaries/a.N)))
    rng = np.random.default_rng(a.seed + 1)
    parts = []
    for xc, vc in zip(x, v):
        parts.append(("carrier", xc, vc))
    coats = coatAll(rng, x, [nPer]*len(x), a.N, a.coarse_graining)
    for api, vc in zip(coats, v):
        for p in api:
            parts.append(("API", p, vc))

    writeCase(a.case, parts, L, a.steps, a.fluid_every, 1e-8,
              "%d carriers, %d API parcels of N %d (%d primaries per "
              "carrier), seed %d (bench/costVsN/powder.py)"
              % (a.carriers, len(parts) - a.carriers, a.N, nPer*a.N, a.seed),
              "costVsN powder (bench/costVsN/powder.py): %d carriers coated "
              "with\n// %d API primaries each as %d parcels of N = %d"
              % (a.carriers, nPer*a.N, nPer, a.N), a.N, a.coarse_graining)
    print("powder.py: %d carriers in a box of %.3g mm, %d API parcels of N %d"
          % (a.carriers, L*1e3, len(parts) - a.carriers, a.N))


def writeCase(case, parts, L, steps, every, dt, note, title, N,
              coarseGraining="scaledContacts"):
    """The dpiFoam DEM-only case of a carrier-API powder: parts (type,
    position, velocity) in the box [0, L] (one edge or three) of six plane
    walls (no wall cohesion), cohesion vdwGuParcel as Case 6, API parcels
    of N primaries, DEM step dt, steps DEM steps, coupling every `every`;
    `note` heads the particle list, `title` the cloud dictionary."""
    for sub in ("system", "constant"):
        os.makedirs(os.path.join(case, sub), exist_ok=True)
    box = ss.boxOf(L)
    ss.writeBlockMesh(case, L, 5*DC, 2, patch="box", patchType="patch")
    ss.writeDecomposeParDict(case)
    nFluid = steps//every
    with open(os.path.join(case, "system/controlDict"), "w") as f:
        f.write(ss.header("dictionary", "controlDict"))
        f.write("application dpiFoam;\nstartFrom startTime;\nstartTime 0;\n"
                "stopAt endTime;\nendTime %.12g;\ndeltaT %.12g;\n"
                "writeControl timeStep;\nwriteInterval 1000000;\n"
                "purgeWrite 0;\nwriteFormat binary;\nwritePrecision 17;\n"
                "writeCompression off;\ntimeFormat general;\n"
                "timePrecision 10;\nrunTimeModifiable false;\n"
                % (nFluid*every*dt, every*dt))
    with open(os.path.join(case, "system/fvSchemes"), "w") as f:
        f.write(ss.header("dictionary", "fvSchemes"))
        f.write("ddtSchemes { default Euler; }\ngradSchemes { default Gauss "
                "linear; }\ndivSchemes { default none; }\nlaplacianSchemes "
                "{ default Gauss linear corrected; }\ninterpolationSchemes "
                "{ default linear; }\nsnGradSchemes { default corrected; }\n")
    ss.writeNoSolvers(case)
    ss.writeNoFluid(case)
    ss.writeGravity(case, (0, 0, -9.81))
    with open(os.path.join(case, "constant/powderParticles"), "w") as f:
        f.write("// %s\n" % note)
        f.write("particles\n(\n")
        for t, p, u in parts:
            f.write("{ type %s; position (%.12e %.12e %.12e); "
                    "U (%.10e %.10e %.10e); }\n"
                    % (t, p[0], p[1], p[2], u[0], u[1], u[2]))
        f.write(");\n")

    walls = ""
    for name, pt, nv in (("xlo", "0 0 0", "1 0 0"), ("xhi", "X 0 0", "-1 0 0"),
                         ("ylo", "0 0 0", "0 1 0"), ("yhi", "0 Y 0", "0 -1 0"),
                         ("zlo", "0 0 0", "0 0 1"), ("zhi", "0 0 Z", "0 0 -1")):
        for c, e in zip("XYZ", box):
            pt = pt.replace(c, "%.12g" % e)
        walls += ("        %s { type plane; point (%s); normal (%s); "
                  "material carrier; }\n" % (name, pt, nv))
    with open(os.path.join(case, "constant/dpiCloudProperties"), "w") as f:
        f.write(ss.header("dictionary", "dpiCloudProperties"))
        f.write("""// %(title)s
%(preamble)sdem
{
    timeStep %(dt)g;
    types
    {
        carrier { diameter %(dc)g; density %(rho)g; youngsModulus %(Y)g; poissonsRatio %(nu)g; N 1; }
        API { diameter %(da)g; density %(rho)g; youngsModulus %(Y)g; poissonsRatio %(nu)g; N %(N)d; api true; }
    }
    pairs { default { restitution 0.85; friction 0.45; rollingFriction 0; } }
    normalModel hertzParcel;
    tangentialModel historyParcel;
    rollingModel none;
    cohesionModel vdwGuParcel;
    coarseGraining %(cg)s;
    vdwGuParcelCoeffs
    {
        chi 3.177672;
        wallCohesion false;
        pairs
        {
            default { hamakerConstant 1e-19; sMin 1e-9; sMins 6.227e-9; s0 4.445e-9; }
            carrier-carrier { sMins 6.276e-9; s0 4.494e-9; }
            API-API { sMins 6.077e-9; s0 4.295e-9; }
        }
    }
    walls
    {
%(walls)s    }
    timeStepCheck { maxImpactVelocity 3; }
}
injectors { powder { type singleParticles; #include "powderParticles" } }
agglomerates { linkGap 0; }
""" % dict(title=title, dt=dt, N=N, cg=coarseGraining, preamble=ss.dpiCloudPreamble(RHO),
           rho=RHO, dc=DC, da=DA, Y=Y, nu=NU, walls=walls))


if __name__ == "__main__":
    main()
