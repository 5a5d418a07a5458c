#!/usr/bin/env python3
"""Writes system/blockMeshDict of the inhaler: the screen-haler of the user
guide's Fig. 13, an L of two round tubes 7 mm in diameter, in the guide's
frame (its deck's DEM box x in [-5, 50], y in [-4, 4], z in [-4, 14] mm):

  - horizontal leg along x (axis y = z = 0) from the outlet at x = 0 to the
    far wall of the corner at x = 45 mm (Fig. 13: 45 mm);
  - vertical leg along z (axis x = 41.5 mm, y = 0) from the floor of the
    corner at z = -3.5 mm up to the inlet at z = 12.5 mm (Fig. 13: 16 mm);
  - the legs meet at the mitre plane x + z = 41.5 mm (a sharp elbow);
  - the exit region: the 5 mm past the outlet (x in [-5, 0]), y and z in
    [-4, 4] mm, where the particles that left the tube fly on through the
    guide's FPF box (x in [-5, 0], y, z in [-3.5, 3.5] mm) before they
    leave the domain. Its cells are the cellZone exitRegion (the tutorial
    switches the gas forces off there: fluidCoupling/gasFreeZones).

The deck's powder cone (axis x = 39 mm, y = 0) then sits on the floor under
the inlet leg, 1 mm inside its outlet-side wall (x = 38 mm), as Figs. 15
and 18a draw it (doc in the tutorial's README, "The device").

Each cross-section is an O-grid (a square of ns x ns cells and four ring
blocks of ns x nr cells, 4 ns cells around); the exit region adds four
blocks of ns x nx cells between the circle and its 8 mm square. Patches,
named as Fig. 14b: wall1 (horizontal leg up to x = 34.5 mm), turn (the
corner: x > 34.5 mm in the horizontal leg, z < 7 mm in the vertical leg),
wall2 (vertical leg above z = 7 mm), inlet (z = 12.5 mm); the guide's
outlet (x = 0) is the plane between the tube and the exit region, whose
boundary is exitEnd (x = -5 mm) and exitSides (y, z = +-4 mm, and the
tube's end face around the circle at x = 0).

Usage: makeBlockMeshDict.py [--ns 6] [--nr 4] [--nx 2] [--dx 1e-3] [--noExit] [--straight]
  > system/blockMeshDict
--noExit:   the tube alone, its outlet (x = 0) a patch named outlet
--straight: only the horizontal leg, from x = 0 to 45 mm with the inlet
            there and the outlet at x = 0, no exit region (the gas-only
            O-grid test tests/cases/gasOGridTube uses it)
"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("--ns", type=int, default=6, help="cells along a quarter circle")
ap.add_argument("--nr", type=int, default=4, help="cells across the ring")
ap.add_argument("--nx", type=int, default=2,
                help="cells between the circle and the exit region's square")
ap.add_argument("--dx", type=float, default=1e-3, help="axial cell size [m]")
ap.add_argument("--noExit", action="store_true",
                help="no exit region: the tube's end is the patch outlet")
ap.add_argument("--straight", action="store_true",
                help="straight horizontal tube only (test mesh)")
a = ap.parse_args()

R = 3.5e-3           # tube radius
xc = 41.5e-3         # axis of the vertical leg
xOut = 0             # outlet: the tube's end
xTurn = xc - 2*R     # start of the turn patch in the horizontal leg
zTurn = 7e-3         # end of the turn patch in the vertical leg
zIn = 12.5e-3        # inlet
xExit = -5e-3        # end of the exit region (the deck's DEM box)
H = 4e-3             # half-width of the exit region (the deck's DEM box in y)
s = 0.45*R           # half-size of the O-grid's inner square
exitRegion = not (a.noExit or a.straight)

# cross-section vertices (a, b): 4 inner, 4 on the circle (counter-
# clockwise), and in the exit region 4 corners of its square
c45 = math.sqrt(0.5)
sec = [(-s, -s), (s, -s), (s, s), (-s, s),
       (-R*c45, -R*c45), (R*c45, -R*c45), (R*c45, R*c45), (-R*c45, R*c45),
       (-H, -H), (H, -H), (H, H), (-H, H)]
outerAngle = [225, 315, 45, 135]

# stations: (exit region end), horizontal leg (x), the mitre, vertical leg (z)
def horiz(x):
    return lambda a_, b_: (x, a_, b_)

def mitre():
    return lambda a_, b_: (xc - b_, a_, b_)

def vert(z):
    return lambda a_, b_: (xc - b_, a_, z)

if a.straight:
    stations = [horiz(xOut), horiz(xTurn), horiz(0.038), horiz(0.04),
                horiz(0.045)]
else:
    stations = [horiz(xOut), horiz(xTurn), mitre(), vert(zTurn), vert(zIn)]
if exitRegion:
    stations.insert(0, horiz(xExit))
nS = len(stations)
# the stations with the exit region's square: its two ends
squared = [0, 1] if exitRegion else []

verts = []
index = []          # index[k][i]: vertex of section point i at station k
for k, st in enumerate(stations):
    index.append({})
    for i, (p, q) in enumerate(sec):
        if i < 8 or k in squared:
            index[k][i] = len(verts)
            verts.append(st(p, q))

def vid(k, i):
    return index[k][i]

# axial cell counts of the segments (mean length / dx)
def seglen(k):
    p0 = stations[k](0, 0)
    p1 = stations[k + 1](0, 0)
    return math.dist(p0, p1)

nAx = [max(2, round(seglen(k)/a.dx)) for k in range(nS - 1)]
# the corner segments are short on the inside of the elbow: at least 4 cells
k0 = 1 if exitRegion else 0     # the first segment of the tube
if not a.straight:
    nAx[k0 + 1] = max(nAx[k0 + 1], 4)
    nAx[k0 + 2] = max(nAx[k0 + 2], 4)

def vol(hexv):
    """Signed volume-like test of blockMesh's right-handed convention."""
    p = [verts[i] for i in hexv]
    u = [p[1][j] - p[0][j] for j in range(3)]
    v = [p[3][j] - p[0][j] for j in range(3)]
    w = [p[4][j] - p[0][j] for j in range(3)]
    cr = (u[1]*v[2] - u[2]*v[1], u[2]*v[0] - u[0]*v[2], u[0]*v[1] - u[1]*v[0])
    return sum(cr[j]*w[j] for j in range(3))

