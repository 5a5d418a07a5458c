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

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("cases", nargs="+")
ap.add_argument("--md", default="transport.md")
a = ap.parse_args()

floorZ = -3.5e-3
xTurn = 29.5e-3
radius = 3.5e-3
window = (0.0185, 0.0235)


def readField(fn):
    """A lagrangian field of an ascii case: a list of scalars or vectors
    (n(...) on one line or over many, or n{value})."""
    text = open(fn).read()
    body = text[text.find("}", text.find("FoamFile")) + 1:]
    m = re.search(r"(\d+)\s*([({])", body)
    n = int(m.group(1))
    if m.group(2) == "{":
        return np.full(n, float(body[m.end():body.find("}", m.end())]))
    if n == 0:
        return np.zeros(0)
    inner = body[m.end():]
    if inner.lstrip().startswith("("):
        rows = re.findall(r"\(([^()]*)\)", inner)[:n]
        return np.array([[float(v) for v in r.split()] for r in rows])
    return np.array([float(v) for v in inner.split(")")[0].split()[:n]])


def lastFile(case, pattern):
    files = glob.glob(os.path.join(case, pattern))
    return max(files, key=lambda p: float(p.split(os.sep)[-2]))


def analyse(case):
    fpf = np.loadtxt(lastFile(case, "postProcessing/fpf/*/fpf.dat"))
    sysSum, boxSum, singSum = fpf[:, 1].sum(), fpf[:, 2].sum(), fpf[:, 3].sum()

    times = sorted(
        (t for t in os.listdir(case)
         if re.fullmatch(r"[0-9.e-]+", t) and float(t) >= 0.01),
        key=float)
    first = {}
    wN, wR, wU = [], [], []
    nWrites = 0
    for t in times:
        d = os.path.join(case, t, "lagrangian", "dpiCloud")
        if not os.path.isdir(d):
            continue
        nWrites += 1
        ty = readField(d + "/typeId")
        if len(ty) == 0:
            continue
        x = readField(d + "/xDEM")
        U = readField(d + "/U")
        N = readField(d + "/nParticle")
        ag = readField(d + "/agglomerateId")
        gid = readField(d + "/globalId")
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
