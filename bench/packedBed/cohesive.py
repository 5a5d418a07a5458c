#!/usr/bin/python3
"""The cohesive variant of bench/packedBed: the settled bed of carriers
coated with API, a dpiFoam DEM-only case (dpiFoam alone: see
bench/packedBed/NOTES.md, "Cohesive variant").

    cohesive.py DIR --bed cases/bed-N2000.npz [--N 10] [--primaries 100]
                [--steps 5000] [--fluid-every 1000] [--dt 1e-8] [--seed 20241]

Each carrier of the bed (positions of bed.py, at rest) gets round(primaries
/ N) API parcels of N primaries (5 um) at random on its surface, touching
it at the adhesive equilibrium overlap (bench/costVsN/powder.py: coat);
a parcel that would overlap another carrier, another carrier's API or a
wall is left out (the bed's carriers touch, so a few are). Materials and
cohesion as bench/costVsN (Case 6: vdwGuParcel A = 1e-19 J, no wall
cohesion), through powder.py's writeCase; six plane walls on the bed's box;
every parcel at rest. DEM step 1e-8 s: the start-up check refuses 5e-8 s
for the 5 um API (t_H/3 of API-API is below it).
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "costVsN"))
import powder  # noqa: E402

ss = powder.ss


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--bed", required=True)
    ap.add_argument("--N", type=int, default=10)
    ap.add_argument("--primaries", type=int, default=100,
                    help="API primaries per carrier")
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--fluid-every", type=int, default=1000)
    ap.add_argument("--dt", type=float, default=1e-8)
    ap.add_argument("--seed", type=int, default=20241)
    a = ap.parse_args()
    if a.steps % a.fluid_every:
        sys.exit("cohesive.py: --steps must be a multiple of --fluid-every")

    from scipy.spatial import cKDTree
    x, _, box, _ = ss.loadPositions(a.bed)
    box = np.array(ss.boxOf(box))
    nPer = max(1, int(round(a.primaries/a.N)))
    rng = np.random.default_rng(a.seed)
    rc, ra = powder.DC/2, powder.DA/2
    carriers = cKDTree(x)
    api, owner = [], []
    for i, xc in enumerate(x):
        for p in powder.coat(rng, nPer, xc, np.zeros((0, 3))):
            if np.any(p < ra) or np.any(p > box - ra):
                continue
            near = carriers.query_ball_point(p, rc + ra)
            if any(j != i for j in near):
                continue
            api.append(p)
            owner.append(i)
    api = np.array(api)
    owner = np.array(owner)
    # API of different carriers that overlap: keep the first of each pair
    drop = set()
    for i, j in cKDTree(api).query_pairs(powder.DA*(1 + 1e-3)):
        if owner[i] != owner[j] and i not in drop:
            drop.add(j)
    keep = np.array([k for k in range(len(api)) if k not in drop], int)
    api = api[keep]
    zero = np.zeros(3)
    parts = [("carrier", p, zero) for p in x] + [("API", p, zero) for p in api]
    note = ("%d carriers of %s, %d API parcels of N %d (%d tried per "
            "carrier, %d left out: overlaps), seed %d "
            "(bench/packedBed/cohesive.py)"
            % (len(x), os.path.basename(a.bed), len(api), a.N, nPer,
               len(x)*nPer - len(api), a.seed))
    powder.writeCase(a.case, parts, box, a.steps, a.fluid_every, a.dt, note,
                     "packedBed cohesive variant: " + note, a.N)
    print("cohesive.py: " + note)


if __name__ == "__main__":
    main()
