"""Figures 5 and 6: one column per potential; rows potential, density, velocity, particle size."""

import matplotlib as mpl
import numpy as np

from particle_replication.plotting import new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

ROWS = ("potential $W$", r"density $\rho_h$", r"velocity $-W' * \rho_h$", "particle size $h_k / h$")


def time_colorbar(fig, axes, colours, times):
    """One discrete colorbar of the snapshot times beside ``axes``: which colour is which t."""
    cmap = mpl.colors.ListedColormap(colours)
    norm = mpl.colors.BoundaryNorm(np.arange(len(times) + 1) - 0.5, cmap.N)
    bar = fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), ax=axes, location="right",
                       fraction=0.05, aspect=70, pad=0.02)
    bar.set_ticks(np.arange(len(times)), labels=[f"{t:.3g}" for t in times])
    bar.ax.tick_params(length=0)
    bar.set_label("snapshot time $t$")
    return bar


def run(d, title, output):
    labels = list(d["labels"])
    fig, axes = new_figure(4, len(labels), width=4.6 * len(labels), height=11)
    axes = np.atleast_2d(axes).reshape(4, len(labels))
    for column, label in enumerate(labels):
        prefix = f"case{column}"
        shown = d[f"{prefix}_shown"]
        times = d[f"{prefix}_times"][shown]
        colours = mpl.colormaps["viridis"](np.linspace(0, 0.9, shown.size))
        axes[0, column].plot(d["x_potential"], d[f"{prefix}_potential"], "k-")
        axes[0, column].set_title(f"W = {label}")
        for colour, t, density, index in zip(colours, times, d[f"{prefix}_densities"], shown):
            centres = d[f"{prefix}_centres"][index]
            axes[1, column].plot(d["grid"], density, color=colour, label=f"t = {t:.3g}")
            axes[2, column].plot(centres, d[f"{prefix}_velocities"][index], color=colour)
            axes[3, column].plot(centres, d[f"{prefix}_widths"][index] / d["h"], color=colour)
        axes[1, column].set_yscale("log")
        axes[1, column].set_ylim(bottom=1e-2)
        axes[3, column].set_yscale("log")
        for row in range(4):
            axes[row, column].set_xlabel("$x$")
            axes[row, column].set_ylabel(ROWS[row])
        # Rows density, velocity and particle size share the snapshot colours of this column.
        time_colorbar(fig, axes[1:, column], colours, times)
    fig.get_layout_engine().set(wspace=0.06)
    suptitle(fig, title)
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.title, snakemake.output)  # noqa: F821
