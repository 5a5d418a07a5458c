#!/usr/bin/python3
"""Checks of an impact recorded by a dpiFoam trace (postProcessing/*/trace).

impactCheck.py impact RUN --parcel 0 --axis y [--e E --e-tol T]
               [--tc TC --fmax F --rel-tol R]
    Restitution (normal velocity after / before, along the axis; for a pair
    give --pair 1 and the relative velocity is used), contact time (first
    to last sub-step with a non-zero force) and peak force magnitude.
impactCheck.py invariance RUN_A RUN_B --parcels 0 [1] --ratio 100
    Positions and velocities equal (relative 1e-12), forces in the ratio
    (relative 1e-9 of the peak force).
Exit status 0 when every check passes; each check prints one line.
"""
import argparse
import glob
import os
import sys

import numpy as np

AX = {"x": 0, "y": 1, "z": 2}
failures = []


def trace(run, pid):
    files = sorted(glob.glob(os.path.join(
        run, "postProcessing", "*", "trace", "*", "parcel%d.dat" % pid)))
    if not files:
        sys.exit("FAIL: no trace of parcel %d in %s" % (pid, run))
    return np.vstack([np.loadtxt(f, ndmin=2) for f in files])


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def impact(a):
    c = AX[a.axis]
    t1 = trace(a.run, a.parcel)
    v = t1[:, 4 + c]
    f = t1[:, 7:10]
    if a.pair is not None:
        t2 = trace(a.run, a.pair)
        v = v - t2[:, 4 + c]
    fm = np.linalg.norm(f, axis=1)
    on = np.nonzero(fm > 0)[0]
    if len(on) == 0:
        check(False, "no contact recorded")
        return
    i0, i1 = on[0], on[-1]
    v0, v1 = v[max(i0 - 1, 0)], v[-1]
    e = -v1/v0
    dt = t1[1, 0] - t1[0, 0]
    # The force is sampled at the end of each sub-step: the contact lasts
    # from before the first non-zero sample to after the last one, so the
    # estimate (i1 - i0 + 1) dt is within one step of the true time.
    tc = (i1 - i0 + 1)*dt
    fmax = fm.max()
    if a.e is not None:
        check(abs(e - a.e) <= a.e_tol,
              "restitution %.6f, expected %.4f +- %g" % (e, a.e, a.e_tol))
    if a.tc is not None:
        err = abs(tc - a.tc)/a.tc
        check(err <= a.rel_tol + dt/a.tc,
              "contact time %.5g s, expected %.5g s (error %.3g %%, "
              "allowed %.3g %% + one step)" % (tc, a.tc, 100*err, 100*a.rel_tol))
    if a.fmax is not None:
        err = abs(fmax - a.fmax)/a.fmax
        check(err <= a.rel_tol,
              "peak force %.5g N, expected %.5g N (error %.3g %%)"
              % (fmax, a.fmax, 100*err))


def invariance(a):
    for p in a.parcels:
        A, B = trace(a.run_a, p), trace(a.run_b, p)
        n = min(len(A), len(B))
        A, B = A[:n], B[:n]
        x_scale = np.abs(A[:, 1:4]).max()
        v_scale = max(np.abs(A[:, 4:7]).max(), 1e-300)
        dx = np.abs(A[:, 1:4] - B[:, 1:4]).max()/x_scale
        dv = np.abs(A[:, 4:7] - B[:, 4:7]).max()/v_scale
        fpeak = max(np.abs(A[:, 7:10]).max(), 1e-300)
        df = np.abs(a.ratio*A[:, 7:10] - B[:, 7:10]).max()/(a.ratio*fpeak)
        # N f/(N m) and f/m round differently: trajectories agree to
        # round-off accumulated over the steps, far below 1e-12 here
        check(dx <= 1e-12 and dv <= 1e-12,
              "parcel %d: positions equal to %.2g, velocities to %.2g "
              "(relative, limit 1e-12)" % (p, dx, dv))
        check(df <= 1e-9,
              "parcel %d: forces in ratio %g to %.2g of the peak (limit 1e-9)"
              % (p, a.ratio, df))
        check(fpeak > 0, "parcel %d: a contact force was recorded" % p)


ap = argparse.ArgumentParser()
sub = ap.add_subparsers(dest="cmd", required=True)
p1 = sub.add_parser("impact")
p1.add_argument("run")
p1.add_argument("--parcel", type=int, default=0)
p1.add_argument("--pair", type=int, default=None)
p1.add_argument("--axis", default="y")
p1.add_argument("--e", type=float)
p1.add_argument("--e-tol", type=float, default=1e-3)
p1.add_argument("--tc", type=float)
p1.add_argument("--fmax", type=float)
p1.add_argument("--rel-tol", type=float, default=5e-3)
p2 = sub.add_parser("invariance")
p2.add_argument("run_a")
p2.add_argument("run_b")
p2.add_argument("--parcels", type=int, nargs="+", default=[0])
p2.add_argument("--ratio", type=float, default=100)
a = ap.parse_args()
impact(a) if a.cmd == "impact" else invariance(a)
sys.exit(1 if failures else 0)
