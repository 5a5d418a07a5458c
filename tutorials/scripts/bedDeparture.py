#!/usr/bin/python3
"""When the powder bed leaves its site and when powder reaches the outlet,
from a case's written times (the user guide's Fig. 18 read as numbers).

    bedDeparture.py CASE --since T1 [--outlet X] [--moved D] [--log LOG ...]

At every written time from T1 (the start of the inhalation) on, with the
parcels at T1 as the bed: the carriers and the API primaries (sum of N)
that have moved more than D (default 1 mm) from where they were at T1 or
have left the domain, and those past the outlet plane x = X (default 0:
the tube's end, x decreasing downstream) or gone. Reads xDEM, typeId,
nParticle and globalId of the reconstructed (or serial) times; typeId 0 is
the carrier, every other type counts as API.

With --log (the stage's dpiFoam logs, in run order) it also prints the
first time a parcel left through a patch ("Patch ...: escaped parcels").
Prints a table; the quick and full inhaler Allruns call it.
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamLagrangian as fl  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("case")
ap.add_argument("--since", type=float, required=True,
                help="the inhalation's start time [s]: the bed as written then")
ap.add_argument("--outlet", type=float, default=0.0,
                help="x of the outlet plane [m]; downstream is x below it")
ap.add_argument("--moved", type=float, default=1e-3,
                help="displacement counted as having left the site [m]")
ap.add_argument("--log", nargs="*", default=[],
                help="dpiFoam logs of the stage, for the first escape")
a = ap.parse_args()

FIELDS = ("xDEM", "typeId", "nParticle", "globalId")
# A time written without a cloud directory has no parcels left
names = [n for n in fl.times(a.case) if float(n) >= a.since - 1e-12]
if not names or not os.path.isdir(fl.cloud_dir(a.case, names[0])):
    sys.exit("bedDeparture.py: no written cloud at or after t = %g s in %s"
             % (a.since, a.case))
bed = fl.read_cloud(a.case, names[0], fields=FIELDS)
ids0 = bed["globalId"].astype(int)
carrier0 = bed["typeId"].astype(int) == 0
N0 = np.asarray(bed["nParticle"], dtype=float)
nCarriers = int(carrier0.sum())
apiTotal = float(N0[~carrier0].sum())

print("bedDeparture: the bed at t = %s s: %d carriers, %g API primaries; "
      "moved: more than %g mm from there or gone; past the outlet: "
      "x < %g mm or gone" % (names[0], nCarriers, apiTotal, a.moved*1e3,
                              a.outlet*1e3))
print("%10s %12s %10s %12s %10s" % ("t - T1 [s]", "carriers", "moved",
                                    "API moved", "past outlet"))
for n in names:
    if n == names[0]:
        c = bed
    elif os.path.isdir(fl.cloud_dir(a.case, n)):
        c = fl.read_cloud(a.case, n, fields=FIELDS)
    else:
        c = {"globalId": np.zeros(0), "xDEM": np.zeros((0, 3))}
    ids = c["globalId"].astype(int)
    # Parcels of the bed still present, matched by globalId (both sorted)
    where = np.searchsorted(ids, ids0)
    where = np.minimum(where, max(len(ids) - 1, 0))
    present = (len(ids) > 0) & (ids[where] == ids0) if len(ids) else \
        np.zeros(len(ids0), bool)
    moved = ~present.copy()
    past = ~present.copy()
    if len(ids):
        x = np.asarray(c["xDEM"])[where]
        dist = np.linalg.norm(x - np.asarray(bed["xDEM"]), axis=1)
        moved |= present & (dist > a.moved)
        past |= present & (x[:, 0] < a.outlet)
    print("%10.5f %11.1f%% %9.1f%% %11.1f%% %9.1f%%" % (
        float(n) - a.since,
        100.0*np.count_nonzero(present & carrier0)/max(nCarriers, 1),
        100.0*np.count_nonzero(moved & carrier0)/max(nCarriers, 1),
        100.0*N0[moved & ~carrier0].sum()/max(apiTotal, 1),
        100.0*(N0[past].sum())/max(N0.sum(), 1)))
print("  carriers: still in the domain; moved: carriers (or API primaries) "
      "moved or gone; past outlet: primaries of every type")

# The first escape, from the logs' per-step counters
first = None
for path in a.log:
    t = None
    with open(path) as f:
        for line in f:
            if line.startswith("Time = "):
                t = float(line.split()[2])
            elif t is not None and re.match(r" +Patch \S+: escaped parcels [1-9]",
                                            line):
                first = t
                break
    if first is not None:
        break
if a.log:
    print("bedDeparture: first parcel out of the domain at t - T1 = %s" %
          ("%.5f s" % (first - a.since) if first is not None
           else "(none in the logs)"))
