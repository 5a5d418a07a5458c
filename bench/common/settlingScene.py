#!/usr/bin/python3
"""The settling-carriers scene shared by the benchmarks in bench/.

N lactose carriers (70 um, 1520 kg/m3, E 5e8 Pa, nu 0.35, e 0.85, mu 0.45,
no rolling friction, no cohesion) placed at random without overlaps in a
cubic box of walls at a given solids fraction (deterministic seed), each
with a random velocity (isotropic Gaussian, rms speed vrms, capped at
2.5 vrms), falling under gravity. At 1e-8 s per DEM step a few thousand
steps are a few tens of microseconds: gravity alone would not bring
particles placed apart into contact in that time, the random velocities
(a stirred powder settling) do.

Writers:
    dpi <dir>       a dpiFoam DEM-only case (fluid none)
    liggghts <dir>  the same scene for stock LIGGGHTS 3.8 (hertz/history)
    openfoam <dir>  the same scene for OpenFOAM's own colliding cloud
                    (icoUncoupledKinematicParcelFoam, pairSpringSliderDashpot
                    and wallLocalSpringSliderDashpot, frozen gas at rest,
                    no drag); the velocities go to <dir>/velocities.txt
                    and are set after a first step by openfoamSetU.py

With --positions the particles come from an NPZ instead (x, box, optional
v: e.g. the settled bed of bench/packedBed/bed.py, at rest) and the box
may be a cuboid.

Usage:
    settlingScene.py dpi <dir> --n 2000 --steps 4000 [--fluid-every 1000]
    settlingScene.py liggghts <dir> --n 2000 --steps 4000 [--contacts]
    settlingScene.py openfoam <dir> --n 2000 --steps 4000 [--of-cell 2]
                     [--of-write-end]
Common options: --phi 0.15 --vrms 0.5 --seed 20240 --dt 1e-8
                --order random|morton (list order, same particles)
                --positions bed.npz (--n 1: its first particle alone)
                --skin 7e-5 --max-impact-velocity 3
"""

import argparse
import math
import os
import sys

import numpy as np

# Material of the carriers and the walls (both types use it)
DIAMETER = 70e-6        # [m]
DENSITY = 1520.0        # [kg/m3]
YOUNG = 5e8             # [Pa]
POISSON = 0.35
RESTITUTION = 0.85
FRICTION = 0.45
GRAVITY = 9.81          # [m/s2], -z


def boxOf(L):
    """(Lx, Ly, Lz) of a box given by one edge (a cube) or three."""
    return tuple(float(c) for c in np.broadcast_to(np.asarray(L, float), (3,)))


def place(n, box, rng, d=None):
    """n centres of spheres of diameter d (DIAMETER) at random without
    overlaps in the box [0, Lx] x [0, Ly] x [0, Lz] (random sequential
    addition on a cell grid): candidate centres uniform in
    [r + gap, L - r - gap] per axis, accepted when no accepted centre is
    closer than d (1 + 1e-3). At solids fractions <= 0.2 this needs ~1.3
    candidates a particle (the jamming limit of the method is ~0.38)."""
    d = DIAMETER if d is None else d
    r = 0.5*d
    box = np.array(boxOf(box))
    gap = 0.01*d
    lo, hi = r + gap, box - r - gap
    if np.all(box == box[0]):
        hi = hi[0]               # a cube: the same draws as always
    dmin2 = (d*(1 + 1e-3))**2

    h = d*(1 + 1e-3)                 # cell size: partners within 27 cells
    nc = np.maximum(1, (box/h).astype(int))
    h = box/nc
    grid = {}
    x = np.empty((n, 3))
    k = 0
    tries = 0
    batch = rng.uniform(lo, hi, size=(4096, 3))
    b = 0
    while k < n:
        if b == len(batch):
            batch = rng.uniform(lo, hi, size=(4096, 3))
            b = 0
        p = batch[b]
        b += 1
        tries += 1
        if tries > 200*n:
            sys.exit("settlingScene: cannot place %d particles at phi %g"
                     % (n, n*math.pi/6*d**3/np.prod(box)))
        c = (int(p[0]/h[0]), int(p[1]/h[1]), int(p[2]/h[2]))
        ok = True
        for i in (c[0] - 1, c[0], c[0] + 1):
            for j in (c[1] - 1, c[1], c[1] + 1):
                for l in (c[2] - 1, c[2], c[2] + 1):
                    for q in grid.get((i, j, l), ()):
                        dx = x[q] - p
                        if dx[0]*dx[0] + dx[1]*dx[1] + dx[2]*dx[2] < dmin2:
                            ok = False
                            break
                    if not ok:
                        break
                if not ok:
                    break
            if not ok:
                break
        if ok:
            x[k] = p
            grid.setdefault(c, []).append(k)
            k += 1
    return x


