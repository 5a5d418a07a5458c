#!/usr/bin/python3
"""Agglomerate statistics and pictures (Case 5, Case 6, the inhaler).

Usage:
  agglomerates.py history  CASE [--prefix P] [--title T]
      reads CASE/postProcessing/<cloud>/agglomerates/*/agglomerates.dat
      (columns: time nAgglomerates apiPrimaries singletAPIPrimaries
      attachedAPIPrimaries histogram...) and draws P_agglomerates.png:
      API primaries attached to carriers / detached / singlets, the
      number of agglomerates and the agglomerates by size (1, 2, 3-4, 5-8,
      ... parcels) against time. Prints the final counts and the time
      since which the attached count has not changed.
  agglomerates.py summary  CASE [--label L]
      prints one line: L: API primaries attached to the carrier X, detached
      Y (singlets Z), of T, at time t, from the last line of agglomerates.dat
      and, as a cross-check, from the agglomerateId field of the last written
      time (API parcels whose agglomerateId is that of a carrier).
  agglomerates.py snapshot CASE --times T1 [T2 ...] [--prefix P] [--title T]
      side views (x-z) of the cloud at the given written times, API coloured
      by attached (same agglomerateId as a carrier) or detached:
      P_snapshots.png.
  agglomerates.py trajectories CASE [--prefix P] [--title T]
      z of the carrier and of every API parcel at every written time
      (attached / detached at the last time): P_trajectories.png.

Parcels are API when their typeId is in --api-types (default 1: the
tutorials list the carrier first, then API). Every count is in primaries
(sum of nParticle).
"""
import argparse
import glob
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamLagrangian as fl  # noqa: E402


def read_history(case, cloud="dpiCloud", histogram=False):
    """Rows of agglomerates.dat by time: time nAgglomerates apiPrimaries
    singletAPIPrimaries attachedAPIPrimaries, and with histogram the size
    classes after them (1, 2, 3-4, 5-8, ... parcels; 0 where not written)."""
    files = glob.glob(os.path.join(case, "postProcessing", cloud,
                                   "agglomerates", "*", "agglomerates.dat"))
    if not files:
        raise SystemExit("no agglomerates.dat in %s" % case)
    rows = {}
    for f in files:
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            rows[float(v[0])] = [float(x) for x in v]
    # the histogram's trailing empty classes are not written: pad with 0
    width = max(len(r) for r in rows.values()) if histogram else 5
    return np.array([rows[t][:width] + [0.0]*(width - len(rows[t]))
                     for t in sorted(rows)])


def attached_from_fields(c, api_types):
    """Per parcel: is API, is attached (shares a carrier's agglomerateId)."""
    is_api = np.isin(c["typeId"].astype(int), api_types)
    carrier_ids = set(c["agglomerateId"][~is_api].astype(int))
    attached = np.array([int(a) in carrier_ids for a in c["agglomerateId"]])
    return is_api, attached


def settled_since(h):
    """Time since which the attached count has not changed."""
    att = h[:, 4]
    k = len(att) - 1
    while k > 0 and att[k - 1] == att[-1]:
        k -= 1
    return h[k, 0]


def cmd_history(a):
    h = read_history(a.case, histogram=True)
    t = h[:, 0]
    sizes = h[:, 5:]
    nPanels = 3 if sizes.shape[1] else 2
    fig, axes = plt.subplots(nPanels, 1, figsize=(7, 3 + 1.5*nPanels),
                             sharex=True)
    ax1, ax2 = axes[0], axes[1]
    ax1.plot(t*1e3, h[:, 4], label="attached to a carrier")
    ax1.plot(t*1e3, h[:, 2] - h[:, 4], label="detached")
    ax1.plot(t*1e3, h[:, 3], "--", label="singlets")
    ax1.set_ylabel("API primaries")
    ax1.legend()
    ax2.plot(t*1e3, h[:, 1], color="k")
    ax2.set_ylabel("agglomerates (incl. singlets)")
    if nPanels == 3:
        # the size classes of agglomerates.dat: 1, 2, 3-4, 5-8, ... parcels
        for k in range(sizes.shape[1]):
            if sizes[:, k].any():
                lo, hi = (1, 1) if k == 0 else (2**(k - 1) + 1, 2**k)
                label = "%d" % hi if lo == hi else "%d-%d" % (lo, hi)
                axes[2].semilogy(t*1e3, np.where(sizes[:, k] > 0,
                                                 sizes[:, k], np.nan),
                                 label=label + (" parcel" if hi == 1
                                                else " parcels"))
        axes[2].set_ylabel("agglomerates by size")
        axes[2].legend(fontsize=7, ncol=3)
    axes[-1].set_xlabel("time [ms]")
    ax1.set_title(a.title or "agglomerates")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig("%s_agglomerates.png" % a.prefix, dpi=120)
    print("wrote %s_agglomerates.png" % a.prefix)
    print("final (t = %g s): %d agglomerates, API primaries %g, attached %g, "
          "detached %g, singlets %g; attached count unchanged since t = %g s"
          " (%.0f %% of the run)" % (
              t[-1], h[-1, 1], h[-1, 2], h[-1, 4], h[-1, 2] - h[-1, 4],
              h[-1, 3], settled_since(h),
              100*(t[-1] - settled_since(h))/(t[-1] - t[0] + (t[1] - t[0]))))


