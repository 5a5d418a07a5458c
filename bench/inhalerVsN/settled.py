#!/usr/bin/env python3
"""The settled bed of inhalerVsN cases, at the end of their stage 1.

Usage: settled.py GROUP=CASE[,CASE...][@TIME] ... [--md settled.md]

Per case, from the particles at the first written time after 0 (the end
of stage 1, when the gas comes on), or at TIME (a time directory's name),
and per GROUP the mean over its cases:
  height     the carriers' centres above the corner's floor (z = -3.5 mm),
             mean [um]
  spread     the carriers' distance from the cone's axis (x = 39 mm,
             y = 0), mean [um]
  bare       carrier pairs closer than their diameter (touching bare)
  nearAPI    share of the API primaries within 10 um (surface to surface)
             of a carrier other than their own (nearest), i.e. in the
             gaps between carriers
  wedged     share of the API primaries within 2 um of another carrier or
             of the floor (bedFrom.py's faceted floor): held, or about to
             be, between their carrier and a second surface
  touching   share of the API parcels touching another parcel at
             coatingCoverage's contact distance (sqrt(N) primary
             diameters; one diameter at N = 1)
  moving     the carriers' mean speed [mm/s] (still settling, or at rest)
  spin       the carriers' mean |omega| [1/s] (omega R at 35 um: 1000 1/s
             is 35 mm/s at the surface)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "costVsN"))
sys.path.insert(0, HERE)
import powder  # noqa: E402
from bedFrom import FLOOR_SLOPE, FLOOR_Z, settledState  # noqa: E402

AXIS = (0.039, 0.0)


def measure(case, time=None):
    C, A, nA, (UC, wC), _ = settledState(case, motion=True, time=time)
    rc, ra = powder.DC/2, powder.DA/2
    D = np.linalg.norm(C[:, None] - C[None], axis=2)
    bare = int(np.sum(np.triu(D < 2*rc + 1e-7, 1)))
    dA = np.sort(np.linalg.norm(A[:, None] - C[None], axis=2), axis=1)
    second = dA[:, 1] - rc - ra if len(C) > 1 else np.full(len(A), np.inf)
    floor = A[:, 2] - ra - (FLOOR_Z + FLOOR_SLOPE*np.abs(A[:, 1]))
    dAA = np.linalg.norm(A[:, None] - A[None], axis=2)
    np.fill_diagonal(dAA, np.inf)
    return dict(
        height=1e6*np.mean(C[:, 2] - FLOOR_Z),
        spread=1e6*np.mean(np.hypot(C[:, 0] - AXIS[0], C[:, 1] - AXIS[1])),
        bare=bare,
        nearAPI=np.sum(nA*(second < 10e-6))/np.sum(nA),
        wedged=np.sum(nA*((second < 2e-6) | (floor < 2e-6)))/np.sum(nA),
        touching=np.mean(np.any(
            dAA < (np.sqrt(nA[:, None]) + np.sqrt(nA[None]))*ra*(1 + 2e-3),
            axis=1)),
        moving=1e3*np.mean(np.linalg.norm(UC, axis=1)),
        spin=np.mean(np.linalg.norm(wC, axis=1)))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("groups", nargs="+", metavar="GROUP=CASE[,CASE...][@TIME]")
    ap.add_argument("--md", default="settled.md")
    ap.add_argument("--title", default="The settled beds (`settled.py`)",
                    help="the Markdown table's heading")
    a = ap.parse_args()
    keys = ["height", "spread", "bare", "nearAPI", "wedged", "touching",
            "moving", "spin"]
    out = ["# " + a.title, "",
           "| group | cases | carriers' height [um] | distance from the "
           "axis [um] | bare carrier pairs | API within 10 um of another "
           "carrier | API wedged | parcels touching a parcel | carriers' speed "
           "[mm/s] | carriers' spin [1/s] |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for g in a.groups:
        name, _, cases = g.partition("=")
        cases, _, time = cases.partition("@")
        if not cases:
            sys.exit("settled.py: %s is not GROUP=CASE[,CASE...][@TIME]" % g)
        rows = [measure(c, time or None) for c in cases.split(",")]
        m = {k: np.mean([r[k] for r in rows]) for k in keys}
        out.append("| %s | %d | %.1f | %.1f | %.1f | %.3f | %.3f | %.3f "
                   "| %.1f | %.0f |" % (
                       name, len(rows), m["height"], m["spread"], m["bare"],
                       m["nearAPI"], m["wedged"], m["touching"],
                       m["moving"], m["spin"]))
    with open(a.md, "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()
