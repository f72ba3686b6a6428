"""Figure 8: SP against LTP, at the paper's time and at the SP steady time, and particle sizes."""

import numpy as np

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def run(d, output):
    fig, axes = new_figure(1, 3, width=15, height=4.6)
    paper, steady = float(d["paper_time"]), float(d["steady_time"])
    for ax, method, colour, name in ((axes[0], "sp", "C3", f"SP (eps = {float(d['sp_eps']):g})"),
                                     (axes[1], "ltp", "C0", "LTP")):
        ax.plot(d[f"{method}_paper_x"], d[f"{method}_paper_density"], "-", color=colour, lw=1,
                label=f"t = {paper:g}")
        ax.plot(d[f"{method}_steady_x"], d[f"{method}_steady_density"], "--", color="k", lw=1,
                label=f"t = {steady:g} (SP steady)")
        ax.set(xlabel="x", ylabel="density", yscale="log", ylim=(1e-2, None))
        ax.legend(fontsize="small", loc="upper center")
        label_panel(ax, f"({'ab'[method == 'ltp']}) {name}")
    index = int(np.argmin(np.abs(d["sp_times"] - paper)))
    axes[2].semilogy(d["sp_centres"][index], d["sp_widths"][index], "-", color="C3", label="SP")
    axes[2].semilogy(d["ltp_centres"][index], d["ltp_widths"][index], ":o", ms=2, color="C0", label="LTP")
    axes[2].set(xlabel="particle centre x_k", ylabel="particle size h_k")
    axes[2].legend(fontsize="small")
    label_panel(axes[2], f"(c) particle sizes at t = {paper:g}")
    suptitle(fig, f"W = {d['label']}, data (6.2), h = {float(d['h']):g}, dt = {float(d['dt']):g} "
                 f"({int(d['steps'])} steps to t = {float(d['t']):g})")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
