#!/usr/bin/env python3
"""Writes system/blockMeshDict of the inhaler: the screen-haler of the user
guide's Fig. 13 as an L of two round tubes, 7 mm in diameter.

  - horizontal leg along x (axis y = z = 0) from the outlet at x = -5 mm to
    the outer wall of the corner at x = 40 mm: 45 mm;
  - vertical leg along z (axis x = 36.5 mm, y = 0) from the bottom of the
    corner at z = -3.5 mm up to the inlet at z = 12.5 mm: 16 mm;
  - the legs meet at the mitre plane x + z = 36.5 mm (a sharp elbow).

This puts the guide's DEM box (x in [-5, 50], y in [-4, 4], z in [-4, 14] mm)
around the device, the FPF box (x in [-5, 0] mm) in the last 5 mm before the
outlet, and the guide's powder cone (axis x = 39 mm, y = 0, z from -3.4 to
-2.35 mm) on the floor of the corner, under the inlet jet.

Each cross-section is an O-grid (a square of ns x ns cells and four ring
blocks of ns x nr cells, 4 ns cells around). Patches: outlet (x = -5 mm),
wall2 (horizontal leg up to x = 29.5 mm), turn (the corner: x > 29.5 mm in
the horizontal leg, z < 7 mm in the vertical leg), wall1 (vertical leg above
z = 7 mm), inlet (z = 12.5 mm).

Usage: makeBlockMeshDict.py [--ns 6] [--nr 4] [--dx 1e-3] [--straight] > system/blockMeshDict
--straight: only the horizontal leg, extended to x = 40 mm with the inlet
there (the gas-only O-grid test tests/cases/gasOGridTube uses it)
"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("--ns", type=int, default=6, help="cells along a quarter circle")
ap.add_argument("--nr", type=int, default=4, help="cells across the ring")
ap.add_argument("--dx", type=float, default=1e-3, help="axial cell size [m]")
ap.add_argument("--straight", action="store_true",
                help="straight horizontal tube only (test mesh)")
a = ap.parse_args()

R = 3.5e-3           # tube radius
xc = 36.5e-3         # axis of the vertical leg
xOut = -5e-3         # outlet
xTurn = 29.5e-3      # start of the turn patch in the horizontal leg
zTurn = 7e-3         # end of the turn patch in the vertical leg
zIn = 12.5e-3        # inlet
s = 0.45*R           # half-size of the O-grid's inner square

# cross-section vertices (a, b): 4 inner, 4 outer (counter-clockwise)
c45 = math.sqrt(0.5)
sec = [(-s, -s), (s, -s), (s, s), (-s, s),
       (-R*c45, -R*c45), (R*c45, -R*c45), (R*c45, R*c45), (-R*c45, R*c45)]
outerAngle = [225, 315, 45, 135]

# stations: horizontal leg (x), the mitre, vertical leg (z)
def horiz(x):
    return lambda a_, b_: (x, a_, b_)

def mitre():
    return lambda a_, b_: (xc - b_, a_, b_)

def vert(z):
    return lambda a_, b_: (xc - b_, a_, z)

if a.straight:
    stations = [horiz(xOut), horiz(xTurn), horiz(0.033), horiz(0.035),
                horiz(0.04)]
else:
    stations = [horiz(xOut), horiz(xTurn), mitre(), vert(zTurn), vert(zIn)]
nS = len(stations)

verts = []
for st in stations:
    for (p, q) in sec:
        verts.append(st(p, q))

def vid(k, i):
    return 8*k + i

# axial cell counts of the four segments (mean length / dx)
def seglen(k):
    p0 = stations[k](0, 0)
    p1 = stations[k + 1](0, 0)
    return math.dist(p0, p1)

nAx = [max(2, round(seglen(k)/a.dx)) for k in range(nS - 1)]
# the corner segments are short on the inside of the elbow: at least 3 cells
nAx[1] = max(nAx[1], 4)
nAx[2] = max(nAx[2], 4)

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

blocks = []
for k in range(nS - 1):
    for (c, n1, n2) in secBlocks:
        h = [vid(k, i) for i in c] + [vid(k + 1, i) for i in c]
        if vol(h) < 0:
            c = (c[0], c[3], c[2], c[1])
            n1, n2 = n2, n1
            h = [vid(k, i) for i in c] + [vid(k + 1, i) for i in c]
        assert vol(h) > 0
        blocks.append((h, (n1, n2, nAx[k])))

# curved edges: the four outer arcs of every station
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

def ringFace(k, j):
    return (vid(k, 4 + j), vid(k, 4 + (j + 1) % 4),
            vid(k + 1, 4 + (j + 1) % 4), vid(k + 1, 4 + j))

def capFaces(k):
    f = [(vid(k, 0), vid(k, 3), vid(k, 2), vid(k, 1))]
    for j in range(4):
        i0, i1 = 4 + j, 4 + (j + 1) % 4
        f.append((vid(k, i0), vid(k, i1), vid(k, i1 - 4), vid(k, i0 - 4)))
    return f

patches = [
    ("outlet", "patch", capFaces(0)),
    ("wall2", "wall", [ringFace(0, j) for j in range(4)]),
    ("turn", "wall", [ringFace(k, j) for k in (1, 2) for j in range(4)]),
    ("wall1", "wall", [ringFace(3, j) for j in range(4)]),
    ("inlet", "patch", capFaces(nS - 1)),
]

def fmt(p):
    return "(%.10g %.10g %.10g)" % p

out = []
out.append("""/*--------------------------------*- C++ -*----------------------------------*\\
  dpiFoam tutorial inhaler: the screen-haler (user guide Fig. 13), an L of
  two 7 mm tubes, O-grid blocks. Written by makeBlockMeshDict.py (%s);
  edit the script, not this file.
\\*---------------------------------------------------------------------------*/
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }

scale 1;
""" % " ".join(
    ["--%s %s" % (k, v) for k, v in vars(a).items() if k != "straight"]
  + (["--straight"] if a.straight else [])))
out.append("vertices\n(")
for i, p in enumerate(verts):
    out.append("    %s    // %d" % (fmt(p), i))
out.append(");\n\nblocks\n(")
for h, n in blocks:
    out.append("    hex (%s) (%d %d %d) simpleGrading (1 1 1)" % (" ".join(map(str, h)), *n))
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
