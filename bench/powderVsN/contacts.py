#!/usr/bin/python3
"""The contacts of bench runs by class, N against N = 1 (powderVsN, inhalerVsN).

Usage: contacts.py cases [--md contacts.md] [--last] [--windows T0 T1 ...]

Reads cases/N<N>-seed<seed>/postProcessing/dpiCloud/contactStatistics/*/
contactStatistics.dat (dem/contactStatistics: per fluid step and class of
contact, the contact-steps, the contacts begun and the normal impulse)
and writes, per half of the window and class, the means over the seeds
of the contacts begun and of the normal impulse for every N, with the
N = 1 seed-to-seed std of the contacts begun. A class is a pair of
material types (carrier-carrier, carrier-API, API-API) or a type against
the walls (API-wall, carrier-wall). The impulse is the parcels' (N times
a primary's for a parcel of N), so a class whose impulse is kept when N
changes exchanges the same momentum.

--last: a run of two stages (bench/inhalerVsN) writes a file per stage
(its start time); take the last stage's. --windows T0 T1 ...: the windows'
edges [s] instead of the two halves of the run.
"""
import argparse
import collections
import glob
import os
import re
import sys

import numpy as np

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("cases")
ap.add_argument("--md", default="contacts.md")
ap.add_argument("--last", action="store_true",
                help="the last stage's file (the latest start time)")
ap.add_argument("--windows", type=float, nargs="+",
                help="window edges [s] (default: the run's two halves)")
a = ap.parse_args()

runs = collections.defaultdict(list)     # N -> list of rows per run
tEnd = 0
for d in sorted(glob.glob(os.path.join(a.cases, "N*-seed*"))):
    m = re.search(r"N(\d+)-seed(\d+)$", d)
    f = glob.glob(os.path.join(d, "postProcessing", "dpiCloud",
                               "contactStatistics", "*",
                               "contactStatistics.dat"))
    if not m or not f:
        continue
    if a.last:
        f.sort(key=lambda p: float(p.split(os.sep)[-2]))
        f = f[-1:]
    elif len(f) > 1:
        sys.exit("contacts.py: %d contactStatistics files in %s: give --last"
                 % (len(f), d))
    rows = [l.split() for l in open(f[0])
            if not l.startswith("#") and l.strip()]
    rows = [(float(r[0]), r[1].split(":")[0], float(r[3]), float(r[4]))
            for r in rows]
    tEnd = max([tEnd] + [r[0] for r in rows])
    runs[int(m.group(1))].append(rows)
if 1 not in runs:
    sys.exit("contacts.py: no N = 1 run with contactStatistics in %s"
             " (run with --contacts)" % a.cases)

edges = a.windows if a.windows else [0, 0.5*tEnd, tEnd]
halves = list(zip(edges[:-1], edges[1:]))
classes = sorted(set(r[1] for rs in runs.values() for rows in rs
                     for r in rows))


def sums(rows, w):
    """Contacts begun and impulse per class over the window w."""
    out = {c: np.zeros(2) for c in classes}
    for t, c, started, impulse in rows:
        if w[0] < t <= w[1]*(1 + 1e-9):
            out[c] += (started, impulse)
    return out


Ns = sorted(runs)
with open(a.md, "w") as md:
    md.write("Contacts by class (dem/contactStatistics), mean over %s seeds;"
             " begun: contacts that began; impulse: normal impulse [N s]"
             " of the parcels (x N for a parcel of N), positive apart.\n\n"
             % "/".join(str(len(runs[N])) for N in Ns))
    for w in halves:
        md.write("%g - %g us:\n\n" % (1e6*w[0], 1e6*w[1]))
        md.write("| class | " + " | ".join(
            "begun N = %d" % N for N in Ns) + " | std N = 1 | " + " | ".join(
            "impulse N = %d" % N for N in Ns) + " |\n")
        md.write("|---|" + "---:|"*(2*len(Ns) + 1) + "\n")
        per = {N: [sums(rows, w) for rows in runs[N]] for N in Ns}
        for c in classes:
            begun = [np.mean([s[c][0] for s in per[N]]) for N in Ns]
            sd1 = np.std([s[c][0] for s in per[1]], ddof=1) \
                if len(per[1]) > 1 else float("nan")
            imp = [np.mean([s[c][1] for s in per[N]]) for N in Ns]
            md.write("| %s | " % c + " | ".join("%.1f" % b for b in begun)
                     + " | %.1f | " % sd1
                     + " | ".join("%.3g" % x for x in imp) + " |\n")
        md.write("\n")
print(open(a.md).read())
