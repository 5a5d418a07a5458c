#!/usr/bin/python3
"""Checks of the freeFlight case test (run by ./run in its run folder).

usage: check.py RUNDIR SCRIPTSDIR
"""
import re
import sys
import numpy as np

top = sys.argv[1]
sys.path.insert(0, sys.argv[2])
import foamLagrangian as fl  # noqa: E402

failed = []


def check(ok, msg):
    print(("ok: " if ok else "FAIL: ") + msg)
    if not ok:
        failed.append(msg)


# The case's numbers (constant/dpiCloudProperties, transportProperties, g)
rhop, d, D = 1520.0, 5e-6, 70e-6
rhof, nuf = 1.2, 1.511e-5
g = np.array([0, 0, -9.81])
dt = 1e-8                               # DEM time step; refreshInterval K = 10
E, nu, e = 5e8, 0.35, 0.85
ma = rhop*np.pi/6*d**3
mc = rhop*np.pi/6*D**3
tau = rhop*d**2/(18*rhof*nuf)          # Stokes relaxation time, 1.164e-4 s
Es = E/(2*(1 - nu**2))                  # E* of two equal materials
cutoff = (D + d)/2                      # carrier-API contact distance


def traces(run):
    return {i: np.loadtxt("%s/%s/postProcessing/dpiCloud/trace/0/parcel%d.dat"
                          % (top, run, i)) for i in range(11)}


def accel(v):
    """The model's acceleration in still air: Wen-Yu drag (wenYuParcel at a
    void fraction of 1; the carrier takes 7.6e-5 of its cell, which moves
    the drag by 2e-4 at most) and gravity (no pressure-gradient force)."""
    Re = d*np.linalg.norm(v)/nuf
    return g - v/tau*(1 + 0.15*Re**0.687)


def rk4Step(f, y, h):
    """One classical Runge-Kutta step of y' = f(y)."""
    k1 = f(y)
    k2 = f(y + h/2*k1)
    k3 = f(y + h/2*k2)
    k4 = f(y + h*k3)
    return y + h/6*(k1 + 2*k2 + 2*k3 + k4)


def rk4(x0, v0, n, h):
    """The model's equation of motion, RK4 at step h/4, sampled every h."""
    y = np.r_[x0, v0].astype(float)
    out = np.empty((n, 6))

    def f(y):
        return np.r_[y[3:], accel(y[3:])]
    for k in range(n):
        for _ in range(4):
            y = rk4Step(f, y, h/4)
        out[k] = y
    return out


def hertzImpact(ms, Rs, v0):
    """The normal contact law's binary impact (hertzParcel at N = 1: Hertz
    spring and the damping that makes the restitution e), integrated
    finely: its largest overlap and its restitution."""
    beta = np.log(e)/np.sqrt(np.log(e)**2 + np.pi**2)

    def a(y):
        dlt, v = y
        if dlt <= 0:
            return np.array([v, 0.0])
        Sn = 2*Es*np.sqrt(Rs*dlt)
        F = 4/3*Es*np.sqrt(Rs)*dlt**1.5 - 2*np.sqrt(5/6)*beta*np.sqrt(Sn*ms)*v
        return np.array([v, -F/ms])
    tc = 3.2*(ms**2/(Rs*Es**2*v0))**0.2     # above the Hertz contact time
    h = tc/20000
    y = np.array([0.0, v0])
    dmax = 0
    while True:
        y = rk4Step(a, y, h)
        dmax = max(dmax, y[0])
        if y[0] < 0:
            return dmax, -y[1]/v0


A = traces("A")
n = len(A[1])
t = A[1][:, 0]
check(n == 20000 and abs(t[0] - dt) < 1e-15 and abs(t[-1] - 2e-4) < 1e-12,
      "A: traces at every sub-step, %d rows from t = %g to %g s" % (n, t[0], t[-1]))

