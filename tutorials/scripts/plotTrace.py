#!/usr/bin/python3
"""Turn dpiFoam parcel traces into the guide's output.dat and figures.

Usage: plotTrace.py --axis y --parcels 0 [1] --title "..." RUN [RUN ...]

Each RUN is a case folder (e.g. N1, N100) holding
postProcessing/dpiCloud/trace/<t>/parcel<id>.dat (written by the cloud's
`trace` entry). For every run it writes RUN/output.dat with the guide's
columns: time, then per traced parcel the position, velocity and force
component along the axis (Case 1: time y vy fy; Case 2: time, overlap,
z1 z2 vz1 vz2 fz1 fz2 when --overlap-diameter is given), and it draws
<prefix>_position.png and <prefix>_force.png with one line per run, like the
guide's figures (position in um, force in N, time in us).
"""
import argparse
import glob
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

AXES = {"x": 0, "y": 1, "z": 2}


def read_trace(run, pid):
    files = sorted(glob.glob(os.path.join(
        run, "postProcessing", "*", "trace", "*", "parcel%d.dat" % pid)))
    if not files:
        raise SystemExit("no trace of parcel %d in %s" % (pid, run))
    return np.vstack([np.loadtxt(f, ndmin=2) for f in files])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--axis", default="y", choices=AXES)
    ap.add_argument("--parcels", type=int, nargs="+", default=[0])
    ap.add_argument("--overlap-diameter", type=float, default=None,
                    help="write the overlap d - |x1 - x2| (two parcels)")
    ap.add_argument("--title", default="")
    ap.add_argument("--prefix", default="trace")
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    c = AXES[a.axis]

    fig1, ax1 = plt.subplots(figsize=(6, 4))
    # forces differ by N: one panel per run, as the guide's figures
    fig2, axes2 = plt.subplots(len(a.runs), 1, figsize=(6, 3*len(a.runs)),
                               sharex=True, squeeze=False)
    for r, run in enumerate(a.runs):
        tr = [read_trace(run, p) for p in a.parcels]
        n = min(len(t) for t in tr)
        tr = [t[:n] for t in tr]
        t = tr[0][:, 0]
        cols = [t]
        header = "time"
        if a.overlap_diameter is not None and len(tr) == 2:
            dist = np.linalg.norm(tr[0][:, 1:4] - tr[1][:, 1:4], axis=1)
            cols.append(a.overlap_diameter - dist)
            header += " overlap"
        for k, p in enumerate(a.parcels):
            cols.append(tr[k][:, 1 + c])
            header += " %s%d" % (a.axis, p + 1)
        for k, p in enumerate(a.parcels):
            cols.append(tr[k][:, 4 + c])
            header += " v%s%d" % (a.axis, p + 1)
        for k, p in enumerate(a.parcels):
            cols.append(tr[k][:, 7 + c])
            header += " f%s%d" % (a.axis, p + 1)
        np.savetxt(os.path.join(run, "output.dat"), np.column_stack(cols),
                   header=header, fmt="%.10e")

        for k, p in enumerate(a.parcels):
            label = run if len(a.parcels) == 1 else "%s parcel %d" % (run, p)
            ax1.plot(t*1e6, tr[k][:, 1 + c]*1e6, label=label,
                     ls="-" if run == a.runs[0] else "--")
            axes2[r, 0].plot(t*1e6, tr[k][:, 7 + c], label=label)

    panels = [(ax1, "position", a.axis + " [um]")]
    panels += [(ax, "force", "f" + a.axis + " [N]") for ax in axes2[:, 0]]
    for ax, what, unit in panels:
        ax.set_xlabel("time [us]")
        ax.set_ylabel(unit)
        ax.set_title("%s: %s" % (a.title, what) if a.title else what)
        ax.grid(True, alpha=0.3)
        ax.legend()
    for fig, what in ((fig1, "position"), (fig2, "force")):
        fig.tight_layout()
        fig.savefig("%s_%s.png" % (a.prefix, what), dpi=120)
        print("wrote %s_%s.png" % (a.prefix, what))


if __name__ == "__main__":
    main()
