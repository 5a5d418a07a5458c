#!/usr/bin/python3
"""The inhaler release ablation's table, from bench/inhalerRelease's cases.

    analyse.py CASES [--output DIR]

Per finished case (CASES/<variant>-seed<k>, CASES/off; a file `done`): from
its Allrun.resume.log the FPF_box and FPF_system over the guide's dumps
(plotFPF.py, as calculateFPF.py) and the API that left as singlets over the
API loaded and the primaries still in the domain (Allrun's last lines); from
bedDeparture.txt the first written time at which half the bed's carriers
had moved 1 mm or left; from postProcessing/emittedDose the emitted API by
class (singlets, API-only agglomerates, on carriers) over the API loaded.
Writes DIR/results.csv (one row per run) and DIR/results.md (mean and
sample standard deviation over the seeds of each variant, and the ratio of
each variant's mean to the default's), DIR/inhalerRelease.png (where the
API loaded went, per variant, stacked: left as singlets, in API-only
clusters, on carriers, deposited on the walls, elsewhere in the device; the
mean over the seeds, the seeds' spread of the singlets as error bars), and
prints the table.
"""
import argparse
import glob
import math
import os
import re
import sys

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("cases")
ap.add_argument("--output", default="results")
a = ap.parse_args()

ORDER = ["default", "WALEparcel", "SmagorinskyShared", "Smagorinsky",
         "legacy", "guide", "off"]
WHAT = {
    "default": "the tutorial (closure WALE, sharing agglomerate)",
    "WALEparcel": "sharing parcel (each parcel its own u*)",
    "SmagorinskyShared": "closure Smagorinsky (consistent tau*)",
    "Smagorinsky": "closure Smagorinsky, sharing parcel (the default before)",
    "legacy": "legacyTimeScale yes (the guide's dispersion)",
    "off": "no turbulentDispersion",
    "guide": "Allrun -guide (every model the guide's)",
}
COLS = ["FPF_box", "FPF_system", "released", "inDevice", "bedLeft",
        "emittedSinglets", "emittedAgglomerates", "emittedOnCarriers",
        "deposited", "airborne", "wall"]


def number(pattern, text, group=1):
    m = re.search(pattern, text)
    return float(m.group(group)) if m else float("nan")


def lastRow(case, pattern):
    """The latest time's row of a function object's series, joined over the
    files of its restarts (postProcessing/PATTERN), or None"""
    rows = {}
    for path in glob.glob(os.path.join(case, "postProcessing", pattern)):
        for line in open(path):
            if not line.startswith("#") and line.strip():
                v = [float(x) for x in line.split()]
                rows[v[0]] = v
    return rows[max(rows)] if rows else None


def measure(case):
    r = {}
    log = open(os.path.join(case, "Allrun.resume.log")).read()
    r["FPF_system"] = number(r"calculateFPF\.py.*FPF_system ([-0-9.eE+]+)", log)
    r["FPF_box"] = number(r"calculateFPF\.py.*FPF_box ([-0-9.eE+]+)", log)
    r["released"] = number(r"left the domain as singlets: \S+ of \S+ "
                           r"primaries loaded \(([-0-9.eE+]+);", log)
    r["inDevice"] = number(r"still in the domain ([-0-9.eE+]+)\)", log)
    r["bedLeft"] = float("nan")
    dep = os.path.join(case, "bedDeparture.txt")
    if os.path.exists(dep):
        for line in open(dep):
            f = line.split()
            if len(f) == 5 and re.match(r"^[0-9.]+$", f[0]):
                if float(f[2].rstrip("%")) >= 50:
                    r["bedLeft"] = float(f[0])
                    break
    last = lastRow(case, "emittedDose/*/emittedDose*.dat")
    if last:
        loaded = last[1]
        r["emittedSinglets"] = last[3]/loaded if loaded else float("nan")
        r["emittedAgglomerates"] = last[4]/loaded if loaded else float("nan")
        r["emittedOnCarriers"] = last[5]/loaded if loaded else float("nan")
        # the API left in the device: deposited on its walls, or neither
        # on a carrier nor on a wall (airborne, or on other API)
        v = lastRow(case, "retention/*/retention*.dat")
        if v and loaded:
            r["deposited"] = (v[1] - v[2] - v[3])/loaded
            r["airborne"] = v[3]/loaded
    r["wall"] = float(open(os.path.join(case, "done")).read().split()[0])
    return r


runs = []
for case in sorted(glob.glob(os.path.join(a.cases, "*"))):
    name = os.path.basename(case)
    if name == "bed" or not os.path.exists(os.path.join(case, "done")):
        continue
    m = re.match(r"^(.*)-seed(\d+)$", name)
    variant, seed = (m.group(1), int(m.group(2))) if m else (name, 0)
    r = measure(case)
    r.update(variant=variant, seed=seed)
    runs.append(r)
