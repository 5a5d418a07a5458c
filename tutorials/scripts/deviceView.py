#!/usr/bin/python3
"""Side views of a whole device at written times, drawn as the user guide's
Figure 18 (stage 2 of the inhaler at 0, 0.02 and 0.04 s): the gas speed on
the mid-plane y = 0 (colour 0 to --uMax, the guide's 0-1000 cm/s) and the
particles on top of it, coloured by radius (the guide's 2.5e-4 to 3.5e-3
cm: blue API, red carriers).

    deviceView.py CASE --times 0.05 0.07 0.09 [--since 0.05] [--labels ...]
                  [--uMax 10] [--box 'X0 Z0 X1 Z1'] [--output fig18.png]
                  [--title T]

x increases to the left, as the guide's views: the inlet leg on the left,
the outlet on the right. Reads the reconstructed (or serial) time
directories: U.air (ascii), the cloud's xDEM and d, and the cell centres
C, which `postProcess -func writeCellCentres -time T` writes (the script
runs it for the first time if no C is there).
"""
import argparse
import os
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamLagrangian as fl  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("case")
ap.add_argument("--times", nargs="+", required=True,
                help="time directory names")
ap.add_argument("--labels", nargs="+",
                help="panel titles (default: t = the times)")
ap.add_argument("--since", type=float,
                help="a stage's start: the titles also give the time since")
ap.add_argument("--uMax", type=float, default=10.0,
                help="upper end of the gas speed's colour range [m/s]")
ap.add_argument("--field", default="U.air", help="gas velocity field")
ap.add_argument("--box", metavar="'X0 Z0 X1 Z1'",
                help="a sampling box to outline (dashed), its corners in the "
                     "view [m] in one argument, e.g. '-5e-3 -3.5e-3 0 3.5e-3'")
ap.add_argument("--output", default="deviceView.png")
ap.add_argument("--title", default="Gas speed and particles, side view")
a = ap.parse_args()
box = None
if a.box:
    try:
        box = [float(v) for v in a.box.split()]
    except ValueError:
        box = []
    if len(box) != 4:
        sys.exit("deviceView.py: --box needs four numbers in one argument, "
                 "got '%s'" % a.box)
if a.labels and len(a.labels) != len(a.times):
    sys.exit("deviceView.py: %d --labels for %d --times"
             % (len(a.labels), len(a.times)))

for t in a.times:
    if not os.path.isfile(os.path.join(a.case, t, a.field)):
        sys.exit("deviceView.py: no %s in %s/%s (times written: %s)"
                 % (a.field, a.case, t, " ".join(fl.times(a.case))))

cPath = os.path.join(a.case, a.times[0], "C")
if not os.path.isfile(cPath):
    r = subprocess.run(["postProcess", "-case", a.case, "-func",
                        "writeCellCentres", "-time", a.times[0]],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    if r.returncode != 0 or not os.path.isfile(cPath):
        sys.exit("deviceView.py: postProcess -func writeCellCentres failed:\n"
                 + r.stderr[-2000:])
C = fl.read_internal_field(cPath)

# The cells next to the mid-plane: those whose centre is within half a
# cell of y = 0 (the O-grid has no centre on it: the two rows either side,
# merged by their (x, z) and averaged)
dy = 0.6e-3
near = np.abs(C[:, 1]) < dy
xz = np.round(C[near][:, [0, 2]]/2e-5).astype(np.int64)
keys, inverse = np.unique(xz, axis=0, return_inverse=True)
inverse = inverse.ravel()
count = np.bincount(inverse)
px = np.bincount(inverse, C[near][:, 0])/count
pz = np.bincount(inverse, C[near][:, 2])/count
tri = mtri.Triangulation(1e3*px, 1e3*pz)
# no triangle across the inside of the elbow: none longer than 2 mm
p = np.stack([tri.x, tri.y], axis=1)[tri.triangles]
edge = np.max(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2), axis=1)
tri.set_mask(edge > 2.0)

fig, ax = plt.subplots(len(a.times), 1, figsize=(8.5, 2.6*len(a.times)),
                       squeeze=False)
for k, t in enumerate(a.times):
    pnl = ax[k][0]
    U = fl.read_internal_field(os.path.join(a.case, t, a.field))
    magU = np.zeros(len(C)) if U is None else np.linalg.norm(U, axis=1)
    speed = np.bincount(inverse, magU[near])/count
    cs = pnl.tripcolor(tri, speed, cmap="coolwarm", vmin=0, vmax=a.uMax,
                       shading="gouraud")
    label = a.labels[k] if a.labels else "t = %s s" % t
    if a.since is not None:
        label += ", %.4g s into the stage" % (float(t) - a.since)
    if os.path.isdir(fl.cloud_dir(a.case, t)):
        c = fl.read_cloud(a.case, t, fields=("xDEM", "d"))
        x = 1e3*c["xDEM"]
        r = 0.5e2*c["d"]        # radius [cm], the guide's colour scale
        big = r > 1e-3
        for sel, size in ((~big, 1.0), (big, 6.0)):
            pnl.scatter(x[sel, 0], x[sel, 2], s=size, c=r[sel],
                        cmap="coolwarm", vmin=2.5e-4, vmax=3.5e-3,
                        linewidths=0)
        label += " (%d parcels)" % len(x)
    else:
        label += " (no cloud)"
    if box:
        x0, z0, x1, z1 = (1e3*v for v in box)
        pnl.plot([x0, x1, x1, x0, x0], [z0, z0, z1, z1, z0], "k--", lw=0.8)
    pnl.set_xlim(1e3*C[:, 0].max() + 0.5, 1e3*C[:, 0].min() - 0.5)
    pnl.set_aspect("equal")
    pnl.set_title(label, fontsize=9)
    pnl.set_ylabel("z [mm]")
    if k == len(a.times) - 1:
        pnl.set_xlabel("x [mm] (increasing to the left, as the guide's views)")
fig.colorbar(cs, ax=[r[0] for r in ax], shrink=0.8,
             label="gas speed [m/s] (y = 0)")
fig.suptitle(a.title)
fig.savefig(a.output, dpi=130, bbox_inches="tight")
print("deviceView.py: %s (%s)" % (a.output, ", ".join(a.times)))
