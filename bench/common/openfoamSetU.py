#!/usr/bin/python3
"""Set the velocities of OpenFOAM's kinematic cloud in a written time
directory from a table in injection order (bench/common/settlingScene.py
writes velocities.txt): U[i] = table[origId[i]].

    openfoamSetU.py <timeDir> <velocities.txt> [--cloud kinematicCloud]

Reads and rewrites the ASCII fields <timeDir>/lagrangian/<cloud>/{origId,U}
(serial case, written with writeFormat ascii).
"""
import argparse
import os
import re
import sys

import numpy as np


def readList(path):
    """Body of an ASCII OpenFOAM list field: header text, count, items."""
    text = open(path).read()
    m = re.search(r"\n(\d+)\s*\n\(\n", text)
    if not m:
        m3 = re.search(r"\n(\d+)\((.*)\)[ \t]*\n", text)
        if m3:       # short list on one line: n(a b) or n((x y z) ...)
            body = m3.group(2)
            items = re.findall(r"\([^()]*\)", body) if "(" in body \
                else body.split()
            if len(items) != int(m3.group(1)):
                sys.exit("openfoamSetU: cannot parse %s" % path)
            return (text[:m3.start() + 1], items,
                    "\n)\n" + text[m3.end():])
        m2 = re.search(r"\n(\d+)\{([^}]*)\}", text)
        if m2:       # uniform list: n{value}
            return (text[:m2.start() + 1], [m2.group(2)]*int(m2.group(1)),
                    "\n)\n" + text[m2.end():])
        sys.exit("openfoamSetU: cannot parse %s" % path)
    n = int(m.group(1))
    start = m.end()
    end = text.index("\n)", start)
    items = text[start:end].split("\n")
    if len(items) != n:
        sys.exit("openfoamSetU: %s lists %d items, expected %d"
                 % (path, len(items), n))
    return text[:m.start() + 1], items, text[end:]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("time")
    ap.add_argument("velocities")
    ap.add_argument("--cloud", default="kinematicCloud")
    a = ap.parse_args()
    d = os.path.join(a.time, "lagrangian", a.cloud)
    _, ids, _ = readList(os.path.join(d, "origId"))
    ids = np.array([int(i) for i in ids])
    v = np.loadtxt(a.velocities, ndmin=2)
    if len(ids) != len(v) or sorted(ids) != list(range(len(v))):
        sys.exit("openfoamSetU: %d parcels with origId, %d velocities"
                 % (len(ids), len(v)))
    head, items, tail = readList(os.path.join(d, "U"))
    rows = ["(%.10e %.10e %.10e)" % tuple(v[i]) for i in ids]
    with open(os.path.join(d, "U"), "w") as f:
        f.write(head + "%d\n(\n" % len(rows) + "\n".join(rows) + tail)
    print("openfoamSetU: %d velocities set in %s" % (len(rows), d))


if __name__ == "__main__":
    main()
