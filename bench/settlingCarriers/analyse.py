#!/usr/bin/python3
"""Collect the settlingCarriers runs into results.csv and plot the cost per
particle-step against N.

Usage: analyse.py --csv results.csv --png cost.png CASE [CASE ...]

Rows already in the CSV for other (N, np) are kept; a re-measured (N, np)
replaces its row. Columns (us = microseconds):

  N, np, steps, fluid_steps          sizes of the run
  order                              particle list order (random, morton)
  engine_particle_steps_per_s        dpiFoam's 'DEM performance' line (rank 0
                                     only when np > 1: its parcels over its
                                     engine time)
  engine_us_per_particle_step        1e6/engine_particle_steps_per_s
  pair_share, wall_share, neighbour_share, integrate_share   [%] of engine
  pair_us, wall_us, neighbour_us, integrate_us   the same in us per
                                     particle-step (rank 0 when np > 1)
  neighbour_builds
  loop_cpu_us_per_particle_step      whole solver loop (engine + cloud:
                                     state copies, relocation, diagnostics),
                                     CPU time of rank 0 x np over
                                     N x DEM steps, first fluid step (start-up,
                                     injection) excluded: core-us per
                                     particle-step, robust to other load
  loop_particle_steps_per_s          N x steps / loop time (all processes)
  elapsed_s, cpu_percent             GNU time of the whole run
  max_rss_MB                         peak RSS (largest process)
  rss_per_particle_kB                max_rss x np / N
  pair_contacts, wall_contacts       at the end (demDiagnostics)
  contacts_per_particle              (2 pair + wall contacts)/N: the mean
                                     coordination number
  max_overlap_over_Rstar
  KE_end_over_first                  kinetic energy at the end over that at
                                     the first fluid step (a settling powder
                                     loses energy: > 1 flags a wrong run)
  parcels_lost                       parcels lost through walls (the cloud's
                                     count; at least injected minus present
                                     at the last diagnostics)
  load_before                        1-min load average before the run
  runs, engine_rates_all, loop_cpu_us_all   with --repeat: the number of
                                     runs and every run's figures; the row
                                     is the run with the highest engine rate
"""

import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
import benchLogs  # noqa: E402

COLUMNS = [
    "N", "np", "order", "steps", "fluid_steps",
    "engine_particle_steps_per_s", "engine_us_per_particle_step",
    "pair_share", "wall_share", "neighbour_share", "integrate_share",
    "pair_us", "wall_us", "neighbour_us", "integrate_us", "neighbour_builds",
    "loop_cpu_us_per_particle_step", "loop_particle_steps_per_s",
    "elapsed_s", "cpu_percent", "max_rss_MB", "rss_per_particle_kB",
    "pair_contacts", "wall_contacts", "contacts_per_particle",
    "max_overlap_over_Rstar", "KE_end_over_first", "parcels_lost",
    "load_before", "runs", "engine_rates_all",
    "loop_cpu_us_all",
]


def row(case):
    log = benchLogs.dpiFoamLog(os.path.join(case, "log.dpiFoam"))
    tm = benchLogs.gnuTime(os.path.join(case, "log.time"))
    dg = benchLogs.demDiagnostics(case)
    n = log["injected"] or int(dg["nParcels"])
    nproc = log["nProcs"]
    steps = log["steps"]
    every = steps//log["nFluid"]
    loopSteps = (log["nFluid"] - 1)*every
    ps0 = log["engineRate"]*log["tEngine"]      # rank-0 particle-steps
    load = float("nan")
    try:
        with open(os.path.join(case, "log.machine")) as f:
            load = float(f.read().split("load average")[1].split()[0])
    except (OSError, IndexError, ValueError):
        pass

    order = "random"
    for name in ("carrierPositions", "carrierParticles"):
        try:
            with open(os.path.join(case, "constant", name)) as f:
                order = f.readline().split("order")[1].split()[0]
            break
        except (OSError, IndexError):
            pass

    r = {
        "N": n, "np": nproc, "order": order, "steps": steps, "fluid_steps": log["nFluid"],
        "engine_particle_steps_per_s": log["engineRate"],
        "engine_us_per_particle_step": 1e6/log["engineRate"],
        "neighbour_builds": log["builds"],
        "loop_cpu_us_per_particle_step":
            1e6*nproc*log["loopCpu"]/(n*loopSteps),
        "loop_particle_steps_per_s": n*loopSteps/log["loopCpu"],
        "elapsed_s": tm["elapsed"], "cpu_percent": tm["cpuPercent"],
        "max_rss_MB": tm["maxRssKB"]/1024.0,
        "rss_per_particle_kB": tm["maxRssKB"]*nproc/n,
        "pair_contacts": int(dg["nPair"]), "wall_contacts": int(dg["nWall"]),
        "contacts_per_particle": (2*dg["nPair"] + dg["nWall"])/n,
        "max_overlap_over_Rstar": dg["maxOverlap"],
        "KE_end_over_first": dg["KE"]/dg["KEfirst"],
        "parcels_lost": max(n - int(dg["nParcels"]),
                            log["lostThroughWalls"]),
        "load_before": load,
    }
    for part, key in (("pair", "tPair"), ("wall", "tWall"),
                      ("neighbour", "tNeighbour"),
                      ("integrate", "tIntegrate")):
        r[part + "_share"] = 100*log[key]/log["tEngine"]
        r[part + "_us"] = 1e6*log[key]/ps0
    return r


