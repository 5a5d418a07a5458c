#!/usr/bin/python3
"""Plot the emitted API as an impactor reads it (dpiEmittedDose's stages.dat).

    plotImpactor.py STAGES.dat [--output ngi.png] [--title T]

Left: the stage bar chart every impactor report has, the API mass in the
induction port and pre-separator (IP+PS: the API on carriers), each stage
and the micro-orifice collector (MOC), as a percentage of the emitted API,
at the last time of the file. Right: the cumulative mass undersize of the
stages (without IP+PS) against each stage's cut-off, on a log axis, with
the MMAD and the 15.87 and 84.13 % points of the GSD as the file gives
them. The cut-offs are read from the file's header (impactorStages'
description). Prints the stage masses, MMAD and GSD.
"""
import argparse
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("file")
ap.add_argument("--output", default="ngi.png")
ap.add_argument("--title", default="Emitted API by impactor stage")
a = ap.parse_args()

lines = open(a.file).read().splitlines()
header = [l for l in lines if l.startswith("# Time")]
rows = [l.split() for l in lines if l.strip() and not l.startswith("#")]
if not header or not rows:
    sys.exit("plotImpactor.py: no header or no rows in %s" % a.file)
names = header[0].split()[2:]
last = dict(zip(names, map(float, rows[-1][1:])))
t = float(rows[-1][0])
described = " ".join(l for l in lines if "cut-offs [um]" in l)
cut = {m.group(1): float(m.group(2)) for m in re.finditer(r"(\S+) ([0-9.e+-]+)(?= |$)", described.split("cut-offs [um]:")[-1])}

buckets = [n for n in names if n not in ("MMAD", "GSD")]
mass = np.array([last[n] for n in buckets])
emitted = mass.sum()
if emitted <= 0:
    sys.exit("plotImpactor.py: no API emitted by t = %g s in %s" % (t, a.file))

fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
left.bar(range(len(buckets)), 100*mass/emitted, color="tab:blue")
left.set_xticks(range(len(buckets)))
left.set_xticklabels([b.replace("stage", "S") for b in buckets])
left.set_ylabel("% of the emitted API")
left.set_title("stage masses at t = %g s" % t)

stages = [b for b in buckets if b in cut]
impactor = mass[1:].sum()
if impactor > 0 and stages:
    d = np.array([cut[s] for s in stages])
    below = np.array([1 - mass[1:2 + i].sum()/impactor for i in range(len(stages))])
    right.semilogx(d, 100*below, "o-", color="tab:blue", label="stages")
    mmad, gsd = last.get("MMAD", 0), last.get("GSD", 0)
    if mmad > 0:
        right.axvline(1e6*mmad, color="tab:red", ls="--",
                      label="MMAD %.2f um, GSD %.2f" % (1e6*mmad, gsd))
    right.axhline(50, color="grey", lw=0.5)
    right.set_xlabel("stage cut-off D50 [um]")
    right.set_ylabel("cumulative % undersize (stages)")
    right.legend(fontsize=8)
right.set_title("cumulative undersize")
fig.suptitle(a.title + "\n" + described.lstrip("# ").split(": ", 1)[-1], fontsize=9)
fig.tight_layout()
fig.savefig(a.output, dpi=110)

print("t = %g s: %s; MMAD %.3g um, GSD %.3g -> %s" % (
    t, ", ".join("%s %.3g %%" % (b, 100*m/emitted) for b, m in zip(buckets, mass)),
    1e6*last.get("MMAD", 0), last.get("GSD", 0), a.output))
