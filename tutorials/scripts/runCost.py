#!/usr/bin/python3
"""Where a run's time went: a table per dpiFoam log, from the lines dpiFoam
prints at its end.

    runCost.py log.dpiFoam.sedimentation log.dpiFoam.inhalation
               [--tools log.blockMesh log.decomposePar.* ...] [--output cost.txt]

Per dpiFoam log (wall-clock seconds of the master process, as dpiFoam's
"Cost" line gives them): start-up (mesh, gas, cloud, injection), the gas
solve, the cloud's fluid steps and, inside those, the DEM engine's terms
(its "DEM performance" lines: pair, wall, neighbour, integrate, halo
exchange, sub-step gas forces) and the rest of the cloud (tracking through
the mesh, agglomerates, the coupling's sources), then the rest of the time
loop (writing, function objects) and the total. The tools' logs (OpenFOAM
utilities: blockMesh, decomposePar, reconstructPar, foamToVTK) add their
ClockTime. A log without a Cost line (a run stopped, then resumed from its
last write: Allrun -resume) gives a row "(stopped)" with its last ClockTime
and the DEM terms of its last fluid step from the case's
postProcessing/<cloud>/demPerformance/<its start time>/demPerformance.dat
(the start-up, gas and the rest are not known for it). Prints the table and
writes it to --output.
"""
import argparse
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dpiLog  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("logs", nargs="+", help="dpiFoam logs, one per stage")
ap.add_argument("--tools", nargs="*", default=[],
                help="logs of OpenFOAM utilities (their ClockTime is added)")
ap.add_argument("--output", help="also write the table here")
a = ap.parse_args()

NUM = r"([-+0-9.eE]+)"
COST = re.compile(r"^Cost \(wall-clock s, this process\): start-up " + NUM +
                  r", gas " + NUM + r", cloud " + NUM +
                  r", the rest \(writing, function objects\) " + NUM +
                  r", total " + NUM)
CLOCK = re.compile(r"ClockTime = " + NUM)


START = re.compile(r"^Create mesh for time = (\S+)", re.M)
DEM_TERMS = ("pair", "wall", "neighbour", "integrate", "halo", "subStepGas")


def stoppedDem(path, text):
    """The DEM terms of a stopped run: the last row of the demPerformance
    series its start wrote, or nothing if there is none"""
    start = START.findall(text)
    if not start:
        return {}
    case = os.path.dirname(os.path.abspath(path))
    found = glob.glob(os.path.join(case, "postProcessing", "*",
                                   "demPerformance", start[0],
                                   "demPerformance.dat"))
    if len(found) != 1:
        return {}
    series = dpiLog.demPerformanceSeries(found[0])
    if not series["time"]:
        return {}
    return {k: series[k][-1] for k in DEM_TERMS}


def stage(path):
    """The cost of one dpiFoam log, or exit with the reason"""
    try:
        text = open(path, errors="replace").read()
    except OSError as e:
        sys.exit("runCost.py: cannot read %s: %s" % (path, e))
    cost = None
    for line in text.splitlines():
        m = COST.match(line)
        if m:
            cost = [float(x) for x in m.groups()]
    perf = dpiLog.demPerformance(text) or {}
    dem = {k: perf.get(k, 0.0) for k in DEM_TERMS}
    if cost is None:
        # A run that was stopped (then resumed from its last write): only
        # its wall time up to its last fluid step is known
        clocks = CLOCK.findall(text)
        if not clocks:
            sys.exit("runCost.py: no 'Cost' line and no ClockTime in %s"
                     % path)
        row = dict(total=float(clocks[-1]), stopped=True)
        row.update(stoppedDem(path, text))
        return row
    startUp, gas, cloud, rest, total = cost
    engine = sum(dem.values())
    row = dict(startUp=startUp, gas=gas, cloud=cloud, rest=rest,
               total=total, cloudOther=cloud - engine)
    row.update(dem)
    return row


def clock(path):
    """The last ClockTime of an OpenFOAM utility's log (0 if none)"""
    try:
        text = open(path, errors="replace").read()
    except OSError:
        return 0.0
    got = CLOCK.findall(text)
    return float(got[-1]) if got else 0.0


cols = [("total", "total"), ("startUp", "start-up"), ("gas", "gas"),
        ("pair", "DEM pair"), ("wall", "DEM wall"),
        ("neighbour", "DEM neighbour"), ("integrate", "DEM integrate"),
        ("halo", "DEM halo"), ("subStepGas", "sub-step gas forces"),
        ("cloudOther", "rest of cloud"), ("rest", "writing, function objects")]

out = ["Where the time went (wall-clock s of the master process; dpiFoam's "
       "'Cost' and 'DEM performance' lines)", ""]
head = "| run | " + " | ".join(label for _, label in cols) + " |"
out += [head, "|---" + "|---:"*len(cols) + "|"]
sumTotal = 0.0
for path in a.logs:
    r = stage(path)
    sumTotal += r["total"]
    name = path.split("/")[-1]
    name = name[len("log.dpiFoam."):] if name.startswith("log.dpiFoam.") \
        else name
    if r.get("stopped"):
        out.append("| %s (stopped) | %.4g | " % (name, r["total"])
                   + " | ".join("%.4g" % r[k] if k in r else "-"
                                for k, _ in cols[1:]) + " |")
        continue
    out.append("| %s | " % name + " | ".join(
        "%.4g (%.0f %%)" % (r.get(k, 0.0), 100*r.get(k, 0.0)/r["total"])
        if k != "total" and r["total"] > 0 else "%.4g" % r.get(k, 0.0)
        for k, _ in cols) + " |")
tools = sum(clock(p) for p in a.tools)
out += ["", "dpiFoam runs: %.4g s; OpenFOAM utilities (%d logs): %.4g s; "
        "together %.4g s = %.2f h" % (sumTotal, len(a.tools), tools,
                                     sumTotal + tools,
                                     (sumTotal + tools)/3600)]
text = "\n".join(out)
print(text)
if a.output:
    with open(a.output, "w") as f:
        f.write(text + "\n")
