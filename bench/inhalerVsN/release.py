#!/usr/bin/python3
"""Which contact frees each API parcel of the inhaler, N against N = 1.

Usage: release.py CASE... [--md release.md] [--window 2e-5] [--min-free 2e-4]

Each CASE is a finished inhalerVsN case (N<N>-seed<S>) whose stage 2 ran
with the contact-event probe (a patch, not in the product: NOTES.md,
"Removed from the tree", gives it back): contactEvents.dat lists every
start (S) and end (E) of a particle pair's contact and of a particle's
contact with any wall, each with the time and both particles' position,
velocity and spin.

Release of an API parcel: the end of its last carrier contact before a
period of at least --min-free with none (or with none to the end of the
run); its host is the carrier of that contact. Each release is put in the
first class that holds within --window before it:
  wall         the parcel touches a wall (squeezed or scraped off)
  carrier2     the parcel touches a carrier other than its host (a bridge)
  hostWall     the host's contact with a wall begins (an impact; a host
               that rests on the floor is not one)
  hostCarrier  the host's contact with another carrier begins
  knockFree    a contact of the parcel with a free API parcel begins
  knockOther   ... with a parcel on another carrier
  knockSame    ... with a parcel on the same host (a neighbour)
  none         none of these: the gas, or the host's spin
Beside the classes: whether the host rests on a wall or on another
carrier at the release (a contact open then, begun or not); and, as the
control for the knocks, the share of releases with an API-API contact of
the parcel begun within the window, against within the window before it;
and the neighbour knocks (API-API contacts begun between two parcels on a
common carrier) per parcel that touched a carrier in the run, with the
share of them followed within the window by the release of either parcel,
split into the first meeting of each pair and its repeats, and into
knocks approaching at FAST (0.1 m/s) or more along the line of centres
and slower ones. Shares are of
the API primaries released (weighted by N); heights above the corner's
floor (z = -3.5 mm) at the release.
"""
import argparse
import collections
import os
import re

import numpy as np

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("cases", nargs="+")
ap.add_argument("--md", default="release.md")
ap.add_argument("--window", type=float, default=2e-5)
ap.add_argument("--min-free", type=float, default=2e-4)
a = ap.parse_args()

floorZ = -3.5e-3
near = 0.3e-3
FAST = 0.1      # m/s: a knock's approach speed along the line of centres
CLASSES = ["wall", "carrier2", "hostWall", "hostCarrier",
           "knockFree", "knockOther", "knockSame", "none"]


def intervals(events, t0, tEnd):
    """(t, isStart, payload) in time order for one contact -> (begin, end,
    payload at the end); a contact open at the start begins at t0"""
    out, begun = [], None
    for t, st, pay in events:
        if st:
            begun = t
        else:
            out.append((t0 if begun is None else begun, t, pay))
            begun = None
    if begun is not None:
        out.append((begun, tEnd, None))
    return out


