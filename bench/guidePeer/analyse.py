#!/usr/bin/python3
"""Side-by-side tables of the guide's LIGGGHTS fork (peer) and dpiFoam on Cases 3, 5 and 6.

Usage: analyse.py WORK [--Ns "1 10 100"] [--seeds K]
Reads WORK/peer/... and WORK/dpi/... as bench/guidePeer/run leaves them and writes, beside
this script, results.csv (one row per code, case, N and seed), results.md (the tables) and
case3_overlap.png (Case 3's overlap and API force against time, both codes, N = 1, 10, 100).

Every count and contact is computed the same way for both codes from the written state
(positions at 15-17 digits): a contact is a pair closer than the sum of radii; 'attached' is
the code's own agglomerate id (peer: compute agglomerate/atom 1e-10 cm; dpiFoam: agglomerateId,
linkGap 0), equal to the carrier's. Counts are in API primaries (parcels x N).
"""
import argparse
import csv
import glob
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tutorials", "scripts"))
import foamLagrangian as fl  # noqa: E402

R_API = 2.5e-6       # m
R_C = 35e-6          # m


# ---- readers: one state as arrays in SI (x [m], v [m/s], r [m], type 0 carrier / 1 API, agg id)
def read_peer_dump(path):
    lines = open(path).read().splitlines()
    k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[k].split()[2:]
    a = np.array([[float(x) for x in l.split()] for l in lines[k + 1:] if l.strip()])
    c = {n: a[:, i] for i, n in enumerate(cols)}
    o = np.argsort(c["id"])
    return dict(x=np.c_[c["x"], c["y"], c["z"]][o]*1e-2,
                v=np.c_[c["vx"], c["vy"], c["vz"]][o]*1e-2,
                r=c["radius"][o]*1e-2, type=c["type"][o].astype(int) - 1,
                agg=c["c_agglomerate"][o].astype(int))


def read_dpi(case, time=None):
    ts = fl.times(case)
    t = time or ts[-1]
    c = fl.read_cloud(case, t, fields=("xDEM", "U", "d", "typeId", "nParticle",
                                       "globalId", "agglomerateId"))
    return dict(x=np.asarray(c["xDEM"]), v=np.asarray(c["U"]), r=np.asarray(c["d"])/2,
                type=np.asarray(c["typeId"]).astype(int),
                agg=np.asarray(c["agglomerateId"]).astype(int))


def state_stats(s, N):
    """Counts of one agglomerate state (one carrier)."""
    x, r, ty = s["x"], s["r"], s["type"]
    ic = int(np.flatnonzero(ty == 0)[0])
    api = np.flatnonzero(ty == 1)
    att = s["agg"][api] == s["agg"][ic]
    d = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)
    ov = r[:, None] + r[None, :] - d
    np.fill_diagonal(ov, -1)
    ca = ov[ic, api]                       # carrier-API overlaps
    aa = ov[np.ix_(api, api)]
    gap_c = d[ic, api] - (r[ic] + r[api])  # surface gap of each API to the carrier
    return dict(
        apiParcels=len(api), apiPrimaries=len(api)*N,
        attached=int(att.sum())*N, detached=int((~att).sum())*N,
        detachedFraction=float((~att).mean()) if len(api) else np.nan,
        carrierAPIContacts=int((ca > 0).sum()),
        apiAPIContacts=int((np.triu(aa, 1) > 0).sum()),
        meanCarrierAPIOverlap=float(ca[ca > 0].mean()) if (ca > 0).any() else np.nan,
        apiOnCarrierShell=int((np.abs(gap_c) < 0.05*R_API).sum()),
        meanAPIGap=float(gap_c.mean()) if len(api) else np.nan,
        maxAPIGap=float(gap_c.max()) if len(api) else np.nan,
        carrierZ=float(x[ic, 2]), carrierVz=float(s["v"][ic, 2]),
        carrierVxy=float(np.hypot(*s["v"][ic, :2])))


# ---- Case 3 -----------------------------------------------------------------------------
def peak_period(t, y):
    """First peak of y and mean period between its maxima (the ringing)."""
    i = np.flatnonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:])) + 1
    i = i[y[i] > np.median(y)]
    if len(i) < 2:
        return np.nan, np.nan
    return y[i[0]], float(np.mean(np.diff(t[i[:10]])))


