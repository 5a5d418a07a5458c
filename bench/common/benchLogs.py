"""Read the numbers the benchmarks report out of dpiFoam, LIGGGHTS and GNU
time logs (bench/common)."""

import glob
import os
import re
import sys

import numpy as np

# The dpiFoam log's DEM performance lines are read by the tutorials' parser
# (one reader for the product and the benchmarks)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "scripts"))
import dpiLog  # noqa: E402

FLOAT = dpiLog.FLOAT


def gnuTime(path):
    """Peak RSS [kB], elapsed [s], CPU percent, user+sys [s] of
    /usr/bin/time -v (for mpirun: the largest single process)."""
    out = {}
    with open(path) as f:
        text = f.read()
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    out["maxRssKB"] = int(m.group(1)) if m else float("nan")
    m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)",
                  text)
    if m:
        parts = [float(p) for p in m.group(1).split(":")]
        sec = 0.0
        for p in parts:
            sec = 60*sec + p
        out["elapsed"] = sec
    m = re.search(r"Percent of CPU this job got: (\d+)%", text)
    out["cpuPercent"] = int(m.group(1)) if m else float("nan")
    u = re.search(r"User time \(seconds\): " + FLOAT, text)
    s = re.search(r"System time \(seconds\): " + FLOAT, text)
    out["cpuTime"] = (float(u.group(1)) + float(s.group(1))) if u and s \
        else float("nan")
    return out


def dpiFoamLog(path):
    """DEM performance line, its breakdown, and the solver loop's CPU time
    (ExecutionTime of the last minus the first fluid step: start-up and
    injection excluded)."""
    with open(path) as f:
        text = f.read()
    perf = dpiLog.demPerformance(text)
    if perf is None:
        raise RuntimeError("no DEM performance line in " + path)
    out = {"steps": perf["steps"], "engineRate": perf["rate"],
           "tPair": perf["pair"], "tWall": perf["wall"],
           "tNeighbour": perf["neighbour"], "tIntegrate": perf["integrate"],
           "builds": perf["builds"], "tEngine": perf["engine"]}
    exe = [float(x) for x in
           re.findall(r"^ExecutionTime = " + FLOAT + " s", text, re.M)]
    clk = [float(x) for x in
           re.findall(r"ClockTime = " + FLOAT + " s", text)]
    out["nFluid"] = len(exe)
    out["loopCpu"] = exe[-1] - exe[0] if len(exe) > 1 else float("nan")
    out["loopClock"] = clk[-1] - clk[0] if len(clk) > 1 else float("nan")
    inj = re.findall(r"Injected (\d+) parcels(?: in " + FLOAT + " s)?", text)
    out["injected"] = sum(int(n) for n, _ in inj)
    # The injection's wall-clock time as logged since 2026-12-04 (nan in
    # older logs): the particle lists read at start-up plus the injections
    read = re.findall(r"injectors/\S+: read \d+ particles in " + FLOAT
                      + " s", text)
    out["injectTime"] = sum(float(t) for t in read) \
        + sum(float(t) for _, t in inj) \
        if inj and all(t for _, t in inj) else float("nan")
    lost = re.findall(r"lost through wall (\d+)", text)
    out["lostThroughWalls"] = int(lost[-1]) if lost else 0
    out["parallel"] = bool(re.search(r"^Exec\s*:.*-parallel", text, re.M))
    m = re.search(r"^nProcs\s*:\s*(\d+)", text, re.M)
    out["nProcs"] = int(m.group(1)) if m else 1
    return out


# The log's per-patch counter of a patch parcels leave the domain through:
# the inhaler's exit region (exitEnd, exitSides), or a tube's outlet
OPEN_PATCH = re.compile(r"Patch (outlet|exit\w*): escaped parcels \d+ "
                        r"\(primaries (\d+)\)")


def apiHistory(path):
    """Per fluid step of a dpiFoam log (the cloud's "API primaries" line):
    time, API primaries attached to carriers and detached, primaries out of
    the open patches (OPEN_PATCH: the inhaler's exit region, or an outlet;
    every type, carriers included: the log's counters, summed) and
    primaries of type carrier in the system; and the last ExecutionTime.
    Arrays keyed t, attached, detached, escaped, carriers; "cpu"."""
    rows = []
    now, escNow, carNow = None, 0, 0
    escByPatch = {}
    exe = 0.0
    with open(path) as f:
        for line in f:
            if line.startswith("Time = "):
                now = float(line.split()[2])
            elif "Primaries of type carrier = " in line:
                carNow = int(line.split("=")[1])
            elif "API primaries: attached to carriers" in line:
                m = re.search(r"attached to carriers (\d+), detached (\d+)",
                              line)
                rows.append([now, int(m.group(1)), int(m.group(2)), escNow,
                             carNow])
            elif OPEN_PATCH.search(line):
                m = OPEN_PATCH.search(line)
                escByPatch[m.group(1)] = int(m.group(2))
                escNow = sum(escByPatch.values())
                if rows:
                    rows[-1][3] = escNow
            elif line.startswith("ExecutionTime = "):
                exe = float(line.split()[2])
    if not rows:
        raise RuntimeError("no 'API primaries' line in " + path)
    cols = list(zip(*rows))
    out = {k: np.array(c) for k, c in
           zip(("t", "attached", "detached", "escaped", "carriers"), cols)}
    out["cpu"] = exe
    return out


