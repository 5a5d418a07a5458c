#!/usr/bin/python3
"""Checks of the voidFraction case test (run by ./run in its run folder):
the alpha.air each variant wrote against the 29-point split of theory 5.1,
computed here independently of the C++ code."""
import re
import sys
import numpy as np

failed = []


def check(ok, msg):
    print(("ok: " if ok else "FAIL: ") + msg)
    if not ok:
        failed.append(msg)


def points29(R):
    """The 29 representative points (theory 5.1): centre; on radii
    0.623926 R and 0.917902 R the 6 axis points and the 8 points at polar
    angles pi/4, 3pi/4 and azimuths pi/4 + k pi/2."""
    pts = [np.zeros(3)]
    for r in (0.623926*R, 0.917902*R):
        for ax in range(3):
            for s in (1, -1):
                p = np.zeros(3)
                p[ax] = s*r
                pts.append(p)
        for th in (np.pi/4, 3*np.pi/4):
            for k in range(4):
                ph = np.pi/4 + k*np.pi/2
                pts.append(r*np.array([np.sin(th)*np.cos(ph),
                                       np.sin(th)*np.sin(ph), np.cos(th)]))
    return np.array(pts)


def alpha(run):
    txt = open(run + "/1e-05/alpha.air").read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", txt)
    if m:
        return np.array([float(x) for x in m.group(2).split()])
    m = re.search(r"internalField\s+uniform\s+([^;]+);", txt)
    return np.full(8, float(m.group(1)))


h = 4e-3                  # cell size: 2 x 2 x 2 cells of an 8 mm box
Vc = h**3
d = 2e-3
Vp = np.pi/6*d**3


def expected(centre, Vs, alphaMin=0.3):
    """Solid volume per cell (cell index i + 2j + 4k as blockMesh numbers
    them) and the resulting alpha with the floor."""
    vol = np.zeros(8)
    for p in points29(d/2) + np.array(centre):
        i, j, k = (int(c // h) for c in p)
        vol[i + 2*j + 4*k] += Vs/29
    return vol, np.maximum(1 - vol/Vc, alphaMin)


corner = (4.05e-3, 4.05e-3, 4.05e-3)
# the split of the points over the eight cells, for the log
vol, _ = expected(corner, 29.0)
print("points per cell (corner variants):", vol.astype(int).tolist())

for run, centre, Vs in [
    ("divided", corner, Vp),            # one particle volume, N ignored
    ("apiParcel", corner, 10*Vp),       # N = 10 primary volumes
    ("inside", (2e-3, 2.5e-3, 1.9e-3), 10*Vp),
]:
    a = alpha(run)
    vol, aRef = expected(centre, Vs)
    solid = (1 - a)*Vc
    # alpha is written with 17 digits: 1 - alpha to ~1e-16 absolute, i.e.
    # ~1e-13 of the smallest cell share (1/29 of V_p/V_c = 2.3e-3)
    err = np.max(np.abs(solid - vol))/Vs
    check(err < 1e-11,
          "%s: per-cell solid volume = 29-point split (max error %.1e of "
          "the parcel volume)" % (run, err))
    tot = solid.sum()/Vs - 1
    check(abs(tot) < 1e-12,
          "%s: total solid volume %.12e m^3 = %s (relative %.1e)"
          % (run, solid.sum(), "V_p" if Vs == Vp else "N V_p", tot))

# apiParcel removes N times what divided removes, cell by cell
r = (1 - alpha("apiParcel"))/(1 - alpha("divided"))
check(np.all(np.abs(r - 10) < 1e-10),
      "apiParcel/divided solid volume per cell = N = 10 (%s)"
      % np.array2string(r, precision=12))

# the floor: N = 40, the fullest cell (9 points) would have theta = 0.81
a = alpha("floor")
vol, aRef = expected(corner, 40*Vp)
check(np.max(np.abs(a - aRef)) < 1e-13 and abs(a.min() - 0.3) < 1e-15,
      "floor: alpha = max(1 - theta, 0.3), min %.15f (theta of the fullest "
      "cell %.4f)" % (a.min(), vol.max()/Vc))
clipped = np.sum(np.maximum(vol - 0.7*Vc, 0))
log = open("floor/log.dpiFoam").read()
m = re.search(r"clips a solid volume of ([0-9.eE+-]+) m\^3", log)
check(m is not None and abs(float(m.group(1))/clipped - 1) < 1e-5,
      "floor: reported clipped volume %s m^3 (expected %.6e)"
      % (m.group(1) if m else "none", clipped))

sys.exit(1 if failed else 0)