def analyse(case, t0):
    pairEv = collections.defaultdict(list)   # (api, partner) -> events
    ccEv = collections.defaultdict(list)     # (carrier, carrier) -> events
    wallEv = collections.defaultdict(list)   # particle -> wall contacts
    types = {}
    tEnd = t0
    with open(os.path.join(case, "contactEvents.dat")) as f:
        for line in f:
            s = line.split()
            t, st = float(s[1]), s[2] == "S"
            tEnd = max(tEnd, t)
            if s[0] == "W":
                wallEv[int(s[3])].append((t, st, None))
                continue
            i, j, ti, tj = int(s[3]), int(s[4]), int(s[5]), int(s[6])
            d = np.array(s[7:25], float)
            types[i], types[j] = ti, tj
            if ti == 0 and tj == 0:
                ccEv[(i, j)].append((t, st, None))
            # payload: the API's x, v, omega, then its partner's
            if ti == 1:
                pairEv[(i, j)].append((t, st, (d[0:3], d[6:9], d[12:15],
                                               d[3:6], d[9:12], d[15:18])))
            if tj == 1:
                pairEv[(j, i)].append((t, st, (d[3:6], d[9:12], d[15:18],
                                               d[0:3], d[6:9], d[12:15])))
    wallIv = {g: intervals(e, t0, tEnd) for g, e in wallEv.items()}
    ccIv = collections.defaultdict(list)
    for (i, j), e in ccEv.items():
        for iv in intervals(e, t0, tEnd):
            ccIv[i].append(iv)
            ccIv[j].append(iv)
    carIv = collections.defaultdict(list)   # api -> (begin, end, pay, carrier)
    apiIv = collections.defaultdict(list)   # api -> (begin, end, partner)
    for (p, o), e in pairEv.items():
        for b0, b1, pay in intervals(e, t0, tEnd):
            if types[o] == 0:
                carIv[p].append((b0, b1, pay, o))
            else:
                apiIv[p].append((b0, b1, o))

    def carriersAt(q, t):
        """The carriers parcel q touches at time t"""
        return {c for c0, c1, _, c in carIv.get(q, []) if c0 <= t <= c1}

    w = a.window
    rows = []
    for p, ivs in carIv.items():
        # The union of the carrier contacts, segment by segment; the
        # release ends the first segment followed by min-free without one
        ivs.sort(key=lambda r: r[0])
        segs = []
        for r in ivs:
            if segs and r[0] <= segs[-1][1]:
                if r[1] >= segs[-1][1]:
                    segs[-1] = [segs[-1][0], r[1], r]
            else:
                segs.append([r[0], r[1], r])
        release = None
        for k, (s0, s1, r) in enumerate(segs):
            if s1 >= tEnd:
                break
            if k + 1 == len(segs) or segs[k + 1][0] - s1 >= a.min_free:
                release = (s1, r)
                break
        # (a segment that ends before tEnd ends with a closed contact, so
        # pay holds the state at its end)
        if release is None:
            continue
        tr, (_, _, pay, host) = release
        xa, _, _, _, _, wc = pay

        def begun(ivList):
            return any(tr - w <= b0 <= tr and b0 > t0 for b0, _, _ in ivList)

        def openAt(ivList, before):
            return any(b0 <= tr and b1 >= tr - before for b0, b1, _ in ivList)

        ctx = set()
        if openAt(wallIv.get(p, []), w):
            ctx.add("wall")
        if any(o != host and b0 <= tr and b1 >= tr - w
               for b0, b1, _, o in ivs):
            ctx.add("carrier2")
        if begun(wallIv.get(host, [])):
            ctx.add("hostWall")
        if begun(ccIv.get(host, [])):
            ctx.add("hostCarrier")
        for b0, _, o in apiIv.get(p, []):
            if tr - w <= b0 <= tr:
                on = carriersAt(o, b0)
                ctx.add("knockFree" if not on else
                        "knockSame" if host in on else "knockOther")
        cls = next((c for c in CLASSES[:-1] if c in ctx), "none")
        # The control for the knocks: an API-API contact of the parcel
        # begun in the window, and in the window before it
        knocks = [tr - b0 for b0, _, _ in apiIv.get(p, [])]
        rows.append(dict(
            p=p, t=tr, z=xa[2] - floorZ, cls=cls,
            restWall=openAt(wallIv.get(host, []), 0),
            restCarrier=openAt(ccIv.get(host, []), 0),
            spin=np.linalg.norm(wc),
            knockNow=any(0 <= d <= w for d in knocks),
            knockBefore=any(w < d <= 2*w for d in knocks)))

    # The neighbour knocks: API-API contacts begun between two parcels on
    # a common carrier, and how many are followed within the window by
    # the release of either
    released = {r["p"]: r["t"] for r in rows}
    # [all, first meetings of the pair, approach >= FAST, slower]: knocks,
    # and how many of them free a parcel
    knocks, freeing = np.zeros(4, int), np.zeros(4, int)
    for (p, o), e in pairEv.items():
        if types[o] != 1 or o < p:
            continue
        met = False
        for t, st, pay in e:
            if not st:
                continue
            if carriersAt(p, t) & carriersAt(o, t):
                xp, vp, _, xo, vo, _ = pay
                n = (xo - xp)/np.linalg.norm(xo - xp)
                fast = np.dot(vp - vo, n) >= FAST
                which = np.array([True, not met, fast, not fast])
                met = True
                knocks += which
                freeing += which*any(t <= released.get(q, -1) <= t + w
                                     for q in (p, o))
    return rows, len(carIv), knocks, freeing


