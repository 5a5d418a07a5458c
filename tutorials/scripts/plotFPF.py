#!/usr/bin/python3
"""Plot the fine particle fraction time series of the dpiFPF function object.

    plotFPF.py postProcessing/fpf/<t>/fpf.dat [--output fpf.png] [--title T]

Top: FPF_box (singlets/API in the box) and FPF_system (singlets in the
box/all API), per sample and accumulated over the samples (theory 6.2).
Bottom: the API primaries in the box and the singlets among them.
Prints the last accumulated values.
"""
import argparse
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("file", help="fpf.dat of the dpiFPF function object")
ap.add_argument("--output", default="fpf.png")
ap.add_argument("--title", default="Fine particle fraction")
a = ap.parse_args()

cols = None
with open(a.file) as f:
    for line in f:
        if line.startswith("#") and "Time" in line and "FPF_box" in line:
            cols = line.lstrip("#").split()
d = np.loadtxt(a.file, comments="#", ndmin=2)
if cols is None or d.size == 0:
    sys.exit("plotFPF: no samples in %s (is the time window reached?)" % a.file)
c = {name: d[:, i] for i, name in enumerate(cols)}
t_ms = 1e3*c["Time"]

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
ax1.plot(t_ms, c["FPF_box"], "C0-", lw=1, label="FPF_box = singlets/API in box")
ax1.plot(t_ms, c["FPF_system"], "C1-", lw=1, label="FPF_system = singlets in box/all API")
ax1.plot(t_ms, c["FPF_box_acc"], "C0--", lw=1.5, label="FPF_box accumulated")
ax1.plot(t_ms, c["FPF_system_acc"], "C1--", lw=1.5, label="FPF_system accumulated")
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