# blocks of one segment: (c0 c1 c2 c3) in the section, counts along c0c1, c0c3
secBlocks = [
    ((0, 1, 2, 3), a.ns, a.ns),     # square
    ((4, 5, 1, 0), a.ns, a.nr),     # ring, b < 0 side
    ((5, 6, 2, 1), a.ns, a.nr),     # ring, a > 0 side
    ((6, 7, 3, 2), a.ns, a.nr),     # ring, b > 0 side
    ((7, 4, 0, 3), a.ns, a.nr),     # ring, a < 0 side
]
# the exit region's blocks between the circle and its square
outerBlocks = [((8 + j, 8 + (j + 1) % 4, 4 + (j + 1) % 4, 4 + j), a.ns, a.nx)
               for j in range(4)]

blocks = []
for k in range(nS - 1):
    inExit = exitRegion and k == 0
    for (c, n1, n2) in secBlocks + (outerBlocks if inExit else []):
        h = [vid(k, i) for i in c] + [vid(k + 1, i) for i in c]
        if vol(h) < 0:
            c = (c[0], c[3], c[2], c[1])
            n1, n2 = n2, n1
            h = [vid(k, i) for i in c] + [vid(k + 1, i) for i in c]
        assert vol(h) > 0
        blocks.append((h, (n1, n2, nAx[k]), "exitRegion" if inExit else ""))