pool = collections.defaultdict(list)
poolKnocks = collections.defaultdict(lambda: np.zeros(9, int))
out = ["# Which contact frees each API parcel", "",
       "`release.py` (window %g s, free for %g s); shares of the API "
       "primaries released, heights above the floor at the release." % (
           a.window, a.min_free), "",
       "## Per case", "",
       "| case | released | within 0.3 mm of the floor | "
       + " | ".join(CLASSES) + " | host resting on a wall | on a carrier "
       "| neighbour knocks per parcel | share of them freeing |",
       "|---|" + "---:|" * (len(CLASSES) + 6)]
for case in a.cases:
    case = case.rstrip("/")
    m = re.search(r"N(\d+)-seed(\d+)$", case)
    if not m:
        raise SystemExit("release.py: %s is not an inhalerVsN case" % case)
    N = int(m.group(1))
    rows, nParcels, knocks, freeing = analyse(case, 0.01)
    variant = os.path.basename(os.path.dirname(os.path.abspath(case)))
    pool[(variant, N)] += rows
    poolKnocks[(variant, N)] += np.concatenate([[nParcels], knocks, freeing])
    n = max(1, len(rows))
    c = collections.Counter(r["cls"] for r in rows)
    out.append("| %s/%s | %d | %.3f | %s | %.3f | %.3f | %.2f | %.3f |" % (
        variant, os.path.basename(case), len(rows) * N,
        sum(r["z"] < near for r in rows) / n,
        " | ".join("%.3f" % (c[k] / n) for k in CLASSES),
        sum(r["restWall"] for r in rows) / n,
        sum(r["restCarrier"] for r in rows) / n,
        knocks[0] / max(1, nParcels), freeing[0] / max(1, knocks[0])))

out += ["", "## Pooled over the seeds, per class", "",
        "| cases, N | class | share | median height [mm] | within 0.3 mm "
        "| median time [ms] | host's spin, median [rad/s] |",
        "|---|---|---:|---:|---:|---:|---:|"]
for (variant, N), rows in sorted(pool.items()):
    for k in CLASSES:
        rs = [r for r in rows if r["cls"] == k]
        if rs:
            out.append("| %s, N = %d | %s | %.3f | %.3f | %.2f | %.2f | %.0f |" % (
                variant, N, k, len(rs) / len(rows),
                1e3 * np.median([r["z"] for r in rs]),
                np.mean([r["z"] < near for r in rs]),
                1e3 * np.median([r["t"] for r in rs]),
                np.median([r["spin"] for r in rs])))
    out.append("| %s, N = %d | host resting on a wall / on a carrier | "
               "%.3f / %.3f | | | | |" % (
                   variant, N, np.mean([r["restWall"] for r in rows]),
                   np.mean([r["restCarrier"] for r in rows])))
    nParcels, knocks, freeing = (poolKnocks[(variant, N)][0],
                                 poolKnocks[(variant, N)][1:5],
                                 poolKnocks[(variant, N)][5:9])
    for k, what in enumerate(["", " (first meetings of a pair)",
                              " (approaching at >= %g m/s)" % FAST,
                              " (approaching slower)"]):
        out.append("| %s, N = %d | neighbour knocks%s per parcel / share "
                   "of them followed by a release | %.2f / %.3f | | | | |" % (
                       variant, N, what, knocks[k] / max(1, nParcels),
                       freeing[k] / max(1, knocks[k])))
    out.append("| %s, N = %d | an API-API contact begun in the window / "
               "in the window before it | %.3f / %.3f | | | | |" % (
                   variant, N, np.mean([r["knockNow"] for r in rows]),
                   np.mean([r["knockBefore"] for r in rows])))
with open(a.md, "w") as f:
    f.write("\n".join(out) + "\n")
print("\n".join(out))
print("wrote", a.md)
