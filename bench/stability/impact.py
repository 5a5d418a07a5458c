#!/usr/bin/python3
"""Single Hertz impacts for the stability benchmark (bench/stability).

One case = one impact, no gravity, no cohesion, head-on along -z:
  wall kinds   API-wall, carrier-wall: one particle onto the plane z = 0
  pair kind    carrier-API: an API parcel of N primaries onto a free carrier
               at rest (the carrier recoils with N times the primary force)
Every material (particles and wall) has the same Young's modulus Y,
nu 0.35, density 1520, e 0.85, mu 0.45, no rolling friction.

Subcommands:
  write DIR --kind K --N N --Y Y --v V --dt DT [--allow-unstable]
            [--cohesion] --mesh M
      writes a dpiFoam case (M: a constant/polyMesh to copy), with
      timeStepCheck maxImpactVelocity V and trace of every parcel;
      --cohesion (carrier-API only): vdwGuParcel with Case 6's A = 1e-19 J
      and the stiffness scaling of Y: chi = (9e9/Y)^0.4 (at least 1),
      sMin 1 nm, sMins 6.227 nm, s0 = sMins - sMin sqrt(chi) (continuity,
      theory 3.3; 4.445 nm at Y = 5e8 as the decks)
  analyse DIR...  prints one CSV row per case (see COLUMNS)
  th --kind K --N N --Y Y --v V   prints the elastic Hertz time t_H [s]
      with the dynamic reduced mass (as the start-up check computes it)

The reference is the same contact law integrated in Python with RK4 at
t_H/20000 (theory 1.3, 2.4: inertia m_dyn, damping with the primary m*):
for m_dyn = m* it gives the closed form of theory 8.1 (e = 0.85 exactly,
F_max = 0.91407 F_max,el).
"""
import argparse
import math
import os
import shutil
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
import settlingScene as ss  # noqa: E402

RHO = 1520.0
NU = 0.35
E_REST = 0.85
MU = 0.45
D = {"API": 5e-6, "carrier": 70e-6}
BETA = math.log(E_REST)/math.sqrt(math.log(E_REST)**2 + math.pi**2)

COLUMNS = ["kind", "cohesion", "N", "Y", "v", "dt", "allowUnstable", "tH", "dt_over_tH",
           "check", "status", "e", "e_ref", "e_err", "Fmax", "Fmax_ref",
           "Fmax_err", "maxOverlap_over_R", "predOverlap_over_R", "reason"]


def mass(t):
    return RHO*math.pi/6*D[t]**3


def params(kind, N, Y, v):
    """R*, m* (damping, primaries), m_dyn (inertia), Y*, t_H, delta_max,el,
    F_max,el for an impact at v."""
    Ystar = Y/(2*(1 - NU**2))
    if kind == "carrier-API":
        ra, rc = D["API"]/2, D["carrier"]/2
        ma, mc = mass("API"), mass("carrier")
        R = ra*rc/(ra + rc)
        mstar = ma*mc/(ma + mc)
        mdyn = 1/(N*(1/(N*ma) + 1/mc))       # pairScaling: S = max(N, 1) = N
    else:
        t = kind.split("-")[0]
        R = D[t]/2
        mstar = mdyn = mass(t)               # N cancels against a wall
    dmax = (15*mdyn*v**2/(16*Ystar*math.sqrt(R)))**0.4
    tH = 2.9433*dmax/v
    Fel = 4/3*Ystar*math.sqrt(R)*dmax**1.5
    return dict(R=R, mstar=mstar, mdyn=mdyn, Ystar=Ystar, tH=tH, dmax=dmax,
                Fel=Fel)


_refCache = {}


