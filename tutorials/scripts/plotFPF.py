#!/usr/bin/python3
"""Plot the fine particle fraction time series of the dpiFPF function object.

    plotFPF.py postProcessing/fpf/<t>/fpf.dat [more fpf.dat] [--output fpf.png]
               [--title T] [--dumps T0 DT T1]

Top: FPF_box (singlets/API in the box) and FPF_system (singlets in the
box/all API), per sample and accumulated over the samples (theory 6.2).
Bottom: the API primaries in the box and the singlets among them.
Prints the last accumulated values. Several files (a run restarted: the
function object begins a file at each start) are taken as one series, by
time, a later file's sample replacing an earlier one's at the same time.

--dumps T0 DT T1: also the fractions accumulated as the user guide's
calculateFPF.py does (section 3.4): over the dump times T0, T0 + DT, ...
up to T1 only (the guide: every 1e5 DEM steps = 1e-3 s from 0.05 to
0.11 s), the sums of singlets in the box over the sums of API in the box
(FPF_box) and in the system (FPF_system, the guide's definition). A dump
time is taken from the sample within half a fluid step of it; dump times
without a sample (e.g. T0 itself when the window opens there: the first
sample is at the end of the first step) are left out and counted. The
dump times are marked on the plot and the values printed.
"""
import argparse
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("files", nargs="+",
                help="fpf.dat of the dpiFPF function object, in run order")
ap.add_argument("--output", default="fpf.png")
ap.add_argument("--title", default="Fine particle fraction")
ap.add_argument("--dumps", nargs=3, type=float, metavar=("T0", "DT", "T1"),
                help="accumulate over the dump times T0, T0 + DT, ... <= T1"
                     " only, as the user guide's calculateFPF.py")
a = ap.parse_args()

cols = None
byTime = {}
for path in a.files:
    with open(path) as f:
        for line in f:
            if line.startswith("#") and "Time" in line and "FPF_box" in line:
                cols = line.lstrip("#").split()
    for row in np.loadtxt(path, comments="#", ndmin=2):
        byTime[row[0]] = row
d = np.array([byTime[t] for t in sorted(byTime)]) if byTime \
    else np.zeros((0, 0))
if cols is None or d.size == 0:
    sys.exit("plotFPF: no samples in %s (is the time window reached?)"
             % " ".join(a.files))
c = {name: d[:, i] for i, name in enumerate(cols)}
t_ms = 1e3*c["Time"]

dumpRows = []
if a.dumps:
    t0, dt, t1 = a.dumps
    if dt <= 0 or t1 < t0:
        sys.exit("plotFPF: --dumps T0 DT T1 needs DT > 0 and T1 >= T0")
    step = np.median(np.diff(c["Time"])) if len(c["Time"]) > 1 else dt
    nDumps = int(np.floor((t1 - t0)/dt + 1e-9)) + 1
    for k in range(nDumps):
        td = t0 + k*dt
        i = int(np.argmin(np.abs(c["Time"] - td)))
        if abs(c["Time"][i] - td) <= 0.5*step:
            dumpRows.append(i)
    if not dumpRows:
        sys.exit("plotFPF: no sample at any of the %d dump times %g, %g, ..."
                 " %g s" % (nDumps, t0, t0 + dt, t1))

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
ax1.plot(t_ms, c["FPF_box"], "C0-", lw=1, label="FPF_box = singlets/API in box")
ax1.plot(t_ms, c["FPF_system"], "C1-", lw=1, label="FPF_system = singlets in box/all API")
ax1.plot(t_ms, c["FPF_box_acc"], "C0--", lw=1.5, label="FPF_box accumulated")
ax1.plot(t_ms, c["FPF_system_acc"], "C1--", lw=1.5, label="FPF_system accumulated")
if dumpRows:
    ax1.plot(t_ms[dumpRows], c["FPF_system"][dumpRows], "ko", ms=3,
             label="dump times (--dumps)")
ax1.set_ylabel("FPF [-]")
ax1.set_ylim(-0.02, 1.02)
ax1.legend(fontsize=8)
ax1.set_title(a.title, fontsize=10)
ax1.grid(alpha=0.3)

ax2.plot(t_ms, c["apiBox"], "C2-", label="API primaries in box")
ax2.plot(t_ms, c["singletsBox"], "C3-", label="singlet API primaries in box")
ax2.set_xlabel("time [ms]")
ax2.set_ylabel("primaries (sum of N)")
ax2.legend(fontsize=8)
ax2.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(a.output, dpi=120)

print("plotFPF: %d samples, t = %g .. %g s; last: FPF_box %.4g, FPF_system %.4g;"
      " accumulated: FPF_box %.4g, FPF_system %.4g; API in system %g -> %s"
      % (len(t_ms), c["Time"][0], c["Time"][-1], c["FPF_box"][-1],
         c["FPF_system"][-1], c["FPF_box_acc"][-1], c["FPF_system_acc"][-1],
         c["apiSystem"][-1], a.output))

if dumpRows:
    sb = c["singletsBox"][dumpRows].sum()
    ab = c["apiBox"][dumpRows].sum()
    asys = c["apiSystem"][dumpRows].sum()
    print("plotFPF: as the user guide's calculateFPF.py, over %d dump times"
          " %g .. %g s every %g s (%d without a sample left out):"
          " FPF_system %.4g (singlets in the box / API in the system),"
          " FPF_box %.4g (singlets in the box / API in the box)"
          % (len(dumpRows), c["Time"][dumpRows[0]], c["Time"][dumpRows[-1]],
             a.dumps[1], nDumps - len(dumpRows), sb/asys if asys else 0,
             sb/ab if ab else 0))
