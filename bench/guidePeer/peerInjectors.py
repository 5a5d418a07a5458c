#!/usr/bin/python3
"""The guide code's (the peer's) particles as dpiFoam injectors.

Usage:
  peerInjectors.py PEER_DUMP DPICLOUDPROPERTIES
      Case 5 ('paired' runs of ./run): the injectors block of DPICLOUDPROPERTIES
      (tutorials/case5Agglomerate's) becomes two singleParticles lists: the carrier and every
      API at the peer's positions and velocities (m, m/s), so that dpiFoam's Case 5 and Case 6
      start from the guide code's settled state.
  peerInjectors.py --bed PEER_DUMP CASE
      The inhaler (a copy of tutorials/inhaler): the peer's stage-1 bed (e.g.
      work/inhaler/peer-s86/post/final.part, its 50 ms) becomes the injectors of the case's
      stage 1: CASE/constant/peerBed/{carrier,API}{Positions,Velocities,Spins} (OpenFOAM
      lists, m, m/s, rad/s) and two particleList injectors (carrier, API) in place of the
      regionPacking bed of CASE/constant/dpiCloudProperties.sedimentation. The parcels take
      their type's diameter and N (the dump's radius is checked against them). A stage 1 of
      one fluid step (./Allrun -guide -t1 1e-05 ...) then injects the bed, the engine finds
      its contacts at the first DEM step (overlaps as the peer left them; tangential history
      starts at zero: the dump has none) and stage 2 restarts from it (README.md).

PEER_DUMP is a LIGGGHTS dump (cgs): id type x y z ... vx vy vz [omegax omegay omegaz] radius.
"""
import os
import re
import sys

import numpy as np


def readDump(dump):
    lines = open(dump).read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[k].split()[2:]
    return sorted((dict(zip(cols, map(float, l.split()))) for l in lines[k + 1:] if l.strip()),
                  key=lambda r: r["id"])


def case5(dump, props):
    rows = readDump(dump)
    items = {1: [], 2: []}
    for r in rows:
        x = np.array([r["x"], r["y"], r["z"]])*1e-2
        v = np.array([r["vx"], r["vy"], r["vz"]])*1e-2
        items[int(r["type"])].append(
            "            { type %s; position (%.17g %.17g %.17g); U (%.17g %.17g %.17g); }"
            % (("carrier" if r["type"] == 1 else "API"), *x, *v))
    block = ("injectors\n{\n    // the guide code's settled Case 5 (%s)\n"
             "    carrier\n    {\n        type        singleParticles;\n"
             "        particles\n        (\n%s\n        );\n    }\n\n"
             "    api\n    {\n        type        singleParticles;\n"
             "        particles\n        (\n%s\n        );\n    }\n}\n"
             % (dump, "\n".join(items[1]), "\n".join(items[2])))
    text = open(props).read()
    new, n = re.subn(r"\ninjectors\n\{.*?\n\}\n", "\n" + block, text, count=1, flags=re.S)
    if n != 1:
        raise SystemExit("peerInjectors: no injectors block in %s" % props)
    open(props, "w").write(new)
    print("peerInjectors: %d carrier, %d API from %s" % (len(items[1]), len(items[2]), dump))


def writeList(path, vals, note):
    with open(path, "w") as f:
        f.write("// %s\n%d\n(\n" % (note, len(vals)))
        for v in vals:
            f.write("(%.17g %.17g %.17g)\n" % tuple(v))
        f.write(")\n")


def bed(dump, case):
    rows = readDump(dump)
    props = os.path.join(case, "constant", "dpiCloudProperties.sedimentation")
    out = os.path.join(case, "constant", "peerBed")
    os.makedirs(out, exist_ok=True)
    names = {1: "carrier", 2: "API"}
    diam = {1: 70e-6, 2: 5e-6}
    entries = []
    for t in (1, 2):
        rs = [r for r in rows if int(r["type"]) == t]
        d = np.array([2e-2*r["radius"] for r in rs])
        if len(d) and np.max(abs(d/diam[t] - 1)) > 1e-9:
            raise SystemExit("peerInjectors: type %d's diameters are not %g m" % (t, diam[t]))
        x = np.array([[r["x"], r["y"], r["z"]] for r in rs])*1e-2
        v = np.array([[r["vx"], r["vy"], r["vz"]] for r in rs])*1e-2
        w = (np.array([[r["omegax"], r["omegay"], r["omegaz"]] for r in rs])
             if rs and "omegax" in rs[0] else np.zeros_like(x))
        n = names[t]
        note = "the guide code's %s parcels from %s" % (n, os.path.abspath(dump))
        writeList(os.path.join(out, n + "Positions"), x, note + " [m]")
        writeList(os.path.join(out, n + "Velocities"), v, note + " [m/s]")
        writeList(os.path.join(out, n + "Spins"), w, note + " [rad/s]")
        entries.append(
            "    %s\n    {\n        type            particleList;\n        SOI             0;\n"
            "        particleType    %s;\n        positions       \"<constant>/peerBed/%sPositions\";\n"
            "        velocities      \"<constant>/peerBed/%sVelocities\";\n"
            "        spins           \"<constant>/peerBed/%sSpins\";\n    }\n"
            % (n.lower(), n, n, n, n))
        print("peerInjectors: %d %s parcels" % (len(rs), n))
    block = ("injectors\n{\n    // the guide code's settled bed (bench/guidePeer/peerInjectors.py --bed)\n"
             + "\n".join(entries) + "}\n")
    text = open(props).read()
    new, k = re.subn(r"\ninjectors\n\{.*?\n\}\n", "\n" + block, text, count=1, flags=re.S)
    if k != 1:
        raise SystemExit("peerInjectors: no injectors block in %s" % props)
    open(props, "w").write(new)
    print("peerInjectors: %s's injectors are the peer's bed (%s)" % (props, dump))


def main():
    a = sys.argv[1:]
    if len(a) == 3 and a[0] == "--bed":
        bed(a[1], a[2])
    elif len(a) == 2 and not a[0].startswith("-"):
        case5(a[0], a[1])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()