# 1. Free flight: parcel 1, 1 mm from everything. Against the model's own
# equation of motion: the sub-stepped drag is first order in dt/tau =
# 8.6e-5 per sub-step (half kicks with the coefficient held) and its
# linearisation refreshed every K = 10 sub-steps lags the Re correction by
# K dt/tau x 0.687 x 0.15 Re^0.687 ~ 4e-5: 3 dt/tau = 2.6e-4 bounds both.
# Against the closed-form Stokes trajectory (linear drag) the bound is the
# Wen-Yu Re correction at the start, 0.15 Re0^0.687.
x0, v0 = np.array([1e-3, 1e-3, 3e-3]), np.array([0.2, 0.1, -0.15])
ref = rk4(x0, v0, n, dt)
travel = np.linalg.norm(ref[-1, :3] - x0)
ex = np.abs(A[1][:, 1:4] - ref[:, :3]).max()/travel
ev = np.abs(A[1][:, 4:7] - ref[:, 3:]).max()/np.linalg.norm(v0)
tol = 3*dt/tau
check(ex < tol and ev < tol,
      "free flight against the model's equation of motion: max |dx|/travel "
      "%.1e, max |dv|/|v0| %.1e (bound 3 dt/tau = %.1e; travel %.1f um)"
      % (ex, ev, tol, 1e6*travel))
vt = g*tau
xs = x0 + np.outer(1 - np.exp(-t/tau), tau*(v0 - vt)) + np.outer(t, vt)
Re0 = d*np.linalg.norm(v0)/nuf
bound = 0.15*Re0**0.687
es = np.abs(A[1][:, 1:4] - xs).max()/travel
check(es < bound,
      "free flight against the closed-form Stokes trajectory: max |dx|/travel "
      "%.2e (bound: the Wen-Yu correction at Re0 = %.3f, %.2e)"
      % (es, Re0, bound))

# 2. Impacts: parcels 2-7 at the carrier (0), 9 and 10 at the floor and the
# wall x = 4 mm. Before the contact each flies as in 1 (its start checked
# against the equation of motion up to the step before it touches; the
# carrier's cell makes the bound 2e-4 larger). Caught in time: its largest
# overlap within [0.97, 1.01] of the contact law's for the approach speed
# (sampled at >= 14 sub-steps per contact, the peak of a half-sine is read
# within 2.5 %; a contact caught a sub-step late would overshoot by
# v dt/delta ~ 20 %), one contact only, and the law's restitution within
# 0.01 (the approach and rebound speeds are read at the sub-steps before and
# after the contact, which begins and ends inside a sub-step: about a
# fifteenth of a sub-step's impulse either side).


def impact(name, gap, vn, ms, Rs, traj):
    inside = np.nonzero(gap < 0)[0]
    if len(inside) == 0:
        check(False, "%s: no contact (closest gap %.3e m)" % (name, gap.min()))
        return None
    k0, k1 = inside[0], inside[-1]
    one = k1 - k0 + 1 == len(inside)
    vin, vout = vn[k0 - 1], vn[k1 + 1]
    dmax, eLaw = hertzImpact(ms, Rs, -vin)
    ratio = -gap[k0:k1 + 1].min()/dmax
    # from its first traced state (t = dt) to the sub-step before contact
    ref = rk4(traj[0, 1:4], traj[0, 4:7], k0 - 1, dt)
    travel = np.linalg.norm(ref[-1, :3] - traj[0, 1:4])
    ef = np.abs(traj[1:k0, 1:4] - ref[:, :3]).max()/travel
    check(one and 0.97 < ratio < 1.01 and abs(-vout/vin - eLaw) < 0.01
          and ef < tol + 2e-4,
          "%s: touches at t = %.2f us after %.1f um of free flight (its path "
          "to it %.1e from the equation of motion), at %.4f m/s; one contact "
          "of %d sub-steps, largest overlap %.4f of the law's %.3e m, "
          "restitution %.4f (law %.4f)"
          % (name, 1e6*t[k0], 1e6*travel, ef, -vin, k1 - k0 + 1, ratio, dmax,
             -vout/vin, eLaw))
    return k0


def impacts(T, run):
    """Each impactor's contact of run T (section 2's checks): API 2-7 on the
    carrier, 9 on the floor, 10 on the wall x = 4 mm; its first sub-step."""
    k = {}
    for i in range(2, 8):
        r = T[i][:, 1:4] - T[0][:, 1:4]
        dist = np.linalg.norm(r, axis=1)
        vn = np.sum((T[i][:, 4:7] - T[0][:, 4:7])*r, axis=1)/dist
        k[i] = impact("%sAPI %d -> carrier" % (run, i), dist - cutoff, vn,
                      ma*mc/(ma + mc), D*d/(2*(D + d)), T[i])
    k[9] = impact("%sAPI 9 -> floor" % run, T[9][:, 3] - d/2, T[9][:, 6],
                  ma, d/2, T[9])
    k[10] = impact("%sAPI 10 -> wall" % run, 4e-3 - T[10][:, 1] - d/2,
                   -T[10][:, 4], ma, d/2, T[10])
    return k


