#!/usr/bin/python3
"""Momentum balance of gas plus parcels in the periodic box (run by ./run in
its run folder): per fluid step, P_n - P_(n-1) = M g dt, where
P = sum(rho alpha U V) over the cells + sum(N m v) over the parcels and M
the total mass.

check.py --compare A B TOL: instead, the gas of runs A and B (U.air,
alpha.air and the cloud's UTrans at A's last time) must agree to TOL
relative to A's largest value (serial against parallel)."""
import glob
import os
import re
import sys
import numpy as np

RHO = 1.2                       # gas density [kg/m^3]
V = (0.8e-3/4)**3               # cell volume of the uniform mesh [m^3]
G = np.array([0.0, 0.0, -9.81])
# Tolerances per step: of the parcels' initial momentum P0 (1e-6, required)
# and of the momentum exchanged in the step (from the command line; the run
# script loosens the second for the unconverged 2-corrector variant)
COMPARE = len(sys.argv) > 1 and sys.argv[1] == "--compare"
TOL = float(sys.argv[1]) if len(sys.argv) > 1 and not COMPARE else 1e-6
TOLX = float(sys.argv[2]) if len(sys.argv) > 2 and not COMPARE else 1e-6
NUM = r"[-+0-9.eE]+"


def body(path):
    txt = open(path).read()
    return txt[txt.index("}", txt.index("FoamFile")) + 1:]


def vectors(txt):
    return np.array([[float(a) for a in v] for v in
                     re.findall(r"\(\s*(%s)\s+(%s)\s+(%s)\s*\)" % (NUM, NUM, NUM),
                                txt)])


def internalVectors(path):
    txt = body(path)
    txt = txt[txt.index("internalField"):txt.index("boundaryField")]
    m = re.search(r"uniform\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", txt)
    if m and "nonuniform" not in txt:
        return np.array([[float(x) for x in m.groups()]]*64)
    return vectors(txt[txt.index("("):])


def internalScalars(path):
    txt = body(path)
    txt = txt[txt.index("internalField"):txt.index("boundaryField")]
    if "nonuniform" not in txt:
        return np.full(64, float(re.search(r"uniform\s+(\S+)", txt).group(1)))
    n = int(re.search(r"List<scalar>\s*(\d+)", txt).group(1))
    vals = txt[txt.index("(") + 1:txt.rindex(")")].split()
    assert len(vals) == n
    return np.array([float(v) for v in vals])


def dimensionedVectors(path):
    """The value list of a DimensionedField (the cloud's UTrans)"""
    txt = body(path)
    txt = txt[txt.index("value"):]
    return vectors(txt[txt.index("("):])


def compare(a, b, tol):
    """Gas of runs a and b at a's last time; the number of fields off"""
    t = max((d for d in os.listdir(a) if re.fullmatch(r"[0-9.e+-]+", d)
             and d != "0"), key=float)
    bad = 0
    for f, read in (("U.air", internalVectors), ("alpha.air", internalScalars),
                    ("dpiCloud:UTrans", dimensionedVectors)):
        x, y = read(os.path.join(a, t, f)), read(os.path.join(b, t, f))
        err = np.abs(x - y).max()/np.abs(x).max()
        print("t = %s: %s max |%s - %s|/max|%s| = %.2e (tolerance %g)"
              % (t, f, a, b, a, err, tol))
        bad += not err <= tol
    return bad


def cloudScalars(path):
    txt = body(path)
    m = re.search(r"(\d+)\s*\{\s*(\S+)\s*\}", txt)
    if m:
        return np.full(int(m.group(1)), float(m.group(2)))
    txt = txt[txt.index("(") + 1:txt.rindex(")")]
    return np.array([float(v) for v in txt.split()])


def state(t):
    U = internalVectors(t + "/U.air")
    alpha = internalScalars(t + "/alpha.air")
    gasP = RHO*V*(alpha[:, None]*U).sum(axis=0)
    gasM = RHO*V*alpha.sum()
    c = t + "/lagrangian/dpiCloud/"
    v = vectors(body(c + "U"))
    N = cloudScalars(c + "nParticle")
    d = cloudScalars(c + "d")
    rho = cloudScalars(c + "rho")
    m = N*rho*np.pi/6*d**3
    return gasP, gasM, (m[:, None]*v).sum(axis=0), m.sum()


if COMPARE:
    sys.exit(1 if compare(sys.argv[2], sys.argv[3], float(sys.argv[4])) else 0)

times = sorted((d for d in glob.glob("[0-9]*") if d != "0" and os.path.isdir(d)),
               key=float)
exchanged = []
for line in open("log.dpiFoam"):
    m = re.search(r"Fluid coupling: momentum to the gas \((\S+) (\S+) (\S+)\)", line)
    if m:
        exchanged.append(np.array([float(x) for x in m.groups()]))

prev = None
P0 = None
worst = 0.0
worstX = 0.0
for i, t in enumerate(times):
    gP, gM, pP, pM = state(t)
    P = gP + pP
    if P0 is None:
        P0 = pP
    if prev is not None:
        dt = float(t) - float(prev[0])
        err = P - prev[1] - (gM + pM)*G*dt
        rel = np.abs(err).max()/np.abs(P0).max()
        relX = np.abs(err).max()/np.abs(exchanged[i]).max()
        worst = max(worst, rel)
        worstX = max(worstX, relX)
        print("t = %-8s gas %s parcels %s  error %.2e of P0, %.2e of the "
              "exchange" % (t, gP, pP, rel, relX))
    prev = (t, P)

fails = []
total = np.abs(np.sum(exchanged, axis=0)).max()
print("initial parcel momentum P0 = %s kg m/s, given to the gas (impulse of the"
      " parcel forces, from the log) %.3e kg m/s" % (P0, total))
if not total > 0.05*np.abs(P0).max():
    fails.append("the parcels gave the gas less than 5 %% of their momentum"
                 " (%.2e of %.2e): the test does not exercise the exchange"
                 % (total, np.abs(P0).max()))
if worst > TOL:
    fails.append("momentum balance per step %.2e of P0 > %g" % (worst, TOL))
if worstX > TOLX:
    fails.append("momentum balance per step %.2e of the exchange > %g"
                 % (worstX, TOLX))
print("%s: worst momentum balance per step %.2e of the parcels' initial "
      "momentum (tolerance %g), %.2e of the momentum exchanged in that step "
      "(tolerance %g)" % ("FAIL" if fails else "ok", worst, TOL, worstX, TOLX))
for f in fails:
    print("FAIL: " + f)
sys.exit(1 if fails else 0)