def case3(work, rows):
    res = {}
    fig, ax = plt.subplots(2, 2, figsize=(11, 7))
    for N, col in zip((1, 10, 100), ("C0", "C1", "C2")):
        p = os.path.join(work, "peer", "case3", "N%d" % N, "output.dat")
        q = os.path.join(work, "dpi", "case3", "N%d" % N, "output.dat")
        tr = glob.glob(os.path.join(work, "dpi", "case3", "N%d" % N, "postProcessing",
                                    "dpiCloud", "trace", "*", "parcel1.dat"))
        out = {}
        if os.path.exists(p):
            a = np.loadtxt(p)
            t, ovl, F = a[:, 0], a[:, 1], a[:, 4]*1e-5   # dyn -> N
            pk, per = peak_period(t, ovl)
            out["peer"] = dict(t=t, ovl=ovl, F=F, final=ovl[-1], peak=pk, period=per,
                               Fpeak=F.min(), Fend=F[-1])
        if os.path.exists(q):
            a = np.loadtxt(q)
            t, ovl = a[:, 0], a[:, 1]
            F = np.loadtxt(tr[0])[:, 9] if tr else np.full_like(t, np.nan)
            pk, per = peak_period(t, ovl)
            out["dpiFoam"] = dict(t=t, ovl=ovl, F=F[:len(t)], final=ovl[-1], peak=pk,
                                  period=per, Fpeak=np.nanmin(F), Fend=F[-1])
        for code, o in out.items():
            ls = "-" if code == "peer" else "--"
            lab = "%s N=%d" % ("guide's LIGGGHTS" if code == "peer" else "dpiFoam", N)
            ax[0, 0].plot(o["t"]*1e6, o["ovl"], ls, color=col, lw=0.8, label=lab)
            m = o["t"] < 3e-6
            ax[0, 1].plot(o["t"][m]*1e6, o["ovl"][m], ls, color=col, lw=1, label=lab)
            ax[1, 0].plot(o["t"][m]*1e6, o["F"][m]/N*1e6, ls, color=col, lw=1, label=lab)
            rows.append(dict(case=3, code=code, N=N, seed="", finalOverlapPerRapi=o["final"],
                             firstPeakOverlapPerRapi=o["peak"], period_s=o["period"],
                             minForceAPI_N=o["Fpeak"], finalForceAPI_N=o["Fend"]))
        if "peer" in out and "dpiFoam" in out:
            a, b = out["peer"], out["dpiFoam"]
            tt = np.intersect1d(np.round(a["t"]*1e9), np.round(b["t"]*1e9))
            ia = np.searchsorted(np.round(a["t"]*1e9), tt)
            ib = np.searchsorted(np.round(b["t"]*1e9), tt)
            diff = np.abs(a["ovl"][ia] - b["ovl"][ib])
            ax[1, 1].semilogy(tt*1e-3, diff + 1e-16, color=col, lw=0.8, label="N=%d" % N)
            out["maxDiff"] = float(diff.max())
            out["FpeakCommon"] = {"peer": float(a["F"][ia].min()), "dpiFoam": float(b["F"][ib].min())}
        res[N] = out
    ax[0, 0].set_title("overlap / r_API")
    ax[0, 1].set_title("overlap / r_API, first 3 us")
    ax[1, 0].set_title("z-force on the API / N [uN], first 3 us")
    ax[1, 1].set_title("|peer - dpiFoam| of overlap / r_API")
    for a_ in ax.flat:
        a_.set_xlabel("time [us]")
        a_.grid(alpha=0.3)
        a_.legend(fontsize=7)
    fig.suptitle("Case 3: the guide's LIGGGHTS fork (solid) and dpiFoam (dashed)")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "case3_overlap.png"), dpi=70)
    return res


# ---- Cases 5 and 6 ------------------------------------------------------------------------
def case56(work, Ns, rows):
    out = {}
    for N in Ns:
        seeds = sorted({int(os.path.basename(p).split("-s")[1])
                        for c in ("peer", "dpi", "dpiPaired")
                        for p in glob.glob(os.path.join(work, c, "N%d-s*" % N))})
        for seed in seeds:
            st = {}
            for case in (5, 6):
                p = os.path.join(work, "peer", "N%d-s%d" % (N, seed), "case%d" % case, "post",
                                 "final.part")
                if os.path.exists(p):
                    st[("peer", case)] = read_peer_dump(p)
            for code, sub in (("dpiFoam", "dpi"), ("dpiPaired", "dpiPaired")):
                d = os.path.join(work, sub, "N%d-s%d" % (N, seed))
                c5 = os.path.join(d, "case5Agglomerate")
                c6 = os.path.join(d, "case6AgglomerateWallCollision")
                if os.path.exists(os.path.join(c5, "0.01", "lagrangian")):
                    st[(code, 5)] = read_dpi(c5, "0.01")
                if os.path.exists(os.path.join(c6, "0.011", "lagrangian")):
                    st[(code, 6)] = read_dpi(c6, "0.011")
            for (code, case), s in st.items():
                r = state_stats(s, N)
                r.update(case=case, code=code, N=N, seed=seed)
                rows.append(r)
                out.setdefault((code, case, N), []).append(r)
    return out


NAMES = {"peer": "guide's LIGGGHTS", "dpiFoam": "dpiFoam",
         "dpiPaired": "dpiFoam from the peer's Case 5"}


