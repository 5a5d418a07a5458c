#!/usr/bin/python3
"""Collect bench/peers runs into results.csv and throughput.png.

Usage: analyse.py --csv results.csv --png throughput.png cases/N2000 ...

Per size, the best of the repeated runs of each code (highest rate):

  N, steps
  dpi_engine_psps       dpiFoam 'DEM performance' (DEM engine, wall clock)
  dpi_loop_cpu_psps     dpiFoam whole solver loop, CPU time, first fluid
                        step excluded (see bench/settlingCarriers/analyse.py)
  lig_loop_psps         LIGGGHTS N x steps / 'Loop time' (wall clock)
  lig_cpu_psps          LIGGGHTS N x steps / (CPU time - CPU of a 0-step run)
  ratio_wall            dpi_engine_psps / lig_loop_psps
  ratio_cpu             dpi_loop_cpu_psps / lig_cpu_psps
  dpi_pair_share ... dpi_integrate_share, lig_pair_share [%]
  dpi_rss_MB, lig_rss_MB, dpi_kB_per_particle, lig_kB_per_particle
  contacts_per_particle (2 pair + wall contacts)/N at the end (dpiFoam)
  KE_rel_diff           |KE_dpi - KE_lig|/KE_lig at the end (same scene?)
  load_before           1-min load average before the best dpiFoam run
"""

import argparse
import csv
import glob
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402

COLUMNS = [
    "N", "steps", "dpi_engine_psps", "dpi_loop_cpu_psps", "lig_loop_psps",
    "lig_cpu_psps", "ratio_wall", "ratio_cpu",
    "dpi_pair_share", "dpi_wall_share", "dpi_neighbour_share",
    "dpi_integrate_share", "lig_pair_share",
    "dpi_rss_MB", "lig_rss_MB", "dpi_kB_per_particle", "lig_kB_per_particle",
    "contacts_per_particle", "KE_rel_diff", "dpi_runs", "lig_runs",
    "load_before",
]


def load(case):
    try:
        with open(os.path.join(case, "log.machine")) as f:
            return float(f.read().split("load average")[1].split()[0])
    except (OSError, IndexError, ValueError):
        return float("nan")


def sizeRow(base):
    dpi = []
    for d in sorted(glob.glob(os.path.join(base, "dpiFoam-r*"))):
        log = benchLogs.dpiFoamLog(os.path.join(d, "log.dpiFoam"))
        tm = benchLogs.gnuTime(os.path.join(d, "log.time"))
        dg = benchLogs.demDiagnostics(d)
        n = int(dg["nParcels"])
        every = log["steps"]//log["nFluid"]
        loopSteps = (log["nFluid"] - 1)*every
        dpi.append(dict(log=log, tm=tm, dg=dg, n=n, case=d,
                        cpuRate=n*loopSteps/log["loopCpu"]))
    lig = []
    setup = benchLogs.gnuTime(os.path.join(base, "liggghts", "time.setup"))
    for d in sorted(glob.glob(os.path.join(base, "liggghts-r*"))):
        log = benchLogs.liggghtsLog(os.path.join(d, "log.liggghts"))
        tm = benchLogs.gnuTime(os.path.join(d, "log.time"))
        ps = log["atoms"]*log["steps"]
        lig.append(dict(log=log, tm=tm, rate=ps/log["loop"],
                        cpuRate=ps/(tm["cpuTime"] - setup["cpuTime"])))
    if not dpi or not lig:
        raise RuntimeError("no runs in " + base)

    bd = max(dpi, key=lambda r: r["log"]["engineRate"])
    bl = max(lig, key=lambda r: r["rate"])
    n = bd["n"]
    lg = bd["log"]
    r = {
        "N": n, "steps": lg["steps"],
        "dpi_engine_psps": lg["engineRate"],
        "dpi_loop_cpu_psps": max(x["cpuRate"] for x in dpi),
        "lig_loop_psps": bl["rate"],
        "lig_cpu_psps": max(x["cpuRate"] for x in lig),
        "dpi_pair_share": 100*lg["tPair"]/lg["tEngine"],
        "dpi_wall_share": 100*lg["tWall"]/lg["tEngine"],
        "dpi_neighbour_share": 100*lg["tNeighbour"]/lg["tEngine"],
        "dpi_integrate_share": 100*lg["tIntegrate"]/lg["tEngine"],
        "lig_pair_share": 100*bl["log"].get("tPair", float("nan"))
        / bl["log"]["loop"],
        "dpi_rss_MB": bd["tm"]["maxRssKB"]/1024.0,
        "lig_rss_MB": bl["tm"]["maxRssKB"]/1024.0,
        "dpi_kB_per_particle": bd["tm"]["maxRssKB"]/n,
        "lig_kB_per_particle": bl["tm"]["maxRssKB"]/n,
        "contacts_per_particle":
            (2*bd["dg"]["nPair"] + bd["dg"]["nWall"])/n,
        "KE_rel_diff": abs(bd["dg"]["KE"] - bl["log"]["KE"])
        / bl["log"]["KE"],
        "dpi_runs": " ".join("%.4g" % x["log"]["engineRate"] for x in dpi),
        "lig_runs": " ".join("%.4g" % x["rate"] for x in lig),
        "load_before": load(bd["case"]),
    }
    r["ratio_wall"] = r["dpi_engine_psps"]/r["lig_loop_psps"]
    r["ratio_cpu"] = r["dpi_loop_cpu_psps"]/r["lig_cpu_psps"]
    return r


