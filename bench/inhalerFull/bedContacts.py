#!/usr/bin/python3
"""The bed's touching contacts by class and how its API hold together, from
a reconstructed write of the inhaler (what a carried-API scheme could take
out of the pair sweep).

    bench/inhalerFull/bedContacts.py CASE TIME

Contacts as the engine sees them with coarseGraining coatingCoverage:
carrier-carrier and carrier-API at the primaries' radii, API-API at
sqrt(N) x theirs (the API type: the smaller diameter). Prints the counts
per class, the API touching 0, 1 or more carriers, the API-API contacts
whose two API touch the same single carrier, and the connected parts of
the bed left when the carrier-carrier contacts are cut (one part holding
most carriers: the coating alone ties the bed together, so no carrier and
its API form a body apart). Needs python3-scipy (bench/packedBed/run
installs it).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "scripts"))
import foamLagrangian  # noqa: E402


def touchingPairs(x, reach, cut):
    """Pairs (i < j) with |x_i - x_j| < cut(i, j) <= reach (as
    bench/packedBed/bed.py finds its contacts)."""
    from scipy.spatial import cKDTree
    pairs = cKDTree(x).query_pairs(reach, output_type="ndarray")
    i, j = pairs[:, 0], pairs[:, 1]
    return pairs[np.linalg.norm(x[i] - x[j], axis=1) < cut(i, j)]


def components(n, pairs):
    """Label of each of n nodes' connected part."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                       shape=(n, n))
    return connected_components(graph, directed=False)[1]


def main(case, time):
    c = foamLagrangian.read_cloud(case, time,
                                  fields=("xDEM", "d", "nParticle"))
    x, d, N = c["xDEM"], c["d"], c["nParticle"]
    api = d < d.max()
    r = 0.5*d
    grown = np.where(api, np.sqrt(N)*r, r)

    def cut(i, j):
        both = api[i] & api[j]
        return np.where(both, grown[i] + grown[j], r[i] + r[j])

    pairs = touchingPairs(x, 2*max(r.max(), grown.max()), cut)
    i, j = pairs[:, 0], pairs[:, 1]
    aa = api[i] & api[j]
    ca = api[i] ^ api[j]
    cc = ~api[i] & ~api[j]
    print("%s at %s: %d parcels (%d carriers, %d API)"
          % (case, time, len(x), (~api).sum(), api.sum()))
    print("touching contacts: carrier-carrier %d, carrier-API %d, API-API %d"
          % (cc.sum(), ca.sum(), aa.sum()))

    # The carriers each API touches
    nOn = np.zeros(len(x), int)
    seat = np.full(len(x), -1)
    for a, b in pairs[ca]:
        p, s = (a, b) if api[a] else (b, a)
        nOn[p] += 1
        seat[p] = s
    onOne = api & (nOn == 1)
    print("API touching no carrier %.1f %%, one %.1f %%, two or more %.1f %%"
          % tuple(100*np.array([(nOn[api] == 0).mean(), onOne[api].mean(),
                                (nOn[api] >= 2).mean()])))
    same = aa & onOne[i] & onOne[j] & (seat[i] == seat[j])
    print("API-API contacts of two API on the same single carrier: %d"
          " (%.1f %%)" % (same.sum(), 100*same.sum()/max(1, aa.sum())))
    riding = ca & (onOne[i] | onOne[j])
    print("contacts a ride on the one carrier would take out: %d of %d"
          " (%.0f %%)" % (riding.sum() + same.sum(), len(pairs),
                          100*(riding.sum() + same.sum())/max(1, len(pairs))))

    lab = components(len(x), pairs[~cc])
    part, size = np.unique(lab, return_counts=True)
    carriersIn = dict(zip(*np.unique(lab[~api], return_counts=True)))
    big = part[np.argmax(size)]
    print("without carrier-carrier contacts: %d parts; the largest holds %d"
          " parcels and %d of %d carriers"
          % (len(part), size.max(), carriersIn.get(big, 0), (~api).sum()))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
