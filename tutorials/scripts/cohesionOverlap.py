#!/usr/bin/python3
"""Case 3 (carrier-API cohesion): the guide's output.dat and overlap figure.

Usage: cohesionOverlap.py [--r-api 2.5e-6] [--r-carrier 35e-6] [--prefix case3] RUN [RUN ...]

Each RUN is a case folder (e.g. N1, N10, N100) holding the traces of parcel
0 (carrier) and 1 (API), postProcessing/dpiCloud/trace/<t>/parcel<id>.dat.
For every run it writes RUN/output.dat with the guide's columns

    time overlap z1 z2

where, as in the guide's deck, overlap = (r_c + r_API - |x2 - x1|)/r_API
(the overlap in units of the API radius; the deck computes
(0.00375 - (z2 - z1))/0.00025 in cm), then one extra column delta = the
overlap in m. It prints, per run, the equilibrium overlap (last value), the
first peak, and the oscillation period (from the maxima of delta, refined
by a parabola through the three samples around each): the first period and
the last one whose amplitude is above 1e-4 of delta_eq; and it draws
<prefix>_overlap.png (overlap vs time, one line per run, with a zoom on the
first microseconds), like the guide's figure 8.
"""
import argparse
import glob
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_trace(run, pid):
    files = sorted(glob.glob(os.path.join(
        run, "postProcessing", "*", "trace", "*", "parcel%d.dat" % pid)))
    if not files:
        raise SystemExit("no trace of parcel %d in %s" % (pid, run))
    return np.vstack([np.loadtxt(f, ndmin=2) for f in files])


def maxima(t, y):
    """Times and values of the local maxima, parabola-refined."""
    tm, ym = [], []
    for k in range(1, len(y) - 1):
        if y[k] > y[k - 1] and y[k] >= y[k + 1]:
            a = 0.5*(y[k - 1] + y[k + 1]) - y[k]
            b = 0.5*(y[k + 1] - y[k - 1])
            dk = -b/(2*a) if a < 0 else 0.0
            tm.append(t[k] + dk*(t[k + 1] - t[k]))
            ym.append(y[k] + b*dk + a*dk*dk)
    return np.array(tm), np.array(ym)


def analyse(t, delta):
    eq = delta[-1]
    tm, ym = maxima(t, delta)
    res = {"deltaEq": eq, "nPeaks": len(tm)}
    if len(tm) >= 2:
        res["firstPeak"] = ym[0]
        res["firstPeriod"] = tm[1] - tm[0]
        last = 1
        for k in range(1, len(ym)):
            if ym[k] - eq > 1e-4*eq:
                last = k
        res["lastPeriod"] = tm[last] - tm[last - 1]
        res["meanPeriod"] = (tm[last] - tm[0])/last
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--r-api", type=float, default=2.5e-6,
                    help="API radius [m] (the guide's 0.00025 cm)")
    ap.add_argument("--r-carrier", type=float, default=35e-6,
                    help="carrier radius [m] (the guide's 0.0035 cm)")
    ap.add_argument("--prefix", default="case3")
    ap.add_argument("--title", default="Case 3: carrier-API cohesion")
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7))
    styles = ["-", "--", ":", "-."]
    for i, run in enumerate(a.runs):
        c, p = read_trace(run, 0), read_trace(run, 1)
        n = min(len(c), len(p))
        c, p = c[:n], p[:n]
        t = c[:, 0]
        dist = np.linalg.norm(p[:, 1:4] - c[:, 1:4], axis=1)
        delta = a.r_carrier + a.r_api - dist
        overlap = delta/a.r_api
        np.savetxt(os.path.join(run, "output.dat"),
                   np.column_stack([t, overlap, c[:, 3], p[:, 3], delta]),
                   header="time overlap z1 z2 delta[m]", fmt="%.10e")

        r = analyse(t, delta)
        line = "%s: delta_eq %.6g m (overlap/r_API %.6g)" % (
            run, r["deltaEq"], r["deltaEq"]/a.r_api)
        if "firstPeriod" in r:
            line += (", first peak %.5g m, period %.5g s (first) -> %.5g s"
                     " (last), mean %.5g s over %d peaks" % (
                         r["firstPeak"], r["firstPeriod"], r["lastPeriod"],
                         r["meanPeriod"], r["nPeaks"]))
        print(line)

        ls = styles[i % len(styles)]
        ax1.plot(t*1e6, overlap, ls=ls, label=run)
        m = t <= 3e-6
        ax2.plot(t[m]*1e6, delta[m]*1e9, ls=ls, label=run)

    ax1.set_ylabel("overlap / r_API")
    ax1.set_title(a.title + ": overlap")
    ax2.set_ylabel("overlap [nm]")
    ax2.set_title("first 3 us")
    for ax in (ax1, ax2):
        ax.set_xlabel("time [us]")
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig("%s_overlap.png" % a.prefix, dpi=120)
    print("wrote %s_overlap.png" % a.prefix)


if __name__ == "__main__":
    main()