contact = impacts(A, "")

# 3. The passing parcel (8): aimed 2 um wide of contact (1.999 um: its
# offsets rounded to the 6 digits foamDictionary writes back). It must come no
# closer than the aim less what gravity and the carrier's recoils move
# (< 0.1 um here) and never touch.
gap8 = np.linalg.norm(A[8][:, 1:4] - A[0][:, 1:4], axis=1) - cutoff
check(1.9e-6 < gap8.min() < 2.1e-6,
      "API 8 passes the carrier untouched: closest gap %.3f um (aimed 2 um)"
      % (1e6*gap8.min()))

# 4. The reference scheme (R: the force models at every sub-step). It
# must catch every contact as A does: the same checks as in 2, the contact
# starting at the same sub-step. Their free flights differ by the lag of
# the refreshed linearisation: the Re correction (0.15 Re^0.687 <= 0.03 of
# the drag) held over K dt = 10 sub-steps, in which |v| changes by K
# dt/tau = 8.6e-4: 0.687 x 0.03 x 8.6e-4 = 1.8e-5 of the drag, so of the
# speed (bound 1e-4). In a contact the two part: a few picometres of
# position are a per cent of its 5 nm overlap, and the contact may end a
# sub-step apart (checked through the restitution above, not row by row).
R = traces("R")
contactR = impacts(R, "R: ")
sameStart = all(k is not None and contactR[i] == k for i, k in contact.items())
worst = 0.0
for i in range(1, 11):
    k = contact.get(i) or n
    worst = max(worst, np.abs(A[i][:k, 4:7] - R[i][:k, 4:7]).max()
                / np.linalg.norm(A[i][0, 4:7]))
check(sameStart and worst < 1e-4,
      "refreshInterval 10 against 1 (the reference): every contact starts "
      "at the same sub-step; in free flight max |dv| %.1e of the start "
      "speed (bound 1e-4: the lagged Re correction)" % worst)


# 5. Serial against 3 and 4 processes, the state at the end by globalId.
# The DEM itself is the same bit for bit in parallel (tests/cases/
# parallelDEM); here the still gas differs: its velocity is round-off of
# the solver (|U| = Co dx/dt, Co from the log), different in every
# decomposition, and the drag passes it on: the parcels' velocities differ
# by at most the two gases' difference (twice the larger gas speed), which
# a contact reflects, at most doubling it (1 + e < 2). Bound: 4 x the
# larger gas speed; spins pick it up through a contact's slip, divided by
# the API radius.
def gasSpeed(run):
    co = [float(m.group(1)) for m in
          re.finditer(r"Courant Number max: (\S+)",
                      open("%s/%s/log.dpiFoam" % (top, run)).read())]
    return max(co)*(4e-3/3)/1e-5


def state(run):
    base = "%s/%s/0.0002/lagrangian/dpiCloud/" % (top, run)
    gid = fl.read_field(base + "globalId").astype(int)
    o = np.argsort(gid)
    return gid[o], fl.read_field(base + "U")[o], fl.read_field(base + "omega")[o]


gA, UA, wA = state("A")
for run in ["P3", "P4"]:
    gP, UP, wP = state(run)
    b = 4*max(gasSpeed("A"), gasSpeed(run))
    dU = np.abs(UP - UA).max() if len(gP) == len(gA) else np.inf
    dw = np.abs(wP - wA).max() if len(gP) == len(gA) else np.inf
    check(np.array_equal(gP, gA) and dU <= b and dw <= b/(d/2),
          "%s: the same 11 parcels as serial; max |dU| %.1e m/s (bound %.1e: "
          "the gas's round-off speed), max |d omega| %.1e rad/s (bound %.1e)"
          % (run, dU, b, dw, b/(d/2)))
    log = open("%s/%s/log.dpiFoam" % (top, run)).read()
    m = re.findall(r"DEM halo: .* (\d+) builds so far, (\d+) of them within", log)
    check(len(m) > 0 and int(m[-1][1]) > 0,
          "%s: the halo was built within fluid steps (%s of %s builds): the "
          "fast API outran one skin per fluid step"
          % (run, m[-1][1] if m else "?", m[-1][0] if m else "?"))

sys.exit(1 if failed else 0)
