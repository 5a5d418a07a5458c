#!/usr/bin/python3
"""Collect bench/costVsN runs into results.csv, results.md and costVsN.png.

Usage: analyse.py --csv results.csv --md results.md --png costVsN.png \
           cases/N1-r1 cases/N10-r1 ...

One row per N (best of its runs, lowest engine time):
  N, parcels (carriers + API parcels), api_parcels, steps,
  engine_s_per_us   DEM engine wall time per simulated microsecond [s]
                    (parcels x steps / 'DEM performance' rate / simulated us)
  loop_cpu_s_per_us solver loop CPU time per simulated microsecond [s]
                    (ExecutionTime last - first fluid step)
  elapsed_s         whole run, wall clock (GNU time), set-up included
  speedup           loop_cpu_s_per_us(N = 1) / loop_cpu_s_per_us(N) (the
                    headline: CPU time is less sensitive to a shared machine)
  speedup_engine    the same for the DEM engine's wall time
  us_per_parcel_step  engine wall time per parcel-step [us]
  pair_share, wall_share, neighbour_share, integrate_share [%]
  contacts_per_parcel  (2 pair + wall contacts)/parcels at the end
  attached_fraction API primaries attached to carriers at the end of the
                    run (its own window: larger N run longer, see run)
  attached_common   the same at the end of the shortest run's window (the
                    same simulated time for every N: the fraction to
                    compare across N)
  t_common_us       that time [us]
  rss_MB            peak memory
  runs              every run's engine s/us
"""
import argparse
import csv
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402

DT = 1e-8


def one(d):
    log = benchLogs.dpiFoamLog(os.path.join(d, "log.dpiFoam"))
    tm = benchLogs.gnuTime(os.path.join(d, "log.time"))
    dg = benchLogs.demDiagnostics(d)
    n = int(dg["nParcels"])
    text = open(os.path.join(d, "log.dpiFoam")).read()
    m = re.findall(r"API primaries: attached to carriers (\d+), detached "
                   r"(\d+)", text)
    att = int(m[-1][0])/(int(m[-1][0]) + int(m[-1][1])) if m else float("nan")
    # The same fraction at the end of every fluid step: (time [us], fraction)
    h = benchLogs.apiHistory(os.path.join(d, "log.dpiFoam"))
    series = [(t*1e6, a_/(a_ + d_)) for t, a_, d_ in
              zip(h["t"], h["attached"], h["detached"])]
    N = int(re.search(r"N(\d+)-r\d+$", d).group(1))
    steps = log["steps"]
    every = steps//log["nFluid"]
    simUs = steps*DT*1e6
    loopUs = (log["nFluid"] - 1)*every*DT*1e6
    engine = n*steps/log["engineRate"]
    return dict(
        N=N, parcels=n, steps=steps,
        engine_s_per_us=engine/simUs,
        loop_cpu_s_per_us=log["loopCpu"]/loopUs,
        elapsed_s=tm["elapsed"],
        us_per_parcel_step=1e6/log["engineRate"],
        pair_share=100*log["tPair"]/log["tEngine"],
        wall_share=100*log["tWall"]/log["tEngine"],
        neighbour_share=100*log["tNeighbour"]/log["tEngine"],
        integrate_share=100*log["tIntegrate"]/log["tEngine"],
        contacts_per_parcel=(2*dg["nPair"] + dg["nWall"])/n,
        attached_fraction=att, series=series, rss_MB=tm["maxRssKB"]/1024.0)


