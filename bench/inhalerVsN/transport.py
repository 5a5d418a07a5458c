#!/usr/bin/python3
"""Where the inhaler's API goes after it leaves its carrier, N against N = 1.

Usage: transport.py CASE... [--md transport.md]

Each CASE is a finished inhalerVsN case (N<N>-seed<S>) whose stage 2 wrote
its lagrangian fields often (bench/inhalerVsN/transport re-runs stage 2 so,
every 25 fluid steps). Per case:
- the FPF's two factors, from postProcessing/fpf: FPF_system accumulated is
  sum(singletsBox)/sum(apiSystem) over the samples, the product of
  sum(apiBox)/sum(apiSystem) (how long the API stays in the box, the last
  5 mm of the outlet tube, against how long it stays in the device) and
  sum(singletsBox)/sum(apiBox) (the share of singlets in the box);
- where the API leaves its carrier: the height above the corner's floor
  (z = -3.5 mm) of each API parcel at the first written time it is alone
  in its agglomerate (to within one write interval), weighted by N;
- how it travels in the horizontal leg (x < 29.5 mm, the tube's radius
  3.5 mm) between 18.5 and 23.5 ms: the mean axial speed and the mean
  distance from the axis, weighted by N, and the share within 0.2 mm of
  the wall.
Then per N the mean and seed-to-seed std of each, and for every N > 1 the
paired difference from N = 1 on the seeds both have.
"""
import argparse
import collections
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "scripts"))
import foamLagrangian as fl  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("cases", nargs="+")
ap.add_argument("--md", default="transport.md")
a = ap.parse_args()

floorZ = -3.5e-3
xTurn = 29.5e-3
radius = 3.5e-3
window = (0.0185, 0.0235)


def lastFile(case, pattern):
    files = glob.glob(os.path.join(case, pattern))
    return max(files, key=lambda p: float(p.split(os.sep)[-2]))


def analyse(case):
    fpf = np.loadtxt(lastFile(case, "postProcessing/fpf/*/fpf.dat"))
    sysSum, boxSum, singSum = fpf[:, 1].sum(), fpf[:, 2].sum(), fpf[:, 3].sum()

    # Stage 2's writes: from the stage-1 state at its end (the second time
    # directory: each stage of inhalerVsN writes at its end only) on
    first = {}
    wN, wR, wU = [], [], []
    nWrites = 0
    for t in fl.times(case)[1:]:
        if not os.path.isdir(fl.cloud_dir(case, t)):
            continue
        nWrites += 1
        c = fl.read_cloud(case, t, fields=("xDEM", "U", "typeId", "nParticle",
                                           "globalId", "agglomerateId"))
        ty = c["typeId"]
        if len(ty) == 0:
            continue
        x, U, N = c["xDEM"], c["U"], c["nParticle"]
        ag, gid = c["agglomerateId"], c["globalId"]
        ids, counts = np.unique(ag, return_counts=True)
        alone = dict(zip(ids, counts == 1))
        for k in np.where(ty == 1)[0]:
            g = int(gid[k])
            if alone[ag[k]] and g not in first:
                first[g] = (x[k, 2] - floorZ, N[k])
        if window[0] <= float(t) <= window[1]:
            m = (ty == 1) & (x[:, 0] < xTurn)
            wN.extend(N[m])
            wR.extend(np.hypot(x[m, 1], x[m, 2]))
            wU.extend(-U[m, 0])
    if nWrites < 20:
        sys.exit("transport.py: %s wrote %d times in stage 2: run it through "
                 "bench/inhalerVsN/transport first" % (case, nWrites))
    h = np.array([v[0] for v in first.values()])
    hw = np.array([v[1] for v in first.values()])
    wN, wR, wU = map(np.array, (wN, wR, wU))
    return collections.OrderedDict([
        ("FPF", singSum/sysSum),
        ("box/system", boxSum/sysSum),
        ("singlets/box", singSum/boxSum if boxSum else float("nan")),
        ("detach height [mm]", 1e3*np.average(h, weights=hw)),
        ("detached below 0.3 mm", hw[h < 0.3e-3].sum()/hw.sum()),
        ("speed in the leg [m/s]", np.average(wU, weights=wN)),
        ("from the axis [mm]", 1e3*np.average(wR, weights=wN)),
        ("within 0.2 mm of the wall", wN[wR > radius - 0.2e-3].sum()/wN.sum()),
    ])


runs = collections.defaultdict(dict)
for case in a.cases:
    m = re.search(r"N(\d+)-seed(\d+)", os.path.basename(os.path.normpath(case)))
    if not m:
        sys.exit("transport.py: %s is not named N<N>-seed<S>" % case)
    runs[int(m.group(1))][int(m.group(2))] = analyse(case)

keys = list(next(iter(next(iter(runs.values())).values())).keys())
lines = ["| quantity | " + " | ".join("N = %d (%d seeds)" % (n, len(runs[n]))
                                      for n in sorted(runs)) + " |",
         "|---|" + "---:|"*len(runs)]
for k in keys:
    cells = []
    for n in sorted(runs):
        v = np.array([r[k] for r in runs[n].values()])
        cell = "%.4g +- %.2g" % (v.mean(), v.std(ddof=1) if len(v) > 1 else 0)
        if n != 1 and 1 in runs:
            seeds = sorted(set(runs[n]) & set(runs[1]))
            if len(seeds) > 1:
                dv = np.array([runs[n][s][k] - runs[1][s][k] for s in seeds])
                cell += " (%+.3g +- %.2g)" % (dv.mean(),
                                             dv.std(ddof=1)/np.sqrt(len(dv)))
        cells.append(cell)
    lines.append("| %s | %s |" % (k, " | ".join(cells)))
text = "\n".join(lines) + (
    "\n\nmean +- seed-to-seed std; in brackets, N > 1 minus N = 1 on the "
    "same seeds: mean +- standard error.\n")
print(text)
with open(a.md, "w") as f:
    f.write(text)
print("wrote", a.md)
