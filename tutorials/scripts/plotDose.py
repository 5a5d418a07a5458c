#!/usr/bin/python3
"""Plot the emitted dose (dpiEmittedDose's emittedDose.dat) over time.

    plotDose.py FILE [FILE ...] [--output dose.png] [--title T]
                [--sizes SIZES ...] [--retention RETENTION ...]

Top: the API that has left, as a fraction of the API loaded, stacked by
how it left (singlets, agglomerates of API alone, on carriers); below:
FPF_emitted (fine over emitted) and FPF_loaded (fine over loaded). With
--retention (dpiDeviceRetention's retention.dat) a panel of the API still
in the device, stacked: on carriers, deposited on each wall patch, neither;
with --sizes (dpiEmittedDose's sizes.dat) a bar chart of the emitted API
by agglomerate size at the last time. Files of one run restarted (one per
start time) are joined in time order; a time written twice keeps the later
file's row. Prints the last row.
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
ap.add_argument("--sizes", nargs="+", default=[],
                help="dpiEmittedDose's sizes.dat file(s)")
ap.add_argument("--retention", nargs="+", default=[],
                help="dpiDeviceRetention's retention.dat file(s)")
a = ap.parse_args()


def readSeries(files, nColumns=None):
    """The column names (from the '# Time' line) and the rows by time"""
    names, rows = None, {}
    for path in files:
        with open(path) as f:
            for line in f:
                if line.startswith("# Time"):
                    names = line.split()[2:]
                elif not line.startswith("#"):
                    v = [float(x) for x in line.split()]
                    if len(v) == (nColumns or len(names) + 1):
                        rows[v[0]] = v
    if not rows:
        sys.exit("plotDose.py: no data rows in %s" % " ".join(files))
    return names, np.array([rows[t] for t in sorted(rows)])


cutOff = None
for path in a.files:
    with open(path) as f:
        for line in f:
            if line.startswith("# aerodynamic cut-off"):
                cutOff = float(line.split(":")[-1])
d = readSeries(a.files, len(COLUMNS))[1]
c = {name: d[:, i] for i, name in enumerate(COLUMNS)}
t_ms = 1e3*c["t"]
loaded = np.where(c["loaded"] > 0, c["loaded"], 1)

panels = 2 + bool(a.retention) + bool(a.sizes)
fig, axes = plt.subplots(panels, 1, figsize=(8, 3.25*panels))
ax1, ax2 = axes[0], axes[1]
ax2.sharex(ax1)
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
k = 2
if a.retention:
    names, r = readSeries(a.retention)
    ax = axes[k]
    k += 1
    ax.sharex(ax1)
    load = np.interp(r[:, 0], c["t"], loaded)
    walls = names[3:]
    ax.stackplot(1e3*r[:, 0], r[:, 2]/load,
                 *[r[:, 4 + i]/load for i in range(len(walls))],
                 r[:, 3]/load,
                 labels=["on carriers"] + ["on " + w for w in walls]
                 + ["neither (airborne, on powder)"],
                 colors=["C7"] + ["C%d" % (i % 3 + 4) for i in range(len(walls))]
                 + ["C9"])
    ax.set_ylabel("API in the device / loaded")
    ax.set_xlabel("t [ms]")
    ax.set_ylim(0, 1)
    ax.legend(loc="upper right", fontsize="small")
    ax.grid(alpha=0.3)
if a.sizes:
    names, sz = readSeries(a.sizes)
    ax = axes[k]
    last = sz[-1, 1:]
    em = max(last.sum(), 1e-300)
    ax.bar(range(len(names)), last/em, color=["C3"] + ["C1"]*(len(names) - 2) + ["C7"])
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(["1 (singlets)"] + names[1:-1] + ["on carriers"])
    ax.set_xlabel("API primaries in one agglomerate")
    ax.set_ylabel("emitted API fraction")
    ax.set_title("Emitted API by agglomerate size at t = %g ms" % (1e3*sz[-1, 0]))
    ax.grid(alpha=0.3, axis="y")
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
