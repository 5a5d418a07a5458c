#!/usr/bin/env python3
"""The bed of an inhalerVsN case made from another run's settled bed.

Usage: bedFrom.py CASE --N N --from SETTLED [--seed 86] [--recoat]
                  [--keep-motion]
                  [--coarse-graining scaledContacts|coatingCoverage]
Writes CASE/constant/bedParticles (a singleParticles list) and prints
"carriers apiParcels primaries", as bed.py does.

SETTLED is a finished inhalerVsN case (any N). Its particles at the end
of its stage 1 (the first written time after 0 with lagrangian fields) are
the start of CASE: every carrier where it came to rest. If SETTLED's API
parcels are all of N primaries, they also keep their places, so the case
repeats SETTLED's bed (unless --recoat). Otherwise each carrier's API (a parcel belongs to
its nearest carrier) is regrouped into parcels of N: the carrier's n
primaries (nParticle summed) make round(n/N) parcels, adjusted so that
the total is round(P/N) of the P primaries (the carriers with the largest
remainders take the extra parcels), placed as bed.py places them (a random
spot of the carrier's surface, at the carrier-API adhesive equilibrium
overlap, the parcels at least one diameter apart, sqrt(N) diameters with
coatingCoverage), and also clear of the other carriers and of the
corner's floor. The floor is the bottom of the 7 mm tube as the mesh
draws it: faces about 15 degrees of the circle wide (the tutorial's
blockMeshDict, --ns 6), with an edge along its lowest line (z = -3.5 mm
at y = 0); under the bed their points rise 137-140 um over 958-967 um of
y, so the floor is taken as z = -3.5 mm + 0.15 |y| (10 um at |y| = 70
um: a primary under a carrier placed against a flat floor would start
outside the mesh or in the wall).

Everything starts at rest, unless --keep-motion: then, where the API keep
their places, every particle also keeps its velocity and spin (what the
new start still resets is the contacts' histories). What this is for: a run of N = 10 from the bed
N = 1 settled into has N = 1's sedimentation and N = 10's breath (and a
run of N = 1 from N = 10's bed the other way round), so comparing it with
N = 1 tells whether a bias is made while the powder settles or while the
gas blows (bench/inhalerVsN/NOTES.md, "Where the bias is made").
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "costVsN"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tutorials", "scripts"))
import foamLagrangian as fl  # noqa: E402
import powder  # noqa: E402

FLOOR_Z = -3.5e-3                       # the floor's lowest line, y = 0
FLOOR_SLOPE = 0.15                      # its faces on either side, at most
CARRIER, API = 0, 1


def settledState(case, motion=False, time=None):
    """(carrier positions, API positions, the API's primaries per parcel)
    at the end of case's stage 1 (the first written time after 0), or at
    time; with motion also (U, omega) of carriers and API. In the order the
    fields list them."""
    d = next((fl.cloud_dir(case, t) for t in fl.times(case)
              if (float(t) > 0 if time is None else t == time)
              and os.path.isfile(os.path.join(fl.cloud_dir(case, t), "xDEM"))),
             None)
    if d is None:
        sys.exit("bedFrom.py: %s has no written time %s with "
                 "lagrangian/dpiCloud/xDEM"
                 % (case, "after 0" if time is None else time))
    x, typeId, n = (fl.read_field(os.path.join(d, f))
                    for f in ("xDEM", "typeId", "nParticle"))
    out = (x[typeId == CARRIER], x[typeId == API], n[typeId == API])
    if motion:
        U, w = (fl.read_field(os.path.join(d, f)) for f in ("U", "omega"))
        out += ((U[typeId == CARRIER], w[typeId == CARRIER]),
                (U[typeId == API], w[typeId == API]))
    return out


def regroup(rng, C, A, nA, N, grow):
    """The API A (of nA primaries each) of the carriers C as parcels of N
    (see the header)"""
    rc, ra = powder.DC/2, powder.DA/2
    host = np.argmin(np.linalg.norm(A[:, None] - C[None], axis=2), axis=1)
    share = np.bincount(host, weights=nA, minlength=len(C))/N
    per = np.floor(share + 1e-9).astype(int)
    extra = max(1, int(round(nA.sum()/N))) - per.sum()
    order = np.lexsort((rng.random(len(C)), -(share - per)))
    per[order[:extra]] += 1
    dist = rc + ra - powder.DELTA_EQ
    dmin = grow*powder.DA*(1 + 1e-3)
    out = np.zeros((0, 3))
    for k, c in enumerate(C):
        others = np.delete(C, k, axis=0)
        placed, tries = 0, 0
        while placed < per[k]:
            tries += 1
            if tries > 200000:
                sys.exit("bedFrom.py: cannot place %d parcels on carrier %d"
                         % (per[k], k))
            u = rng.normal(size=3)
            p = c + dist*u/np.linalg.norm(u)
            if p[2] - ra < FLOOR_Z + FLOOR_SLOPE*abs(p[1]) + 1e-7:
                continue
            if len(others) and \
                    np.min(np.linalg.norm(others - p, axis=1)) < rc + ra:
                continue
            if len(out) and np.min(np.linalg.norm(out - p, axis=1)) < dmin:
                continue
            out = np.vstack([out, p])
            placed += 1
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--N", type=int, required=True)
    ap.add_argument("--from", dest="settled", required=True)
    ap.add_argument("--seed", type=int, default=86)
    ap.add_argument("--recoat", action="store_true",
                    help="regroup the API also when N is SETTLED's")
    ap.add_argument("--keep-motion", action="store_true",
                    help="keep the velocities and spins where the API are "
                    "kept")
    ap.add_argument("--coarse-graining", default="scaledContacts",
                    choices=["scaledContacts", "coatingCoverage"])
    a = ap.parse_args()
    if a.N < 1:
        sys.exit("bedFrom.py: --N must be positive, got %d" % a.N)
    C, A, nA, *motion = settledState(a.settled, a.keep_motion)
    kept = np.all(nA == a.N) and not a.recoat
    if a.keep_motion and not kept:
        sys.exit("bedFrom.py: --keep-motion needs the API kept in place "
                 "(the same N as %s, no --recoat)" % a.settled)
    if kept:
        api = A
    else:
        grow = math.sqrt(a.N) if a.coarse_graining == "coatingCoverage" \
            else 1.0
        api = regroup(np.random.default_rng(a.seed), C, A, nA, a.N, grow)

    def entry(kind, x, k, moving):
        if not a.keep_motion:
            return "{ type %s; position (%.12e %.12e %.12e); }" % (
                (kind,) + tuple(x))
        U, w = moving[0][k], moving[1][k]
        return ("{ type %s; position (%.12e %.12e %.12e); "
                "U (%.12e %.12e %.12e); omega (%.12e %.12e %.12e); }"
                % ((kind,) + tuple(x) + tuple(U) + tuple(w)))

    lines = [entry("carrier", c, k, motion[0] if motion else None)
             for k, c in enumerate(C)]
    lines += [entry("API", p, k, motion[1] if motion else None)
              for k, p in enumerate(api)]
    with open(os.path.join(a.case, "constant", "bedParticles"), "w") as f:
        f.write("// bench/inhalerVsN/bedFrom.py: the settled carriers of %s,"
                " API as parcels of N = %d\nparticles\n(\n%s\n);\n"
                % (os.path.abspath(a.settled), a.N, "\n".join(lines)))
    print(len(C), len(api), len(api)*a.N)


if __name__ == "__main__":
    main()
