#!/usr/bin/python3
"""Where on the carrier the detached API were (bench/accuracyVsN, after a
run): for every N in cases/, the probability that an API parcel detaches
in the impact against the polar position it had on the carrier before the
impact (cos theta = z component of the unit vector carrier -> API; the
wall is below, -1 faces it), and the fraction of API not touching the
carrier before the impact (centre farther than r_c + r_API + 1 um: a second
layer). Prints a table; used to find why N = 10 detaches less than N = 1.

Usage: bench/accuracyVsN/polar.py [casesDir]
(lastTime and field are also used by landing.py)
"""
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "scripts"))
from foamLagrangian import read_field  # noqa: E402


def lastTime(case):
    times = [t for t in os.listdir(case)
             if os.path.isdir(os.path.join(case, t, "lagrangian"))]
    return os.path.join(case, max(times, key=float), "lagrangian", "dpiCloud")


def field(d, name, dtype=float):
    return np.asarray(read_field(os.path.join(d, name)), dtype=dtype)


def main():
    top = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "cases")
    Ns = sorted({int(re.match(r"N(\d+)-", os.path.basename(c)).group(1))
                 for c in glob.glob(os.path.join(top, "N*-seed*"))})
    bins = np.linspace(-1, 1, 6)
    print("| N | runs | API parcels | detached | second layer | "
          + " | ".join("cos in [%.1f, %.1f]" % (bins[k], bins[k + 1])
                       for k in range(5)) + " |")
    print("|---:|---:|---:|---:|---:|" + "---:|"*5)
    for N in Ns:
        cosT, det, far = [], [], []
        runs = sorted(glob.glob(os.path.join(top, "N%d-seed*" % N)))
        for c in runs:
            d0, d1 = lastTime(os.path.join(c, "agg")), lastTime(os.path.join(c, "impact"))
            g0, x0 = field(d0, "globalId", int), field(d0, "xDEM")
            t0, r0 = field(d0, "typeId", int), field(d0, "d")/2
            g1, a1, t1 = field(d1, "globalId", int), field(d1, "agglomerateId", int), \
                field(d1, "typeId", int)
            xc, rc = x0[t0 == 0][0], r0[t0 == 0][0]
            carrierAgg = a1[t1 == 0][0]
            agg = dict(zip(g1, a1))
            for g, x, t, r in zip(g0, x0, t0, r0):
                if t != 1:
                    continue
                s = np.linalg.norm(x - xc)
                cosT.append((x - xc)[2]/s)
                det.append(agg.get(g, -1) != carrierAgg)
                far.append(s > rc + r + 1e-6)
        cosT, det = np.array(cosT), np.array(det)
        band = np.clip(np.digitize(cosT, bins) - 1, 0, 4)
        cells = ["%.2f (%d)" % (det[band == k].mean(), (band == k).sum()) for k in range(5)]
        print("| %d | %d | %d | %.3f | %.4f | %s |" % (
            N, len(runs), len(det), det.mean(), np.mean(far), " | ".join(cells)))


if __name__ == "__main__":
    main()
