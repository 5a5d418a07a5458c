#!/usr/bin/python3
"""A settled bed of 70 um lactose carriers for bench/packedBed, made once
with stock LIGGGHTS 3.8 and cached as an NPZ.

    bed.py OUT.npz --n 2000 [--seed 20240] [--np 1] [--work DIR]

The materials of the settling scene (bench/common/settlingScene.py: 1520
kg/m3, E 5e8 Pa, nu 0.35, e 0.85, mu 0.45, Hertz + history, no cohesion),
in a box of six plane walls with a square floor of edge W = (N v_p /
0.6)^(1/3) (a bed about as high as it is wide):

 1. the N carriers are placed at random without overlaps (seeded random
    sequential addition, settlingScene.place) at solids fraction 0.3 in
    W x W x H0 (H0 = 2 W), at rest;
 2. pour (softened): E 5e6 Pa, e 0.5, mu 0.45, gravity 20 g, dt 4e-7 s,
    for 1.3 free-fall times through H0;
 3. rest: the same at g, a viscous drag (tau = m/gamma = 2e-5 s), every
    velocity zeroed every 500 steps, 3000 steps (1.2 ms);
 4. stiffen: E 5e7 Pa, frictionless, drag tau 2e-6 s, zeroed every 300
    steps, dt 1.2e-7 s, 3000 steps; 5. real: E 5e8, e 0.85, frictionless,
    drag 2e-6 s, zeroed every 400 steps, dt 5e-8 s, 4000 steps (the
    frictionless stages let the overlaps of the softened, 20 g pour relax:
    with friction, the tangential springs lock them in and they are
    released as soon as a run starts without contact history);
 6. friction: the real material (mu 0.45), drag, zeroed every 400 steps,
    2000 steps;
 7. check: from the positions of 6 at rest and without contact history,
    as the benchmarks start, the real material without drag for 2000 steps
    (0.1 ms): kinetic energy and pair contacts at its start and end (from
    LIGGGHTS' thermo output) say whether the bed is at rest.
Velocities are set to zero between the stages (each is one LIGGGHTS run
reading the previous one's positions, written at 17 digits: overlaps are
~1e-9 m). The NPZ holds x [m] (the positions at the start of the check:
the bed), box [m] (W x W x the bed top + one diameter: the benchmark's
box), and the numbers of the check (stats, JSON).
"""

import argparse
import glob
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import settlingScene as ss  # noqa: E402

PHI_BED = 0.6       # for the floor edge only (the bed makes its own)
PHI_START = 0.3     # random sequential addition, below its ~0.38

# (name, E [Pa], restitution, friction, dt [s], gravity factor, steps
#  (None: 1.3 free-fall times through the box height), viscous drag
#  tau = m/gamma [s] or None, quench: zero every velocity so many steps or 0)
STAGES = (
    ("pour", 5e6, 0.5, ss.FRICTION, 4e-7, 20.0, None, None, 0),
    ("rest", 5e6, 0.5, ss.FRICTION, 4e-7, 1.0, 3000, 2e-5, 500),
    ("stiffen", 5e7, 0.5, 0.0, 1.2e-7, 1.0, 3000, 2e-6, 300),
    ("real", 5e8, ss.RESTITUTION, 0.0, 5e-8, 1.0, 4000, 2e-6, 400),
    ("friction", 5e8, ss.RESTITUTION, ss.FRICTION, 5e-8, 1.0, 2000, 2e-6, 400),
    ("check", 5e8, ss.RESTITUTION, ss.FRICTION, 5e-8, 1.0, 2000, None, 0),
)


def mass():
    return ss.DENSITY*math.pi/6*ss.DIAMETER**3


