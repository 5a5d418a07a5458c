#!/usr/bin/python3
"""Checks of the turbulentDispersion case test (run by ./run)."""
import re
import sys
import numpy as np

failed = []
T = "6e-05"


def check(ok, msg):
    print(("ok: " if ok else "FAIL: ") + msg)
    if not ok:
        failed.append(msg)


def field(case, name, t=T):
    txt = open("%s/%s/lagrangian/dpiCloud/%s" % (case, t, name)).read()
    body = txt[txt.index("// * *"):]
    vec = re.findall(r"\(([-0-9.eE+]+ [-0-9.eE+]+ [-0-9.eE+]+)\)", body)
    if vec:
        return np.array([[float(x) for x in v.split()] for v in vec])
    m = re.search(r"\n(\d+)\s*\(([^)]*)\)", body) or re.search(r"(\d+)\(([^)]*)\)", body)
    return np.array([float(x) for x in m.group(2).split()])


def byId(case, name):
    ids = field(case, "globalId").astype(int)
    return field(case, name)[np.argsort(ids)], np.sort(ids)


u, ids = byId("les", "UTurb")
check(len(ids) == 100, "100 parcels at %s" % T)
rms = np.sqrt(np.mean(u**2))
kmax = max(float(x) for x in re.findall(r"max k ([0-9.eE+-]+)", open("les/log.dpiFoam").read()))
check(np.all(np.isfinite(u)) and rms > 0,
      "u* written (UTurb), rms %.4g m/s per component" % rms)
# Per component u* ~ N(0, 2k/3) at most (k <= kmax): the largest |u*| of
# 300 samples stays below 5 standard deviations of the largest k
check(np.abs(u).max() < 5*np.sqrt(2*kmax/3),
      "max |u*_i| %.4g m/s < 5 sqrt(2 k_max/3) = %.4g m/s"
      % (np.abs(u).max(), 5*np.sqrt(2*kmax/3)))

for case, tol, what in [("restart", 1e-12, "restart 2 + 4 steps"),
                        ("parallel", 1e-10, "mpirun -np 2")]:
    for name in ("UTurb", "U", "xDEM"):
        a, ia = byId("les", name)
        b, ib = byId(case, name)
        same = len(ia) == len(ib) and np.all(ia == ib)
        err = np.abs(a - b).max()/np.abs(a).max() if same else np.inf
        check(same and err <= tol, "%s: %s equal to the straight serial run "
              "(max relative difference %.2g, limit %.0e)" % (what, name, err, tol))

uw, _ = byId("wale1", "UTurb")
check(np.all(np.isfinite(uw)) and np.sqrt(np.mean(uw**2)) > 0,
      "default (WALE, agglomerate): u* written, rms %.4g m/s (Smagorinsky's "
      "%.4g)" % (np.sqrt(np.mean(uw**2)), rms))
for name in ("UTurb", "U", "xDEM"):
    a, ia = byId("wale1", name)
    b, ib = byId("wale2", name)
    same = len(ia) == len(ib) and np.all(ia == ib)
    err = np.abs(a - b).max()/max(np.abs(a).max(), 1e-300) if same else np.inf
    check(same and err <= 1e-10, "default, 2 processes: %s equal to serial "
          "(max relative difference %.2g, limit 1e-10)" % (name, err))

us, _ = byId("substep", "UTurb")
r = np.mean(us**2)/np.mean(u**2)
# two independent samples of 300: each sample variance has a relative
# standard error sqrt(2/300), their ratio sqrt(2) times that; 4 sigma
tol = 4*np.sqrt(2)*np.sqrt(2/300)
check(abs(r - 1) < tol, "subStep: variance of u* / held's = %.3f (limit 1 +- %.2f)"
      % (r, tol))
check(np.abs(us - u).max() > 0, "subStep draws its own numbers (u* differs from held)")

ul, _ = byId("legacy", "UTurb")
rmsl = np.sqrt(np.mean(ul**2))
check(rmsl < 0.05*rms, "legacyTimeScale: rms u* %.3g m/s, %.2g of the default's "
      "(tau* |S| ~ 1e4-1e5 times longer)" % (rmsl, rmsl/rms))

# the inlet follows the table: 2 + 2 t/1e-4 m/s
txt = open("ras/%s/U.air" % T).read()
inlet = txt[txt.index("inlet"):]
m = re.search(r"value\s+uniform\s+\(([-0-9.eE+]+)", inlet)
check(m is not None and abs(float(m.group(1)) - 3.2) < 1e-12,
      "RAS run: inlet U at t = %s is %s m/s (table: 3.2)" % (T, m.group(1) if m else "?"))
txt = open("les/%s/nut.air" % T).read()
body = txt[txt.index("internalField"):txt.index("boundaryField")]
nut = [float(x) for x in body[body.index("(") + 1:body.index(")")].split()] if "(" in body else []
check(len(nut) > 0 and max(nut) > 0, "LES: nut.air written, max %.3g m2/s" % max(nut or [0]))

sys.exit(1 if failed else 0)
