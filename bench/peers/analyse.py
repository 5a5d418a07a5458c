#!/usr/bin/python3
"""Collect bench/peers runs into results.csv, results.md and throughput.png.

Usage: analyse.py --csv results.csv --png throughput.png --md results.md \
           cases/N2000 cases/N10000 ...

One row per size N and process count np; per code the best of the repeated
runs (highest loop rate). Rates are particle-steps per second of the solver
loop, set-up excluded, in CPU seconds per process:

  dpi_psps      dpiFoam: N x DEM steps after the first fluid step /
                (ExecutionTime last - ExecutionTime first fluid step)
  dpi_engine_psps  dpiFoam 'DEM performance' line (DEM engine, wall clock)
  lig_psps      LIGGGHTS: N x steps / (CPU per process of the run - CPU per
                process of a 0-step run); lig_loop_psps from 'Loop time'
                (wall clock)
  of_psps       OpenFOAM: N x (steps - 1) / (ExecutionTime last - first)
  ratio_lig     dpi_psps / lig_psps   (dpiFoam / LIGGGHTS, > 1: dpiFoam faster)
  ratio_of      dpi_psps / of_psps    (dpiFoam / OpenFOAM)
  *_kB_per_particle  peak RSS (GNU time) summed over the processes / N
  *_KE          translational kinetic energy at the end [J] (same physics?)
  *_runs        every run's rate
  load_before   1-min load average before the best dpiFoam run
"""

import argparse
import csv
import glob
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402
import peersPlot  # noqa: E402

COLUMNS = [
    "N", "np", "steps", "dpi_psps", "lig_psps", "of_psps",
    "ratio_lig", "ratio_of", "dpi_engine_psps", "lig_loop_psps",
    "dpi_kB_per_particle", "lig_kB_per_particle", "of_kB_per_particle",
    "dpi_rss_MB", "lig_rss_MB", "of_rss_MB",
    "dpi_KE", "lig_KE", "of_KE", "of_parcels_end",
    "dpi_runs", "lig_runs", "of_runs", "load_before",
]
NAN = float("nan")


load = benchLogs.machineLoad
times = benchLogs.gnuTimes


def dpiRun(d):
    log = benchLogs.dpiFoamLog(os.path.join(d, "log.dpiFoam"))
    dg = benchLogs.demDiagnostics(d)
    n = int(dg["nParcels"])
    every = log["steps"]//log["nFluid"] if log["nFluid"] else 0
    loopSteps = (log["nFluid"] - 1)*every
    return dict(case=d, n=n, steps=log["steps"],
                rate=n*loopSteps/log["loopCpu"], engine=log["engineRate"],
                KE=dg["KE"], tm=times(d))


def ligRun(d, setup):
    log = benchLogs.liggghtsLog(os.path.join(d, "log.liggghts"))
    tm = times(d)
    ps = log["atoms"]*log["steps"]
    return dict(case=d, n=log["atoms"], rate=ps/(tm["cpu"] - setup["cpu"]),
                loop=ps/log["loop"], KE=log.get("KE", NAN), tm=tm)


def ofRun(d):
    log = benchLogs.openfoamLog(os.path.join(d, "log.openfoam"))
    return dict(case=d, n=log["n"], nEnd=log["nEnd"], rate=log["rate"],
                KE=log["KE"], tm=times(d))