def generate(n, phi, vrms, seed):
    """Positions, velocities and box edge L for n carriers: placed at
    random without overlaps in a cube at solids fraction phi (place()),
    velocities Gaussian per component, rms speed vrms, capped at 2.5 vrms.
    """
    d = DIAMETER
    vp = math.pi/6*d**3
    L = (n*vp/phi)**(1/3)
    rng = np.random.default_rng(seed)
    x = place(n, L, rng, d)

    # Velocities: Gaussian components, rms speed vrms, capped at 2.5 vrms
    sigma = vrms/math.sqrt(3.0)
    v = rng.normal(0.0, sigma, size=(n, 3))
    cap = 2.5*vrms
    speed = np.linalg.norm(v, axis=1)
    big = speed > cap
    v[big] *= (cap/speed[big])[:, None]

    return x, v, L


def mortonOrder(x, L):
    """Permutation that sorts the particles along a Morton (Z-order) curve
    on cells of one diameter: neighbours in space become neighbours in
    the list (the row order the DEM sees)."""
    nc = max(1, int(L/DIAMETER))
    ijk = np.clip((x/L*nc).astype(np.int64), 0, nc - 1)
    code = np.zeros(len(x), dtype=np.int64)
    for bit in range(21):
        for d in range(3):
            code |= ((ijk[:, d] >> bit) & 1) << (3*bit + d)
    return np.argsort(code, kind="stable")


def check(x, L):
    """Smallest gap between particles and to the walls (for the log)."""
    r = 0.5*DIAMETER
    wall = min(x.min() - r, (L - x.max()) - r)
    # Pair check on a grid (vectorised per cell would be overkill here)
    h = DIAMETER
    nc = max(1, int(L/h))
    h = L/nc
    cells = {}
    for i, p in enumerate(x):
        cells.setdefault(tuple((p/h).astype(int)), []).append(i)
    best = np.inf
    for c, members in cells.items():
        near = []
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for dk in (-1, 0, 1):
                    near += cells.get((c[0] + di, c[1] + dj, c[2] + dk), [])
        near = np.array(near)
        for i in members:
            dd = np.linalg.norm(x[near] - x[i], axis=1)
            dd = dd[near != i]
            if dd.size:
                best = min(best, dd.min())
    return best - DIAMETER, wall


def writeBlockMesh(case, L, cell, nMin, comment="", patch="walls",
                   patchType="wall"):
    """system/blockMeshDict of the box [0, Lx] x [0, Ly] x [0, Lz] (L: one
    edge or three), all faces in one patch (default: the wall patch
    `walls`), cells of about `cell` [m] (at least nMin per edge)."""
    box = boxOf(L)
    n = [max(nMin, int(round(e/cell))) for e in box]
    with open(os.path.join(case, "system/blockMeshDict"), "w") as f:
        f.write(header("dictionary", "blockMeshDict"))
        f.write(comment)
        if box[0] == box[1] == box[2]:
            f.write("scale %.12g;\n" % box[0])
            f.write("vertices\n(\n    (0 0 0) (1 0 0) (1 1 0) (0 1 0)\n"
                    "    (0 0 1) (1 0 1) (1 1 1) (0 1 1)\n);\n")
        else:
            f.write("scale 1;\nvertices\n(\n")
            for z in (0.0, box[2]):
                f.write("   ")
                for xy in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    f.write(" (%.12g %.12g %.12g)"
                            % (xy[0]*box[0], xy[1]*box[1], z))
                f.write("\n")
            f.write(");\n")
        f.write("blocks\n(\n    hex (0 1 2 3 4 5 6 7) (%d %d %d) "
                "simpleGrading (1 1 1)\n);\n" % tuple(n))
        f.write("boundary\n(\n    %s\n    {\n        type %s;\n"
                "        faces\n        (\n"
                "            (0 4 7 3) (2 6 5 1) (1 5 4 0)\n"
                "            (0 3 2 1) (4 5 6 7) (3 7 6 2)\n"
                "        );\n    }\n);\n" % (patch, patchType))