# curved edges: the four arcs on the circle of every station
def edgePoints(k, j, n=12):
    st = stations[k]
    a0 = math.radians(outerAngle[j])
    a1 = math.radians(outerAngle[(j + 1) % 4])
    if a1 < a0:
        a1 += 2*math.pi
    pts = []
    for m in range(1, n):
        t = a0 + (a1 - a0)*m/n
        pts.append(st(R*math.cos(t), R*math.sin(t)))
    return pts

edges = []
for k in range(nS):
    for j in range(4):
        edges.append((vid(k, 4 + j), vid(k, 4 + (j + 1) % 4), edgePoints(k, j)))

def sideFace(k, i0, i1):
    """The face between stations k and k + 1 along section edge i0-i1."""
    return (vid(k, i0), vid(k, i1), vid(k + 1, i1), vid(k + 1, i0))

def ringFace(k, j):
    return sideFace(k, 4 + j, 4 + (j + 1) % 4)

def capFaces(k):
    f = [(vid(k, 0), vid(k, 3), vid(k, 2), vid(k, 1))]
    for j in range(4):
        i0, i1 = 4 + j, 4 + (j + 1) % 4
        f.append((vid(k, i0), vid(k, i1), vid(k, i1 - 4), vid(k, i0 - 4)))
    return f

def lipFaces(k):
    """The exit region's faces between the circle and the square at k."""
    return [(vid(k, 4 + j), vid(k, 8 + j), vid(k, 8 + (j + 1) % 4),
             vid(k, 4 + (j + 1) % 4)) for j in range(4)]

tube = [k0 + k for k in range(4)]   # the tube's four segments
patches = []
if exitRegion:
    patches += [
        ("exitEnd", "patch", capFaces(0) + lipFaces(0)),
        ("exitSides", "patch",
         [sideFace(0, 8 + j, 8 + (j + 1) % 4) for j in range(4)] + lipFaces(1)),
    ]
else:
    patches.append(("outlet", "patch", capFaces(0)))
patches += [
    ("wall1", "wall", [ringFace(tube[0], j) for j in range(4)]),
    ("turn", "wall", [ringFace(k, j) for k in tube[1:3] for j in range(4)]),
    ("wall2", "wall", [ringFace(tube[3], j) for j in range(4)]),
    ("inlet", "patch", capFaces(nS - 1)),
]

def fmt(p):
    return "(%.10g %.10g %.10g)" % p

options = ["--%s %s" % (k, v) for k, v in vars(a).items()
           if k not in ("straight", "noExit")]
options += ["--%s" % k for k in ("noExit", "straight") if getattr(a, k)]
out = []
out.append("""/*--------------------------------*- C++ -*----------------------------------*\\
  dpiFoam tutorial inhaler: the screen-haler (user guide Fig. 13), an L of
  two 7 mm tubes in the guide's frame, O-grid blocks. Written by
  makeBlockMeshDict.py (%s);
  edit the script, not this file.
\\*---------------------------------------------------------------------------*/
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }

scale 1;
""" % " ".join(options))
out.append("vertices\n(")
for i, p in enumerate(verts):
    out.append("    %s    // %d" % (fmt(p), i))
out.append(");\n\nblocks\n(")
for h, n, zone in blocks:
    out.append("    hex (%s) %s(%d %d %d) simpleGrading (1 1 1)"
               % (" ".join(map(str, h)), zone + " " if zone else "", *n))
out.append(");\n\nedges\n(")
for i0, i1, pts in edges:
    out.append("    polyLine %d %d (%s)" % (i0, i1, " ".join(fmt(p) for p in pts)))
out.append(");\n\nboundary\n(")
for name, typ, faces in patches:
    out.append("    %s\n    {\n        type %s;\n        faces\n        (" % (name, typ))
    for f in faces:
        out.append("            (%s)" % " ".join(map(str, f)))
    out.append("        );\n    }")
out.append(");\n\nmergePatchPairs ();\n")
print("\n".join(out))