def rows(base):
    out = []
    nps = sorted({int(m.group(1)) for p in glob.glob(os.path.join(base, "*-np*-r*"))
                  for m in [re.search(r"-np(\d+)-r", p)] if m})
    for np_ in nps:
        dpi = [dpiRun(d) for d in
               sorted(glob.glob(os.path.join(base, "dpiFoam-np%d-r*" % np_)))]
        setupDir = os.path.join(base, "liggghts-setup-np%d" % np_)
        lig = []
        if os.path.isdir(setupDir):
            setup = times(setupDir)
            lig = [ligRun(d, setup) for d in sorted(glob.glob(
                os.path.join(base, "liggghts-np%d-r*" % np_)))]
        of = [ofRun(d) for d in
              sorted(glob.glob(os.path.join(base, "openfoam-np%d-r*" % np_)))]
        best = {k: (max(v, key=lambda r: r["rate"]) if v else None)
                for k, v in (("dpi", dpi), ("lig", lig), ("of", of))}
        any_ = next(b for b in best.values() if b)
        r = {"N": any_["n"], "np": np_,
             "steps": best["dpi"]["steps"] if best["dpi"] else ""}
        for k, runs in (("dpi", dpi), ("lig", lig), ("of", of)):
            b = best[k]
            r[k + "_psps"] = b["rate"] if b else NAN
            r[k + "_rss_MB"] = b["tm"]["rss"]/1024.0 if b else NAN
            r[k + "_kB_per_particle"] = b["tm"]["rss"]/b["n"] if b else NAN
            r[k + "_KE"] = b["KE"] if b else NAN
            r[k + "_runs"] = " ".join("%.4g" % x["rate"] for x in runs)
        r["dpi_engine_psps"] = best["dpi"]["engine"] if best["dpi"] else NAN
        r["lig_loop_psps"] = best["lig"]["loop"] if best["lig"] else NAN
        r["of_parcels_end"] = best["of"]["nEnd"] if best["of"] else ""
        r["ratio_lig"] = r["dpi_psps"]/r["lig_psps"]
        r["ratio_of"] = r["dpi_psps"]/r["of_psps"]
        r["load_before"] = load(best["dpi"]["case"]) if best["dpi"] else NAN
        out.append(r)
    return out


def fmt(v):
    return "%.6g" % v if isinstance(v, float) else str(v)


def f(r, k):
    try:
        return float(r[k])
    except (KeyError, ValueError):
        return NAN


def plot(rows, png):
    peersPlot.bars(rows, png, "Settling 70 um carriers, Hertz, dt 1e-8 s: "
                   "ratios dpiFoam/LIGGGHTS, dpiFoam/OpenFOAM")


def markdown(rows, md):
    with open(md, "w") as fh:
        fh.write("| particles | np | dpiFoam | LIGGGHTS | OpenFOAM | "
                 "dpiFoam/LIGGGHTS | dpiFoam/OpenFOAM | kB per particle "
                 "dpiFoam / LIGGGHTS / OpenFOAM |\n")
        fh.write("|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            fh.write("| %s | %s | %.3g | %.3g | %.3g | **%.2f** | **%.1f** | "
                     "%.1f / %.1f / %.1f |\n"
                     % (r["N"], r["np"], f(r, "dpi_psps"), f(r, "lig_psps"),
                        f(r, "of_psps"), f(r, "ratio_lig"), f(r, "ratio_of"),
                        f(r, "dpi_kB_per_particle"),
                        f(r, "lig_kB_per_particle"),
                        f(r, "of_kB_per_particle")))
        fh.write("\n(particle-steps/s of the solver loop, CPU time per "
                 "process; best of the runs in results.csv)\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("cases", nargs="*")
    args = ap.parse_args()

    table = {}
    for base in args.cases:
        for r in rows(base):
            table[(int(r["N"]), int(r["np"]))] = {k: fmt(v)
                                                  for k, v in r.items()}
    ordered = [table[k] for k in sorted(table)]

    with open(args.csv, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=COLUMNS)
        w.writeheader()
        for r in ordered:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    markdown(ordered, args.md)
    print(open(args.md).read())
    for r in ordered:
        print("N %s np %s: final KE dpiFoam %.4g, LIGGGHTS %.4g, OpenFOAM "
              "%.4g J; OpenFOAM parcels at the end %s"
              % (r["N"], r["np"], f(r, "dpi_KE"), f(r, "lig_KE"),
                 f(r, "of_KE"), r["of_parcels_end"]))
    plot(ordered, args.png)
    print("wrote %s, %s and %s" % (args.csv, args.md, args.png))


if __name__ == "__main__":
    main()
