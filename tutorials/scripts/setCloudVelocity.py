#!/usr/bin/python3
"""Set the velocity of every parcel of a cloud at a written time.

Usage: setCloudVelocity.py TIMEDIR UX UY UZ [--cloud dpiCloud]

Rewrites TIMEDIR/lagrangian/<cloud>/U with (UX UY UZ) [m/s] for every
parcel, keeping the header and the parcel count: the guide's
`velocity all set 0 0 -25 units box` (cm/s) before a restart. Spins
(omega), positions, contact forces and histories are left as written.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamLagrangian as fl  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("timedir")
    ap.add_argument("U", type=float, nargs=3)
    ap.add_argument("--cloud", default="dpiCloud")
    a = ap.parse_args()
    path = os.path.join(a.timedir, "lagrangian", a.cloud, "U")
    old = fl.read_field(path)
    new = np.tile(np.array(a.U), (len(old), 1))
    fl.write_vector_field(path, new)
    check = fl.read_field(path)
    assert check.shape == old.shape and np.all(check == new)
    print("setCloudVelocity: %d parcels in %s set to (%g %g %g) m/s"
          % (len(new), path, *a.U))


if __name__ == "__main__":
    main()