def ms(v, fmt="%.3f"):
    v = np.array([x for x in v if x == x], float)
    if not len(v):
        return "-"
    if len(v) == 1:
        return fmt % v[0]
    return (fmt + " +- " + fmt) % (v.mean(), v.std(ddof=1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("work")
    ap.add_argument("--Ns", default="1 10 100")
    a = ap.parse_args()
    Ns = [int(n) for n in a.Ns.split()]
    rows = []
    c3 = case3(a.work, rows)
    c56 = case56(a.work, Ns, rows)

    keys = []
    for r in rows:
        for k in r:
            if k not in keys:
                keys.append(k)
    with open(os.path.join(here, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})

    L = []
    L.append("## Case 3: carrier-API cohesion (no gravity, 10000 steps of 1e-8 s)\n")
    L.append("| N | code | final overlap/r_API | first peak overlap/r_API | period (first 10 peaks) "
             "[s] | largest pull on the API / N [N] (steps 2-10000) | "
             "max abs(peer - dpiFoam) overlap/r_API |")
    L.append("|---:|---|---:|---:|---:|---:|---:|")
    for N, o in c3.items():
        for code in ("peer", "dpiFoam"):
            if code in o:
                x = o[code]
                L.append("| %d | %s | %.6e | %.5e | %.4e | %.5e | %s |" % (
                    N, NAMES[code], x["final"],
                    x["peak"], x["period"], -o.get("FpeakCommon", {code: x["Fpeak"]})[code]/N,
                    ("%.2e" % o["maxDiff"]) if code == "dpiFoam" and "maxDiff" in o else ""))
    L.append("\n![Case 3 overlay](case3_overlap.png)\n")

    L.append("## Case 5: the agglomerate after settling (1e6 steps, A = 5e-19 J, no gravity)\n")
    L.append("Mean +- std over seeds. Contacts and gaps from the positions; "
             "attached from each code's agglomerate id.\n")
    L.append("| N | code | seeds | API primaries | attached | carrier-API contacts | API-API contacts | "
             "mean carrier-API overlap [m] | API centre gap to carrier, mean [um] | max [um] | "
             "carrier z [um] |")
    L.append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for N in Ns:
        for code in ("peer", "dpiFoam", "dpiPaired"):
            r = c56.get((code, 5, N), [])
            if not r:
                continue
            g = lambda k: [x[k] for x in r]  # noqa: E731
            L.append("| %d | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                N, NAMES[code], len(r),
                ms(g("apiPrimaries"), "%.1f"), ms(g("attached"), "%.1f"),
                ms(g("carrierAPIContacts"), "%.1f"), ms(g("apiAPIContacts"), "%.1f"),
                ms(g("meanCarrierAPIOverlap"), "%.3e"),
                ms([x*1e6 for x in g("meanAPIGap")], "%.3f"),
                ms([x*1e6 for x in g("maxAPIGap")], "%.3f"),
                ms([x*1e6 for x in g("carrierZ")], "%.4f")))

    L.append("\n## Case 6: the wall impact (1e5 steps, A = 1e-19 J, 0.25 m/s, gravity)\n")
    L.append("| N | code | seeds | detached API fraction (mean +- std) | per seed | "
             "vs N = 1 of the same code | carrier z at the end [um] | carrier vz [m/s] |")
    L.append("|---:|---|---:|---:|---|---:|---:|---:|")
    ref = {}
    for N in Ns:
        for code in ("peer", "dpiFoam", "dpiPaired"):
            r = c56.get((code, 6, N), [])
            if not r:
                continue
            f = [x["detachedFraction"] for x in r]
            if N == Ns[0]:
                ref[code] = np.mean(f)
            rel = ""
            if code in ref and N != Ns[0]:
                rel = "%+.3f (%+.0f %%)" % (np.mean(f) - ref[code],
                                          100*(np.mean(f) - ref[code])/ref[code])
            L.append("| %d | %s | %d | %s | %s | %s | %s | %s |" % (
                N, NAMES[code], len(r), ms(f),
                " ".join("%.2f" % x for x in f), rel,
                ms([x["carrierZ"]*1e6 for x in r], "%.1f"),
                ms([x["carrierVz"] for x in r], "%.3f")))
    L.append("\nPaired: the same settled agglomerate (the peer's Case 5 state) impacted by both "
             "codes; difference of the detached fraction, peer minus dpiFoam, per seed.\n")
    L.append("| N | seeds | peer - dpiFoam (mean +- std of the mean) | std of the difference |")
    L.append("|---:|---:|---:|---:|")
    for N in Ns:
        a_ = {x["seed"]: x["detachedFraction"] for x in c56.get(("peer", 6, N), [])}
        b_ = {x["seed"]: x["detachedFraction"] for x in c56.get(("dpiPaired", 6, N), [])}
        dd = np.array([a_[k] - b_[k] for k in a_ if k in b_])
        if len(dd) > 1:
            L.append("| %d | %d | %+.3f +- %.3f | %.3f |" % (
                N, len(dd), dd.mean(), dd.std(ddof=1)/np.sqrt(len(dd)), dd.std(ddof=1)))
    # the inhaler's stage 1 (runInhalerStage1's table), kept when these cases are re-run
    inh = os.path.join(here, "inhalerStage1.md")
    if os.path.isfile(inh):
        L.append("\n" + INHALER_HEADER + "\n")
        L.append(open(inh).read().rstrip("\n"))
    open(os.path.join(here, "results.md"), "w").write("\n".join(L) + "\n")
    print("\n".join(L))


INHALER_HEADER = ("## The inhaler's stage 1 (quick size, 50 ms; runInhalerStage1, "
                  "its own run's date in README.md)")


if __name__ == "__main__":
    main()
