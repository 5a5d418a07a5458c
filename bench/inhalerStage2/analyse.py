#!/usr/bin/python3
"""Analyse bench/inhalerStage2: per run (cases/<variant>-r<k>) the stage-2
cost (wall, CPU, parcel-steps per second of wall) and outcome; per variant
the best of the repeats; ratios against `before`. Writes results.csv and
results.md."""
import argparse
import glob
import os
import re
import numpy as np

FLOAT = r"([-+0-9.eE]+)"


def run(d):
    log = open(os.path.join(d, "log.dpiFoam")).read()
    wall, user, sysT, rssKB = open(os.path.join(d, "time.txt")).read().split()[:4]
    # parcels in the system at each fluid step (the DEM steps of a step
    # advance them): sum x DEM steps per fluid step
    parcels = [int(x) for x in re.findall(
        r"Current number of parcels\s+= (\d+)", log)]
    m = re.search(r"^DEM performance: (\d+) steps", log, re.M)
    demSteps = int(m.group(1))
    nFluid = len(parcels)
    perFluid = demSteps/max(nFluid, 1)
    parcelSteps = perFluid*sum(parcels)
    out = dict(variant=re.sub(r"-r\d+$", "", os.path.basename(d)),
               repeat=int(re.search(r"-r(\d+)$", d).group(1)),
               wall=float(wall), cpu=float(user) + float(sysT),
               maxRssMB=float(rssKB)/1024, fluidSteps=nFluid,
               demSteps=demSteps, parcelSteps=parcelSteps,
               rate=parcelSteps/float(wall))
    m = re.findall(r"API primaries: attached to carriers (\d+), detached (\d+)"
                   r" \(singlets (\d+)\)", log)
    a, det, sing = (int(x) for x in m[-1])
    # (none left in the system: every primary out of the outlet)
    out["apiAttachedEnd"] = a/(a + det) if a + det else float("nan")
    # the open patches' counters (the exit region's two, or an outlet) at
    # the last step that reports them
    esc = {}
    for name, prim in re.findall(r"Patch (outlet|exit\w*): escaped parcels"
                                 r" \d+ \(primaries " + FLOAT + r"\)", log):
        esc[name] = float(prim)
    out["outletPrimaries"] = sum(esc.values())
    out["apiPrimaries"] = a + det + out["outletPrimaries"]
    m = re.findall(r"accumulated over (\d+) samples: FPF_box " + FLOAT
                   + r", FPF_system " + FLOAT, log)
    out["fpfSystemAcc"] = float(m[-1][2]) if m else float("nan")
    m = re.search(r"sub-step fluid forces " + FLOAT, log)
    out["tFluidForces"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"halo exchange " + FLOAT, log)
    out["tHalo"] = float(m.group(1)) if m else float("nan")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases")
    ap.add_argument("--K", required=True)
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", required=True)
    ap.add_argument("--machine", default="")
    ap.add_argument("--np", default="2")
    a = ap.parse_args()

    runs = [run(d) for d in sorted(glob.glob(os.path.join(a.cases, "*-r*")))
            if os.path.exists(os.path.join(d, "time.txt"))]
    cols = ["variant", "repeat", "wall", "cpu", "maxRssMB", "fluidSteps",
            "demSteps", "parcelSteps", "rate", "tFluidForces", "tHalo",
            "apiAttachedEnd", "outletPrimaries", "apiPrimaries",
            "fpfSystemAcc"]
    with open("results.csv", "w") as f:
        f.write(",".join(cols) + "\n")
        for r in runs:
            f.write(",".join("%.6g" % r[c] if isinstance(r[c], float)
                             else str(r[c]) for c in cols) + "\n")

    order = ["before", "K1", "K" + a.K]
    label = {"before": "before (%s): an engine call per sub-step" % a.before,
             "K1": "this tree (%s), refreshInterval 1" % a.after,
             "K" + a.K: "this tree (%s), refreshInterval %s" % (a.after, a.K)}
    best = {}
    for v in order:
        g = [r for r in runs if r["variant"] == v]
        if g:
            best[v] = max(g, key=lambda r: r["rate"])
    base = best.get("before")
    lines = ["| variant | runs | wall [s] (best) | CPU [s] | parcel-steps/s "
             "of wall | ratio to before | API out of the outlet | "
             "FPF_system accumulated | API attached at the end |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for v in order:
        if v not in best:
            continue
        r = best[v]
        n = len([x for x in runs if x["variant"] == v])
        lines.append("| %s | %d | %.0f | %.0f | %.3g | **%.2f** | %.3f | "
                     "%.4f | %.3f |" % (
                         label[v], n, r["wall"], r["cpu"], r["rate"],
                         r["rate"]/base["rate"] if base else float("nan"),
                         r["outletPrimaries"]/r["apiPrimaries"],
                         r["fpfSystemAcc"], r["apiAttachedEnd"]))
    lines += ["", "The quick inhaler's stage 2 (%d fluid steps, %d DEM steps, "
              "%s processes) from one stage 1 state; parcel-steps = the "
              "parcels in the device at each fluid step x its DEM steps. "
              "Outcome columns: single runs of a chaotic flow. Machine: %s."
              % (runs[0]["fluidSteps"], runs[0]["demSteps"], a.np,
                 a.machine)]
    text = "\n".join(lines) + "\n"
    open("results.md", "w").write(text)
    print(text)


main()
