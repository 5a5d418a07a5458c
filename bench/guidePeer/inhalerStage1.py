#!/usr/bin/python3
"""The inhaler's stage 1 (sedimentation) of the guide's code and of dpiFoam, measured alike.

Usage:
  inhalerStage1.py series DIR --code peer|dpi [--api-contact-scale S] [--out CSV]
      one run's time series: DIR is the peer's run directory (post/dump*.part, cgs) or a
      dpiFoam case (its time directories' lagrangian/dpiCloud, SI); S multiplies the API
      parcels' radius where two API parcels meet (dpiFoam's coatingCoverage: sqrt(N); the
      guide's scaling and -guide: 1). One CSV row per dump/write.
  inhalerStage1.py report CSV... --labels L... --md MD --png PNG [--at 0.05]
      the table (mean +- std over the seeds of each label at time --at) and the plot.

Everything is counted from positions, velocities and radii, the same way for both codes:
  contact: centre distance <= r_i + r_j + 1e-12 m (the agglomerate link of the guide's
           compute agglomerate/atom 1e-10 cm and dpiFoam's linkGap 0); carrier-API and
           carrier-carrier at the primaries' radii, API-API at S x the API radius (and, for
           the column "API-API @r", at the primary radius in every code)
  attached API: API primaries (N per parcel) in a contact cluster holding a carrier;
  free API: the rest (singlets and API-only clusters);
  bed height: the highest carrier top above the tube's lowest point (z = -3.5 mm; the
      O-grid's facets lie up to ~10 um inside the circle), and the carriers' mean centre;
  KE: translational, of each parcel's N primaries (m = N rho pi d^3/6), carriers and API
      apart; rotational likewise (I = N 0.4 m r^2 per primary);
  API speed: |v| of the API parcels (median, 90th percentile), and of the attached ones;
  drift: the displacement since the previous dump/write over its interval (the same parcels,
      by id), the speed at which parcels get anywhere, as against |v|, which holds vibration.
"""
import argparse
import csv
import glob
import math
import os
import re
import sys

import numpy as np
from scipy.spatial import cKDTree

RHO = 1520.0
FLOOR = -3.5e-3     # the floor leg: a tube of radius 3.5 mm along x, axis y = z = 0
N_API = 10
LINK = 1e-12

COLS = ["t", "carriers", "apiParcels", "apiPrimaries", "attachedFrac", "freePrimaries",
        "singletParcels", "apiOnlyClusters", "apiOnCarrierDirect",
        "carrierApiContacts", "apiApiPerApi", "apiApiPerApiPrimaryR", "carrierCarrierContacts",
        "bedHeight_um", "carrierMeanZ_um", "keCarrier", "keApi",
        "keRotCarrier", "keRotApi", "apiSpeedMedian", "apiSpeedP90", "attachedApiSpeedMedian",
        "attachedApiSpeedP90", "carrierSpeedMedian", "carrierSpeedP90", "apiDriftMedian",
        "apiDriftP90", "carrierDriftMedian", "carrierDriftP90"]


def readPeerDump(path):
    lines = open(path).read().splitlines()
    step = int(lines[lines.index("ITEM: TIMESTEP") + 1])
    k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[k].split()[2:]
    a = np.array([list(map(float, l.split())) for l in lines[k + 1:] if l.strip()])
    c = {n: a[:, i] for i, n in enumerate(cols)}
    o = np.argsort(c["id"])
    x = np.c_[c["x"], c["y"], c["z"]][o]*1e-2
    v = np.c_[c["vx"], c["vy"], c["vz"]][o]*1e-2
    w = np.c_[c["omegax"], c["omegay"], c["omegaz"]][o] if "omegax" in c else np.zeros_like(x)
    r = c["radius"][o]*1e-2
    api = c["type"][o] == 2
    n = np.where(api, N_API, 1.0)
    return step*1e-8, x, v, w, r, api, n


def foamList(path):
    """The values of an ascii OpenFOAM list file (scalars, labels or vectors)."""
    txt = open(path).read()
    m = re.search(r"\n(\d+)\s*\n\(", txt)
    n = int(m.group(1))
    inner = txt[m.end():txt.rindex(")")]
    if "(" in inner:
        vals = np.array(re.findall(r"\(([^()]*)\)", inner)[:n], dtype=object)
        return np.array([list(map(float, s.split())) for s in vals])
    return np.array(inner.split()[:n], dtype=float)


