"""Numbers a dpiFoam log reports at its end, read in one place for the
tutorials' scripts (runCost.py) and the benchmarks (bench/common).

The DEM engine ends a run with two lines (demEngine::writePerformance):

    DEM performance: <steps> steps, <rate> particle-steps/s
        pair <s> s (<%> %), wall <s> s (<%> %), neighbour <s> s (<%> %,
        <n> builds, <n> near builds, <n> of <n> listed pairs near on
        average), integrate <s> s (<%> %)[, halo exchange <s> s (not in the
        rate)][, sub-step fluid forces <s> s (not in the rate)]

demPerformance() reads the last such pair of lines term by term, so a term
the engine does not print (no halo in a serial run, no sub-step forces
without a fluid) reads as 0 and a term added later does not break it.

The same timers, so far, at the end of every fluid step are the series
postProcessing/<cloud>/demPerformance/<start>/demPerformance.dat;
demPerformanceSeries() reads one, its columns named as TERMS' keys.
"""
import re

FLOAT = r"([-+0-9.eE]+|nan|inf)"

HEAD = re.compile(r"^DEM performance: (\d+) steps, " + FLOAT
                  + r" particle-steps/s")

# key: (pattern on the second line, group holding the value, type)
TERMS = {
    "pair": (r"\bpair " + FLOAT + r" s", 1, float),
    "wall": (r"\bwall " + FLOAT + r" s", 1, float),
    "neighbour": (r"\bneighbour " + FLOAT + r" s", 1, float),
    "builds": (r"(\d+) builds", 1, int),
    "nearBuilds": (r"(\d+) near builds", 1, int),
    "integrate": (r"\bintegrate " + FLOAT + r" s", 1, float),
    "halo": (r"\bhalo exchange " + FLOAT + r" s", 1, float),
    "subStepGas": (r"\bsub-step fluid forces " + FLOAT + r" s", 1, float),
}

# The terms inside the rate (the engine's own work); halo and sub-step
# forces are printed beside it
ENGINE = ("pair", "wall", "neighbour", "integrate")


def demPerformance(text):
    """The last DEM performance block of a log's text as a dict (steps,
    rate and every term of TERMS), or None if the log has none"""
    lines = text.splitlines()
    found = None
    for i, line in enumerate(lines):
        m = HEAD.match(line)
        if m and i + 1 < len(lines):
            found = (m, lines[i + 1])
    if found is None:
        return None
    m, terms = found
    out = {"steps": int(m.group(1)), "rate": float(m.group(2))}
    for key, (pat, group, kind) in TERMS.items():
        t = re.search(pat, terms)
        out[key] = kind(t.group(group)) if t else kind(0)
    out["engine"] = sum(out[k] for k in ENGINE)
    return out


# The series' column names (its header) as TERMS' keys
SERIES_NAMES = {"subSteps": "steps", "haloExchange": "halo",
                "subStepFluidForces": "subStepGas", "searches": "builds"}


def demPerformanceSeries(path):
    """A demPerformance.dat as a dict of columns (lists of floats) keyed as
    TERMS (plus "time" and "steps"), from the names of its last header
    line; columns are empty if it has no row yet"""
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                names = line[1:].split()
            elif line.strip():
                rows.append([float(v) for v in line.split()])
    if names is None:
        raise ValueError("%s: no header line" % path)
    keys = [SERIES_NAMES.get(n, n) for n in names]
    return {k: [r[i] for r in rows] for i, k in enumerate(keys)}