def contacts(x, box):
    """Pair contacts (overlapping pairs), wall contacts and the largest
    pair overlap / R* of positions x in box."""
    from scipy.spatial import cKDTree
    d = ss.DIAMETER
    pairs = cKDTree(x).query_pairs(d, output_type="ndarray")
    gap = np.linalg.norm(x[pairs[:, 0]] - x[pairs[:, 1]], axis=1)
    over = (d - gap)/(0.25*d)
    r = 0.5*d
    b = np.array(ss.boxOf(box))
    walls = int(np.sum(x < r) + np.sum(x > b - r))
    return len(pairs), walls, float(over.max()) if len(over) else 0.0


def readDump(path):
    """id x y z vx vy vz of a LIGGGHTS custom dump, sorted by id."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = lines.index(next(ln for ln in lines if ln.startswith("ITEM: ATOMS")))
    a = np.array([[float(t) for t in ln.split()] for ln in lines[k + 1:]
                  if ln.strip()])
    a = a[np.argsort(a[:, 0])]
    return a[:, 1:4], a[:, 4:7]


def thermo(log):
    """Rows (step atoms ke rotke contacts) of every run of a LIGGGHTS log."""
    rows = []
    on = False
    for ln in open(log):
        t = ln.split()
        if t[:2] == ["Step", "Atoms"]:
            on = True
            continue
        if on and t and t[0].isdigit() and len(t) == 5:
            rows.append([float(c) for c in t])
        elif on and ln.startswith("Loop time"):
            on = False
    return np.array(rows)


def stage(work, k, name, x, box, E, e, mu, dt, gfac, steps, tau, quench,
          np_, g=None):
    """One LIGGGHTS run from positions x at rest (gravity gfac g along -z,
    or the vector g); returns the positions, velocities at the end and the
    thermo rows."""
    d = os.path.join(work, "%d-%s" % (k, name))
    os.makedirs(d, exist_ok=True)
    for old in glob.glob(os.path.join(d, "dump.*")):
        os.remove(old)
    ss.writeLiggghtsData(os.path.join(d, "data.bed"), x, np.zeros_like(x),
                         box, "packedBed stage %s" % name)
    total = steps
    if quench:
        # runs of `quench` steps, every velocity zeroed after each (LIGGGHTS
        # 3.8's set command cannot zero the spin)
        run = ("variable        q loop %d\nlabel           quench\n"
               "run             %d\nvelocity        all set 0.0 0.0 0.0\n"
               "next            q\n"
               "jump            SELF quench\n" % (steps//quench, quench))
        total = steps//quench*quench
    else:
        run = "run             %d\n" % steps
    with open(os.path.join(d, "in.bed"), "w") as f:
        f.write(ss.liggghtsSetup(
            "packedBed generation, stage %s (bench/packedBed/bed.py)" % name,
            "data.bed", 0.25*ss.DIAMETER, E, e, mu, dt,
            gfac*ss.GRAVITY if g is None else g, box))
        f.write("""compute         cn all contact/atom
compute         cnsum all reduce sum c_cn
thermo_style    custom step atoms ke c_rke c_cnsum
thermo          %(every)d
thermo_modify   lost ignore norm no

