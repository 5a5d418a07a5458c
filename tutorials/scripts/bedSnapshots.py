#!/usr/bin/python3
"""Side views of a case's particles at written times (the user guide's
Figure 18: the bed settling), one panel per time.

    bedSnapshots.py CASE --times 0.01 0.02 0.04 [--output bed.png]
                    [--view xz|yz|xy] [--title T]

Each panel: the carriers (typeId 0) as grey discs and the API parcels as
red discs, to scale (diameter d), at their DEM positions (xDEM), seen along the axis left out of
--view (default xz: from the side, gravity down). The frame is the
particles' bounding box at the first time, with a margin, the same in every
panel. Reads the reconstructed (or serial) time directories.
"""
import argparse
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import EllipseCollection
from matplotlib.patches import Patch
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamLagrangian as fl  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("case")
ap.add_argument("--times", nargs="+", required=True,
                help="time directory names, e.g. 0.01 0.02 0.04")
ap.add_argument("--output", default="bed.png")
ap.add_argument("--view", default="xz", choices=("xz", "yz", "xy"))
ap.add_argument("--title", default="Particles")
a = ap.parse_args()

axes = ["xyz".index(c) for c in a.view]
clouds = []
for t in a.times:
    if not os.path.isdir(fl.cloud_dir(a.case, t)):
        sys.exit("bedSnapshots.py: no cloud in %s/%s (times written: %s)"
                 % (a.case, t, " ".join(fl.times(a.case))))
    clouds.append(fl.read_cloud(a.case, t, fields=("xDEM", "typeId", "d")))

x0 = clouds[0]["xDEM"][:, axes]
lo, hi = x0.min(axis=0), x0.max(axis=0)
pad = 0.15*(hi - lo).max()
lo, hi = lo - pad, hi + pad

fig, ax = plt.subplots(1, len(a.times), figsize=(4*len(a.times), 3.6),
                       squeeze=False)
for k, (t, c) in enumerate(zip(a.times, clouds)):
    p = ax[0][k]
    x = 1e3*c["xDEM"][:, axes]
    car = c["typeId"] == 0
    # discs to scale (their primary diameter d)
    handles = []
    for sel, colour, name in ((car, "0.6", "carriers"),
                              (~car, "tab:red", "API parcels")):
        dmm = 1e3*c["d"][sel]
        p.add_collection(EllipseCollection(
            dmm, dmm, np.zeros(sel.sum()), units="xy", offsets=x[sel],
            transOffset=p.transData, facecolors=colour, linewidths=0))
        handles.append(Patch(color=colour,
                             label="%s (%d)" % (name, sel.sum())))
    p.set_xlim(1e3*lo[0], 1e3*hi[0])
    p.set_ylim(1e3*lo[1], 1e3*hi[1])
    p.set_aspect("equal")
    p.set_title("t = %s s" % t)
    p.set_xlabel("%s [mm]" % a.view[0])
    if k == 0:
        p.set_ylabel("%s [mm]" % a.view[1])
        p.legend(handles=handles, loc="upper right", fontsize=7)
fig.suptitle(a.title)
fig.tight_layout()
fig.savefig(a.output, dpi=130)
print("bedSnapshots.py: %s (%s)" % (a.output, ", ".join(a.times)))
