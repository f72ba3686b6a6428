"""two_bumps, whose aggregates move and merge: (a) the exact aggregates' paths (line width growing with the mass),
the smallest equal-mass SPD's heavy clusters and the blob's, SP's and Godunov's centres of the aggregates' levels;
(b) W1 against t at each method's largest size (LTP and the particle method only before the first blow-up); (c) the
largest W1 over t against the size."""

import numpy as np

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

STYLES = {"SPD, equal masses": ("C0", "o"), "SPD, grid weights": ("C1", "s"), "Godunov for F": ("C3", "D"),
          "LTP": ("C6", ">"), "SP": ("C7", "p"), "particle method": ("C2", "^")}
BLOB = ("C4", "v")


def run(d, p, output):
    fig, axes = new_figure(1, 3, width=11, height=3.6)
    ax = axes[0]
    times, positions, masses = d["path_times"], d["path_positions"], d["path_masses"]
    total = float(np.nanmax(masses))
    for slot in range(positions.shape[1]):
        for i in range(times.size - 1):
            if np.isfinite(positions[i, slot]) and np.isfinite(positions[i + 1, slot]):
                ax.plot(times[i:i + 2], positions[i:i + 2, slot], color="k", lw=0.8 + 3.0 * masses[i, slot] / total,
                        solid_capstyle="butt")
    ax.plot(np.repeat(times, d["spd_clusters"].shape[1]), d["spd_clusters"].ravel(), "o", color="C0", ms=2.5,
            mfc="none", label=f"SPD clusters, n = {p['spd_n'][0]}")
    ax.plot([], [], color="k", lw=2, label="exact aggregates")
    # Each method's centres of the exact aggregates' levels at its largest size, on the time grid.
    methods, sizes = d["methods"], d["size"]
    for name in ("SP", "Godunov for F", next(str(n) for n in methods if str(n).startswith("blob"))):
        rows = np.flatnonzero(methods == name)
        largest = rows[np.argmax(sizes[rows])]
        colour, marker = STYLES.get(name, BLOB)
        for slot in range(d["centre"].shape[2]):
            ax.plot(d["times"], d["centre"][largest][:, slot], marker, color=colour, ms=4, mfc="none", ls="none",
                    label=f"{name} ({sizes[largest]}), centres" if slot == 0 else None)
    for t in d["blowups"]:
        ax.axvline(t, color="0.6", lw=0.6, ls=":")
    ax.axvline(float(d["merger"]), color="C3", lw=0.6, ls="--", label=f"exact merger, t = {float(d['merger']):.4f}")
    low, high = float(np.nanmin(positions)), float(np.nanmax(positions))
    # Room below the paths for the legend.
    ax.set(xlabel="t", ylabel="position x", xlim=(0, times[-1]),
           ylim=(low - 1.3 * (high - low), high + 0.05 * (high - low)))
    ax.legend(loc="lower right", fontsize="x-small")
    label_panel(ax, "(a) aggregates")
    errors = d["error"]
    floor = max(float(np.nanmin(errors[errors > 0])) / 3.0, 1e-16)
    for name in dict.fromkeys(map(str, methods)):
        rows = np.flatnonzero(methods == name)
        rows = rows[np.argsort(sizes[rows])]
        colour, marker = STYLES.get(name, BLOB)
        largest = rows[-1]
        axes[1].plot(d["times"], np.maximum(errors[largest], floor), "-" + marker, color=colour, ms=3)
        axes[2].plot(sizes[rows], np.nanmax(errors[rows], axis=1), "-" + marker, color=colour, ms=4, label=name)
    for t in d["blowups"]:
        axes[1].axvline(t, color="0.6", lw=0.6, ls=":")
    axes[1].axvline(float(d["merger"]), color="C3", lw=0.6, ls="--")
    axes[1].set(yscale="log", xlabel="t", ylabel="W1 error", ylim=(floor, None))
    label_panel(axes[1], "(b) W1 against t")
    axes[2].set(xscale="log", yscale="log", xlabel="particles, 1/h or cells", ylabel="largest W1 over t")
    # One legend for (b) and (c), below the panels (inside, it would hide lines of one or the other).
    handles, labels = axes[2].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=(len(labels) + 1) // 2, fontsize="small")
    label_panel(axes[2], "(c) W1 uniformly in time")
    suptitle(fig, "K = |x|/2 from two bumps: aggregates that move and merge, against the exact solution by the hull")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.cfg, snakemake.output)  # noqa: F821
