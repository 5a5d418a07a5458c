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

With --overlap-diameter d and two parcels it also draws <prefix>_overlap.png,
the overlap normalised by d, (d - |x1 - x2|)/d, against time for every run
(the guide's Case 2 Figure 6 and its Eq. (1): negative while the particles
approach, positive in contact), and prints per run the contact (where the
normalised overlap crosses zero, interpolated between steps), its peak, the
peak force on parcel 1 along the axis and the restitution coefficient
(relative speed along the axis at the end over that at the start).
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


def zero_crossings(t, y):
    """Times where y changes sign, linearly interpolated between samples"""
    s = np.sign(y)
    i = np.nonzero(s[:-1]*s[1:] < 0)[0]
    return t[i] - y[i]*(t[i+1] - t[i])/(y[i+1] - y[i])


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
    overlap = a.overlap_diameter is not None and len(a.parcels) == 2
    if overlap:
        fig3, ax3 = plt.subplots(figsize=(6, 4))
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
            ov = (a.overlap_diameter - dist)/a.overlap_diameter
            ax3.plot(t*1e6, ov, label=run,
                     ls="-" if run == a.runs[0] else "--")
            tz = zero_crossings(t, ov)
            f1 = tr[0][:, 7 + c]
            dv0 = tr[1][0, 4 + c] - tr[0][0, 4 + c]
            dv1 = tr[1][-1, 4 + c] - tr[0][-1, 4 + c]
            contact = ("contact %.4g to %.4g us (%.4g us)"
                       % (tz[0]*1e6, tz[1]*1e6, (tz[1] - tz[0])*1e6)
                       if len(tz) >= 2 else "contact not closed")
            print("%s: %s, peak overlap/d %.4g at %.4g us, peak |f%s1| "
                  "%.4g N, restitution %.4g, %d steps to t = %.4g us"
                  % (run, contact, ov.max(), t[np.argmax(ov)]*1e6, a.axis,
                     np.abs(f1).max(), abs(dv1/dv0), len(t), t[-1]*1e6))
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
    if overlap:
        panels.append((ax3, "overlap", "(d - |x1 - x2|)/d [-]"))
    panels += [(ax, "force", "f" + a.axis + " [N]") for ax in axes2[:, 0]]
    for ax, what, unit in panels:
        ax.set_xlabel("time [us]")
        ax.set_ylabel(unit)
        ax.set_title("%s: %s" % (a.title, what) if a.title else what)
        ax.grid(True, alpha=0.3)
        ax.legend()
    figs = [(fig1, "position"), (fig2, "force")]
    if overlap:
        figs.append((fig3, "overlap"))
    for fig, what in figs:
        fig.tight_layout()
        fig.savefig("%s_%s.png" % (a.prefix, what), dpi=120)
        print("wrote %s_%s.png" % (a.prefix, what))


if __name__ == "__main__":
    main()