def writeDecomposeParDict(case):
    """system/decomposeParDict: 2 processors, split along x."""
    with open(os.path.join(case, "system/decomposeParDict"), "w") as f:
        f.write(header("dictionary", "decomposeParDict"))
        f.write("numberOfSubdomains 2;\nmethod simple;\n"
                "coeffs { n (2 1 1); }\n")


def writeNoSolvers(case):
    """system/fvSolution with no solvers: the case has no gas to solve."""
    with open(os.path.join(case, "system/fvSolution"), "w") as f:
        f.write(header("dictionary", "fvSolution"))
        f.write("solvers {}\n")


def writeNoFluid(case):
    """constant/couplingProperties of a DEM-only dpiFoam case."""
    with open(os.path.join(case, "constant/couplingProperties"), "w") as f:
        f.write(header("dictionary", "couplingProperties"))
        f.write("fluid       none;\ncloudName   dpiCloud;\n")


def writeGravity(case, g):
    """constant/g: the gravity vector g (3 numbers) [m/s2]."""
    with open(os.path.join(case, "constant/g"), "w") as f:
        f.write(header("uniformDimensionedVectorField", "g"))
        f.write("dimensions      [0 1 -2 0 0 0 0];\n"
                "value           (%.12g %.12g %.12g);\n" % tuple(g))


def header(cls, obj):
    return ("FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            "    class       %s;\n    object      %s;\n}\n" % (cls, obj))


def dpiCloudPreamble(rho):
    """The part of a DEM-only dpiCloudProperties before its dem dictionary:
    a KinematicCloud without gas, stock submodels off (the DEM engine
    replaces them), particle density rho [kg/m^3]"""
    return """solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes { rho.none cell; U.none cell; mu.none cell; }
    integrationSchemes { U Euler; }
}

constantProperties
{
    rho0            %g;
    alphaMax        0.9;
}

subModels
{
    particleForces {}
    injectionModels {}
    dispersionModel none;
    patchInteractionModel none;
    stochasticCollisionModel none;
    surfaceFilmModel none;
}

cloudFunctions {}
""" % rho


def maxImpactVelocity(vrms):
    # Two particles at the cap speed head-on, plus a margin
    return max(1.0, 2*2.5*vrms*1.2)