def reference(kind, N, Y, v):
    """e, F_max (primary) and contact time of the law, RK4 at t_H/20000.
    Dimensionless results depend only on m*/m_dyn: cached on it."""
    p = params(kind, N, Y, v)
    key = round(p["mstar"]/p["mdyn"], 9)
    if key not in _refCache:
        R, ms, md, Ys = p["R"], p["mstar"], p["mdyn"], p["Ystar"]

        def acc(d, dd):                 # d = overlap, dd = d(overlap)/dt
            if d <= 0:
                return 0.0, 0.0
            kn = 4/3*Ys*math.sqrt(R*d)
            Sn = 2*Ys*math.sqrt(R*d)
            gn = -2*math.sqrt(5/6)*BETA*math.sqrt(Sn*ms)
            f = kn*d + gn*dd            # v_n = -dd (approaching: dd > 0)
            return -f/md, f

        h = p["tH"]/20000
        d, dd, t, fmax = 0.0, v, 0.0, 0.0
        while True:
            k1v, f = acc(d, dd)
            fmax = max(fmax, f)
            k1x = dd
            k2v, _ = acc(d + 0.5*h*k1x, dd + 0.5*h*k1v)
            k2x = dd + 0.5*h*k1v
            k3v, _ = acc(d + 0.5*h*k2x, dd + 0.5*h*k2v)
            k3x = dd + 0.5*h*k2v
            k4v, _ = acc(d + h*k3x, dd + h*k3v)
            k4x = dd + h*k3v
            d += h/6*(k1x + 2*k2x + 2*k3x + k4x)
            dd += h/6*(k1v + 2*k2v + 2*k3v + k4v)
            t += h
            if d <= 0 and t > h:
                break
            if t > 10*p["tH"]:
                sys.exit("impact.py: reference contact did not end")
        _refCache[key] = dict(e=-dd/v, F=fmax/p["Fel"], tc=t/p["tH"])
    r = _refCache[key]
    return dict(e=r["e"], Fmax=r["F"]*p["Fel"], tc=r["tc"]*p["tH"])


def write(a):
    p = params(a.kind, a.N, a.Y, a.v)
    case = a.dir
    cohesion = "none"
    if a.cohesion and a.kind != "carrier-API":
        sys.exit("impact.py: --cohesion is for carrier-API")
    if os.path.exists(case):
        shutil.rmtree(case)
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "constant"))
    shutil.copytree(a.mesh, os.path.join(case, "constant", "polyMesh"))

    # Start 0.3 t_H before touching; run to 3 t_H after (the contact lasts
    # ~1.02 t_H; a failed rebound shows as a contact still open at the end)
    gap = 0.3*p["tH"]*a.v
    nSteps = int(math.ceil((0.3 + 3.0)*p["tH"]/a.dt))
    Dt = nSteps*a.dt
    if a.kind == "carrier-API":
        rc, ra = D["carrier"]/2, D["API"]/2
        zc = 2e-4
        parts = ("{ type carrier; position (0 0 %.15g); U (0 0 0); }\n"
                 "{ type API; position (0 0 %.15g); U (0 0 %.15g); }"
                 % (zc, zc + rc + ra + gap, -a.v))
        types = ("carrier { diameter %g; density %g; youngsModulus %g; "
                 "poissonsRatio %g; N 1; }\n"
                 "API { diameter %g; density %g; youngsModulus %g; "
                 "poissonsRatio %g; N %d; api true; }"
                 % (D["carrier"], RHO, a.Y, NU, D["API"], RHO, a.Y, NU, a.N))
        walls = "{}"
        trace = "(0 1)"
        if a.cohesion:
            chi = max(1.0, (9e9/a.Y)**0.4)
            cohesion = ("vdwGuParcel;\n    vdwGuParcelCoeffs { chi %.9g; "
                        "wallCohesion false; pairs { default { "
                        "hamakerConstant 1e-19; sMin 1e-9; sMins 6.227e-9; "
                        "s0 %.9g; } } }" % (chi, 6.227e-9 - 1e-9*math.sqrt(chi)))
    else:
        t = a.kind.split("-")[0]
        r = D[t]/2
        parts = ("{ type %s; position (0 0 %.15g); U (0 0 %.15g); }"
                 % (t, r + gap, -a.v))
        types = ("%s { diameter %g; density %g; youngsModulus %g; "
                 "poissonsRatio %g; N %d;%s }\n"
                 "wallMaterial { youngsModulus %g; poissonsRatio %g; }"
                 % (t, D[t], RHO, a.Y, NU, a.N,
                    " api true;" if t == "API" else "", a.Y, NU))
        walls = ("{ floor { type plane; point (0 0 0); normal (0 0 1); "
                 "material wallMaterial; } }")
        trace = "(0)"

    with open(os.path.join(case, "system/controlDict"), "w") as f:
        f.write(ss.header("dictionary", "controlDict"))
        f.write("application dpiFoam;\nstartFrom startTime;\nstartTime 0;\n"
                "stopAt endTime;\nendTime %.17g;\ndeltaT %.17g;\n"
                "writeControl timeStep;\nwriteInterval 1000000;\n"
                "purgeWrite 0;\nwriteFormat ascii;\nwritePrecision 17;\n"
                "writeCompression off;\ntimeFormat general;\n"
                "timePrecision 17;\nrunTimeModifiable false;\n" % (Dt, Dt))
    with open(os.path.join(case, "system/fvSchemes"), "w") as f:
        f.write(ss.header("dictionary", "fvSchemes"))
        f.write("ddtSchemes { default Euler; }\ngradSchemes { default Gauss "
                "linear; }\ndivSchemes { default none; }\nlaplacianSchemes "
                "{ default Gauss linear corrected; }\ninterpolationSchemes "
                "{ default linear; }\nsnGradSchemes { default corrected; }\n")
    ss.writeNoSolvers(case)
    ss.writeNoFluid(case)
    ss.writeGravity(case, (0, 0, 0))
    with open(os.path.join(case, "constant/dpiCloudProperties"), "w") as f:
        f.write(ss.header("dictionary", "dpiCloudProperties"))
        f.write("""// bench/stability: %(kind)s, N %(N)d, Y %(Y)g Pa, v %(v)g m/s,
// dt %(dt)g s = %(r).4g t_H (t_H %(tH)g s with m_dyn)
%(preamble)sdem
{
    timeStep %(dt).17g;
    types
    {
%(types)s
    }
    pairs { default { restitution %(e)g; friction %(mu)g; rollingFriction 0; } }
    normalModel hertzParcel;
    tangentialModel historyParcel;
    rollingModel none;
    cohesionModel %(cohesion)s;
    walls %(walls)s
    timeStepCheck { maxImpactVelocity %(v)g; allowUnstable %(allow)s; }
}
injectors { impact { type singleParticles; particles ( %(parts)s ); } }
trace { parcels %(trace)s; }
""" % dict(kind=a.kind, N=a.N, Y=a.Y, v=a.v, dt=a.dt, r=a.dt/p["tH"],
           tH=p["tH"], preamble=ss.dpiCloudPreamble(RHO), rho=RHO, types=types, e=E_REST, mu=MU, walls=walls,
           allow="true" if a.allow_unstable else "false", parts=parts,
           trace=trace, cohesion=cohesion))
    with open(os.path.join(case, "impact.info"), "w") as f:
        f.write("%s %d %.17g %.17g %.17g %d %d\n"
                % (a.kind, a.N, a.Y, a.v, a.dt, int(a.allow_unstable),
                   int(a.cohesion)))


