#!/usr/bin/env python3
"""The state a settled bed hands to the breath: its contact histories by
kind, and its motion; and that state with some of it reset, in place.

A contact's history is its tangential spring xi (doc/theory.md 1.4),
written with the cloud as contactKeys (the partner: a globalId, or < 0 for
a wall) and contactXi, one list per parcel. A missing entry is xi = 0, a
contact that begins afresh, so resetting a kind is dropping its entries.

Kinds, by the types of the two sides (typeId 0 carrier, 1 API):
  cc carrier-carrier, cw carrier-wall, ac API-carrier,
  aa API-API, aw API-wall

Motion: U and omega; --still carrier,API sets them to zero for the types
named (typeId 0 carrier, 1 API), the bed at rest where it lies.

  handOver.py CASE --time T [--reset cc,cw,...] [--still carrier,API]
  handOver.py --check [--reset ...] [--still ...]

prints one line per kind of contact (contacts, mean and largest |xi|) and
per type (mean |U| and |omega|); --reset rewrites
CASE/T/lagrangian/dpiCloud/contactKeys and contactXi without the kinds
named, --still its U and omega (the case is edited in place: give it a
copy). --check only checks the kinds and types named (handOver does, before
it copies any case: the names are listed here alone).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "scripts"))
import foamLagrangian as fl  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bedFrom import API, CARRIER  # noqa: E402

KINDS = ("cc", "cw", "ac", "aa", "aw")
TYPES = {"carrier": CARRIER, "API": API}    # name: typeId


def kinds(typeId, globalId, keys):
    """The kind of every contact, row by row."""
    typeOf = dict(zip(globalId.astype(int), typeId.astype(int)))
    out = []
    for i, row in enumerate(keys):
        own = "a" if typeId[i] == API else "c"
        ks = []
        for key in row:
            if key < 0:
                ks.append(own + "w")
            else:
                other = "a" if typeOf.get(key, -1) == API else "c"
                ks.append("".join(sorted(own + other)))
        out.append(ks)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", nargs="?")
    ap.add_argument("--time")
    ap.add_argument("--check", action="store_true",
                    help="check --reset and --still, touch no case")
    ap.add_argument("--reset", default="",
                    help="kinds to reset, comma-separated (%s)" % ",".join(KINDS))
    ap.add_argument("--still", default="",
                    help="types to stop, comma-separated (%s)" % ",".join(TYPES))
    a = ap.parse_args()
    reset = [k for k in a.reset.split(",") if k]
    still = [k for k in a.still.split(",") if k]
    for given, valid, what in ((reset, KINDS, "--reset kind"),
                               (still, TYPES, "--still type")):
        bad = [k for k in given if k not in valid]
        if bad:
            sys.exit("handOver.py: unknown %s(s) %s; valid: %s"
                     % (what, ",".join(bad), ", ".join(valid)))
    if a.check:
        return
    if not a.case or not a.time:
        ap.error("CASE and --time are needed (or --check)")
    d = fl.cloud_dir(a.case, a.time)
    typeId = fl.read_field(os.path.join(d, "typeId"))
    globalId = fl.read_field(os.path.join(d, "globalId"))
    keys = fl.read_nested_field(os.path.join(d, "contactKeys"))
    xi = fl.read_nested_field(os.path.join(d, "contactXi"), vectors=True)
    if len(keys) != len(typeId) or len(xi) != len(typeId) \
            or any(len(a_) != len(b_) for a_, b_ in zip(keys, xi)):
        sys.exit("handOver.py: %s: contactKeys, contactXi and typeId "
                 "do not match" % d)
    ks = kinds(typeId, globalId, keys)
    mag = {k: [] for k in KINDS}
    for row, rowx in zip(ks, xi):
        for k, v in zip(row, rowx):
            mag[k].append(np.linalg.norm(v))
    print("# %s t = %s: kind contacts mean|xi| max|xi| [m]"
          % (os.path.basename(os.path.abspath(a.case)), a.time))
    for k in KINDS:
        m = np.array(mag[k])
        print("%s %d %.3g %.3g" % (k, len(m), m.mean() if len(m) else 0,
                                   m.max() if len(m) else 0))
    if reset:
        newKeys, newXi = [], []
        for row, rk, rx in zip(ks, keys, xi):
            keep = [j for j, k in enumerate(row) if k not in reset]
            newKeys.append([rk[j] for j in keep])
            newXi.append([rx[j] for j in keep])
        fl.write_nested_field(os.path.join(d, "contactKeys"), newKeys)
        fl.write_nested_field(os.path.join(d, "contactXi"), newXi,
                              vectors=True)
        print("# reset: %s" % ",".join(reset))
    U = fl.read_field(os.path.join(d, "U"))
    omega = fl.read_field(os.path.join(d, "omega"))
    for name, t in TYPES.items():
        m = typeId == t
        print("%s |U| %.3g |omega| %.3g" % (
            name, np.linalg.norm(U[m], axis=1).mean() if m.any() else 0,
            np.linalg.norm(omega[m], axis=1).mean() if m.any() else 0))
    if still:
        m = np.isin(typeId, [TYPES[k] for k in still])
        U[m] = 0
        omega[m] = 0
        fl.write_vector_field(os.path.join(d, "U"), U)
        fl.write_vector_field(os.path.join(d, "omega"), omega)
        print("# still: %s" % ",".join(still))


if __name__ == "__main__":
    main()