def writeDpi(case, x, v, L, args):
    """A dpiFoam DEM-only case: box of walls (patch walls), carriers."""
    for sub in ("system", "constant"):
        os.makedirs(os.path.join(case, sub), exist_ok=True)

    n = len(x)
    dt = args.dt
    # Mesh: cells of about 5 carrier diameters (a fluid mesh of a real run
    # is of that order); the DEM does not use it, tracking does once per
    # fluid step
    writeBlockMesh(case, L, 5*DIAMETER, 4,
                   "// settlingCarriers: cubic box of edge %.9g m, all walls\n"
                   % boxOf(L)[0])

    every = args.fluid_every
    nFluid = args.steps//every
    with open(os.path.join(case, "system/controlDict"), "w") as f:
        f.write(header("dictionary", "controlDict"))
        f.write("// DEM only: deltaT = coupling interval = %d DEM steps of "
                "%g s; %d fluid steps\n" % (every, dt, nFluid))
        f.write("application     dpiFoam;\nstartFrom       startTime;\n"
                "startTime       0;\nstopAt          endTime;\n")
        f.write("endTime         %.12g;\n" % (nFluid*every*dt))
        f.write("deltaT          %.12g;\n" % (every*dt))
        f.write("writeControl    timeStep;\nwriteInterval   1000000;\n"
                "purgeWrite      0;\nwriteFormat     binary;\n"
                "writePrecision  17;\nwriteCompression off;\n"
                "timeFormat      general;\ntimePrecision   10;\n"
                "runTimeModifiable false;\n")

    with open(os.path.join(case, "system/fvSchemes"), "w") as f:
        f.write(header("dictionary", "fvSchemes"))
        f.write("ddtSchemes { default Euler; }\n"
                "gradSchemes { default Gauss linear; }\n"
                "divSchemes { default none; }\n"
                "laplacianSchemes { default Gauss linear corrected; }\n"
                "interpolationSchemes { default linear; }\n"
                "snGradSchemes { default corrected; }\n")
    writeNoSolvers(case)
    writeDecomposeParDict(case)

    writeNoFluid(case)
    writeGravity(case, args.g)

    # Plain lists for the particleList injector (read as a lagrangian
    # field is; one dictionary per particle would dominate the set-up time
    # and the peak memory at 50,000: bench/packedBed/NOTES.md)
    for name, values in (("carrierPositions", x), ("carrierVelocities", v)):
        with open(os.path.join(case, "constant", name), "w") as f:
            f.write("// %d carriers, %s (bench/common/settlingScene.py)\n"
                    % (n, args.source))
            f.write("%d\n(\n" % len(values))
            for p in values:
                f.write("(%.10e %.10e %.10e)\n" % (p[0], p[1], p[2]))
            f.write(")\n")

    with open(os.path.join(case, "constant/dpiCloudProperties"), "w") as f:
        f.write(header("dictionary", "dpiCloudProperties"))
        f.write("""// settlingCarriers benchmark (bench/common/settlingScene.py)
%(preamble)s
dem
{
    timeStep        %(dt)g;

    types
    {
        carrier
        {
            diameter        %(d)g;
            density         %(rho)g;
            youngsModulus   %(E)g;
            poissonsRatio   %(nu)g;
            N               1;
        }
        wallMaterial
        {
            youngsModulus   %(E)g;
            poissonsRatio   %(nu)g;
        }
    }

    pairs
    {
        default { restitution %(e)g; friction %(mu)g; rollingFriction 0; }
    }

    normalModel         hertzParcel;
    tangentialModel     historyParcel;
    rollingModel        none;
    cohesionModel       none;

    walls
    {
%(walls)s    }

    // Verlet skin: the default (smallest diameter), stated for the peers
    neighbourSearch { skin %(skin)g; order %(sweep)s; }

    timeStepCheck { maxImpactVelocity %(vmax)g; }
}

injectors
{
    carriers
    {
        type            particleList;
        particleType    carrier;
        order           %(idOrder)s;
        positions       "<constant>/carrierPositions";
        velocities      "<constant>/carrierVelocities";
    }
}
""" % dict(preamble=dpiCloudPreamble(DENSITY), rho=DENSITY, dt=dt, d=DIAMETER, E=YOUNG, nu=POISSON,
           e=RESTITUTION, mu=FRICTION, skin=args.skin,
           vmax=args.max_impact_velocity, idOrder=args.dpi_order,
           sweep=args.dpi_sweep, walls=dpiWalls(L, args.walls)))


def boxFaces(L):
    """The six faces of the box [0, Lx] x [0, Ly] x [0, Lz]: (axis index,
    axis name, side lo|hi, the face's coordinate, the inward normal's
    sign)."""
    for k, (a, e) in enumerate(zip("xyz", boxOf(L))):
        yield k, a, "lo", 0.0, 1
        yield k, a, "hi", e, -1


def dpiWalls(L, kind):
    """The dpiFoam walls of the box: the mesh patch `walls` (mesh, the
    default) or six plane walls on its faces (planes)."""
    if kind != "planes":
        return ("        box { type patch; patches (walls); "
                "material wallMaterial; }\n")
    walls = ""
    for k, a, side, pos, sign in boxFaces(L):
        p = [0.0, 0.0, 0.0]
        p[k] = pos
        nrm = [0, 0, 0]
        nrm[k] = sign
        walls += ("        %s%s { type plane; point (%.12g %.12g %.12g); "
                  "normal (%d %d %d); material wallMaterial; }\n"
                  % (a, side, p[0], p[1], p[2], nrm[0], nrm[1], nrm[2]))
    return walls


def writeLiggghtsData(path, x, v, L, title):
    """A LIGGGHTS data file: the carriers (type 1; type 2 is the walls'
    material) in the box [0, Lx] x [0, Ly] x [0, Lz], velocities v."""
    with open(path, "w") as f:
        f.write(title + "\n\n")
        f.write("%d atoms\n2 atom types\n\n" % len(x))
        for a, e in zip("xyz", boxOf(L)):
            f.write("0 %.12g %slo %shi\n" % (e, a, a))
        f.write("\nAtoms\n\n")
        for i, p in enumerate(x):
            f.write("%d 1 %g %g %.10e %.10e %.10e\n"
                    % (i + 1, DIAMETER, DENSITY, p[0], p[1], p[2]))
        f.write("\nVelocities\n\n")
        for i, u in enumerate(v):
            f.write("%d %.10e %.10e %.10e 0 0 0\n" % (i + 1, u[0], u[1], u[2]))


