"""The peers' bar chart (bench/peers, bench/packedBed): particle-steps per
second of dpiFoam, LIGGGHTS and OpenFOAM's colliding cloud per size and
process count, the ratios under each group."""

import numpy as np


def num(r, k):
    """r[k] as a float (NaN when missing or empty)."""
    try:
        return float(r[k])
    except (KeyError, ValueError, TypeError):
        return float("nan")


def bars(rows, png, title, what="particles"):
    """rows: dicts with N, np, dpi_psps, lig_psps, of_psps, ratio_lig,
    ratio_of; a log-scale bar chart to png."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.arange(len(rows))
    w = 0.27
    fig, ax = plt.subplots(figsize=(8, 4.8))
    series = (("dpi_psps", "dpiFoam", "C0"), ("lig_psps", "LIGGGHTS 3.8", "C3"),
              ("of_psps", "OpenFOAM colliding cloud", "C2"))
    for k, (key, lab, col) in enumerate(series):
        ax.bar(x + (k - 1)*w, [num(r, key)/1e6 for r in rows], w, label=lab,
               color=col)
    ax.set_xticks(x)
    ax.set_xticklabels(["%s %s, np %s\n/LIG %.2f, /OF %.1f"
                        % (r["N"], what, r["np"], num(r, "ratio_lig"),
                           num(r, "ratio_of")) for r in rows], fontsize=7)
    ax.set_yscale("log")
    ax.set_ylabel("million particle-steps/s (solver loop, CPU per process)")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