def fmt(v):
    return "%.6g" % v if isinstance(v, float) else str(v)


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    rows = sorted(rows, key=lambda r: int(r["N"]))
    x = np.arange(len(rows))
    w = 0.2
    fig, ax = plt.subplots(figsize=(7, 4.5))
    series = (("dpi_engine_psps", "dpiFoam DEM engine (wall clock)", "C0"),
              ("dpi_loop_cpu_psps", "dpiFoam solver loop (CPU)", "C9"),
              ("lig_loop_psps", "LIGGGHTS loop (wall clock)", "C3"),
              ("lig_cpu_psps", "LIGGGHTS (CPU)", "C1"))
    for k, (key, lab, col) in enumerate(series):
        ax.bar(x + (k - 1.5)*w, [float(r[key])/1e6 for r in rows], w,
               label=lab, color=col)
    ax.set_xticks(x)
    ax.set_xticklabels(["N = %s\ndpiFoam/LIGGGHTS %.2f (wall), %.2f (CPU)"
                        % (r["N"], float(r["ratio_wall"]),
                           float(r["ratio_cpu"])) for r in rows], fontsize=8)
    ax.set_ylabel("million particle-steps per second (1 process)")
    ax.set_title("Settling 70 um carriers, hertz/history, dt 1e-8 s")
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("cases", nargs="*")
    args = ap.parse_args()

    rows = {}
    if os.path.exists(args.csv):
        with open(args.csv) as f:
            for r in csv.DictReader(f):
                rows[int(r["N"])] = r
    for base in args.cases:
        r = sizeRow(base)
        rows[r["N"]] = {k: fmt(v) for k, v in r.items()}
    ordered = [rows[k] for k in sorted(rows)]

    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in ordered:
            w.writerow({k: r.get(k, "") for k in COLUMNS})

    print("%7s %12s %12s %12s %12s %8s %8s %8s %8s %9s" % (
        "N", "dpi engine", "dpi loop CPU", "LIG loop", "LIG CPU",
        "ratio w", "ratio c", "dpi kB/p", "LIG kB/p", "KE diff"))
    for r in ordered:
        print("%7s %12.4g %12.4g %12.4g %12.4g %8.3f %8.3f %8.2f %8.2f %9.2e"
              % (r["N"], float(r["dpi_engine_psps"]),
                 float(r["dpi_loop_cpu_psps"]), float(r["lig_loop_psps"]),
                 float(r["lig_cpu_psps"]), float(r["ratio_wall"]),
                 float(r["ratio_cpu"]), float(r["dpi_kB_per_particle"]),
                 float(r["lig_kB_per_particle"]), float(r["KE_rel_diff"])))
    plot(ordered, args.png)
    print("wrote %s and %s" % (args.csv, args.png))


if __name__ == "__main__":
    main()
