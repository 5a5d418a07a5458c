#!/usr/bin/python3
"""Collect bench/inhalerVsN runs.

Usage: analyse.py cases --t1 T1 --ramp R --csv results/results.csv \
           --summary results/summary.csv --md results/results.md \
           --png results/inhalerVsN.png

Per run (cases/N<N>-seed<seed>, the tutorial inhaler run by Allrun -np 1),
from its logs:
  carriers, parcels, primaries (bed.txt: the API primaries packed),
  attached_t1 (API primaries attached to carriers / primaries at the end of
  stage 1), detached_ramp and detached_end (1 - attached / primaries at the
  end of the inlet ramp, t1 + ramp, and at the end of stage 2), t50 (time
  from gas on to half of the API primaries detached [ms]), emitted
  (API primaries out of the outlet / primaries at the end: the outlet's
  primaries minus the carriers that left), fpf_acc (FPF_system
  accumulated over stage 2: the tutorial's figure), fpf_max (its largest
  sample), cpu_sed, cpu_inh (ExecutionTime of each stage [s]), cpu_total,
  maxRssMB (peak of the Allrun's processes).
summary.csv: one row per N and measure (tradeCurve.summarise).
The plot: detached and emitted fractions against time (mean over seeds per
N, the band is the seeds' range), and the trade curve of the three end
measures.
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

MEASURES = [("t50", "half detached, ms after gas on"),
            ("emitted", "fraction out of the outlet"),
            ("fpf_acc", "FPF (FPF_system accumulated)")]


def fpf(d):
    files = sorted(glob.glob(os.path.join(d, "postProcessing", "fpf", "*",
                                          "fpf.dat")),
                   key=lambda p: float(p.split(os.sep)[-2]))
    data = np.atleast_2d(np.loadtxt(files[-1], comments="#"))
    # Time apiSystem apiBox singletsBox FPF_box FPF_system FPF_box_acc
    # FPF_system_acc
    return data[-1, 7], data[:, 5].max()


def run(d, t1, ramp):
    m = re.search(r"N(\d+)-seed(\d+)$", d)
    N, seed = int(m.group(1)), int(m.group(2))
    carriers, parcels, primaries = map(int, open(os.path.join(d, "bed.txt"))
                                       .read().split())
    sed = benchLogs.apiHistory(os.path.join(d, "log.dpiFoam.sedimentation"))
    inh = benchLogs.apiHistory(os.path.join(d, "log.dpiFoam.inhalation"))
    ts, as_, cs = sed["t"], sed["attached"], sed["cpu"]
    ti, ai, ci = inh["t"], inh["attached"], inh["cpu"]
    # API primaries out of the outlet: the counter minus the carriers gone
    ei = inh["escaped"] - (carriers - inh["carriers"])
    k = min(np.searchsorted(ti, t1 + ramp - 1e-9), len(ti) - 1)
    t50 = tradeCurve.halfTime(ti, 1 - ai/primaries)
    fAcc, fMax = fpf(d)
    gt = benchLogs.gnuTime(os.path.join(d, "time.txt"))
    return dict(N=N, seed=seed, carriers=carriers, parcels=parcels,
                primaries=primaries, attached_t1=as_[-1]/primaries,
                detached_ramp=1 - ai[k]/primaries,
                detached_end=1 - ai[-1]/primaries, t50=1e3*(t50 - t1),
                emitted=ei[-1]/primaries,
                fpf_acc=fAcc, fpf_max=fMax, cpu_sed=cs, cpu_inh=ci,
                cpu_total=cs + ci, maxRssMB=gt["maxRssKB"]/1024.0), \
        (np.concatenate([ts, ti]), 1 - np.concatenate([as_, ai])/primaries,
         np.concatenate([np.zeros_like(ts), ei])/primaries)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases")
    ap.add_argument("--t1", type=float, required=True)
    ap.add_argument("--ramp", type=float, required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--summary", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--png", required=True)
    a = ap.parse_args()

    dirs = sorted(glob.glob(os.path.join(a.cases, "N*-seed*")))
    got = [run(d, a.t1, a.ramp) for d in dirs]
    if not got:
        sys.exit("analyse.py: no runs in " + a.cases)
    runs = [g[0] for g in got]
    curves = [g[1] for g in got]
    order = sorted(range(len(runs)), key=lambda i: (runs[i]["N"],
                                                    runs[i]["seed"]))
    tradeCurve.writeCsv(a.csv, [runs[i] for i in order], list(runs[0]))

    summs = {key: tradeCurve.summarise(runs, key) for key, _ in MEASURES}
    rows = []
    for key, _ in MEASURES:
        for s in summs[key]:
            rows.append(dict(s, measure=key))
    scols = ["measure", "N", "runs", "mean", "std", "sem", "error",
             "rel_error", "within_spread", "cpu_mean", "speedup"]
    tradeCurve.writeCsv(a.summary, rows, scols)

    # Markdown: one row per N, the three measures side by side
    Ns = [s["N"] for s in summs[MEASURES[0][0]]]
    head = "| N | API parcels | runs |"
    rule = "|---:|---:|---:|"
    for _, label in MEASURES:
        head += " %s: mean +- std (error vs N = 1) |" % label
        rule += "---:|"
    head += " CPU per run [s] | speed-up |"
    rule += "---:|---:|"
    lines = [head, rule]
    for i, N in enumerate(Ns):
        g = [r for r in runs if r["N"] == N]
        line = "| %d | %d | %d |" % (N, g[0]["parcels"], len(g))
        for key, _ in MEASURES:
            s = summs[key][i]
            line += " %.4g +- %.2g (%+.1f %%%s) |" % (
                s["mean"], s["std"], 100*s["rel_error"],
                "" if s["within_spread"] in ("", True) else ", outside")
        s = summs[MEASURES[0][0]][i]
        line += " %.0f | **%.1f** |" % (s["cpu_mean"], s["speedup"])
        lines.append(line)
    r0 = runs[0]
    lines += ["", "%d carriers, %d API primaries per run; API attached to "
              "carriers at the end of stage 1: %s (mean per N). \"outside\": "
              "the error is larger than the N = 1 seed-to-seed std." % (
                  r0["carriers"], r0["primaries"], ", ".join(
                      "N = %d %.2f" % (N, np.mean([r["attached_t1"] for r in
                                                   runs if r["N"] == N]))
                      for N in Ns))]
    with open(a.md, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.6))
    for j, (ax, what) in enumerate(zip(axs[:2], ("detached from carriers",
                                                 "out of the outlet"))):
        for c, N in enumerate(Ns):
            idx = [i for i in range(len(runs)) if runs[i]["N"] == N]
            # The runs' logs need not start at one time or sample the same
            # times (a run restarted from another's state logs only what
            # it ran): each curve is read at the first run's times inside
            # the span that every run covers, not sample by sample
            lo = max(curves[i][0][0] for i in idx)
            hi = min(curves[i][0][-1] for i in idx)
            t = curves[idx[0]][0]
            t = t[(t >= lo) & (t <= hi)]
            y = np.array([np.interp(t, curves[i][0], curves[i][1 + j])
                          for i in idx])
            ax.plot(1e3*t, y.mean(axis=0), color="C%d" % c,
                    label="N = %d (%d seeds)" % (N, len(idx)))
            ax.fill_between(1e3*t, y.min(axis=0), y.max(axis=0),
                            color="C%d" % c, alpha=0.2)
        ax.axvline(1e3*a.t1, color="0.5", ls=":", lw=1)
        ax.axvline(1e3*(a.t1 + a.ramp), color="0.5", ls=":", lw=1)
        ax.set_xlabel("time [ms] (dotted: gas on, end of the inlet ramp)")
        ax.set_ylabel("fraction of the API primaries " + what)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    axs[0].set_title("Inhaler, %d carriers + %d API primaries: mean over "
                     "seeds, band = range" % (r0["carriers"], r0["primaries"]),
                     fontsize=9)
    ax = axs[2]
    drawn = [tradeCurve.tradeAxes(ax, summs[key], label, color="C%d" % c,
                                  annotate=(c == 0), relative=True)
             for c, (key, label) in enumerate(MEASURES)]
    ax.set_ylabel("relative error vs N = 1")
    ax.set_title("The trade curve: error against speed-up", fontsize=9)
    if any(drawn):
        ax.legend(fontsize=7)
    elif 1 not in Ns:
        ax.text(0.5, 0.5, "no N = 1 run among these: the errors are\n"
                "against N = 1 (run it into the same cases)",
                ha="center", va="center", transform=ax.transAxes)
    else:
        ax.text(0.5, 0.5, "no measure with a non-zero mean at N = 1\n"
                "(no API detached or emitted in this window?)",
                ha="center", va="center", transform=ax.transAxes)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote %s, %s, %s, %s" % (a.csv, a.summary, a.md, a.png))


if __name__ == "__main__":
    main()
