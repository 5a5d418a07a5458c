#!/usr/bin/python3
"""The trade curves of two coarse-graining models side by side: a scene's
summary.csv (the reference, dem/coarseGraining scaledContacts) and
summary-coatingCoverage.csv, as written by the accuracy scripts
(common/tradeCurve.py's summary).

    modelsPlot.py --before summary.csv --after summary-coatingCoverage.csv
                  --png models.png --ylabel "detached fraction"
                  [--measure attached_end] [--title TEXT]

Left: the measure's mean against N, the seed-to-seed standard deviation
as bars, N = 1's spread as a band; right: the error against N = 1 (in N = 1
standard deviations) against the speed-up, one point per N, for both.
--measure picks the rows of a summary with a "measure" column (powderVsN).
"""
import argparse
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path, measure):
    with open(path) as f:
        out = [r for r in csv.DictReader(f)
               if measure is None or r.get("measure") == measure]
    if not out:
        sys.exit("modelsPlot.py: no rows%s in %s"
                 % ("" if measure is None else " of " + measure, path))
    return sorted(out, key=lambda r: float(r["N"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("--ylabel", required=True)
    ap.add_argument("--measure")
    ap.add_argument("--title", default="")
    a = ap.parse_args()

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    for path, label, style in ((a.before, "scaledContacts (reference)", "o--"),
                               (a.after, "coatingCoverage", "s-")):
        r = rows(path, a.measure)
        N = [float(x["N"]) for x in r]
        mean = [float(x["mean"]) for x in r]
        std = [float(x["std"]) for x in r]
        ax.errorbar(N, mean, yerr=std, fmt=style, capsize=3, label=label)
        one = [x for x in r if float(x["N"]) == 1]
        if not one:
            sys.exit("modelsPlot.py: no N = 1 row in %s" % path)
        s1 = float(one[0]["std"])
        err = [abs(float(x["error"]))/s1 for x in r]
        speed = [float(x["speedup"]) for x in r]
        bx.plot(speed, err, style, label=label)
        for n, sp, e in zip(N, speed, err):
            bx.annotate("%g" % n, (sp, e), textcoords="offset points",
                        xytext=(4, 4), fontsize=8)
    r1 = [x for x in rows(a.after, a.measure) if float(x["N"]) == 1][0]
    m1, s1 = float(r1["mean"]), float(r1["std"])
    ax.axhspan(m1 - s1, m1 + s1, color="0.85", label="N = 1 +- std")
    ax.set_xscale("log")
    ax.set_xlabel("coarsening factor N")
    ax.set_ylabel(a.ylabel)
    ax.legend(fontsize=8)
    bx.axhline(1, color="0.5", lw=0.8)
    bx.set_xscale("log")
    bx.set_xlabel("speed-up against N = 1 (CPU time)")
    bx.set_ylabel("|error against N = 1| / N = 1 std")
    bx.legend(fontsize=8)
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("wrote %s" % a.png)


if __name__ == "__main__":
    main()