def readTrace(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(x) for x in line.split()])
    return np.array(rows)


def analyse(case):
    kind, N, Y, v, dt, allow, coh = open(
        os.path.join(case, "impact.info")).read().split()
    N, Y, v, dt = int(N), float(Y), float(v), float(dt)
    allow, coh = int(allow), int(coh)
    p = params(kind, N, Y, v)
    ref = reference(kind, N, Y, v)
    row = dict(kind=kind, cohesion=coh, N=N, Y=Y, v=v, dt=dt,
               allowUnstable=allow,
               tH=p["tH"], dt_over_tH=dt/p["tH"], e_ref=ref["e"],
               Fmax_ref=ref["Fmax"], e=float("nan"), e_err=float("nan"),
               Fmax=float("nan"), Fmax_err=float("nan"),
               maxOverlap_over_R=float("nan"),
               predOverlap_over_R=p["dmax"]/p["R"], reason="")
    log = open(os.path.join(case, "log.dpiFoam"), errors="replace").read() \
        if os.path.exists(os.path.join(case, "log.dpiFoam")) else ""
    # refused by the start-up check: the time step (t_H) or the elastic
    # overlap at maxImpactVelocity (> 0.5 R*)
    if "FOAM FATAL" in log and ("above the stability limit" in log
                                or "elastic overlap of" in log):
        row.update(check="refused", status="refused",
                   reason="overlap" if "elastic overlap of" in log
                   else "time step")
        return row
    row["check"] = "warned (allowUnstable)" if "running anyway" in log \
        else "accepted"
    tdir = os.path.join(case, "postProcessing", "dpiCloud", "trace", "0")
    if "FOAM FATAL" in log or "End" not in log:
        row.update(status="crashed", reason="dpiFoam stopped: see log")
        return row
    try:
        if kind == "carrier-API":
            c = readTrace(os.path.join(tdir, "parcel0.dat"))
            a = readTrace(os.path.join(tdir, "parcel1.dat"))
            n = min(len(a), len(c))
            a, c = a[:n], c[:n]
            dist = np.linalg.norm(a[:, 1:4] - c[:, 1:4], axis=1)
            R = (D["API"] + D["carrier"])/2
            delta = R - dist
            vrel = a[:, 6] - c[:, 6]            # z: API above the carrier
            force = a[:, 9]/N                   # primary force on the API
            Rstar = p["R"]
            vx = np.hstack([a[:, 4:7], c[:, 4:7]])
        else:
            a = readTrace(os.path.join(tdir, "parcel0.dat"))
            r = D[kind.split("-")[0]]/2
            delta = r - a[:, 3]
            vrel = a[:, 6]
            force = a[:, 9]/N
            Rstar = r
            vx = a[:, 4:7]
    except (OSError, ValueError, IndexError) as ex:
        row.update(status="crashed", reason="no trace: %s" % ex)
        return row
    if not np.all(np.isfinite(a)) or not np.all(np.isfinite(vx)):
        row.update(status="blow-up", reason="NaN/inf in the trace")
        return row
    touching = np.where(delta > 0)[0]
    row["maxOverlap_over_R"] = float(delta.max()/Rstar)
    if len(touching) == 0:
        # contact missed entirely within one step: passed through?
        row.update(status="blow-up", reason="no contact step seen")
        return row
    last = touching[-1]
    if delta.max() > Rstar:
        row.update(status="blow-up", reason="overlap above R*")
        return row
    if last == len(delta) - 1:
        if coh:
            # captured by cohesion: bounded if the overlap stays below R*
            row.update(e=0.0, e_err=float("nan"), status="ran",
                       Fmax=force[touching[0]:].max(),
                       reason="captured (sticks)")
            return row
        row.update(status="blow-up",
                   reason="still overlapping at 3 t_H (no rebound)")
        return row
    e = vrel[last + 1]/v                       # separating speed / impact
    if coh and touching[0] > 0:
        # cohesion accelerates the approach and brakes the rebound outside
        # the contact: restitution of the contact itself, from the speed
        # one step before the first touch to one step after the last
        e = vrel[last + 1]/(-vrel[touching[0] - 1])
    Fmax = force[touching[0]:last + 2].max()
    row.update(e=e, e_err=e/ref["e"] - 1, Fmax=Fmax,
               Fmax_err=Fmax/ref["Fmax"] - 1)
    if coh:
        # no closed form with cohesion (the errors are against the
        # non-cohesive law, for information): bounded = finite, overlap
        # below R*, no energy gained by the contact (e <= 1)
        row["reason"] = "rebound, cohesive (errors vs the non-cohesive law)"
        row["status"] = "blow-up" if e > 1.0 else "ran"
        return row
    if e > 1.0:
        row.update(status="blow-up", reason="energy gained (e > 1)")
    elif abs(row["e_err"]) > 0.5 or abs(row["Fmax_err"]) > 0.5:
        row.update(status="large error", reason="error above 50 %")
    else:
        row["status"] = "ran"
    return row


def fmt(x):
    return "%.6g" % x if isinstance(x, float) else str(x)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    w = sub.add_parser("write")
    w.add_argument("dir")
    for s in ("th", "write"):
        q = w if s == "write" else sub.add_parser("th")
        q.add_argument("--kind", required=True,
                       choices=("API-wall", "carrier-wall", "carrier-API"))
        q.add_argument("--N", type=int, default=1)
        q.add_argument("--Y", type=float, default=5e8)
        q.add_argument("--v", type=float, default=3.0)
    w.add_argument("--dt", type=float, required=True)
    w.add_argument("--allow-unstable", action="store_true")
    w.add_argument("--cohesion", action="store_true")
    w.add_argument("--mesh", required=True)
    an = sub.add_parser("analyse")
    an.add_argument("cases", nargs="+")
    an.add_argument("--header", action="store_true")
    a = ap.parse_args()
    if a.cmd == "write":
        write(a)
    elif a.cmd == "th":
        print("%.17g" % params(a.kind, a.N, a.Y, a.v)["tH"])
    else:
        if a.header:
            print(",".join(COLUMNS))
        for c in a.cases:
            r = analyse(c)
            print(",".join(fmt(r.get(k, "")) for k in COLUMNS))


if __name__ == "__main__":
    main()