dump            d all custom %(total)d dump.* id x y z vx vy vz
dump_modify     d format "%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g"
%(drag)s
%(run)s""" % dict(
            every=max(1, min(total, 500)), total=total,
            drag="fix             drag all viscous %.6g\n" % (mass()/tau)
            if tau else "", run=run))
    cmd = ["liggghts", "-in", "in.bed", "-log", "log.liggghts",
           "-screen", "none"]
    if np_ > 1:
        cmd = ["mpirun", "-np", str(np_)] + cmd
    t0 = time.time()
    subprocess.run(cmd, cwd=d, check=True)
    wall = time.time() - t0
    dumps = glob.glob(os.path.join(d, "dump.*"))
    last = max(dumps, key=lambda p: int(p.rsplit(".", 1)[1]))
    xe, ve = readDump(last)
    rows = thermo(os.path.join(d, "log.liggghts"))
    print("bed.py: stage %-8s E %.0e mu %g dt %.1e g x%-2g %6d steps%s%s: "
          "%3.0f s, KE %.3g J, contacts/particle %.2f"
          % (name, E, mu, dt, gfac, total, " drag %g s" % tau if tau else "",
             ", quench every %d" % quench if quench else "", wall,
             rows[-1, 2], rows[-1, 4]/len(x)), flush=True)
    return xe, ve, rows, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--n", type=int, required=True)
    ap.add_argument("--seed", type=int, default=20240)
    ap.add_argument("--np", type=int, default=1,
                    help="LIGGGHTS processes (the bed differs with np)")
    ap.add_argument("--work", help="LIGGGHTS runs (default OUT without "
                    ".npz + '.work')")
    a = ap.parse_args()
    work = a.work or os.path.splitext(a.out)[0] + ".work"
    os.makedirs(work, exist_ok=True)

    n = a.n
    vp = math.pi/6*ss.DIAMETER**3
    W = (n*vp/PHI_BED)**(1/3)
    H0 = n*vp/(PHI_START*W*W)
    box0 = (W, W, H0)
    t0 = time.time()
    x = ss.place(n, box0, np.random.default_rng(a.seed))
    print("bed.py: %d carriers at random in %.3g x %.3g x %.3g mm (phi %.2f)"
          % (n, W*1e3, W*1e3, H0*1e3, PHI_START), flush=True)

    walls = 0.0
    for k, (name, E, e, mu, dt, gfac, steps, tau, quench) in \
            enumerate(STAGES):
        if steps is None:
            # 1.3 times the free fall through the box height at gfac g
            steps = int(math.ceil(1.3*math.sqrt(2*H0/(gfac*ss.GRAVITY))/dt))
        xStart = x
        x, v, rows, w = stage(work, k, name, x, box0, E, e, mu, dt, gfac,
                              steps, tau, quench, a.np)
        walls += w

    # The check: the last stage, the real material from rest without
    # contact history (as the benchmarks start), no drag
    # The bed is the check's start (the end of the stage before): the
    # benchmarks start from it as the check did
    x = xStart
    m = mass()
    ke = rows[-1, 2]
    chk = rows
    zStart, zEnd = chk[0, 4]/n, chk[-1, 4]/n
    top = float(x[:, 2].max()) + 0.5*ss.DIAMETER
    box = (W, W, top + ss.DIAMETER)
    nPair, nWall, maxOver = contacts(x, box)
    stats = dict(
        n=n, seed=a.seed, np=a.np, W=W, H0=H0, top=top,
        phi=n*vp/(W*W*top), seconds=time.time() - t0, liggghts_seconds=walls,
        KE=ke, KE_per_mgd=ke/(n*m*ss.GRAVITY*ss.DIAMETER),
        v_rms=math.sqrt(2*ke/(n*m)),
        v_max=float(np.linalg.norm(v, axis=1).max()),
        z_check_start=zStart, z_check_end=zEnd,
        z_geometric=2.0*nPair/n, wall_contacts=nWall, max_overlap=maxOver,
        KE_check_start=chk[0, 2], KE_check=list(chk[:, 2]))
    np.savez(a.out, x=x, box=np.array(box), stats=json.dumps(stats))
    print("bed.py: %s: %d carriers, floor %.3g mm, bed top %.3g mm (phi "
          "%.3f), contacts/particle %.2f -> %.2f over the last 0.1 ms "
          "(geometric %.2f, %d wall contacts), KE %.3g J (v_rms %.2g m/s, "
          "KE/(N m g d) %.2g), max overlap %.2g R*, %.0f s"
          % (a.out, n, W*1e3, top*1e3, stats["phi"], zStart, zEnd,
             stats["z_geometric"], nWall, ke, stats["v_rms"],
             stats["KE_per_mgd"], maxOver, stats["seconds"]))


if __name__ == "__main__":
    main()