def attachedAt(series, tUs):
    """The attached fraction at the last fluid step at or before tUs."""
    before = [f for t, f in series if t <= tUs*(1 + 1e-9)]
    return before[-1] if before else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()

    allRuns = [one(d) for d in a.cases]
    rows = []
    for N in sorted({r["N"] for r in allRuns}):
        g = [r for r in allRuns if r["N"] == N]
        b = dict(min(g, key=lambda r: r["engine_s_per_us"]))
        b["loop_cpu_s_per_us"] = min(r["loop_cpu_s_per_us"] for r in g)
        b["runs"] = " ".join("%.4g" % r["engine_s_per_us"] for r in g)
        rows.append(b)
    # The common window: the shortest run's simulated time
    tCommon = min(r["steps"] for r in rows)*DT*1e6
    for r in rows:
        r["t_common_us"] = tCommon
        r["attached_common"] = attachedAt(r["series"], tCommon)
    carriers = None
    base = next((r for r in rows if r["N"] == 1), rows[0])
    for r in rows:
        r["speedup_engine"] = base["engine_s_per_us"]/r["engine_s_per_us"]
        r["speedup"] = (base["loop_cpu_s_per_us"]/r["loop_cpu_s_per_us"]
                             if r["loop_cpu_s_per_us"] > 0 else float("nan"))
    # API parcels: parcels minus carriers (the N = 1 run has carriers x
    # (1 + primaries) parcels; carriers are the same in every run)
    if len(rows) > 1:
        n1, n2 = rows[0], rows[-1]
        # parcels = C + C*P/N  ->  C from two rows
        P1, P2 = n1["parcels"], n2["parcels"]
        invN1, invN2 = 1.0/n1["N"], 1.0/n2["N"]
        CP = (P1 - P2)/(invN1 - invN2)
        carriers = int(round(P1 - CP*invN1))
    for r in rows:
        r["api_parcels"] = r["parcels"] - carriers if carriers is not None \
            else ""

    cols = ["N", "parcels", "api_parcels", "steps", "engine_s_per_us",
            "loop_cpu_s_per_us", "elapsed_s", "speedup", "speedup_engine",
            "us_per_parcel_step", "pair_share", "wall_share",
            "neighbour_share", "integrate_share", "contacts_per_parcel",
            "attached_fraction", "attached_common", "t_common_us",
            "rss_MB", "runs"]
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6g" % r[k] if isinstance(r[k], float)
                            else r[k]) for k in cols})

    lines = ["| N | parcels (API) | solver loop, CPU s per simulated us | "
             "DEM engine, wall s per us | speed-up vs N = 1 (loop CPU / "
             "engine wall) "
             "| us per parcel-step | pair share | contacts per parcel | "
             "simulated time [us] | API attached at the end | "
             "API attached at %.3g us (every N) | peak RSS |" % tCommon,
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
             "---:|"]
    for r in rows:
        lines.append("| %d | %d (%s) | %.3g | %.3g | **%.1f** / %.1f | %.3f | "
                     "%.0f %% | %.2f | %.3g | %.3f | %.3f | %.0f MB |" % (
                         r["N"], r["parcels"], r["api_parcels"],
                         r["loop_cpu_s_per_us"], r["engine_s_per_us"],
                         r["speedup"], r["speedup_engine"],
                         r["us_per_parcel_step"], r["pair_share"],
                         r["contacts_per_parcel"], r["steps"]*DT*1e6,
                         r["attached_fraction"], r["attached_common"],
                         r["rss_MB"]))
    with open(a.md, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    Ns = [r["N"] for r in rows]
    ax.loglog(Ns, [r["engine_s_per_us"] for r in rows], "o-",
              label="DEM engine (wall clock)")
    ax.loglog(Ns, [r["loop_cpu_s_per_us"] for r in rows], "s--",
              label="solver loop (CPU)")
    ideal = [base["loop_cpu_s_per_us"]*(r["parcels"]/base["parcels"])
             for r in rows]
    ax.loglog(Ns, ideal, ":", color="0.5",
              label="proportional to the parcel count")
    for r in rows:
        ax.annotate("%.1fx" % r["speedup"], (r["N"], r["loop_cpu_s_per_us"]),
                    textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xlabel("coarsening factor N (same primary mass of API)")
    ax.set_ylabel("seconds per simulated microsecond")
    ax.set_title("Coated carrier powder, vdW cohesion, dt 1e-8 s "
                 "(labels: speed-up of the loop CPU time vs N = 1)", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote %s, %s, %s" % (a.csv, a.md, a.png))


if __name__ == "__main__":
    main()
