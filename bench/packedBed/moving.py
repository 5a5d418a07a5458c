#!/usr/bin/python3
"""Beds in motion for bench/packedBed, made from a settled bed of bed.py
(its NPZ and its LIGGGHTS stages) and cached as NPZs with velocities.

    moving.py OUT.npz --bed cases/bed-N10000.npz --kind relaxing|pile|rattlers
              [--seed 20241]

 relaxing  the bed as LIGGGHTS leaves its own settling, still relaxing:
           the positions at the end of bed.py's stiffening stage (E 5e7,
           frictionless), run on with the real material (E 5e8, e 0.85,
           mu 0.45, dt 5e-8 s, no drag) from rest for --release steps
           (default 400, 20 us): the overlaps left by the softer material
           spring back and the bed shakes, at about 1 cm/s rms, losing
           contacts as it goes;
 pile      the settled bed under gravity tilted by --tilt degrees (default
           40, about y, downhill towards +x: beyond the angle of repose,
           so the free surface flows), run on in LIGGGHTS for --flow steps
           (default 20,000, 1 ms): a pile whose surface still flows into
           the lower corner while its base rests;
 rattlers  the settled bed at rest with --fraction (default 3 %) of its
           carriers, drawn at random (--seed), moving at --speed (default
           0.1 m/s) in random directions: a few fast rattlers in a still
           bed.

The NPZ holds x, v [m, m/s], box [m], g [m/s2] (the tilted gravity of the
pile; the others -z) and stats (JSON: v_rms, v_max, geometric contacts per
particle). The benchmark starts from it without contact history, as it
starts from the still bed.
"""

import argparse
import glob
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, HERE)
import settlingScene as ss  # noqa: E402
import bed  # noqa: E402

REAL_DT = 5e-8


def lastDump(d):
    dumps = glob.glob(os.path.join(d, "dump.*"))
    if not dumps:
        sys.exit("moving.py: no LIGGGHTS dump in %s (make the bed again: "
                 "delete its NPZ and run bed.py)" % d)
    return max(dumps, key=lambda p: int(p.rsplit(".", 1)[1]))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--bed", required=True, help="NPZ of bed.py")
    ap.add_argument("--kind", required=True,
                    choices=("relaxing", "pile", "rattlers"))
    ap.add_argument("--release", type=int, default=400)
    ap.add_argument("--tilt", type=float, default=40.0)
    ap.add_argument("--flow", type=int, default=20000)
    ap.add_argument("--fraction", type=float, default=0.03)
    ap.add_argument("--speed", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=20241)
    a = ap.parse_args()

    data = np.load(a.bed)
    still = np.array(data["x"], float)
    box = np.array(data["box"], float)
    st = json.loads(str(data["stats"]))
    n = len(still)
    work = os.path.splitext(a.bed)[0] + ".work"
    g = np.array([0.0, 0.0, -ss.GRAVITY])
    mu = ss.FRICTION

    if a.kind == "relaxing":
        # the stiffening stage ran in bed.py's own box (W x W x H0)
        x0, _ = bed.readDump(lastDump(os.path.join(work, "2-stiffen")))
        x, v, _, _ = bed.stage(work, 10, "relaxing", x0,
                               (st["W"], st["W"], st["H0"]), ss.YOUNG,
                               ss.RESTITUTION, mu, REAL_DT, 1.0, a.release,
                               None, 0, 1)
        # the benchmark's box is the still bed's (its top + a diameter):
        # the bed has not risen by a diameter in 20 us
        if x[:, 2].max() + 0.5*ss.DIAMETER > box[2]:
            sys.exit("moving.py: the relaxing bed rose above the box")
    elif a.kind == "pile":
        t = math.radians(a.tilt)
        g = ss.GRAVITY*np.array([math.sin(t), 0.0, -math.cos(t)])
        x, v, _, _ = bed.stage(work, 11, "pile", still, box, ss.YOUNG,
                               ss.RESTITUTION, mu, REAL_DT, 1.0, a.flow,
                               None, 0, 1, g=g)
    else:
        rng = np.random.default_rng(a.seed)
        x = still.copy()
        v = np.zeros_like(x)
        k = rng.choice(n, size=max(1, int(round(a.fraction*n))),
                       replace=False)
        u = rng.normal(size=(len(k), 3))
        v[k] = a.speed*u/np.linalg.norm(u, axis=1)[:, None]

    speed = np.linalg.norm(v, axis=1)
    nPair, nWall, _ = bed.contacts(x, box)
    stats = dict(kind=a.kind, n=n, bed=os.path.basename(a.bed),
                 v_rms=float(math.sqrt(np.mean(speed**2))),
                 v_max=float(speed.max()),
                 moving_1mm_s=float(np.mean(speed > 1e-3)),
                 z_geometric=2.0*nPair/n, wall_contacts=nWall,
                 g=list(g), args=vars(a))
    np.savez(a.out, x=x, v=v, box=box, g=g, stats=json.dumps(stats))
    print("moving.py: %s: %s bed of %d carriers, v_rms %.3g cm/s, v_max "
          "%.3g cm/s, %.0f %% faster than 1 mm/s, contacts/particle %.2f"
          % (a.out, a.kind, n, 100*stats["v_rms"], 100*stats["v_max"],
             100*stats["moving_1mm_s"], stats["z_geometric"]))


if __name__ == "__main__":
    main()