if not runs:
    sys.exit("analyse.py: no finished case in %s" % a.cases)

os.makedirs(a.output, exist_ok=True)
with open(os.path.join(a.output, "results.csv"), "w") as f:
    f.write("variant,seed," + ",".join(COLS) + "\n")
    for r in runs:
        f.write("%s,%d," % (r["variant"], r["seed"])
                + ",".join("%.6g" % r.get(c, float("nan")) for c in COLS)
                + "\n")


def stats(values):
    v = [x for x in values if not math.isnan(x)]
    if not v:
        return float("nan"), float("nan"), 0
    mean = sum(v)/len(v)
    sd = math.sqrt(sum((x - mean)**2 for x in v)/(len(v) - 1)) \
        if len(v) > 1 else float("nan")
    return mean, sd, len(v)


by = {}
for r in runs:
    by.setdefault(r["variant"], []).append(r)
variants = [v for v in ORDER if v in by] + sorted(set(by) - set(ORDER))
table = {v: {c: stats([r.get(c, float("nan")) for r in by[v]]) for c in COLS}
         for v in variants}

SHOW = [("FPF_box", "FPF_box over the dumps", "%.3f"),
        ("FPF_system", "FPF_system", "%.4f"),
        ("released", "API left as singlets / loaded", "%.3f"),
        ("inDevice", "API primaries in the device at the end", "%.0f"),
        ("bedLeft", "half the carriers moved by [s]", "%.3f"),
        ("emittedAgglomerates", "API left in API-only clusters / loaded", "%.3f"),
        ("emittedOnCarriers", "API left on carriers / loaded", "%.3f"),
        ("deposited", "API deposited on the walls / loaded", "%.3f"),
        ("airborne", "API in the device on no carrier or wall / loaded", "%.3f")]
lines = ["| variant | seeds | " + " | ".join(s[1] for s in SHOW)
         + " | released / default's |",
         "|---|---|" + "---|"*len(SHOW) + "---|"]
ref = table.get("default", {}).get("released", (float("nan"),))[0]
for v in variants:
    cells = []
    for c, _, fmt in SHOW:
        mean, sd, n = table[v][c]
        cells.append((fmt % mean) + ("" if math.isnan(sd) else
                                     " +- " + (fmt % sd)))
    rel = table[v]["released"][0]/ref if ref and not math.isnan(ref) \
        else float("nan")
    lines.append("| %s: %s | %d | %s | %.2f |" % (
        v, WHAT.get(v, v), len(by[v]), " | ".join(cells), rel))
text = "\n".join(lines)
with open(os.path.join(a.output, "results.md"), "w") as f:
    f.write("Mean +- sample standard deviation over the paired seeds "
            "(turbulentDispersion/seed 0, 1, ...); one run for off.\n\n"
            + text + "\n")
print(text)


# Where the API loaded went, per variant: a stacked bar of the means
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

parts = [("emittedSinglets", "left as singlets", "tab:green"),
         ("emittedAgglomerates", "left in API-only clusters", "tab:olive"),
         ("emittedOnCarriers", "left on carriers", "tab:blue"),
         ("deposited", "deposited on the walls", "tab:red"),
         ("airborne", "in the device, on no carrier or wall", "tab:gray")]
fig, ax = plt.subplots(figsize=(1.6*len(variants) + 3, 4.5))
bottom = [0.0]*len(variants)
for key, label, color in parts:
    means = [table[v][key][0] if not math.isnan(table[v][key][0]) else 0
             for v in variants]
    err = None
    if key == "emittedSinglets":
        err = [table[v][key][1] if not math.isnan(table[v][key][1]) else 0
               for v in variants]
    ax.bar(range(len(variants)), means, bottom=bottom, color=color,
           label=label, yerr=err, capsize=4)
    bottom = [b + m for b, m in zip(bottom, means)]
ax.axhspan(0.10, 0.30, color="k", alpha=0.08,
           label="van Wachem et al. 2017: 10-30 % released")
ax.set_xticks(range(len(variants)))
ax.set_xticklabels(["%s\n(%d)" % (v, len(by[v])) for v in variants])
ax.set_ylabel("fraction of the API loaded, at 0.11 s")
ax.set_ylim(0, 1.05)
ax.set_title("Inhaler, release size (quick bed, the guide's breath): "
             "where the API went\n(mean over the seeds; error bar: the "
             "seeds' spread of the singlets)", fontsize=9)
ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
fig.tight_layout()
fig.savefig(os.path.join(a.output, "inhalerRelease.png"), dpi=110)
