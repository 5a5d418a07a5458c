#!/usr/bin/python3
"""Collect bench/packedBed runs into results.csv, results.md, throughput.png.

Usage: analyse.py --csv results.csv --png throughput.png --md results.md \\
           cases/N2000 cases/N10000 ... [cases/cohesive-N2000]

One row per bed, bed size N and process count np (code "bed": the still
bed with dpiFoam's mesh patch and LIGGGHTS' planes; "<bed>-<walls>": a bed
of moving.py, or the still one, with walls as planes or as a mesh in both
codes), per code the
best of the repeated runs (highest loop rate); the cohesive variant's rows
have code "cohesive" (dpiFoam only). Columns:

  dpi_psps, lig_psps, of_psps   particle-steps per CPU second of the solver
                loop (per process: on 2 processes the rate of the whole run),
                set-up excluded: dpiFoam N x DEM steps after the first fluid
                step / (ExecutionTime last - first); LIGGGHTS N x steps /
                (CPU of the run - CPU of a 0-step run, per process);
                OpenFOAM N x (steps - 1) / (ExecutionTime last - first)
  ratio_lig, ratio_of   dpi_psps / lig_psps, dpi_psps / of_psps
  *_speedup     rate on this np / rate on 1 process (same N)
  *_pair_speedups  each repeat's run on this np over the same repeat's on 1
                (run alternates them: the two are minutes apart at most)
  dpi_engine_psps   dpiFoam's 'DEM performance' (DEM engine, wall clock)
  dpi_pair_share    pair term / DEM engine time (dpiFoam's breakdown)
  lig_pair_share    LIGGGHTS' Pair time / loop time
  z_start       pair contacts per particle (2 x overlapping pairs / N) of
                the start positions (the bed's, geometric; all codes)
  dpi_z_first, dpi_z_end   dpiFoam's demDiagnostics after the first fluid
                step and at the end; lig_z_start, lig_z_end LIGGGHTS'
                contact/atom sum / N at step 0 and at the end; of_z_end
                geometric from OpenFOAM's written positions at the end
  *_KE          translational kinetic energy at the end [J]
  *_rss_MB, *_empty_rss_MB   peak RSS (GNU time) summed over the processes,
                of the run and of the empty case (the bed's first carrier
                alone in the same box and mesh)
  *_kB_per_particle   (rss - empty rss) / N
  *_anon_MB, *_empty_anon_MB, *_anon_kB_per_particle   the same with the
                peak of the anonymous pages (common/memsample.py): the
                processes' own data, without the shared libraries' pages
  dpi_setup_s   dpiFoam's set-up before the loop: ExecutionTime of the
                first fluid step minus one loop step's (CPU)
  dpi_inject_s  the injection's wall-clock time as dpiFoam logs it (the
                particle list read at start-up, "injectors/<name>: read N
                particles in T s", plus "Injected N parcels in T s":
                ordering, locating in the mesh, creating); for logs
                before that line: dpi_setup_s - the empty case's (a
                difference of two step times, good to about a second at
                50,000 on a loaded machine)
  dpi_near_builds   dpiFoam's near-list builds (its first process)
  *_runs        every run's rate
  load_before   1-min load average before the best dpiFoam run
  parcels, api_attached, api_detached   cohesive rows: DEM parcels, API
                primaries attached to carriers / detached at the end
"""

import argparse
import csv
import glob
import json
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import benchLogs  # noqa: E402
import peersPlot  # noqa: E402
import settlingScene as ss  # noqa: E402

COLUMNS = [
    "code", "N", "np", "steps", "of_steps", "dpi_psps", "lig_psps",
    "of_psps", "ratio_lig", "ratio_of", "dpi_speedup", "lig_speedup",
    "of_speedup", "dpi_pair_speedups", "lig_pair_speedups",
    "of_pair_speedups", "dpi_engine_psps", "dpi_pair_share", "lig_pair_share",
    "z_start", "dpi_z_first", "dpi_z_end", "lig_z_start", "lig_z_end",
    "of_z_end", "dpi_KE", "lig_KE", "of_KE", "of_parcels_end",
    "dpi_rss_MB", "lig_rss_MB", "of_rss_MB", "dpi_empty_rss_MB",
    "lig_empty_rss_MB", "of_empty_rss_MB", "dpi_kB_per_particle",
    "lig_kB_per_particle", "of_kB_per_particle", "dpi_anon_MB",
    "lig_anon_MB", "of_anon_MB", "dpi_empty_anon_MB", "lig_empty_anon_MB",
    "of_empty_anon_MB", "dpi_anon_kB_per_particle",
    "lig_anon_kB_per_particle", "of_anon_kB_per_particle", "dpi_setup_s",
    "dpi_inject_s", "parcels", "api_attached", "api_detached",
    "dpi_runs", "lig_runs", "of_runs", "load_before", "dpi_near_builds",
]
NAN = float("nan")