def liggghtsWalls(L, kind="planes"):
    """Six primitive plane walls (type 2) on the faces of the box, or
    (mesh) the box as a triangle mesh, box.stl (writeBoxStl)."""
    if kind == "mesh":
        return ("fix box all mesh/surface file box.stl type 2\n"
                "fix wbox all wall/gran model hertz tangential history "
                "mesh n_meshes 1 meshes box\n")
    walls = ""
    for _, a, side, pos, _ in boxFaces(L):
        walls += ("fix w%s%s all wall/gran model hertz tangential history"
                  " primitive type 2 %splane %.12g\n" % (a, side, a, pos))
    return walls


def writeBoxStl(path, L):
    """The box [0, Lx] x [0, Ly] x [0, Lz] as an ASCII STL: two triangles
    a face, normals outwards."""
    b = boxOf(L)
    c = [(i*b[0], j*b[1], k*b[2]) for k in (0, 1) for j in (0, 1)
         for i in (0, 1)]
    # faces as corner indices (i + 2 j + 4 k), counter-clockwise seen
    # from outside
    quads = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3),
             (0, 4, 6, 2), (1, 3, 7, 5))
    with open(path, "w") as f:
        f.write("solid box\n")
        for q in quads:
            for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                p = [np.array(c[i]) for i in t]
                nrm = np.cross(p[1] - p[0], p[2] - p[0])
                nrm /= np.linalg.norm(nrm)
                f.write("facet normal %g %g %g\nouter loop\n" % tuple(nrm))
                for v in p:
                    f.write("vertex %.12g %.12g %.12g\n" % tuple(v))
                f.write("endloop\nendfacet\n")
        f.write("endsolid box\n")


def liggghtsMaterial(E, nu, e, mu):
    """The LIGGGHTS material of both types (carriers and walls)."""
    return ("fix m1 all property/global youngsModulus peratomtype %(E)g %(E)g\n"
            "fix m2 all property/global poissonsRatio peratomtype %(nu)g %(nu)g\n"
            "fix m3 all property/global coefficientRestitution peratomtypepair"
            " 2 %(e)g %(e)g %(e)g %(e)g\n"
            "fix m4 all property/global coefficientFriction peratomtypepair 2"
            " %(mu)g %(mu)g %(mu)g %(mu)g\n" % dict(E=E, nu=nu, e=e, mu=mu))


def writeLiggghts(case, x, v, L, args):
    """The same scene for stock LIGGGHTS 3.8: hertz/history pair and six
    primitive plane walls of the same material, same skin, nve/sphere."""
    os.makedirs(case, exist_ok=True)
    n = len(x)
    # --contacts: the pair contacts summed over the atoms (each pair twice)
    # in the thermo output, after the rotational energy
    contacts = contactsThermo = ""
    if args.contacts:
        contacts = ("compute         cn all contact/atom\n"
                    "compute         cnsum all reduce sum c_cn\n")
        contactsThermo = " c_cnsum"
    writeLiggghtsData(os.path.join(case, "data.settling"), x, v, L,
                      "settlingCarriers: %d carriers, %s" % (n, args.source))
    if args.walls == "mesh":
        writeBoxStl(os.path.join(case, "box.stl"), L)

    with open(os.path.join(case, "in.settling"), "w") as f:
        f.write(liggghtsSetup(
            "settlingCarriers in stock LIGGGHTS (bench/common/settlingScene.py)",
            "data.settling", args.skin, YOUNG, RESTITUTION, FRICTION, args.dt,
            args.g, L, args.walls or "planes"))
        f.write("""%(contacts)sthermo_style    custom step atoms ke c_rke%(contactsThermo)s
thermo          %(every)d
thermo_modify   lost ignore norm no

# -var nsteps 0 on the command line: set-up only (the CPU baseline)
variable        nsteps index %(steps)d
run             ${nsteps}
""" % dict(every=args.fluid_every, steps=args.steps, contacts=contacts,
           contactsThermo=contactsThermo))