def readDpiTime(case, tdir):
    d = os.path.join(case, tdir, "lagrangian", "dpiCloud")
    x = foamList(os.path.join(d, "xDEM"))
    v = foamList(os.path.join(d, "U"))
    w = foamList(os.path.join(d, "omega"))
    r = foamList(os.path.join(d, "d"))/2
    typ = foamList(os.path.join(d, "typeId"))
    n = foamList(os.path.join(d, "nParticle"))
    gid = foamList(os.path.join(d, "globalId"))
    o = np.argsort(gid)
    return float(tdir), x[o], v[o], w[o], r[o], (typ[o] == 1), n[o]


def clusters(npts, pairs):
    parent = np.arange(npts)

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for i, j in pairs:
        a, b = find(i), find(j)
        if a != b:
            parent[a] = b
    return np.array([find(i) for i in range(npts)])


def measure(t, x, v, w, r, api, n, s, prev=None):
    rc = np.where(api, s*r, r)          # contact radii (API-API only use s)
    tree = cKDTree(x)
    pairs = np.array(sorted(tree.query_pairs(2*rc.max() + 1e-9)), dtype=int).reshape(-1, 2)
    i, j = pairs[:, 0], pairs[:, 1]
    dist = np.linalg.norm(x[i] - x[j], axis=1)
    bothApi = api[i] & api[j]
    reach = np.where(bothApi, rc[i] + rc[j], r[i] + r[j])
    touch = dist <= reach + LINK
    touchR = dist <= r[i] + r[j] + LINK
    cp = pairs[touch]
    lab = clusters(len(x), cp)
    carrierLabs = set(lab[~api])
    attached = api & np.isin(lab, list(carrierLabs))
    free = api & ~attached
    sizes = {}
    for L in lab[api]:
        sizes[L] = sizes.get(L, 0) + 1
    freeLabs = set(lab[free])
    singlets = sum(1 for L in freeLabs if sizes[L] == 1)
    ca = touch & (api[i] != api[j])
    direct = np.zeros(len(x), bool)
    direct[i[ca]] = True
    direct[j[ca]] = True
    direct &= api
    nApi = api.sum()
    m = n*RHO*math.pi*(2*r)**3/6
    inertia = 0.4*m*r**2
    ke = 0.5*m*(v**2).sum(1)
    kr = 0.5*inertia*(w**2).sum(1)
    sp = np.linalg.norm(v, axis=1)
    zc = x[~api, 2]
    q = lambda a, p: float(np.percentile(a, p)) if len(a) else float("nan")
    return {
        "t": t, "carriers": int((~api).sum()), "apiParcels": int(nApi),
        "apiPrimaries": float(n[api].sum()),
        "attachedFrac": float(n[attached].sum()/max(n[api].sum(), 1)),
        "freePrimaries": float(n[free].sum()), "singletParcels": singlets,
        "apiOnlyClusters": len(freeLabs) - singlets,
        "apiOnCarrierDirect": int(direct.sum()),
        "carrierApiContacts": int(ca.sum()),
        "apiApiPerApi": float((touch & bothApi).sum()*2/max(nApi, 1)),
        "apiApiPerApiPrimaryR": float((touchR & bothApi).sum()*2/max(nApi, 1)),
        "carrierCarrierContacts": int((touch & ~api[i] & ~api[j]).sum()),
        "bedHeight_um": float((zc + r[~api]).max() - FLOOR)*1e6 if len(zc) else float("nan"),
        "carrierMeanZ_um": float(zc.mean() - FLOOR)*1e6 if len(zc) else float("nan"),
        "keCarrier": float(ke[~api].sum()), "keApi": float(ke[api].sum()),
        "keRotCarrier": float(kr[~api].sum()), "keRotApi": float(kr[api].sum()),
        "apiSpeedMedian": q(sp[api], 50), "apiSpeedP90": q(sp[api], 90),
        "attachedApiSpeedMedian": q(sp[attached], 50), "attachedApiSpeedP90": q(sp[attached], 90),
        "carrierSpeedMedian": q(sp[~api], 50), "carrierSpeedP90": q(sp[~api], 90),
        **drift(t, x, api, prev, q),
    }


