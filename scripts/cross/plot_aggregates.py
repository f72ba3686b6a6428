"""Bump data whose aggregates move and merge: (a) the exact aggregates' paths from their blow-ups (line width growing
with the mass) and the smallest equal-mass SPD's heavy clusters; (b) each method's mean distance of the exact
aggregates' levels from them (the measure that tells whether a method holds an aggregate: it is 0 only for the right
mass at the right place), against t, at its largest size; (c) W1 against t at each method's largest size (LTP and the
particle method only before the first blow-up); (d) the largest W1 over t > 0 against the particles or cells."""

import numpy as np

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

STYLES = {"SPD, equal masses": ("C0", "o"), "SPD, grid weights": ("C1", "s"), "Godunov for F": ("C3", "D"),
          "LTP": ("C6", ">"), "SP": ("C7", "p"), "particle method": ("C2", "^")}
BLOB = ("C4", "v")


def largest_row(d, name):
    rows = np.flatnonzero(d["methods"] == name)
    return rows[np.argmax(d["size"][rows])]


def run(d, p, output):
    fig, grid = new_figure(2, 2, width=11, height=7.5)
    ax, spread_ax, time_ax, size_ax = grid.ravel()
    times, positions, masses = d["path_times"], d["path_positions"], d["path_masses"]
    total = float(np.nanmax(masses))
    # Each aggregate joined to the nearest one at the next time: an aggregate moves at most M/2 per unit time (its
    # levels' speeds M/2 - w lie in [-M/2, M/2]), and a new one to the left shifts the slots, which hold positions
    # in increasing order.
    reach = 0.5 * float(d["mass"])
    for i in range(times.size - 1):
        now, later = positions[i][np.isfinite(positions[i])], positions[i + 1][np.isfinite(positions[i + 1])]
        for slot, x in enumerate(now):
            if later.size == 0:
                continue
            nearest = later[np.argmin(np.abs(later - x))]
            if abs(nearest - x) <= 1.01 * reach * (times[i + 1] - times[i]):
                ax.plot(times[i:i + 2], [x, nearest], color="k", lw=0.8 + 3.0 * masses[i, slot] / total,
                        solid_capstyle="butt")
    ax.plot(np.repeat(times, d["spd_clusters"].shape[1]), d["spd_clusters"].ravel(), "o", color="C0", ms=2.5,
            mfc="none", label=f"SPD clusters, n = {p['spd_n'][0]}")
    ax.plot([], [], color="k", lw=2, label="exact aggregates")
    for t in d["blowups"]:
        ax.axvline(t, color="0.6", lw=0.6, ls=":")
    merger = float(d["merger"])
    ax.axvline(merger, color="C3", lw=0.6, ls="--", label=f"exact merger, t = {merger:.4f}")
    low, high = float(np.nanmin(positions)), float(np.nanmax(positions))
    ax.set(xlabel="t", ylabel="position x", xlim=(0, 1.02 * times[-1]),
           ylim=(low - 0.1 * (high - low), high + 0.1 * (high - low)))
    label_panel(ax, "(a) aggregates")
    methods, sizes, errors = d["methods"], d["size"], d["error"]
    grid_times = d["times"]
    later = grid_times > 0
    spreads = d["spread"]
    positive = spreads[np.isfinite(spreads) & (spreads > 0)]
    floor = max(float(positive.min()) / 3.0, 1e-16) if positive.size else 1e-16
    for name in dict.fromkeys(map(str, methods)):
        colour, marker = STYLES.get(name, BLOB)
        row = largest_row(d, name)
        with np.errstate(all="ignore"):
            worst = np.nanmax(np.where(np.isfinite(spreads[row]), spreads[row], -np.inf), axis=1)
        shown = np.isfinite(worst) & (worst > -np.inf)
        if shown.any():
            spread_ax.plot(grid_times[shown], np.maximum(worst[shown], floor), "-" + marker, color=colour, ms=3)
    for t in d["blowups"]:
        spread_ax.axvline(t, color="0.6", lw=0.6, ls=":")
    spread_ax.axvline(merger, color="C3", lw=0.6, ls="--")
    spread_ax.set(yscale="log", xlabel="t", ylabel="levels' distance", xlim=(0, 1.02 * times[-1]))
    label_panel(spread_ax, "(b) each exact aggregate's levels")
    floor = max(float(np.nanmin(errors[errors > 0])) / 3.0, 1e-16)
    for name in dict.fromkeys(map(str, methods)):
        rows = np.flatnonzero(methods == name)
        rows = rows[np.argsort(sizes[rows])]
        colour, marker = STYLES.get(name, BLOB)
        time_ax.plot(grid_times, np.maximum(errors[rows[-1]], floor), "-" + marker, color=colour, ms=3)
        size_ax.plot(d["count"][rows], np.nanmax(errors[rows][:, later], axis=1), "-" + marker, color=colour, ms=4,
                     label=name)
    for t in d["blowups"]:
        time_ax.axvline(t, color="0.6", lw=0.6, ls=":")
    time_ax.axvline(merger, color="C3", lw=0.6, ls="--")
    time_ax.set(yscale="log", xlabel="t", ylabel="W1 error", ylim=(floor, None))
    label_panel(time_ax, "(c) W1 against t")
    size_ax.set(xscale="log", yscale="log", xlabel="particles or cells", ylabel="largest W1 over t > 0")
    # One legend below the panels for (a), (c) and (d) (inside, it would hide lines).
    handles, labels = [sum(pair, []) for pair in zip(ax.get_legend_handles_labels(),
                                                     size_ax.get_legend_handles_labels())]
    fig.legend(handles, labels, loc="outside lower center", ncol=(len(labels) + 1) // 3, fontsize="small")
    label_panel(size_ax, "(d) W1 uniformly in t > 0")
    suptitle(fig, f"K = |x|/2 from {p['data'].replace('_', ' ')}: aggregates that move and merge, against the exact "
             "solution by the hull")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.cfg, snakemake.output)  # noqa: F821
