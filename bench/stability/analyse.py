#!/usr/bin/python3
"""Collect bench/stability cases into results.csv, results.md, stability.png.

Usage: analyse.py cases --csv results.csv --md results.md --png stability.png

Columns: impact.py's (kind, N, Y, v, dt, allowUnstable, tH, dt_over_tH,
check, status, e, e_ref, e_err, Fmax, Fmax_ref, Fmax_err, maxOverlap_over_R,
reason) plus set (sweep or grid) and name. e_err, Fmax_err are relative to
the reference; Fmax is the primary force.
"""
import argparse
import csv
import glob
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import impact  # noqa: E402

NAN = float("nan")


def amax(xs):
    """Largest finite value (nan when none)."""
    xs = [x for x in xs if isinstance(x, float) and math.isfinite(x)]
    return max(xs) if xs else NAN


def label(r):
    if r.get("cohesion"):
        return "carrier-API+vdW N %d" % r["N"]
    return "%s N %d" % (r["kind"], r["N"]) if r["kind"] == "carrier-API" \
        else r["kind"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cases")
    ap.add_argument("--csv", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--png", required=True)
    a = ap.parse_args()

    rows = []
    for d in sorted(glob.glob(os.path.join(a.cases, "*"))):
        if not os.path.exists(os.path.join(d, "impact.info")):
            continue
        r = impact.analyse(d)
        r["name"] = os.path.basename(d)
        r["set"] = r["name"].split("-")[0]
        rows.append(r)
    if not rows:
        sys.exit("analyse.py: no cases in " + a.cases)

    cols = ["set", "name"] + impact.COLUMNS
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow({k: impact.fmt(r.get(k, "")) for k in cols})

    default = [r for r in rows if not r["allowUnstable"]]
    allow = {r["name"][:-len("-allow")]: r for r in rows
             if r["allowUnstable"]}
    bad = [r for r in default if r["status"] not in ("ran", "refused")]
    ran = [r for r in default if r["status"] == "ran"]
    refused = [r for r in default if r["status"] == "refused"]

    out = []
    out.append("### Time-step sweep (3 m/s, Y = 5e8 Pa)\n")
    out.append("dt/t_H of the colliding pair; errors of restitution e and "
               "peak primary force against the reference; `refused` = the "
               "start-up check stopped the run (default), the numbers after "
               "it are the same run with `allowUnstable true`.\n")
    sweep = [r for r in default if r["set"] == "sweep"]
    kinds = []
    for r in sweep:
        if label(r) not in kinds:
            kinds.append(label(r))
    out.append("| dt/t_H | " + " | ".join(kinds) + " |")
    out.append("|---:|" + "---|"*len(kinds))
    ratios = sorted({round(r["dt_over_tH"], 3) for r in sweep})
    for q in ratios:
        cells = []
        for k in kinds:
            m = [r for r in sweep if label(r) == k
                 and round(r["dt_over_tH"], 3) == q]
            if not m:
                cells.append("")
                continue
            r = m[0]
            s = r
            pre = ""
            if r["status"] == "refused":
                pre = "refused; "
                s = allow.get(r["name"], r)
            if s["status"] in ("ran", "large error") or (
                    s["status"] == "blow-up" and math.isfinite(s["e"])):
                cells.append("%se %+.1f %%, F %+.1f %%%s"
                             % (pre, 100*s["e_err"], 100*s["Fmax_err"],
                                "" if s["status"] == "ran"
                                else " (%s: %s)" % (s["status"], s["reason"])))
            else:
                cells.append("%s%s: %s" % (pre, s["status"], s["reason"]))
        out.append("| %.3g | " % q + " | ".join(cells) + " |")

    out.append("\n### Extremes grid at dt = 1e-8 s, default check\n")
    out.append("| pair | cases | ran | refused | max abs e error (ran) | "
               "max abs F error (ran) | max overlap/R* (ran) | not bounded "
               "with the default check | refused cases run anyway "
               "(allowUnstable) |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---|---|")
    grid = [r for r in default if r["set"] == "grid"]
    gk = []
    for r in grid:
        if label(r) not in gk:
            gk.append(label(r))
    for k in gk:
        g = [r for r in grid if label(r) == k]
        gr = [r for r in g if r["status"] == "ran"]
        gf = [r for r in g if r["status"] == "refused"]
        anyway = {}
        for r in gf:
            s = allow.get(r["name"])
            if s:
                anyway[s["status"]] = anyway.get(s["status"], 0) + 1
        gb = [r for r in g if r["status"] not in ("ran", "refused")]
        out.append("| %s | %d | %d | %d | %s | %s | %s | %s | %s |" % (
            k, len(g), len(gr), len(gf),
            ("captured %d, contact e %.2f-%.2f" % (
                sum(1 for r in gr if r["e"] == 0),
                min([r["e"] for r in gr if r["e"] > 0] or [NAN]),
                max([r["e"] for r in gr] or [NAN])))
            if gr and gr[0]["cohesion"] else
            "%.1f %%" % (100*amax(abs(r["e_err"]) for r in gr)) if gr else "",
            "%.1f %%" % (100*amax(abs(r["Fmax_err"]) for r in gr)) if gr
            and not gr[0]["cohesion"] else "",
            "%.3g" % max(r["maxOverlap_over_R"] for r in gr) if gr else "",
            "; ".join("Y %g v %g: %s (%s, predicted overlap/R* %.2f)"
                      % (r["Y"], r["v"], r["status"], r["reason"],
                         r["predOverlap_over_R"]) for r in gb) or "none",
            ", ".join("%d %s" % (n, s) for s, n in sorted(anyway.items()))))
    ranR = [r["dt_over_tH"] for r in default if r["status"] == "ran"]
    refR = [r["dt_over_tH"] for r in refused]
    out.append("")
    out.append("Accepted runs reach dt/t_H = %.3g; refused runs start at "
               "dt/t_H = %.3g (of the colliding pair; the check uses the "
               "worst pair of the material table)." % (
                   max(ranR) if ranR else NAN, min(refR) if refR else NAN))
    blow = [r for r in allow.values() if r["status"] != "ran"]
    if blow:
        out.append("With allowUnstable, the first non-bounded run is at "
                   "dt/t_H = %.3g (%s); the velocity-Verlet limit of "
                   "theory 7.1 is 1/2.015 = 0.496."
                   % (min(r["dt_over_tH"] for r in blow),
                      ", ".join(sorted({"%s %s" % (label(r), r["status"])
                                        for r in blow}))))
    out.append("")
    plain = [r for r in ran if not r["cohesion"]]
    summary = ("stability: %d cases with the default check: %d ran with "
               "bounded error (without cohesion: max |e error| %.1f %%, max "
               "|F error| %.1f %%; with cohesion: no energy gained), "
               "%d refused by the start-up check, %d FAILED (ran and not "
               "bounded)%s" % (
                   len(default), len(ran),
                   100*amax([abs(r["e_err"]) for r in plain]),
                   100*amax([abs(r["Fmax_err"]) for r in plain]),
                   len(refused), len(bad),
                   "" if not bad else ": " + "; ".join(
                       "%s %s (%s)" % (r["name"], r["status"], r["reason"])
                       for r in bad)))
    out.append(summary)
    with open(a.md, "w") as f:
        f.write("\n".join(out) + "\n")
    print("\n".join(out))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(12, 4.8))
    ax = axs[0]
    for i, k in enumerate(kinds):
        pts = []
        for r in sweep:
            if label(r) != k:
                continue
            s = allow.get(r["name"], r) if r["status"] == "refused" else r
            pts.append((s["dt_over_tH"], s["e_err"], s["Fmax_err"],
                        s["status"], r["status"] == "refused"))
        pts.sort()
        x = [p[0] for p in pts]
        ax.plot(x, [100*abs(p[1]) for p in pts], "o-", color="C%d" % i,
                label="%s: restitution" % k)
        ax.plot(x, [100*abs(p[2]) for p in pts], "s--", color="C%d" % i,
                mfc="none", label="%s: peak force" % k)
        for p in pts:
            if p[4]:
                ax.plot(p[0], 100*max(abs(p[1]), abs(p[2]))
                        if math.isfinite(p[1]) else 100, "x", color="k",
                        ms=9)
    ax.axvline(1/3, color="k", ls=":", lw=1)
    ax.axvline(1/2.015, color="r", ls=":", lw=1)
    ax.text(1/3, 0.02, " check limit t_H/3", fontsize=7, rotation=90,
            va="bottom", transform=ax.get_xaxis_transform())
    ax.text(1/2.015, 0.02, " Verlet limit t_H/2.015", fontsize=7,
            rotation=90, va="bottom", color="r",
            transform=ax.get_xaxis_transform())
    ax.set_yscale("log")
    ax.set_xlabel("dt / t_H (colliding pair)")
    ax.set_ylabel("|error| vs reference [%]  (x: refused by default)")
    ax.set_title("Time-step sweep, 3 m/s, Y 5e8 Pa", fontsize=9)
    ax.legend(fontsize=6)
    ax.grid(True, which="both", alpha=0.3)

    ax = axs[1]
    mk = {"ran": "o", "refused": "x", "blow-up": "v", "large error": "^",
          "crashed": "*"}
    for i, k in enumerate(gk):
        if "vdW" in k:
            continue            # no closed form with cohesion
        for r in [r for r in grid if label(r) == k]:
            s = r
            if r["status"] == "refused":
                s = allow.get(r["name"], r)
            y = max(abs(s["e_err"]), abs(s["Fmax_err"]))
            y = 100*y if math.isfinite(y) else 200
            ax.plot(r["dt_over_tH"], max(y, 1e-3), mk.get(r["status"], "*"),
                    color="C%d" % i, ms=6, mfc="none"
                    if r["status"] == "ran" else None)
        ax.plot([], [], "o", color="C%d" % i, label=k, mfc="none")
    ax.plot([], [], "x", color="k", label="refused (error if run anyway)")
    ax.axvline(1/3, color="k", ls=":", lw=1)
    ax.axvline(1/2.015, color="r", ls=":", lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("dt / t_H (colliding pair), dt = 1e-8 s, "
                  "Y 9e9-5e6 Pa, v 0.1-30 m/s")
    ax.set_ylabel("max(|e error|, |F error|) [%]")
    ax.set_title("Extremes grid, default start-up check (without cohesion;"
                 " filled: not bounded)", fontsize=9)
    ax.legend(fontsize=6)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote %s, %s, %s" % (a.csv, a.md, a.png))


if __name__ == "__main__":
    main()