def geometricContacts(x):
    """2 x overlapping pairs / particles of positions x."""
    from scipy.spatial import cKDTree
    pairs = cKDTree(x).query_pairs(ss.DIAMETER, output_type="ndarray")
    return 2.0*len(pairs)/len(x)


def dpiRun(d):
    path = os.path.join(d, "log.dpiFoam")
    log = benchLogs.dpiFoamLog(path)
    dg = benchLogs.demDiagnostics(d)
    n = int(dg["nParcels"])
    every = log["steps"]//log["nFluid"] if log["nFluid"] else 0
    loopSteps = (log["nFluid"] - 1)*every
    text = open(path).read()
    exe = [float(x) for x in re.findall(
        r"^ExecutionTime = " + benchLogs.FLOAT + " s", text, re.M)]
    api = re.findall(r"API primaries: attached to carriers (\d+), "
                     r"detached (\d+)", text)
    return dict(case=d, n=n, steps=log["steps"],
                rate=n*loopSteps/log["loopCpu"]
                if loopSteps and log["loopCpu"] > 0 else NAN,
                engine=log["engineRate"],
                pairShare=log["tPair"]/log["tEngine"],
                setup=exe[0] - log["loopCpu"]/(log["nFluid"] - 1)
                if log["nFluid"] > 1 else NAN,
                injectTime=log["injectTime"],
                zFirst=2*dg["first"]["nPair"]/n, zEnd=2*dg["nPair"]/n,
                KE=dg["KE"], tm=benchLogs.gnuTimes(d),
                nearBuilds=nearBuilds(text),
                api=[int(x) for x in api[-1]] if api else [NAN, NAN])


def nearBuilds(text):
    """Near-list builds of a dpiFoam log: its last performance line (the
    master process's own on more than one)."""
    m = re.findall(r"(\d+) near builds", text)
    return int(m[-1]) if m else NAN


def ligRun(d, setup):
    log = benchLogs.liggghtsLog(os.path.join(d, "log.liggghts"))
    tm = benchLogs.gnuTimes(d)
    ps = log["atoms"]*log["steps"]
    # thermo rows: step atoms ke rke contacts
    text = open(os.path.join(d, "log.liggghts")).read()
    rows = [ln.split() for ln in text.splitlines()
            if len(ln.split()) == 5 and ln.split()[0].isdigit()]
    n = log["atoms"]
    return dict(case=d, n=n,
                rate=ps/(tm["cpu"] - setup["cpu"]) if setup else NAN,
                KE=log.get("KE", NAN),
                pairShare=log.get("tPair", NAN)/log["loop"],
                zStart=float(rows[0][4])/n if rows else NAN,
                zEnd=float(rows[-1][4])/n if rows else NAN, tm=tm)


def ofPositions(d):
    """Positions of OpenFOAM's cloud at the latest written time (serial or
    decomposed)."""
    roots = sorted(glob.glob(os.path.join(d, "processor[0-9]*"))) or [d]
    x = []
    for r in roots:
        times = [t for t in os.listdir(r) if re.match(r"^[0-9.eE+-]+$", t)
                 and float(t) > 0]
        if not times:
            continue
        t = max(times, key=float)
        f = os.path.join(r, t, "lagrangian", "kinematicCloud", "positions")
        if os.path.isfile(f):
            x += re.findall(r"^\(([^()]+)\) \d+", open(f).read(), re.M)
    return np.array([[float(c) for c in s.split()] for s in x])


def ofRun(d):
    log = benchLogs.openfoamLog(os.path.join(d, "log.openfoam"))
    x = ofPositions(d)
    return dict(case=d, n=log["n"], nEnd=log["nEnd"], steps=log["steps"],
                rate=log["rate"], KE=log["KE"],
                zEnd=geometricContacts(x) if len(x) > 1 else NAN,
                tm=benchLogs.gnuTimes(d))


def best(runs):
    return max(runs, key=lambda r: r["rate"]) if runs else None


