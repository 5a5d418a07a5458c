#!/usr/bin/python3
"""Collect bench/accuracyVsN runs.

Usage: analyse.py cases --csv results.csv --summary summary.csv \
           --md results.md --png tradeCurve.png

results.csv, one row per run (cases/N<N>-seed<seed>):
  N, seed, parcels, primaries, attached_before, detached_before (end of the
  agglomeration), attached_after, detached_after (end of the impact),
  detached_fraction (detached_after / primaries), cpu_agg, cpu_impact
  (ExecutionTime of each stage [s]), cpu_total, wall_total (GNU time
  elapsed of both runs [s]).
summary.csv, one row per N:
  N, runs, parcels, mean, std (seed to seed, ddof 1), sem, error (mean -
  mean at N = 1, in detached fraction), rel_error (error / mean at N = 1),
  within_spread (|error| <= std at N = 1), cpu_mean, speedup (cpu_mean at
  N = 1 / cpu_mean), not_attached_before (runs with API not yet attached
  when the impact started).
"""
import argparse
import glob
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402
import tradeCurve  # noqa: E402


def lastCounts(log):
    h = benchLogs.apiHistory(log)
    return int(h["attached"][-1]), int(h["detached"][-1]), h["cpu"]


def run(d):
    m = re.search(r"N(\d+)-seed(\d+)$", d)
    N, seed = int(m.group(1)), int(m.group(2))
    ab, db, ca = lastCounts(os.path.join(d, "agg", "log.dpiFoam"))
    aa, da, ci = lastCounts(os.path.join(d, "impact", "log.dpiFoam"))
    txt = open(os.path.join(d, "agg", "log.dpiFoam")).read()
    mp = re.search(r"regionPacking api: (\d+) particles", txt)
    wall = sum(benchLogs.gnuTime(os.path.join(d, s, "log.time"))["elapsed"]
               for s in ("agg", "impact"))
    return dict(N=N, seed=seed, parcels=int(mp.group(1)) if mp else -1,
                primaries=aa + da, attached_before=ab, detached_before=db,
                attached_after=aa, detached_after=da,
                detached_fraction=da/(aa + da), cpu_agg=ca, cpu_impact=ci,
                cpu_total=ca + ci, wall_total=wall)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases")
    ap.add_argument("--csv", required=True)
    ap.add_argument("--summary", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--png", required=True)
    a = ap.parse_args()

    runs = [run(d) for d in sorted(glob.glob(os.path.join(a.cases, "N*-seed*")))]
    if not runs:
        sys.exit("analyse.py: no runs in " + a.cases)
    cols = list(runs[0].keys())
    tradeCurve.writeCsv(a.csv, sorted(runs, key=lambda r: (r["N"], r["seed"])),
                        cols)

    summ = tradeCurve.summarise(runs, "detached_fraction")
    base = next((s for s in summ if s["N"] == 1), None)
    for s in summ:
        g = [r for r in runs if r["N"] == s["N"]]
        s["parcels"] = g[0]["parcels"]
        s["not_attached_before"] = sum(1 for r in g if r["detached_before"])
    scols = ["N", "runs", "parcels", "mean", "std", "sem", "error",
             "rel_error", "within_spread", "cpu_mean", "speedup",
             "not_attached_before"]
    tradeCurve.writeCsv(a.summary, summ, scols)

    lines = ["| N | parcels | runs | detached fraction, mean | seed-to-seed "
             "std | error vs N = 1 | relative error | within N = 1 spread | "
             "CPU per run [s] | speed-up |",
             "|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|"]
    for s in summ:
        lines.append("| %d | %d | %d | %.3f | %.3f | %+.3f | %+.0f %% | %s | "
                     "%.1f | **%.1f** |" % (
                         s["N"], s["parcels"], s["runs"], s["mean"], s["std"],
                         s["error"], 100*s["rel_error"],
                         "yes" if s["within_spread"] is True else "no",
                         s["cpu_mean"], s["speedup"]))
    nb = sum(s["not_attached_before"] for s in summ)
    lines.append("")
    lines.append("Runs with API not yet attached when the impact started: "
                 "%d of %d." % (nb, len(runs)))
    with open(a.md, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.5))
    ax = axs[0]
    for s in summ:
        g = [r["detached_fraction"] for r in runs if r["N"] == s["N"]]
        ax.plot([s["N"]]*len(g), g, ".", color="0.6")
    ax.errorbar([s["N"] for s in summ], [s["mean"] for s in summ],
                yerr=[s["std"] for s in summ], fmt="o-", capsize=3,
                label="mean, seed-to-seed std")
    if base:
        ax.axhspan(base["mean"] - base["std"], base["mean"] + base["std"],
                   color="C0", alpha=0.12, label="N = 1 mean +- std")
    ax.set_xscale("log")
    ax.set_xlabel("coarsening factor N (primaries per API parcel)")
    ax.set_ylabel("detached API fraction after the wall impact")
    ax.set_title("Case 6-like impact, %d API primaries, %d seeds"
                 % (runs[0]["primaries"], max(s["runs"] for s in summ)),
                 fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)

    ax = axs[1]
    if base:
        tradeCurve.tradeAxes(ax, summ, "detached fraction")
        ax.set_ylabel("error of the detached fraction vs N = 1")
        ax.set_title("The trade curve: error against speed-up", fontsize=9)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote %s, %s, %s, %s" % (a.csv, a.summary, a.md, a.png))


if __name__ == "__main__":
    main()
