#!/usr/bin/env python3
"""The powder bed of bench/inhalerVsN: coated carriers in the tutorial's cone.

Usage: bed.py CASE --N N [--carriers 8] [--scale 0.25] [--seed 86]
              [--coarse-graining scaledContacts|coatingCoverage]
Writes CASE/constant/bedParticles (a singleParticles list) and prints
"carriers apiParcels primaries".

The powder is the tutorial's: the guide's mass split 0.995357 carrier to
0.004643 API parcel (equal density, 70 and 5 um primaries: 12.80 API
parcels per carrier) with parcels of N = 10 primaries (the deck's nparcel;
regionPacking's basis mass is of the parcels' primary masses), i.e. 128.0
API primaries per carrier. Here every carrier starts coated with them (an
ordered mixture, as after blending): round(128 C/N) parcels of N primaries
(at least one) spread over the C carriers as evenly as the count allows,
each at a random spot of its carrier's surface, touching it at the
carrier-API adhesive equilibrium overlap, without API-API overlaps
(bench/costVsN/powder.py's coat; with --coarse-graining coatingCoverage
sqrt(N) x their diameter apart, on a carrier and across carriers, as the
model's parcels touch). The tutorial instead packs loose API
between the carriers and lets them attach while settling (88 % attached
after its 10 ms): in a bed of a few carriers, which must be looser to fit
the narrow cone, most loose API would fall past the carriers and never
attach, and the breath would have nothing to detach.

Carriers: random positions, at rest, in the guide's cone (base radius
0.8 mm at z = -3.4 mm, top 0.1 mm at z = -2.35 mm, axis x = 39 mm, y = 0)
scaled by --scale about its base centre, as the tutorial's Allrun -scale;
the coated sphere (carrier + one API diameter) wholly inside the cone and
clear of the other coated spheres.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "costVsN"))
import powder  # noqa: E402

MASS_SPLIT = (0.995357, 0.004643)       # carrier, API (guide's discrete 66)
N_DECK = 10                             # the deck's nparcel for the API
AXIS = (0.039, 0.0)
Z_BASE, R_BASE, HEIGHT, R_TOP = -3.4e-3, 8e-4, 1.05e-3, 1e-4


def primaries_per_carrier():
    return N_DECK*MASS_SPLIT[1]/MASS_SPLIT[0]*(powder.DC/powder.DA)**3


def carriers_in_cone(rng, n, scale, maxAttempts=1000000):
    """n coated carrier centres in the scaled cone, no overlaps."""
    R = powder.DC/2 + powder.DA          # coated radius
    h, r0, r1 = HEIGHT*scale, R_BASE*scale, R_TOP*scale
    # distance from the axis to the slanted side, per unit of cone radius
    slant = np.hypot(h, r0 - r1)/h
    out = []
    for _ in range(maxAttempts):
        z = Z_BASE + R + (h - 2*R)*rng.random()
        rz = r0 + (r1 - r0)*(z - Z_BASE)/h
        rmax = rz - R*slant
        if rmax <= 0:
            continue
        rad = rmax*np.sqrt(rng.random())
        phi = 2*np.pi*rng.random()
        p = np.array([AXIS[0] + rad*np.cos(phi), AXIS[1] + rad*np.sin(phi), z])
        if all(np.linalg.norm(p - q) >= 2*R for q in out):
            out.append(p)
            if len(out) == n:
                return out
    sys.exit("bed.py: only %d of %d coated carriers fit the cone at scale %g;"
             " use a larger --scale" % (len(out), n, scale))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--N", type=int, required=True)
    ap.add_argument("--carriers", type=int, default=8)
    ap.add_argument("--scale", type=float, default=0.25)
    ap.add_argument("--seed", type=int, default=86)
    ap.add_argument("--coarse-graining", default="scaledContacts",
                    choices=["scaledContacts", "coatingCoverage"])
    a = ap.parse_args()
    if a.carriers < 1 or a.N < 1:
        sys.exit("bed.py: --carriers and --N must be positive, got %d, %d"
                 % (a.carriers, a.N))

    primaries = int(round(primaries_per_carrier()*a.carriers))
    parcels = max(1, int(round(primaries/a.N)))
    rng = np.random.default_rng(a.seed)
    centres = carriers_in_cone(rng, a.carriers, a.scale)
    # parcels per carrier: as even as possible, the remainder at random
    per = np.full(a.carriers, parcels//a.carriers)
    per[rng.choice(a.carriers, parcels % a.carriers, replace=False)] += 1
    lines = []
    for c in centres:
        lines.append("{ type carrier; position (%.12e %.12e %.12e); }"
                     % tuple(c))
    for api in powder.coatAll(rng, centres, per, a.N, a.coarse_graining):
        for p in api:
            lines.append("{ type API; position (%.12e %.12e %.12e); }"
                         % tuple(p))
    with open(os.path.join(a.case, "constant", "bedParticles"), "w") as f:
        f.write("// bench/inhalerVsN/bed.py: %d carriers coated with %d API "
                "parcels of N = %d (%d primaries), cone scale %g, seed %d\n"
                "particles\n(\n%s\n);\n" % (a.carriers, parcels, a.N,
                                          parcels*a.N, a.scale, a.seed,
                                          "\n".join(lines)))
    print(a.carriers, parcels, parcels*a.N)


if __name__ == "__main__":
    main()