def kindOf(base):
    """The code of a case directory's rows and its bed's NPZ: "bed" and
    bed-N<n>.npz for cases/N<n> (the still bed, default walls);
    "<bed>-<walls>" and <bed>-N<n>.npz (or bed-N<n>.npz for the still one)
    for cases/<bed>-N<n>-<walls>; "cohesive" for cases/cohesive-N<n>."""
    name = os.path.basename(base.rstrip("/"))
    top = os.path.dirname(base.rstrip("/"))
    m = re.match(r"^N(\d+)$", name)
    if m:
        return "bed", os.path.join(top, "bed-N%s.npz" % m.group(1))
    m = re.match(r"^(\w+)-N(\d+)-(\w+)$", name)
    if m:
        bed = "bed" if m.group(1) == "still" else m.group(1)
        return (m.group(1) + "-" + m.group(3),
                os.path.join(top, "%s-N%s.npz" % (bed, m.group(2))))
    return "cohesive", ""


def rows(base):
    out = []
    code, bedFile = kindOf(base)
    cohesive = code == "cohesive"
    nps = sorted({int(m.group(1)) for p in glob.glob(os.path.join(base, "*-np*-r*"))
                  for m in [re.search(r"-np(\d+)-r", p)] if m})
    zStart = NAN
    if os.path.isfile(bedFile):
        zStart = json.loads(str(np.load(bedFile)["stats"]))["z_geometric"]
    for np_ in nps:
        runs = {}
        runs["dpi"] = [dpiRun(d) for d in sorted(glob.glob(
            os.path.join(base, "dpiFoam-np%d-r*" % np_)))]
        setupDir = os.path.join(base, "liggghts-setup-np%d" % np_)
        setup = benchLogs.gnuTimes(setupDir) if os.path.isdir(setupDir) \
            else None
        runs["lig"] = [ligRun(d, setup) for d in sorted(glob.glob(
            os.path.join(base, "liggghts-np%d-r*" % np_)))]
        runs["of"] = [ofRun(d) for d in sorted(glob.glob(
            os.path.join(base, "openfoam-np%d-r*" % np_)))]
        b = {k: best(v) for k, v in runs.items()}
        anyRun = next(r for r in b.values() if r)
        r = {"code": code, "N": anyRun["n"],
             "np": np_, "z_start": zStart,
             "steps": b["dpi"]["steps"] if b["dpi"] else "",
             "of_steps": b["of"]["steps"] - 1 if b["of"] else ""}
        for k in ("dpi", "lig", "of"):
            x = b[k]
            r[k + "_psps"] = x["rate"] if x else NAN
            r[k + "_KE"] = x["KE"] if x else NAN
            r[k + "_rss_MB"] = x["tm"]["rss"]/1024 if x else NAN
            r[k + "_runs"] = " ".join("%.4g" % y["rate"] for y in runs[k])
            empty = os.path.join(base, {"dpi": "dpiFoam", "lig": "liggghts",
                                        "of": "openfoam"}[k]
                                 + "-empty-np%d" % np_)
            e = benchLogs.gnuTimes(empty) if os.path.isdir(empty) else None
            r[k + "_empty_rss_MB"] = e["rss"]/1024 if e else NAN
            r[k + "_kB_per_particle"] = (x["tm"]["rss"] - e["rss"])/x["n"] \
                if x and e else NAN
            # The anonymous pages alone (common/memsample.py): the data
            # that grows with the particles, without the shared libraries'
            # pages whose residency moves between runs
            r[k + "_anon_MB"] = x["tm"]["anon"]/1024 if x else NAN
            r[k + "_empty_anon_MB"] = e["anon"]/1024 if e else NAN
            r[k + "_anon_kB_per_particle"] = \
                (x["tm"]["anon"] - e["anon"])/x["n"] if x and e else NAN
        d = b["dpi"]
        if d:
            r.update(dpi_engine_psps=d["engine"], dpi_pair_share=d["pairShare"],
                     dpi_near_builds=d["nearBuilds"],
                     dpi_z_first=d["zFirst"], dpi_z_end=d["zEnd"],
                     dpi_setup_s=d["setup"], parcels=d["n"],
                     load_before=benchLogs.machineLoad(d["case"]))
            if cohesive:
                r.update(api_attached=d["api"][0], api_detached=d["api"][1])
            empty = os.path.join(base, "dpiFoam-empty-np%d" % np_)
            if not np.isnan(d["injectTime"]):
                r["dpi_inject_s"] = d["injectTime"]
            elif os.path.isdir(empty):
                r["dpi_inject_s"] = d["setup"] - dpiRun(empty)["setup"]
        if b["lig"]:
            r.update(lig_pair_share=b["lig"]["pairShare"],
                     lig_z_start=b["lig"]["zStart"],
                     lig_z_end=b["lig"]["zEnd"])
        if b["of"]:
            r.update(of_z_end=b["of"]["zEnd"], of_parcels_end=b["of"]["nEnd"])
        r["ratio_lig"] = r["dpi_psps"]/r["lig_psps"]
        r["ratio_of"] = r["dpi_psps"]/r["of_psps"]
        out.append(r)
    one = next((r for r in out if r["np"] == 1), None)
    for r in out:
        for k in ("dpi", "lig", "of"):
            r[k + "_speedup"] = r[k + "_psps"]/one[k + "_psps"] if one \
                else NAN
            # Each repeat's own pair: run r on np processes over run r on
            # 1, which `run` makes one after the other (the best-of ratio
            # above can take its two runs from different states of the
            # machine)
            pairs = []
            if one and r["np"] != 1:
                many = [float(x) for x in r[k + "_runs"].split()]
                single = [float(x) for x in one[k + "_runs"].split()]
                pairs = [a/b for a, b in zip(many, single)]
            r[k + "_pair_speedups"] = " ".join("%.3g" % x for x in pairs)
    return out