def drift(t, x, api, prev, q):
    keys = ("apiDriftMedian", "apiDriftP90", "carrierDriftMedian", "carrierDriftP90")
    if prev is None or prev[1].shape != x.shape or t <= prev[0]:
        return dict.fromkeys(keys, float("nan"))
    u = np.linalg.norm(x - prev[1], axis=1)/(t - prev[0])
    return dict(zip(keys, (q(u[api], 50), q(u[api], 90), q(u[~api], 50), q(u[~api], 90))))


def series(a):
    rows = []
    if a.code == "peer":
        files = glob.glob(os.path.join(a.dir, "post", "dump*.part"))
        prev = None
        for f in sorted(files, key=lambda f: int(re.sub(r"\D", "", os.path.basename(f)))):
            st = readPeerDump(f)
            rows.append(measure(*st, a.api_contact_scale, prev))
            prev = st[:2]
    else:
        times = [d for d in os.listdir(a.dir)
                 if re.fullmatch(r"[0-9.eE+-]+", d)
                 and os.path.isfile(os.path.join(a.dir, d, "lagrangian", "dpiCloud", "xDEM"))]
        prev = None
        for d in sorted(times, key=float):
            st = readDpiTime(a.dir, d)
            rows.append(measure(*st, a.api_contact_scale, prev))
            prev = st[:2]
    out = open(a.out, "w") if a.out else sys.stdout
    wr = csv.DictWriter(out, COLS)
    wr.writeheader()
    for r in rows:
        wr.writerow(r)


