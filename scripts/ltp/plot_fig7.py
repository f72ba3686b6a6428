"""Figure 7: density snapshots over time."""

import matplotlib as mpl
import numpy as np

from particle_replication.plotting import new_figure, save_figure
from particle_replication.workflow import load_results, logged


def run(d, output):
    fig, ax = new_figure(1, 1, width=8, height=4.5)
    colours = mpl.colormaps["viridis"](np.linspace(0, 0.9, d["times"].size))
    for colour, t, density in zip(colours, d["times"], d["densities"]):
        ax.plot(d["grid"], density, color=colour, label=f"t = {t:.3g}")
    ax.set(xlabel="x", ylabel="density rho_h", yscale="log", ylim=(1e-2, 2 * d["densities"].max()))
    ax.legend(ncol=2, fontsize="small", loc="upper center")
    ax.set_title(f"LTP, W = {d['label']}, data (6.3), h = {float(d['h']):g}, dt = {float(d['dt']):g}, "
                 f"N = {int(d['steps'])} steps", fontsize="medium")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