def demDiagnostics(case):
    """Last row of postProcessing/dpiCloud/demDiagnostics/*/demDiagnostics.dat:
    time KE rotKE nPairContacts nWallContacts maxOverlap/R* nParcels (the
    first row under "first")."""
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing", "dpiCloud", "demDiagnostics", "*",
        "demDiagnostics.dat")))
    rows = []
    for fn in files:
        with open(fn) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    rows.append([float(x) for x in line.split()])
    if not rows:
        raise RuntimeError("no DEM diagnostics in " + case)
    rows.sort(key=lambda r: r[0])
    keys = ("time", "KE", "rotKE", "nPair", "nWall", "maxOverlap", "nParcels")
    out = dict(zip(keys, rows[-1]))
    out["KEfirst"] = rows[0][1]
    out["first"] = dict(zip(keys, rows[0]))
    return out


def liggghtsLog(path):
    """Loop time, steps, atoms and the timing breakdown of a LIGGGHTS run."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"Loop time of " + FLOAT + r" on (\d+) procs for (\d+) "
                  r"steps with (\d+) atoms", text)
    if not m:
        raise RuntimeError("no 'Loop time' in " + path)
    out = {"loop": float(m.group(1)), "procs": int(m.group(2)),
           "steps": int(m.group(3)), "atoms": int(m.group(4))}
    # LIGGGHTS 3.8: "Pair  time (%) = 0.27 (31.4)"; walls and the
    # integrator are in Modify/Other
    for sec in ("Pair", "Neigh", "Comm", "Outpt", "Modify", "Other"):
        mm = re.search(r"^" + sec + r"\s+time \(%\) = " + FLOAT, text, re.M)
        if mm:
            out["t" + sec] = float(mm.group(1))
    # Last thermo row before the loop line: step atoms ke rotational-ke
    head = text[:m.start()].rsplit("Step", 1)
    rows = [ln.split() for ln in head[-1].splitlines()[1:]
            if ln.split() and ln.split()[0].isdigit()] if len(head) > 1 \
        else []
    if rows:
        out["KE"] = float(rows[-1][2])
        out["rotKE"] = float(rows[-1][3])
    mm = re.search(r"Neighbor list builds = (\d+)", text)
    out["builds"] = int(mm.group(1)) if mm else -1
    return out


def memPeaks(path):
    """Peaks [kB] written by common/memsample.py: VmRSS, RssAnon, RssFile,
    RssShmem."""
    out = {}
    with open(path) as f:
        for line in f:
            k, v = line.split()
            out[k] = int(v)
    return out


def gnuTimes(case):
    """GNU time of every process of a run (case/time.0, time.1, ...):
    summed peak RSS [kB], mean CPU [s], number of processes; and the summed
    peak of the anonymous pages [kB] (case/mem.0, ...; NaN without them)."""
    ts = [gnuTime(p)
          for p in sorted(glob.glob(os.path.join(case, "time.[0-9]*")))]
    if not ts:
        return dict(rss=float("nan"), cpu=float("nan"), n=0,
                    anon=float("nan"))
    ms = [memPeaks(p)
          for p in sorted(glob.glob(os.path.join(case, "mem.[0-9]*")))]
    anon = sum(m.get("RssAnon", float("nan")) for m in ms) \
        if len(ms) == len(ts) else float("nan")
    return dict(rss=sum(t["maxRssKB"] for t in ts),
                cpu=sum(t["cpuTime"] for t in ts)/len(ts), n=len(ts),
                anon=anon)


def machineLoad(case):
    """1-min load average in case/log.machine (bench/common/prepare's
    benchMachine), NaN when missing."""
    try:
        with open(os.path.join(case, "log.machine")) as f:
            return float(f.read().split("load average")[1].split()[0])
    except (OSError, IndexError, ValueError):
        return float("nan")


def openfoamLog(path):
    """An icoUncoupledKinematicParcelFoam log: parcels at the first and
    last step, the rate (parcels x steps after the first / ExecutionTime
    last - first: particle-steps per CPU second, the first step with its
    injection excluded), the last linear kinetic energy."""
    with open(path) as f:
        text = f.read()
    exe = [float(x) for x in re.findall(
        r"^ExecutionTime = " + FLOAT + " s", text, re.M)]
    n = [int(x) for x in re.findall(
        r"Current number of parcels\s*=\s*(\d+)", text)]
    ke = re.findall(r"Linear kinetic energy\s*=\s*" + FLOAT, text)
    if len(exe) < 2 or not n:
        raise RuntimeError("no time steps in " + path)
    return dict(n=n[0], nEnd=n[-1], steps=len(exe),
                rate=n[0]*(len(exe) - 1)/(exe[-1] - exe[0]),
                KE=float(ke[-1]) if ke else float("nan"))
