#!/usr/bin/python3
"""Plot the emitted dose (dpiEmittedDose's emittedDose.dat) over time.

    plotDose.py FILE [FILE ...] [--output dose.png] [--title T]

Top: the API that has left, as a fraction of the API loaded, stacked by
how it left (singlets, agglomerates of API alone, on carriers); bottom:
FPF_emitted (fine over emitted) and FPF_loaded (fine over loaded). Files
of one run restarted (one per start time) are joined in time order; a
time written twice keeps the later file's row. Prints the last row.
"""
import argparse
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

COLUMNS = ("t", "loaded", "emitted", "singlets", "agglomerates",
           "onCarriers", "fine", "FPF_emitted", "FPF_loaded", "primaries")

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("files", nargs="+")
ap.add_argument("--output", default="dose.png")
ap.add_argument("--title", default="Emitted dose")
a = ap.parse_args()

rows = {}
for path in a.files:
    with open(path) as f:
        cutOff = None
        for line in f:
            if line.startswith("#"):
                if line.startswith("# aerodynamic cut-off"):
                    cutOff = float(line.split(":")[-1])
                continue
            v = [float(x) for x in line.split()]
            if len(v) == len(COLUMNS):
                rows[v[0]] = v
if not rows:
    sys.exit("plotDose.py: no data rows in %s" % " ".join(a.files))
d = np.array([rows[t] for t in sorted(rows)])
c = {name: d[:, i] for i, name in enumerate(COLUMNS)}
t_ms = 1e3*c["t"]
loaded = np.where(c["loaded"] > 0, c["loaded"], 1)

fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
ax1.stackplot(t_ms, c["singlets"]/loaded, c["agglomerates"]/loaded,
              c["onCarriers"]/loaded,
              labels=("singlets", "agglomerates of API", "on carriers"),
              colors=("C3", "C1", "C7"))
ax1.set_ylabel("API that left / API loaded")
ax1.set_ylim(0, 1)
ax1.legend(loc="upper left")
ax1.set_title(a.title)
cut = "" if cutOff is None else " (d_ae < %.3g um)" % (cutOff*1e6)
# over emitted: undefined before anything has left (drawn from then on)
fpfE = np.where(c["emitted"] > 0, c["FPF_emitted"], np.nan)
ax2.plot(t_ms, fpfE, "C0-", label="FPF over emitted" + cut)
ax2.plot(t_ms, c["FPF_loaded"], "C2-", label="FPF over loaded" + cut)
ax2.set_ylabel("fine particle fraction")
ax2.set_xlabel("t [ms]")
ax2.set_ylim(0, 1)
ax2.legend(loc="upper left")
for ax in (ax1, ax2):
    ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(a.output, dpi=110)

last = {name: c[name][-1] for name in COLUMNS}
print("plotDose: t = %g s: API left %.4g of %.4g kg loaded (singlets %.4g, "
      "agglomerates %.4g, on carriers %.4g); FPF_emitted %.4g, FPF_loaded "
      "%.4g; %s" % (last["t"], last["emitted"], last["loaded"],
                    last["singlets"], last["agglomerates"],
                    last["onCarriers"], last["FPF_emitted"],
                    last["FPF_loaded"], a.output))
