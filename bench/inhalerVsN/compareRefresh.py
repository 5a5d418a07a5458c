#!/usr/bin/python3
"""Compare two inhalerVsN result tables (run --refresh): the reference
(refreshInterval 1) and K. Per N and measure: mean +- std of both, the
difference of the means in units of the reference's seed-to-seed std (the
issue's criterion: inside the spread) and of its standard error (whether
it is a shift at all), and the stage-2 CPU ratio."""
import argparse
import csv
import math
import numpy as np

MEASURES = [("t50", "half detached, ms after gas on"),
            ("emitted", "fraction out of the outlet"),
            ("fpf_acc", "FPF (FPF_system accumulated)"),
            ("detached_end", "detached at the end")]


def load(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ref")
    ap.add_argument("other")
    ap.add_argument("--K", required=True)
    ap.add_argument("--md", required=True)
    a = ap.parse_args()
    ref, oth = load(a.ref), load(a.other)
    Ns = sorted({int(r["N"]) for r in ref})
    head = ("| N | measure | refreshInterval 1: mean +- std | %s: mean +- std "
            "| difference | difference / std(1) | difference / its standard "
            "error | inside the spread |" % a.K)
    lines = [head, "|---:|---|---:|---:|---:|---:|---:|---|"]
    allInside = True
    for N in Ns:
        r = [x for x in ref if int(x["N"]) == N]
        o = [x for x in oth if int(x["N"]) == N]
        for key, label in MEASURES:
            xr = np.array([x[key] for x in r])
            xo = np.array([x[key] for x in o])
            sr = xr.std(ddof=1) if len(xr) > 1 else float("nan")
            so = xo.std(ddof=1) if len(xo) > 1 else float("nan")
            d = xo.mean() - xr.mean()
            ratio = abs(d)/sr if sr > 0 else (0.0 if d == 0 else float("inf"))
            se = math.sqrt(sr**2/len(xr) + so**2/len(xo)) \
                if len(xr) > 1 and len(xo) > 1 else float("nan")
            z = abs(d)/se if se > 0 else (0.0 if d == 0 else float("inf"))
            inside = ratio <= 1
            allInside = allInside and inside
            lines.append("| %d | %s | %.4g +- %.2g | %.4g +- %.2g | %+.3g | "
                         "%.2f | %.1f | %s |" % (
                             N, label, xr.mean(), sr, xo.mean(), so, d, ratio,
                             z, "yes" if inside else "**no**"))
    lines.append("")
    cols = ["N", "stage 2 CPU [s], 1", "stage 2 CPU [s], %s" % a.K,
            "speed-up of stage 2", "whole run CPU [s], 1",
            "whole run CPU [s], %s" % a.K]
    lines += ["| " + " | ".join(cols) + " |",
              "|" + "---:|"*len(cols)]
    for N in Ns:
        r = [x for x in ref if int(x["N"]) == N]
        o = [x for x in oth if int(x["N"]) == N]
        ci = (np.mean([x["cpu_inh"] for x in r]),
              np.mean([x["cpu_inh"] for x in o]))
        ct = (np.mean([x["cpu_total"] for x in r]),
              np.mean([x["cpu_total"] for x in o]))
        lines.append("| %d | %.0f | %.0f | **%.2f** | %.0f | %.0f |"
                     % (N, ci[0], ci[1], ci[0]/ci[1], ct[0], ct[1]))
    lines += ["", "Every difference inside the reference's seed-to-seed "
              "std: %s." % ("yes" if allInside else "**no**")]
    text = "\n".join(lines) + "\n"
    with open(a.md, "w") as f:
        f.write(text)
    print(text)


main()