def liggghtsSetup(title, data, skin, E, e, mu, dt, g, L, walls="planes"):
    """The start of a LIGGGHTS input: the carriers of the data file (type
    1, walls type 2, one material of Young's modulus E, restitution e,
    friction mu), hertz/history, six plane walls of the box L, gravity g
    [m/s2] along -z (or a vector), nve/sphere, neighbour skin, time step
    dt, and the
    compute rke (rotational energy); thermo and run are the caller's."""
    return """# %(title)s
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
units           si
processors      * * *

read_data       %(data)s

neighbor        %(skin)g bin
neigh_modify    delay 0 every 1 check yes

%(material)s
pair_style      gran model hertz tangential history
pair_coeff      * *

timestep        %(dt)g

fix             grav all gravity %(g)s
%(walls)s
fix             integr all nve/sphere

compute         rke all erotate/sphere
""" % dict(title=title, data=data, skin=skin,
           material=liggghtsMaterial(E, POISSON, e, mu), dt=dt,
           g=liggghtsGravity(g), walls=liggghtsWalls(L, walls))


def liggghtsGravity(g):
    """fix gravity's arguments for g [m/s2] along -z, or a vector g."""
    g = np.broadcast_to(np.asarray(g, float), (3,)) if np.ndim(g) \
        else np.array([0.0, 0.0, -float(g)])
    mag = float(np.linalg.norm(g))
    return "%.12g vector %.12g %.12g %.12g" % ((mag,) + tuple(g/mag))


def tsujiAlpha(e):
    """OpenFOAM's pairSpringSliderDashpot damping eta = alpha sqrt(M kN)
    delta^(1/4) with kN = (4/3) E* sqrt(R) is LIGGGHTS' Hertz dashpot
    gamma_n = -2 sqrt(5/6) beta sqrt(S_n m*), S_n = 2 E* sqrt(R delta),
    when alpha = -sqrt(5) beta (theory 1.3): same restitution."""
    beta = math.log(e)/math.sqrt(math.log(e)**2 + math.pi**2)
    return -math.sqrt(5.0)*beta


