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
    fig, grid = new_figure(2, 2, width=11, height=7.0)
    # (a) across the top, the space-time plot; (b) and (c) below it.
    spec = grid[0, 0].get_gridspec()
    for unused in grid[0]:
        unused.remove()
    ax = fig.add_subplot(spec[0, :])
    axes = [ax, *grid[1]]
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
    # Each method's centres of the exact aggregates' levels at its largest size, on the time grid: hollow markers of
    # decreasing sizes, so that each stays visible where they coincide.
    methods, sizes = d["methods"], d["size"]
    blob = next(str(n) for n in methods if str(n).startswith("blob"))
    for name, size in (("Godunov for F", 9), ("SP", 6.5), (blob, 4)):
        rows = np.flatnonzero(methods == name)
        largest = rows[np.argmax(sizes[rows])]
        colour, marker = STYLES.get(name, BLOB)
        for slot in range(d["centre"].shape[2]):
            ax.plot(d["times"], d["centre"][largest][:, slot], marker, color=colour, ms=size, mfc="none", ls="none",
                    zorder=3, label=f"{name} ({sizes[largest]}), centres" if slot == 0 else None)
    for t in d["blowups"]:
        ax.axvline(t, color="0.6", lw=0.6, ls=":")
    ax.axvline(float(d["merger"]), color="C3", lw=0.6, ls="--", label=f"exact merger, t = {float(d['merger']):.4f}")
    low, high = float(np.nanmin(positions)), float(np.nanmax(positions))
    ax.set(xlabel="t", ylabel="position x", xlim=(0, 1.02 * times[-1]),
           ylim=(low - 0.1 * (high - low), high + 0.1 * (high - low)))
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="small")
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
