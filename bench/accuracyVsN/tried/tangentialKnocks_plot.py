#!/usr/bin/python3
"""The knocks prototype's trade curves against today's scaling (bench/README.md
section 4, "Knocks along the carrier's surface"): Case 6's detached fraction
and the stirred powder's attached fraction at 300 us against N, mean and
seed-to-seed std, with N = 1's spread as a band. The numbers are the
runs' summaries as written in that section (the runs' folders are not kept).

usage: tangentialKnocks_plot.py [OUT.png]
"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

# N: (mean, std); Case 6 20 seeds (40 at N = 1 and 10), reference 10 (40 at 10)
case6 = {
    "today's scaling": {1: (0.632, 0.061), 2: (0.658, 0.055), 5: (0.620, 0.111),
                        10: (0.510, 0.168), 20: (0.480, 0.235),
                        50: (0.400, 0.394), 100: (0.400, 0.516)},
    "knocks along the surface (w = 1)": {1: (0.632, 0.061), 2: (0.689, 0.072),
                                         5: (0.673, 0.112), 10: (0.630, 0.202),
                                         20: (0.580, 0.158), 50: (0.500, 0.397),
                                         100: (0.450, 0.510)},
}
# the powder, 4 seeds each
powder = {
    "today's scaling": {1: (0.302, 0.008), 2: (0.323, 0.022), 5: (0.340, 0.024),
                        10: (0.367, 0.006), 20: (0.386, 0.027),
                        50: (0.426, 0.034), 100: (0.458, 0.068)},
    "knocks along the surface (w = 1)": {1: (0.302, 0.008), 2: (0.291, 0.017),
                                         5: (0.303, 0.022), 10: (0.309, 0.008),
                                         20: (0.316, 0.013), 50: (0.330, 0.031),
                                         100: (0.323, 0.044)},
}

fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for ax, data, title, ylabel in [
        (axes[0], case6, "Case 6 impact", "API detached at the end"),
        (axes[1], powder, "stirred coated powder", "API attached at 300 us")]:
    m1, s1 = data["today's scaling"][1]
    ax.axhspan(m1 - s1, m1 + s1, color="0.85", label="N = 1 mean +- std")
    for (name, runs), style, shift in zip(data.items(), ["o-", "s-"], [0.96, 1.04]):
        Ns = sorted(runs)
        ax.errorbar([n*shift for n in Ns], [runs[n][0] for n in Ns],
                    yerr=[runs[n][1] for n in Ns], fmt=style, capsize=3,
                    label=name)
    ax.set_xscale("log")
    ax.set_xticks([1, 2, 5, 10, 20, 50, 100])
    ax.set_xticklabels(["1", "2", "5", "10", "20", "50", "100"])
    ax.set_xlabel("coarsening factor N (100 API primaries per carrier)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=8, loc="lower left")
fig.suptitle("Serial prototype, not in the product (bench/README.md section 4)")
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "tangentialKnocks.png"
fig.savefig(out, dpi=110)
print("wrote", out)
