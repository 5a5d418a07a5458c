#!/usr/bin/python3
"""Plot where the DEM's time went over a run, from its demPerformance series.

    plotCost.py CASE [--cloud dpiCloud] [--output cost.png] [--title T]
                [--stages T ...]

Reads every postProcessing/<cloud>/demPerformance/<t>/demPerformance.dat of
the case (one per start: a stage, or a run resumed from a write), whose
columns are the master processor's cumulative wall-clock seconds per cost
term at the end of each fluid step. Each file is differenced step by step
(its timers start at 0 with its run), so several runs join into one
series. Top: wall-clock seconds per simulated millisecond, stacked by term
(pair, wall, neighbour search, integration, halo exchange, sub-step gas
forces), against the simulated time, over windows of 1/250 of the run
(single fluid steps jitter with the machine). Bottom: searches and near
builds per 1,000 DEM steps. --stages marks times (e.g. the end of stage 1) with a
vertical line. Prints each term's share of the whole.
"""
import argparse
import glob
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dpiLog  # noqa: E402

# The series' columns in the order used below (dpiLog's names), and the
# six cost terms' labels
COLS = ["time", "steps", "pair", "wall", "neighbour", "integrate", "halo",
        "subStepGas", "builds", "nearBuilds"]
TERMS = ["pair", "wall", "neighbour", "integrate", "halo exchange",
         "sub-step gas forces"]

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("case", help="the case directory")
ap.add_argument("--cloud", default="dpiCloud")
ap.add_argument("--output", default="cost.png")
ap.add_argument("--title", default="Where the DEM's time went")
ap.add_argument("--stages", nargs="*", type=float, default=[],
                help="times to mark (e.g. the end of stage 1) [s]")
a = ap.parse_args()

files = glob.glob(os.path.join(a.case, "postProcessing", a.cloud,
                               "demPerformance", "*", "demPerformance.dat"))
if not files:
    sys.exit("plotCost.py: no %s/postProcessing/%s/demPerformance/*/"
             "demPerformance.dat (dpiFoam writes it at every fluid step)"
             % (a.case, a.cloud))

# Per file: the start time (its directory) and its rows, differenced
segments = []
for f in files:
    start = float(os.path.basename(os.path.dirname(f)))
    series = dpiLog.demPerformanceSeries(f)
    if not series["time"]:
        continue
    rows = np.array([series[c] for c in COLS]).T
    # the first row's increments are from the run's start (all 0 then)
    prev = np.concatenate([[start], np.zeros(rows.shape[1] - 1)])
    full = np.vstack([prev, rows])
    d = np.diff(full, axis=0)
    segments.append((start, rows[:, 0], d))
segments.sort(key=lambda s: s[0])

# One series by time: a later start replaces what an earlier run wrote
# from that time on (a stage resumed from a write)
t, inc = [], []
for k, (start, times, d) in enumerate(segments):
    nextStart = segments[k + 1][0] if k + 1 < len(segments) else np.inf
    keep = times <= nextStart + 1e-15
    t.append(times[keep])
    inc.append(d[keep])
t = np.concatenate(t)
inc = np.concatenate(inc)
dtSim = inc[:, 0]
ok = dtSim > 0
t, inc, dtSim = t[ok], inc[ok], dtSim[ok]

terms = inc[:, 2:8]                          # seconds in the step, per term


def smooth(v):
    # The sums over a window of about 1/250 of the run (a fluid step's
    # timings jitter with the machine), then the rates of those sums
    w = max(1, len(v)//250)
    return np.convolve(v, np.ones(w), mode="same")


rate = np.array([smooth(c) for c in terms.T]).T \
    / (smooth(dtSim)[:, None]*1e3)           # seconds per simulated ms
steps = np.maximum(smooth(inc[:, 1]), 1)
searches = 1e3*smooth(inc[:, 8])/steps
near = 1e3*smooth(inc[:, 9])/steps

total = terms.sum(axis=0)
print("plotCost.py: %d fluid steps from %g to %g s, DEM %.4g s on the "
      "master:" % (len(t), t[0] - dtSim[0], t[-1], total.sum()))
for name, v in zip(TERMS, total):
    print("    %-20s %10.4g s (%.0f %%)"
          % (name, v, 100*v/total.sum() if total.sum() > 0 else 0))

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 7), sharex=True,
                               gridspec_kw=dict(height_ratios=[2, 1]))
ms = 1e3*t
ax1.stackplot(ms, rate.T, labels=TERMS, step="pre")
ax1.set_ylabel("wall-clock s per simulated ms")
ax1.set_title(a.title)
ax1.legend(loc="upper left", fontsize=8)
ax2.step(ms, searches, where="pre", label="searches")
ax2.step(ms, near, where="pre", label="near builds")
ax2.set_ylabel("per 1,000 DEM steps")
ax2.set_xlabel("simulated time [ms]")
ax2.legend(loc="upper left", fontsize=8)
for ts in a.stages:
    for ax in (ax1, ax2):
        ax.axvline(1e3*ts, color="k", lw=0.8, ls="--")
fig.tight_layout()
fig.savefig(a.output, dpi=120)
print("plotCost.py: wrote " + a.output)
