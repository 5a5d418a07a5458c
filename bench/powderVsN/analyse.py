#!/usr/bin/python3
"""Collect bench/powderVsN runs.

Usage: analyse.py cases --csv results.csv --summary summary.csv \
           --md results.md --png tradeCurve.png

results.csv, one row per run (cases/N<N>-seed<seed>):
  N, seed, parcels_per_carrier (API parcels per carrier), t_end_us (the
  window), attached_end (API primaries attached to carriers at the end /
  all API primaries), attached_mid (the same at half the window), t50_us
  (first time half the API are detached, linear between fluid steps; NaN
  when not reached: tradeCurve.halfTime), cpu (the last ExecutionTime [s]).
summary.csv, one row per N and measure (attached_end, attached_mid,
  t50_us): N, measure, runs, parcels_per_carrier, mean, std (seed to seed,
  ddof 1), sem, error (mean - mean at N = 1), rel_error, within_spread
  (|error| <= std at N = 1), cpu_mean, speedup (cpu_mean at N = 1 /
  cpu_mean).
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402
import tradeCurve  # noqa: E402

MEASURES = (("attached_end", "API attached at the end of the window"),
            ("attached_mid", "API attached at half the window"),
            ("t50_us", "time to half detachment t50 [us]"))


def run(d):
    m = re.search(r"N(\d+)-seed(\d+)$", d)
    N, seed = int(m.group(1)), int(m.group(2))
    h = benchLogs.apiHistory(os.path.join(d, "log.dpiFoam"))
    t = h["t"]*1e6
    f = h["attached"]/(h["attached"] + h["detached"])
    # The first fluid step's line is at t = 10 us; half the window is the
    # sample nearest t_end/2
    mid = int(np.argmin(np.abs(t - 0.5*t[-1])))
    txt = open(os.path.join(d, "log.dpiFoam")).read()
    nCarriers = int(re.search(r"Primaries of type carrier = (\d+)", txt)
                    .group(1))
    nApi = int(re.findall(r"Primaries of type API = (\d+)", txt)[-1])
    return dict(N=N, seed=seed, parcels_per_carrier=nApi/N/nCarriers,
                t_end_us=t[-1], attached_end=f[-1], attached_mid=f[mid],
                t_mid_us=t[mid], t50_us=tradeCurve.halfTime(t, 1 - f),
                cpu=h["cpu"],
                series=(t, f))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases")
    ap.add_argument("--csv", required=True)
    ap.add_argument("--summary", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--png", required=True)
    a = ap.parse_args()

    runs = [run(d) for d in
            sorted(glob.glob(os.path.join(a.cases, "N*-seed*")))]
    if not runs:
        sys.exit("analyse.py: no runs in " + a.cases)
    cols = ["N", "seed", "parcels_per_carrier", "t_end_us", "attached_end",
            "t_mid_us", "attached_mid", "t50_us", "cpu"]
    tradeCurve.writeCsv(a.csv, sorted(runs, key=lambda r: (r["N"], r["seed"])),
                        cols)

    summ = {}
    rows = []
    for key, _ in MEASURES:
        ok = [r for r in runs if r[key] == r[key]]
        summ[key] = tradeCurve.summarise(ok, key, cpu="cpu")
        for s in summ[key]:
            s["measure"] = key
            s["parcels_per_carrier"] = next(
                r["parcels_per_carrier"] for r in runs if r["N"] == s["N"])
            rows.append(s)
    tradeCurve.writeCsv(a.summary, rows,
                        ["N", "measure", "runs", "parcels_per_carrier",
                         "mean", "std", "sem", "error", "rel_error",
                         "within_spread", "cpu_mean", "speedup"])

    tEnd = runs[0]["t_end_us"]
    tMid = runs[0]["t_mid_us"]
    lines = ["| N | API parcels per carrier | runs | attached at %.0f us "
             "(mean +- std) | error vs N = 1 | attached at %.0f us | "
             "error | t50 [us] | error | inside the N = 1 spread "
             "(end / half / t50) | CPU per run [s] | speed-up |"
             % (tEnd, tMid),
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|"]
    yn = {True: "yes", False: "no", "": "-"}
    for e, h_, t5 in zip(summ["attached_end"], summ["attached_mid"],
                         summ["t50_us"]):
        lines.append(
            "| %d | %g | %d | %.3f +- %.3f | %+.3f (%+.0f %%) | "
            "%.3f +- %.3f | %+.3f | %.0f +- %.0f | %+.0f | %s / %s / %s | "
            "%.1f | **%.1f** |" % (
                e["N"], e["parcels_per_carrier"], e["runs"], e["mean"],
                e["std"], e["error"], 100*e["rel_error"], h_["mean"],
                h_["std"], h_["error"], t5["mean"], t5["std"], t5["error"],
                yn[e["within_spread"]], yn[h_["within_spread"]],
                yn[t5["within_spread"]], e["cpu_mean"], e["speedup"]))
    with open(a.md, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(11, 4.5))
    ax = axs[0]
    for i, s in enumerate(summ["attached_end"]):
        g = [r["series"] for r in runs if r["N"] == s["N"]]
        n = min(len(t) for t, _ in g)
        tm = g[0][0][:n]
        fm = np.mean([f[:n] for _, f in g], axis=0)
        ax.plot(tm, fm, "-", color="C%d" % i, label="N = %d" % s["N"])
        for _, f in g:
            ax.plot(tm, f[:n], "-", color="C%d" % i, lw=0.5, alpha=0.35)
    ax.set_xlabel("time [us]")
    ax.set_ylabel("API primaries attached to carriers (fraction)")
    ax.set_title("Stirred coated powder: mean (thick) and every seed (thin)",
                 fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)

    ax = axs[1]
    for i, (key, label) in enumerate(MEASURES):
        tradeCurve.tradeAxes(ax, summ[key], label, color="C%d" % i,
                             annotate=(i == 0), relative=True)
    ax.set_ylabel("|error| vs N = 1, relative to the N = 1 mean")
    ax.set_title("The trade curve: error against speed-up", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote %s, %s, %s, %s" % (a.csv, a.summary, a.md, a.png))


if __name__ == "__main__":
    main()