def cmd_summary(a):
    h = read_history(a.case)
    last = h[-1]
    print("%s: API primaries attached to the carrier %g, detached %g "
          "(singlets %g), of %g, at t = %g s" % (
              a.label, last[4], last[2] - last[4], last[3], last[2], last[0]))
    ts = fl.times(a.case)
    if ts:
        c = fl.read_cloud(a.case, ts[-1])
        is_api, att = attached_from_fields(c, a.api_types)
        n = c["nParticle"]
        print("%s: from agglomerateId at t = %s s: attached %g, detached %g"
              % (a.label, ts[-1], n[is_api & att].sum(),
                 n[is_api & ~att].sum()))


def _side_view(ax, c, api_types, title):
    is_api, att = attached_from_fields(c, api_types)
    x, z, d = c["xDEM"][:, 0], c["xDEM"][:, 2], c["d"]
    for sel, col, lab in ((~is_api, "0.6", "carrier"),
                          (is_api & att, "tab:blue", "API attached"),
                          (is_api & ~att, "tab:red", "API detached")):
        for xi, zi, di in zip(x[sel]*1e6, z[sel]*1e6, d[sel]*1e6):
            ax.add_patch(plt.Circle((xi, zi), di/2, color=col, alpha=0.8))
        ax.plot([], [], "o", color=col, label="%s (%d)" % (lab, sel.sum()))
    ax.axhline(0, color="k", lw=2)
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x [um]")
    ax.set_ylabel("z [um]")
    ax.legend(fontsize=7, loc="upper right")
    return x, z


def cmd_snapshot(a):
    fig, axes = plt.subplots(1, len(a.times), figsize=(4.5*len(a.times), 4.5),
                             squeeze=False)
    for ax, t in zip(axes[0], a.times):
        c = fl.read_cloud(a.case, t)
        x, z = _side_view(ax, c, a.api_types, "t = %s s" % t)
        # frame: the carrier +- 70 um (and its neighbourhood), the wall z = 0
        # drawn when in view
        xc, zc = x[0]*1e6, z[0]*1e6
        ax.set_xlim(xc - 70, xc + 70)
        ax.set_ylim(max(zc - 70, -10), max(zc - 70, -10) + 140)
    fig.suptitle(a.title or "")
    fig.tight_layout()
    fig.savefig("%s_snapshots.png" % a.prefix, dpi=120)
    print("wrote %s_snapshots.png" % a.prefix)


def cmd_trajectories(a):
    ts = fl.times(a.case)
    data = [fl.read_cloud(a.case, t) for t in ts]
    n = len(data[-1]["globalId"])
    data = [(float(t), c) for t, c in zip(ts, data) if len(c["globalId"]) == n]
    is_api, att = attached_from_fields(data[-1][1], a.api_types)
    t = np.array([tc[0] for tc in data])
    z = np.array([tc[1]["xDEM"][:, 2] for tc in data])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i in range(n):
        if is_api[i]:
            ax.plot(t*1e3, z[:, i]*1e6, color="tab:blue" if att[i]
                    else "tab:red", lw=0.6, alpha=0.6)
    ax.plot(t*1e3, z[:, ~is_api]*1e6, color="k", lw=2)
    ax.plot([], [], color="k", lw=2, label="carrier (centre)")
    ax.plot([], [], color="tab:blue", label="API attached at the end")
    ax.plot([], [], color="tab:red", label="API detached at the end")
    ax.axhline(0, color="0.3", lw=1)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("z [um]")
    ax.set_title(a.title or "trajectories")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig("%s_trajectories.png" % a.prefix, dpi=120)
    print("wrote %s_trajectories.png" % a.prefix)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("command", choices=("history", "summary", "snapshot",
                                        "trajectories"))
    ap.add_argument("case")
    ap.add_argument("--prefix", default="agglomerate")
    ap.add_argument("--title", default="")
    ap.add_argument("--label", default="agglomerates")
    ap.add_argument("--times", nargs="+", default=[])
    ap.add_argument("--api-types", type=int, nargs="+", default=[1])
    a = ap.parse_args()
    {"history": cmd_history, "summary": cmd_summary,
     "snapshot": cmd_snapshot, "trajectories": cmd_trajectories}[a.command](a)


if __name__ == "__main__":
    main()
