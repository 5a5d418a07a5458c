#!/usr/bin/python3
"""Write the device's surfaces as STL files into constant/triSurface, as a
CAD program would export them (one file per part, in metres):

    walls.stl   the duct: an L of two square channels 6 mm wide, the
                inlet leg 10 mm above the floor leg, the floor leg 36 mm
                long (everything but its two open ends)
    inlet.stl   the inlet leg's top (z = 16 mm)
    outlet.stl  the floor leg's end (x = 36 mm), the mouthpiece
    grid.stl    three bars across the floor leg at x = 24-25 mm, 0.75 mm
                high with 0.75 mm gaps between them: the grid the flow
                meets (closed boxes, longer than the duct is wide)
    bed.stl     a closed box on the floor under the inlet leg: the region
                the powder bed is packed into

    makeSurfaces.py [CASE]      (default: the current directory)

The device is the case's own: change the numbers below and run Allrun.
It is drawn in its design frame (x along the floor leg, z up) and written,
as a CAD program exports a part in a frame of its own, turned by 25
degrees about the oblique axis (1, 1, 1): no face of it is parallel to the
background mesh's cells, so snappyHexMesh snaps every wall to the surface
and to its feature edges (surfaceFeatureExtract), as with a real CAD
export. Gravity, the lab's down, is the design frame's -z turned the same
way (constant/g); the bed region, bed.stl, turns with the device. The
numbers the case's dictionaries take from this turn (the background box,
locationInMesh, g) are printed at the end (log.makeSurfaces).
"""
import math
import os
import sys

MM = 1e-3
W = 6.0         # channel width (y from -W/2 to W/2) and floor-leg height
L = 36.0        # floor leg length (x from 0)
H = 16.0        # height of the inlet (z)
GRID_X = (24.0, 25.0)
GRID_Z = ((1.0, 1.75), (2.5, 3.25), (4.0, 4.75))
BED = ((2.7, -0.3, 0.0), (3.3, 0.3, 0.2))
# The CAD frame: the design frame turned by ANGLE degrees about AXIS
AXIS = (1.0, 1.0, 1.0)
ANGLE = 25.0
INSIDE = (3.1, 0.12, 3.1)   # a point in the duct (design frame, mm)


def rotation(axis, angle):
    """The rotation matrix of angle [degrees] about axis (Rodrigues)."""
    n = sum(c*c for c in axis)**0.5
    k = [c/n for c in axis]
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    KK = [[sum(K[i][m]*K[m][j] for m in range(3)) for j in range(3)]
          for i in range(3)]
    return [[(i == j) + s*K[i][j] + (1 - c)*KK[i][j] for j in range(3)]
            for i in range(3)]


ROT = rotation(AXIS, ANGLE)


def turn(v):
    """A design-frame point in the CAD frame."""
    return tuple(sum(ROT[i][j]*v[j] for j in range(3)) for i in range(3))


def quad(a, b, c, d):
    """Two triangles of the quad a b c d (in order around it)."""
    return [(a, b, c), (a, c, d)]


def box(lo, hi):
    """The 12 triangles of a closed box, facing out."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    f = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2),
         (0, 4, 7, 3), (1, 2, 6, 5)]
    tris = []
    for a, b, c, d in f:
        tris += quad(v[a], v[b], v[c], v[d])
    return tris


def duct():
    """The L duct's walls: two side walls (an L each) and the perimeter
    without the inlet (z = H) and outlet (x = L) faces."""
    y0, y1 = -W/2, W/2
    # The L in x-z, anticlockwise from the origin; (W, W) is where the
    # inlet leg's wall meets the floor leg's roof
    outline = [(0, 0), (L, 0), (L, W), (W, W), (W, H), (0, H)]
    tris = []
    # Side walls: the floor leg's pentagon (with the T vertex (W, W)) and
    # the inlet leg's rectangle above it
    pent = [(0, 0), (L, 0), (L, W), (W, W), (0, W)]
    rect = [(0, W), (W, W), (W, H), (0, H)]
    for poly in (pent, rect):
        for k in range(1, len(poly) - 1):
            a, b, c = poly[0], poly[k], poly[k + 1]
            tris.append(((a[0], y0, a[1]), (c[0], y0, c[1]), (b[0], y0, b[1])))
            tris.append(((a[0], y1, a[1]), (b[0], y1, b[1]), (c[0], y1, c[1])))
    # Perimeter strips, except the outlet (L, 0)-(L, W) and the inlet
    # (W, H)-(0, H); the left wall x = 0 in two pieces, matching the side
    # walls' vertex (0, W)
    edges = [((0, 0), (L, 0)), ((L, W), (W, W)), ((W, W), (W, H)),
             ((0, H), (0, W)), ((0, W), (0, 0))]
    for (ax, az), (bx, bz) in edges:
        tris += quad((ax, y0, az), (bx, y0, bz), (bx, y1, bz), (ax, y1, az))
    return tris


def write(path, name, tris):
    """An ASCII STL in metres, in the CAD frame; returns its points [mm]."""
    pts = []
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for t in tris:
            p = [[c*MM for c in turn(v)] for v in t]
            pts += [turn(v) for v in t]
            u = [p[1][i] - p[0][i] for i in range(3)]
            w = [p[2][i] - p[0][i] for i in range(3)]
            n = [u[1]*w[2] - u[2]*w[1], u[2]*w[0] - u[0]*w[2],
                 u[0]*w[1] - u[1]*w[0]]
            m = sum(c*c for c in n)**0.5 or 1.0
            f.write(" facet normal %.9g %.9g %.9g\n  outer loop\n"
                    % tuple(c/m for c in n))
            for v in p:
                f.write("   vertex %.9g %.9g %.9g\n" % tuple(v))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)
    return pts


case = sys.argv[1] if len(sys.argv) > 1 else "."
out = os.path.join(case, "constant", "triSurface")
os.makedirs(out, exist_ok=True)
y0, y1 = -W/2, W/2
pts = write(os.path.join(out, "walls.stl"), "walls", duct())
write(os.path.join(out, "inlet.stl"), "inlet",
      quad((0, y0, H), (W, y0, H), (W, y1, H), (0, y1, H)))
write(os.path.join(out, "outlet.stl"), "outlet",
      quad((L, y0, 0), (L, y1, 0), (L, y1, W), (L, y0, W)))
bars = []
for z0, z1 in GRID_Z:
    bars += box((GRID_X[0], y0 - 0.5, z0), (GRID_X[1], y1 + 0.5, z1))
write(os.path.join(out, "grid.stl"), "grid", bars)
write(os.path.join(out, "bed.stl"), "bed", box(*BED))
print("makeSurfaces: walls, inlet, outlet, grid, bed in %s" % out)
print("makeSurfaces: turned by %g degrees about (%g %g %g)" % ((ANGLE,) + AXIS))
lo = [min(p[i] for p in pts) for i in range(3)]
hi = [max(p[i] for p in pts) for i in range(3)]
print("makeSurfaces: the walls' bounding box (%.3f %.3f %.3f) (%.3f %.3f %.3f) mm"
      % tuple(lo + hi))
print("makeSurfaces: locationInMesh (%.4e %.4e %.4e)"
      % tuple(c*MM for c in turn(INSIDE)))
print("makeSurfaces: g (%.6g %.6g %.6g)" % turn((0, 0, -9.81)))
