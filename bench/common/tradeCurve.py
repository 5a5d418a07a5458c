"""Accuracy against the coarsening factor N, shared by bench/accuracyVsN,
bench/inhalerVsN and bench/powderVsN: a measure per run summarised per N
(mean, seed-to-seed spread, error against N = 1, speed-up), the time to half
detachment of a run, the CSV writer and the trade-curve axes (error against
speed-up).

A run is a dict with at least "N" and the measured keys; the CPU key gives
the speed-up (mean CPU time of the N = 1 runs / mean CPU time of the N
runs)."""

import csv
import math

import numpy as np


def halfTime(t, detached):
    """t50: the time at which the detached fraction first reaches one half,
    linear between the samples around it; NaN when it never does or
    already has at the first sample (no sample before it)."""
    j = np.argmax(detached >= 0.5) if detached[-1] >= 0.5 else -1
    if j > 0:
        return t[j - 1] + (0.5 - detached[j - 1]) \
            / (detached[j] - detached[j - 1])*(t[j] - t[j - 1])
    return float("nan")


def summarise(runs, key, cpu="cpu_total"):
    """One dict per N (ascending): N, runs, mean, std (ddof 1), sem,
    cpu_mean, error (mean - mean at N = 1), rel_error, within_spread
    (|error| <= std at N = 1) and speedup; NaN/'' without N = 1 runs."""
    out = []
    for N in sorted({r["N"] for r in runs}):
        g = [r for r in runs if r["N"] == N]
        x = np.array([r[key] for r in g], dtype=float)
        many = len(x) > 1
        out.append(dict(
            N=N, runs=len(g), mean=x.mean(),
            std=x.std(ddof=1) if many else float("nan"),
            sem=x.std(ddof=1)/math.sqrt(len(x)) if many else float("nan"),
            cpu_mean=float(np.mean([r[cpu] for r in g]))))
    base = next((s for s in out if s["N"] == 1), None)
    for s in out:
        if base:
            s["error"] = s["mean"] - base["mean"]
            s["rel_error"] = s["error"]/base["mean"] if base["mean"] \
                else float("nan")
            s["within_spread"] = bool(abs(s["error"]) <= base["std"]) \
                if base["std"] == base["std"] else ""
            s["speedup"] = base["cpu_mean"]/s["cpu_mean"]
        else:
            s.update(error=float("nan"), rel_error=float("nan"),
                     within_spread="", speedup=float("nan"))
    return out


def writeCsv(path, rows, cols):
    """rows (dicts) to path, floats as %.6g."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6g" % r[k] if isinstance(r[k], float)
                            else r[k]) for k in cols})


def tradeAxes(ax, summ, label, color=None, annotate=True, relative=False):
    """|error| of one measure against speed-up, +- its sem at N, and the
    N = 1 seed-to-seed std as a dashed line of the same colour; relative:
    all three divided by |mean at N = 1| (measures of different units on
    one axis). False when there is nothing to draw."""
    base = next((s for s in summ if s["N"] == 1), None)
    if not base:
        return False
    scale = abs(base["mean"]) if relative else 1.0
    er = [abs(s["error"])/scale if scale else float("nan") for s in summ]
    if all(e != e for e in er):
        # nothing to draw (e.g. relative to a zero mean in a short run)
        return False
    sp = [s["speedup"] for s in summ]
    sem = [s["sem"]/scale for s in summ]
    what = "|mean(N) - mean(1)|%s" % ("/mean(1)" if relative else "")
    line = ax.errorbar(sp, er, yerr=None if all(e != e for e in sem) else sem,
                       fmt="o-", capsize=3, color=color,
                       label="%s: %s +- sem(N)" % (label, what))
    c = line[0].get_color()
    if annotate:
        for s, x, y in zip(summ, sp, er):
            ax.annotate("N=%d" % s["N"], (x, y), textcoords="offset points",
                        xytext=(4, 4), fontsize=8)
    ax.axhline(base["std"]/scale, color=c, ls="--",
               label="%s: N = 1 seed-to-seed std%s"
               % (label, "/mean(1)" if relative else ""))
    ax.set_xscale("log")
    ax.set_xlabel("speed-up (CPU time of N = 1 / CPU time of N)")
    ax.grid(True, which="both", alpha=0.3)
    return True