def fmt(v):
    if isinstance(v, float):
        return "%.6g" % v
    return str(v)


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def series(nproc, order):
        rs = sorted((r for r in rows
                     if int(r["np"]) == nproc and r["order"] == order),
                    key=lambda r: int(r["N"]))
        return rs, [int(r["N"]) for r in rs]

    def col(rs, key):
        return [float(r[key]) for r in rs]

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)

    # Left: the benchmark (np 1, particles in the order placed)
    rs, n = series(1, "random")
    if rs:
        a1.plot(n, col(rs, "engine_us_per_particle_step"), "C0-o", lw=2,
                label="DEM engine total (dpiFoam's line, wall clock)")
        a1.plot(n, col(rs, "loop_cpu_us_per_particle_step"), "k-s",
                label="whole solver loop (CPU time)")
        for part, c in (("pair", "C1"), ("wall", "C2"),
                        ("neighbour", "C3"), ("integrate", "C4")):
            a1.plot(n, col(rs, part + "_us"), c + "--o", ms=4, lw=1,
                    label="  " + part)
        ref = float(rs[0]["engine_us_per_particle_step"])
        a1.axhspan(ref, 1.5*ref, color="C0", alpha=0.08,
                   label="target band: cost(%d) .. 1.5x" % n[0])
    a1.set_title("np 1 (benchmark)")

    # Right: diagnostics (row order, two processes)
    for (nproc, order, c, m, lab) in (
            (1, "random", "k", "s", "np 1, list in placement order"),
            (1, "morton", "C5", "^", "np 1, list sorted along a Morton curve"),
            (2, "random", "C3", "v",
             "np 2 (no halo exchange yet: physics wrong)")):
        rs, n = series(nproc, order)
        if not rs:
            continue
        a2.plot(n, col(rs, "loop_cpu_us_per_particle_step"), c + "-" + m,
                label="whole loop (CPU), " + lab)
        if nproc == 1:
            a2.plot(n, col(rs, "pair_us"), c + ":" + m, ms=4, lw=1,
                    label="  pair, " + lab)
    a2.set_title("diagnostics: memory locality, 2 processes")

    ns = sorted({int(r["N"]) for r in rows})
    for a in (a1, a2):
        a.set_xscale("log")
        a.set_xticks(ns)
        a.set_xticklabels(["{:,}".format(v) for v in ns])
        a.minorticks_off()
        a.set_xlabel("number of carriers N")
        a.grid(True, which="both", alpha=0.3)
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize=7, loc="upper left")
    a1.set_ylabel("cost per particle-step [core-us]")
    a1.set_ylim(0, None)
    fig.suptitle("dpiFoam DEM: settling 70 um carriers, hertzParcel/"
                 "historyParcel, dt 1e-8 s, 15 % solids, box of patch walls")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


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
                rows[(int(r["N"]), int(r["np"]),
                      r.get("order") or "random")] = r
    groups = {}
    for case in args.cases:
        r = row(case)
        groups.setdefault((r["N"], r["np"], r["order"]), []).append(r)
    for key, rs in groups.items():
        best = dict(max(rs, key=lambda r: r["engine_particle_steps_per_s"]))
        best["runs"] = len(rs)
        best["engine_rates_all"] = " ".join(
            "%.4g" % r["engine_particle_steps_per_s"] for r in rs)
        best["loop_cpu_us_all"] = " ".join(
            "%.4g" % r["loop_cpu_us_per_particle_step"] for r in rs)
        rows[key] = {k: fmt(v) for k, v in best.items()}

    ordered = [rows[k] for k in sorted(rows)]
    with open(args.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        for r in ordered:
            w.writerow({k: r.get(k, "") for k in COLUMNS})

    print("%8s %3s %7s %12s %10s %10s %6s %6s %6s %6s %10s %9s %5s %6s %4s"
          % ("N", "np", "order", "psteps/s", "us/pstep", "loop us", "pair%",
             "wall%", "neigh%", "integ%", "kB/part", "contacts", "CPU%",
             "KEend", "lost"))
    for r in ordered:
        print("%8s %3s %7s %12.4g %10.4f %10.4f %6.1f %6.1f %6.1f %6.1f %10.3f "
              "%9.4f %5s %6.3f %4s" % (
                  r["N"], r["np"], r["order"],
                  float(r["engine_particle_steps_per_s"]),
                  float(r["engine_us_per_particle_step"]),
                  float(r["loop_cpu_us_per_particle_step"]),
                  float(r["pair_share"]), float(r["wall_share"]),
                  float(r["neighbour_share"]), float(r["integrate_share"]),
                  float(r["rss_per_particle_kB"]),
                  float(r["contacts_per_particle"]), r["cpu_percent"],
                  float(r.get("KE_end_over_first") or "nan"),
                  r.get("parcels_lost", "")))

    for nproc, order in ((1, "random"), (2, "random"), (1, "morton"),
                         (2, "morton")):
        rs = {int(r["N"]): r for r in ordered
              if int(r["np"]) == nproc and r["order"] == order}
        if len(rs) > 1:
            lo, hi = min(rs), max(rs)
            print("np %d, %s order: cost(%d)/cost(%d) = %.3f (DEM engine), "
                  "%.3f (whole loop, CPU)" % (
                      nproc, order, hi, lo,
                      float(rs[hi]["engine_us_per_particle_step"])
                      / float(rs[lo]["engine_us_per_particle_step"]),
                      float(rs[hi]["loop_cpu_us_per_particle_step"])
                      / float(rs[lo]["loop_cpu_us_per_particle_step"])))

    plot(ordered, args.png)
    print("wrote %s and %s" % (args.csv, args.png))


if __name__ == "__main__":
    main()
