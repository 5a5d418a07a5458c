#!/usr/bin/python3
"""Replace the injectors of a dpiFoam Case 5 copy by the peer's settled agglomerate.

Usage: peerInjectors.py PEER_DUMP DPICLOUDPROPERTIES

PEER_DUMP is the peer's Case 5 post/final.part (cgs); the injectors block of
DPICLOUDPROPERTIES (tutorials/case5Agglomerate's) becomes two singleParticles lists:
the carrier and every API at the peer's positions and velocities (m, m/s), so that
dpiFoam's Case 5 and Case 6 start from the guide code's settled state (the 'paired' runs).
"""
import re
import sys

import numpy as np


def main():
    dump, props = sys.argv[1:3]
    lines = open(dump).read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[k].split()[2:]
    rows = sorted((dict(zip(cols, map(float, l.split()))) for l in lines[k + 1:] if l.strip()),
                  key=lambda r: r["id"])
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


if __name__ == "__main__":
    main()