def report(a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    data = {}
    for f, L in zip(a.csv, a.labels):
        rows = list(csv.DictReader(open(f)))
        if not rows:
            print("inhalerStage1: %s has no rows: left out" % f, file=sys.stderr)
            continue
        data.setdefault(L, []).append({k: np.array([float(r[k]) for r in rows]) for k in COLS})
    show = [("attachedFrac", "attached API", "%.4f", 1), ("freePrimaries", "free API primaries", "%.0f", 1),
            ("singletParcels", "singlet parcels", "%.1f", 1), ("apiOnlyClusters", "API-only clusters", "%.1f", 1),
            ("apiApiPerApi", "API-API contacts / API parcel (own radii)", "%.3f", 1),
            ("apiApiPerApiPrimaryR", "API-API / API parcel @r", "%.3f", 1),
            ("carrierApiContacts", "carrier-API contacts", "%.1f", 1),
            ("carrierCarrierContacts", "carrier-carrier contacts", "%.1f", 1),
            ("bedHeight_um", "bed height: highest carrier top [um]", "%.1f", 1),
            ("carrierMeanZ_um", "carriers' mean centre height [um]", "%.1f", 1),
            ("keCarrier", "KE carriers [J]", "%.2e", 1), ("keApi", "KE API [J]", "%.2e", 1),
            ("apiSpeedMedian", "API speed median [um/s]", "%.1f", 1e6),
            ("apiSpeedP90", "API speed p90 [um/s]", "%.1f", 1e6),
            ("attachedApiSpeedMedian", "attached API speed median [um/s]", "%.1f", 1e6),
            ("carrierSpeedMedian", "carrier speed median [um/s]", "%.1f", 1e6),
            ("carrierSpeedP90", "carrier speed p90 [um/s]", "%.1f", 1e6),
            ("apiDriftMedian", "API drift over the last 2 ms, median [um/s]", "%.2f", 1e6),
            ("apiDriftP90", "API drift, p90 [um/s]", "%.2f", 1e6),
            ("carrierDriftMedian", "carrier drift, median [um/s]", "%.2f", 1e6)]
    out = []
    out.append("At t = %g s (mean +- std over seeds; one seed: the value):\n" % a.at)
    def atT(d):
        return abs(d["t"][np.argmin(abs(d["t"] - a.at))] - a.at) < 1e-6
    nAt = {L: sum(atT(d) for d in data[L]) for L in data}
    out.append("| quantity | " + " | ".join("%s (%d seed%s)" % (L, nAt[L], "s" if nAt[L] > 1 else "")
                                           for L in data) + " |")
    out.append("|---|" + "---:|"*len(data))
    for k, name, fmt, sc in show:
        cells = []
        for L in data:
            vals = []
            for d in data[L]:
                idx = np.argmin(abs(d["t"] - a.at))
                if abs(d["t"][idx] - a.at) < 1e-6:
                    vals.append(d[k][idx]*sc)
            if not vals:
                cells.append("-")
            elif len(vals) == 1:
                cells.append(fmt % vals[0])
            else:
                cells.append((fmt + " +- " + fmt) % (np.mean(vals), np.std(vals, ddof=1)))
        out.append("| %s | %s |" % (name, " | ".join(cells)))
    # the time series of the first seed of each label
    out.append("\nAgainst time (the first seed of each):\n")
    tk = [("attachedFrac", "attached", "%.4f", 1), ("freePrimaries", "free prim.", "%.0f", 1),
          ("apiApiPerApi", "API-API/API", "%.2f", 1), ("carrierCarrierContacts", "c-c", "%.0f", 1),
          ("bedHeight_um", "height um", "%.0f", 1), ("keCarrier", "KE carriers J", "%.2e", 1),
          ("keApi", "KE API J", "%.2e", 1), ("apiSpeedMedian", "API |v| median um/s", "%.1f", 1e6),
          ("apiSpeedP90", "API |v| p90 um/s", "%.1f", 1e6),
          ("apiDriftMedian", "API drift median um/s", "%.2f", 1e6)]
    for L in data:
        d = data[L][0]
        out.append("%s:\n" % L)
        out.append("| t [ms] | " + " | ".join(n for _, n, _, _ in tk) + " |")
        out.append("|---:|" + "---:|"*len(tk))
        for m in range(len(d["t"])):
            if round(d["t"][m]*1e3) not in (2, 4, 6, 8, 10, 14, 20, 30, 40, 50) and m != len(d["t"]) - 1:
                continue
            out.append("| %.0f | " % (d["t"][m]*1e3) + " | ".join(f % (d[k][m]*sc) for k, _, f, sc in tk) + " |")
        out.append("")
    open(a.md, "w").write("\n".join(out) + "\n")
    print("\n".join(out))

    fig, ax = plt.subplots(2, 2, figsize=(11, 7.5))
    colors = ["C0", "C1", "C2", "C3", "C4"]
    for c, L in zip(colors, data):
        for s, d in enumerate(data[L]):
            kw = dict(color=c, lw=1.4 if s == 0 else 0.7, alpha=1 if s == 0 else 0.6,
                      label=L if s == 0 else None)
            t = d["t"]*1e3
            ax[0, 0].plot(t, d["attachedFrac"], **kw)
            ax[0, 1].semilogy(t[1:], d["keCarrier"][1:], **kw)
            ax[1, 0].semilogy(t[1:], d["keApi"][1:], **kw)
            ax[1, 1].semilogy(t[1:], d["apiSpeedMedian"][1:]*1e6, **kw)
    ax[0, 0].set_ylabel("attached API fraction (primaries)")
    ax[0, 1].set_ylabel("KE of the carriers [J]")
    ax[1, 0].set_ylabel("KE of the API [J]")
    ax[1, 1].set_ylabel("API speed, median [um/s]")
    for b in ax.flat:
        b.set_xlabel("t [ms]")
        b.grid(alpha=0.3)
    ax[0, 0].legend(fontsize=8)
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("series")
    s.add_argument("dir")
    s.add_argument("--code", choices=["peer", "dpi"], required=True)
    s.add_argument("--api-contact-scale", type=float, default=1.0)
    s.add_argument("--out")
    r = sub.add_parser("report")
    r.add_argument("csv", nargs="+")
    r.add_argument("--labels", nargs="+", required=True)
    r.add_argument("--md", required=True)
    r.add_argument("--png", required=True)
    r.add_argument("--at", type=float, default=0.05)
    r.add_argument("--title", default="Inhaler stage 1 (quick size): the guide's code and dpiFoam")
    a = p.parse_args()
    if a.cmd == "series":
        series(a)
    else:
        if len(a.labels) != len(a.csv):
            p.error("one label per CSV")
        report(a)


if __name__ == "__main__":
    main()