def fmt(v):
    return "%.6g" % v if isinstance(v, float) else str(v)


f = peersPlot.num


def plot(table, png):
    peersPlot.bars([r for r in table if r["code"] == "bed"], png,
                   "Packed bed of 70 um carriers (3-4.5 contacts per particle),"
                   " Hertz + history, dt 5e-8 s", "carriers")


def g(v, form):
    return "-" if v != v else form % v


def cells(r, spec):
    """Row r's columns formatted, spec a list of (column, format)."""
    return tuple(g(f(r, k), form) for k, form in spec)


def markdown(table, md):
    bed = [r for r in table if r["code"] == "bed"]
    coh = [r for r in table if r["code"] == "cohesive"]
    with open(md, "w") as fh:
        fh.write("| carriers | np | dpiFoam | LIGGGHTS | OpenFOAM | "
                 "dpiFoam/LIGGGHTS | dpiFoam/OpenFOAM | 2-process speed-up "
                 "dpiFoam / LIGGGHTS / OpenFOAM | dpiFoam pair share |\n")
        fh.write("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in bed:
            sp = " / ".join(g(f(r, k + "_speedup"), "%.2f")
                            for k in ("dpi", "lig", "of")) \
                if int(r["np"]) > 1 else ""
            fh.write("| %s | %s | %s | %s | %s | **%s** | **%s** | %s | %s |\n"
                     % (r["N"], r["np"], g(f(r, "dpi_psps"), "%.3g"),
                        g(f(r, "lig_psps"), "%.3g"), g(f(r, "of_psps"), "%.3g"),
                        g(f(r, "ratio_lig"), "%.2f"),
                        g(f(r, "ratio_of"), "%.1f"), sp,
                        g(100*f(r, "dpi_pair_share"), "%.0f %%")))
        fh.write("\n(particle-steps per CPU second of the solver loop, per "
                 "process: on 2 processes the rate of the whole run; best "
                 "of the runs in results.csv)\n")
        for r in bed:
            if r["dpi_pair_speedups"]:
                fh.write("\nSpeed-up on %s processes at %s carriers, each "
                         "repeat's runs paired (dpiFoam; LIGGGHTS; "
                         "OpenFOAM): %s; %s; %s\n"
                         % (r["np"], r["N"], r["dpi_pair_speedups"],
                            r["lig_pair_speedups"] or "-",
                            r["of_pair_speedups"] or "-"))
        fh.write("\n")
        fh.write("| carriers | np | contacts/particle at the start "
                 "(geometric) | dpiFoam after 1st fluid step -> end | "
                 "LIGGGHTS start -> end | OpenFOAM end | KE at the end "
                 "dpiFoam / LIGGGHTS / OpenFOAM [J] |\n")
        fh.write("|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in bed:
            fh.write("| %s | %s | %s | %s -> %s | %s -> %s | %s | %s / %s / "
                     "%s |\n"
                     % ((r["N"], r["np"])
                        + cells(r, [(k, "%.2f") for k in (
                            "z_start", "dpi_z_first", "dpi_z_end",
                            "lig_z_start", "lig_z_end", "of_z_end")])
                        + cells(r, [(k + "_KE", "%.4g")
                                    for k in ("dpi", "lig", "of")])))
        fh.write("\n| carriers | np | peak RSS dpiFoam / LIGGGHTS / OpenFOAM "
                 "[MB] | empty case [MB] | kB per particle above the empty "
                 "case | anonymous pages only: kB per particle above the "
                 "empty case | dpiFoam set-up [s CPU] | injection [s] "
                 "|\n")
        fh.write("|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in bed:
            fh.write("| %s | %s | %s / %s / %s | %s / %s / %s | "
                     "%s / %s / %s | %s / %s / %s | %s | %s |\n"
                     % ((r["N"], r["np"])
                        + cells(r, [(k + col, form) for col, form in (
                            ("_rss_MB", "%.0f"), ("_empty_rss_MB", "%.0f"),
                            ("_kB_per_particle", "%.2f"),
                            ("_anon_kB_per_particle", "%.2f"))
                            for k in ("dpi", "lig", "of")])
                        + cells(r, [("dpi_setup_s", "%.2f"),
                                    ("dpi_inject_s", "%.2f")])))
        moving = [r for r in table if r["code"] not in ("bed", "cohesive")]
        if moving:
            fh.write("\nBeds in motion (moving.py) and walls as planes or a "
                     "mesh in both codes:\n\n"
                     "| bed | walls | carriers | np | dpiFoam | LIGGGHTS | "
                     "dpiFoam/LIGGGHTS | contacts/particle at the start "
                     "(geometric) -> dpiFoam's end | KE at the end dpiFoam / "
                     "LIGGGHTS [J] | dpiFoam pair share | near builds |\n"
                     "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
            for r in moving:
                bed, walls = r["code"].split("-")
                fh.write("| %s | %s | %s | %s | %s | %s | **%s** | %s -> %s "
                         "| %s / %s | %s | %s |\n"
                         % ((bed, walls, r["N"], r["np"])
                            + cells(r, [("dpi_psps", "%.3g"),
                                        ("lig_psps", "%.3g"),
                                        ("ratio_lig", "%.2f"),
                                        ("z_start", "%.2f"),
                                        ("dpi_z_end", "%.2f"),
                                        ("dpi_KE", "%.3g"), ("lig_KE", "%.3g")])
                            + (g(100*f(r, "dpi_pair_share"), "%.0f %%"),
                               r.get("dpi_near_builds", "-"))))
        if coh:
            fh.write("\nCohesive variant (dpiFoam only):\n\n"
                     "| parcels | np | parcel-steps/s | 2-process speed-up | "
                     "pair share | contacts per parcel after 1st fluid step "
                     "-> end | API attached / detached at the end | peak "
                     "RSS [MB] |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n")
            for r in coh:
                fh.write("| %s | %s | %s | %s | %s | %s -> %s | %s / %s | %s |\n"
                         % (r["parcels"], r["np"], g(f(r, "dpi_psps"), "%.3g"),
                            g(f(r, "dpi_speedup"), "%.2f")
                            if int(r["np"]) > 1 else "",
                            g(100*f(r, "dpi_pair_share"), "%.0f %%"),
                            g(f(r, "dpi_z_first"), "%.2f"),
                            g(f(r, "dpi_z_end"), "%.2f"),
                            r.get("api_attached", "-"),
                            r.get("api_detached", "-"),
                            g(f(r, "dpi_rss_MB"), "%.0f")))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("cases", nargs="*")
    args = ap.parse_args()

    # Rows of earlier runs (other sizes) are kept; re-measured ones replaced
    table = {}
    if os.path.isfile(args.csv):
        with open(args.csv) as fh:
            for r in csv.DictReader(fh):
                table[(r["code"], int(r["N"]), int(r["np"]))] = r
    for base in args.cases:
        for r in rows(base):
            table[(r["code"], int(r["N"]), int(r["np"]))] = {
                k: fmt(v) for k, v in r.items()}
    ordered = [table[k] for k in sorted(table)]

    with open(args.csv, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=COLUMNS)
        w.writeheader()
        for r in ordered:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    markdown(ordered, args.md)
    print(open(args.md).read())
    plot(ordered, args.png)
    print("wrote %s, %s and %s" % (args.csv, args.md, args.png))


if __name__ == "__main__":
    main()