def writeOpenfoam(case, x, v, L, args):
    """The same scene for OpenFOAM v1912's colliding kinematic cloud:
    icoUncoupledKinematicParcelFoam (the gas is a frozen field at rest, no
    drag force: only gravity and collisions), manualInjection of the
    positions at t = 0 (U 0), Hertz pairSpringSliderDashpot (b 1.5) with
    alpha from the restitution, the same E, nu, mu for particles and walls,
    deltaT = the DEM step with one collision sub-cycle. The per-particle
    velocities are written to velocities.txt (in injection order = origId)
    and set after the first step (openfoamSetU.py)."""
    for sub in ("system", "constant", "0"):
        os.makedirs(os.path.join(case, sub), exist_ok=True)
    n = len(x)
    dt = args.dt
    alpha = tsujiAlpha(RESTITUTION)
    # OpenFOAM's pair search visits the particles of the neighbouring cells
    # within maxInteractionDistance: its cost grows with the particles per
    # cell, so its mesh is finer than dpiFoam's (--of-cell diameters)
    writeBlockMesh(case, L, args.of_cell*DIAMETER, 2)
    # One first step (t = dt: injection), then the run proper from dt
    with open(os.path.join(case, "system/controlDict"), "w") as f:
        f.write(header("dictionary", "controlDict"))
        f.write("application     icoUncoupledKinematicParcelFoam;\n"
                "startFrom       latestTime;\nstartTime       0;\n"
                "stopAt          endTime;\n")
        f.write("endTime         %.12g;\n" % ((args.steps + 1)*dt))
        f.write("deltaT          %.12g;\n" % dt)
        f.write("writeControl    timeStep;\nwriteInterval   %d;\n"
                % (args.steps + 1 if args.of_write_end else 1000000000))
        f.write("purgeWrite      0;\nwriteFormat     ascii;\n"
                "writePrecision  17;\nwriteCompression off;\n"
                "timeFormat      general;\ntimePrecision   12;\n"
                "runTimeModifiable false;\n")
    with open(os.path.join(case, "system/fvSchemes"), "w") as f:
        f.write(header("dictionary", "fvSchemes"))
        f.write("ddtSchemes { default none; }\ngradSchemes { default none; }\n"
                "divSchemes { default none; }\n"
                "laplacianSchemes { default none; }\n"
                "interpolationSchemes { default linear; }\n")
    writeNoSolvers(case)
    writeDecomposeParDict(case)
    writeGravity(case, args.g)
    with open(os.path.join(case, "constant/transportProperties"), "w") as f:
        f.write(header("dictionary", "transportProperties"))
        f.write("rhoInf 1.2;\ntransportModel Newtonian;\nnu 1.5e-05;\n")
    with open(os.path.join(case, "constant/turbulenceProperties"), "w") as f:
        f.write(header("dictionary", "turbulenceProperties"))
        f.write("simulationType laminar;\n")
    with open(os.path.join(case, "0/U"), "w") as f:
        f.write(header("volVectorField", "U"))
        f.write("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n"
                "boundaryField { walls { type noSlip; } }\n")
    with open(os.path.join(case, "constant/kinematicCloudPositions"),
              "w") as f:
        f.write(header("vectorField", "kinematicCloudPositions"))
        f.write("%d\n(\n" % n)
        for p in x:
            f.write("(%.10e %.10e %.10e)\n" % (p[0], p[1], p[2]))
        f.write(")\n")
    np.savetxt(os.path.join(case, "velocities.txt"), v, fmt="%.10e",
               header="initial velocities in injection order (origId)")

    wall = ("youngsModulus %(E)g; poissonsRatio %(nu)g; alpha %(a).8g; "
            "b 1.5; mu %(mu)g; cohesionEnergyDensity 0;"
            % dict(E=YOUNG, nu=POISSON, a=alpha, mu=FRICTION))
    with open(os.path.join(case, "constant/kinematicCloudProperties"),
              "w") as f:
        f.write(header("dictionary", "kinematicCloudProperties"))
        f.write("""// settlingCarriers in OpenFOAM's colliding cloud
// (bench/common/settlingScene.py); alpha = -sqrt(5) beta(e = %(e)g)
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           1;
    interpolationSchemes { rho cell; U cell; mu cell; }
    integrationSchemes { U Euler; }
}

constantProperties
{
    rho0            %(rho)g;
    youngsModulus   %(E)g;
    poissonsRatio   %(nu)g;
}

subModels
{
    particleForces
    {
        gravity;
    }

    injectionModels
    {
        carriers
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "kinematicCloudPositions";
            U0              (0 0 0);
            sizeDistribution
            {
                type        fixedValue;
                fixedValueDistribution { value %(d)g; }
            }
        }
    }

    dispersionModel none;
    patchInteractionModel none;
    surfaceFilmModel none;
    stochasticCollisionModel none;

    collisionModel pairCollision;

    pairCollisionCoeffs
    {
        maxInteractionDistance  %(d)g;
        writeReferredParticleCloud no;

        pairModel pairSpringSliderDashpot;
        pairSpringSliderDashpotCoeffs
        {
            useEquivalentSize   no;
            alpha               %(a).8g;
            b                   1.5;
            mu                  %(mu)g;
            cohesionEnergyDensity 0;
            // one sub-cycle per deltaT (= the DEM step) up to ~50 m/s
            collisionResolutionSteps 12;
        }

        wallModel    wallLocalSpringSliderDashpot;
        wallLocalSpringSliderDashpotCoeffs
        {
            useEquivalentSize no;
            collisionResolutionSteps 12;
            walls { %(wall)s }
        }
    }
}

cloudFunctions {}
""" % dict(e=RESTITUTION, rho=DENSITY, E=YOUNG, nu=POISSON, d=DIAMETER,
           a=alpha, mu=FRICTION, wall=wall))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("kind", choices=("dpi", "liggghts", "openfoam"))
    ap.add_argument("case")
    ap.add_argument("--n", type=int, required=True)
    ap.add_argument("--steps", type=int, default=4000)
    ap.add_argument("--fluid-every", type=int, default=1000,
                    help="DEM steps per fluid (coupling) step")
    ap.add_argument("--phi", type=float, default=0.15)
    ap.add_argument("--vrms", type=float, default=0.5)
    ap.add_argument("--seed", type=int, default=20240)
    ap.add_argument("--dt", type=float, default=1e-8)
    ap.add_argument("--order", choices=("random", "morton"), default="random",
                    help="order of the particle list (the parcels' rows): "
                    "random (as placed) or sorted along a Morton curve")
    ap.add_argument("--dpi-order", choices=("none", "morton"),
                    default="none",
                    help="dpiFoam: the injector's order (globalIds as "
                    "listed, or along a Morton curve)")
    ap.add_argument("--dpi-sweep", choices=("globalId", "morton"),
                    default="globalId",
                    help="dpiFoam's pair sweep and sums (neighbourSearch/"
                         "order): in globalId order (the default), or along "
                         "a Morton curve of the positions at each fluid step")
    ap.add_argument("--of-cell", type=float, default=2.0,
                    help="openfoam: mesh cell edge in diameters")
    ap.add_argument("--of-write-end", action="store_true",
                    help="openfoam: write the cloud at the last step")
    ap.add_argument("--positions", metavar="NPZ",
                    help="take the particles from NPZ (arrays x [m], box "
                    "[m], optional v [m/s]; e.g. a settled bed of "
                    "bench/packedBed/bed.py) instead of placing them; "
                    "--phi, --vrms, --seed, --order then do not apply")
    ap.add_argument("--skin", type=float, default=DIAMETER,
                    help="Verlet skin [m] (dpiFoam, LIGGGHTS)")
    ap.add_argument("--max-impact-velocity", type=float,
                    help="dpiFoam timeStepCheck [m/s] (default from --vrms)")
    ap.add_argument("--walls", choices=("planes", "mesh"),
                    help="the box's walls: six planes, or a mesh (dpiFoam "
                    "the mesh patch, LIGGGHTS an STL); default dpiFoam's "
                    "mesh patch and LIGGGHTS' planes")
    ap.add_argument("--contacts", action="store_true",
                    help="liggghts: pair contacts in the thermo output")
    args = ap.parse_args()
    if args.max_impact_velocity is None:
        args.max_impact_velocity = maxImpactVelocity(args.vrms)

    if args.steps % args.fluid_every:
        sys.exit("settlingScene: --steps must be a multiple of --fluid-every")
    # the benchmarks time the solver loop from the first fluid step's end
    # to the last's (start-up excluded): that needs two fluid steps
    if args.steps < 2*args.fluid_every:
        sys.exit("settlingScene: --steps %d gives %d fluid step(s) of "
                 "--fluid-every %d; the timed loop needs at least 2"
                 % (args.steps, args.steps//args.fluid_every,
                    args.fluid_every))

    args.g = (0.0, 0.0, -GRAVITY)
    if args.positions:
        x, v, L, args.g = loadPositions(args.positions, args.n)
        args.source = "from %s" % os.path.basename(args.positions)
        print("settlingScene: %d particles from %s, box %s mm"
              % (len(x), args.positions,
                 " x ".join("%.4g" % (e*1e3) for e in boxOf(L))))
        write(args.kind, args.case, x, v, L, args)
        return

    x, v, L = generate(args.n, args.phi, args.vrms, args.seed)
    args.source = "seed %d, phi %g, vrms %g m/s, order %s" % (
        args.seed, args.phi, args.vrms, args.order)
    if args.order == "morton":
        perm = mortonOrder(x, L)
        x, v = x[perm], v[perm]
    gapPair, gapWall = check(x, L)
    if gapPair <= 0 or gapWall <= 0:
        sys.exit("settlingScene: overlap in the generated packing")
    print("settlingScene: %d carriers in a box of %.4g mm, phi %.3f, "
          "smallest gap %.3g um (pairs) %.3g um (walls), vrms %g m/s"
          % (args.n, L*1e3, args.n*math.pi/6*DIAMETER**3/L**3,
             gapPair*1e6, gapWall*1e6, args.vrms))

    write(args.kind, args.case, x, v, L, args)


def write(kind, case, x, v, L, args):
    {"dpi": writeDpi, "liggghts": writeLiggghts,
     "openfoam": writeOpenfoam}[kind](case, x, v, L, args)


def loadPositions(path, n=None):
    """x, v (zero if not stored), box and gravity g [m/s2] (-z if not
    stored) of an NPZ of particles; n, when given, must match (or 1: the
    first particle only, an 'empty' case)."""
    data = np.load(path)
    x = np.array(data["x"], float)
    v = np.array(data["v"], float) if "v" in data else np.zeros_like(x)
    if n is not None and n != len(x):
        if n != 1:
            sys.exit("settlingScene: --n %d but %s has %d particles"
                     % (n, path, len(x)))
        x, v = x[:1], v[:1]
    g = np.array(data["g"], float) if "g" in data \
        else np.array([0.0, 0.0, -GRAVITY])
    return x, v, np.array(data["box"], float), g


if __name__ == "__main__":
    main()
