#!/usr/bin/python3
"""How the carrier lands (bench/accuracyVsN, after a run): for every run in
cases/, the API parcels in the landing cap before the impact (those whose
lowest point is below the carrier's lowest point, so that they reach the
wall first: with 5 um API on a 70 um carrier, a cap of 30 degrees around
the point facing the wall), the largest rotational kinetic energy during the
impact (demDiagnostics), and the detached API fraction at the end. Runs are
split into "lands on API" (at least one parcel in the cap) and "head-on"
(none), per N: the measured mechanism of the N = 10 bias
(bench/accuracyVsN/NOTES.md, "How the carrier lands").

Usage: bench/accuracyVsN/landing.py [casesDir]
"""
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402
from polar import lastTime, field  # noqa: E402


def one(case):
    """(API parcels in the landing cap, largest rotational energy [J],
    detached fraction) of one run."""
    d0 = lastTime(os.path.join(case, "agg"))
    x, t = field(d0, "xDEM"), field(d0, "typeId", int)
    r = field(d0, "d")/2
    c = np.where(t == 0)[0][0]
    api = t == 1
    low = x[:, 2] - r
    inCap = int(np.sum(low[api] < low[c]))
    dat = glob.glob(os.path.join(case, "impact", "postProcessing", "dpiCloud",
                                 "demDiagnostics", "*", "demDiagnostics.dat"))
    eRot = np.loadtxt(dat[0], ndmin=2)[:, 2].max()
    h = benchLogs.apiHistory(os.path.join(case, "impact", "log.dpiFoam"))
    detached = h["detached"][-1]/(h["attached"][-1] + h["detached"][-1])
    return inCap, eRot, detached


top = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "cases")
runs = {}
for c in sorted(glob.glob(os.path.join(top, "N*-seed*"))):
    N = int(re.match(r"N(\d+)-", os.path.basename(c)).group(1))
    runs.setdefault(N, []).append(one(c))

print("| N | runs | API parcels in the landing cap (mean) | landing | runs "
      "| detached fraction (mean +- std) | largest rotational energy, "
      "mean [J] |")
print("|---:|---:|---:|---|---:|---:|---:|")
for N in sorted(runs):
    a = np.array(runs[N])
    for label, sel in (("all", a[:, 0] >= 0), ("on API", a[:, 0] > 0),
                       ("head-on", a[:, 0] == 0)):
        s = a[sel]
        if not len(s):
            continue
        std = s[:, 2].std(ddof=1) if len(s) > 1 else float("nan")
        print("| %d | %d | %.2f | %s | %d | %.3f +- %.3f | %.3g |" % (
            N, len(a), a[:, 0].mean(), label, len(s), s[:, 2].mean(), std,
            s[:, 1].mean()))
