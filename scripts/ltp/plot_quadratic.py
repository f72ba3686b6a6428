"""Figures 2 and 3 from the cached W = x^2 runs."""

import numpy as np

from particle_methods.convergence import fit_order
from particle_replication.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def figure2(d, output):
    fig, axes = new_figure(1, 3, width=14, height=4.2)
    ax = axes[0]
    ax.plot(d["grid"], d["exact"], "k-", lw=2, label="exact (6.4)")
    for h, density in zip(d["plot_h"], d["plot_density"]):
        ax.plot(d["grid"], density, "--", label=f"LTP, h = {h:g}")
    ax.set(xlabel="x", ylabel="density", xlim=(-0.6, 0.4))
    ax.legend()
    label_panel(ax, f"(a) exact vs LTP at t = {float(d['t']):g}")

    ax = axes[1]
    k = int(d["order_points"])
    for column, name, marker in ((0, "L1", "o"), (1, "Linf", "s")):
        errors = d["ltp_errors"][:, column]
        order = fit_order(d["h_values"][-k:], errors[-k:])
        ax.loglog(d["h_values"], errors, marker + "-", label=f"LTP {name} error (order {order:.2f})")
    ax.set(xlabel="h", ylabel=f"error at t = {float(d['t']):g}")
    hide_minor_log_labels(ax)
    ax.legend()
    label_panel(ax, "(b) LTP errors against h")

    ax = axes[2]
    exact_variation = np.abs(np.diff(d["exact"])).sum()
    for eps, density in zip(d["sp_eps"], d["sp_densities"]):
        # Widths below h oscillate at the particle spacing (total variation far above the exact
        # one): thin and translucent, under the rest, so they cannot fill the panel.
        rough = np.abs(np.diff(density)).sum() > 1.5 * exact_variation
        ax.plot(
            d["grid"],
            density,
            lw=0.5 if rough else 1.2,
            alpha=0.45 if rough else 0.9,
            zorder=1 if rough else 2,
            label=f"SP, eps = {eps:g}",
        )
    # The exact solution last and on top, so the oscillating curves cannot hide it.
    ax.plot(d["grid"], d["exact"], color="k", ls=(0, (4, 2)), lw=1.4, zorder=10, label="exact (6.4)")
    ax.set(xlabel="x", ylabel="density", xlim=(-0.6, 0.4))
    legend = ax.legend(loc="upper left")
    for handle in legend.legend_handles:
        handle.set_linewidth(1.5)
        handle.set_alpha(1.0)
    label_panel(ax, f"(c) SP with h = {float(d['sp_h']):g} and fixed eps")
    suptitle(fig, f"W = x^2, data (6.1), dt = {float(d['dt']):g}, B3 shape, t = {float(d['t']):g}")
    save_figure(fig, output.fig2_pdf, output.fig2_png)


def figure3(d, output):
    fig, axes = new_figure(1, 3, width=11, height=5.6)
    t = float(d["t"])
    ax = axes[0]
    for column, name, colour in ((0, "L1", "C0"), (1, "Linf", "C3")):
        ax.loglog(d["eps_values"], d["scan_sp"][:, column], "o-", ms=3, color=colour,
                  label=f"SP {name}, dt = {float(d['scan_dt']):g}")
        ax.axhline(d["scan_ltp"][column], color=colour, ls="--", label=f"LTP {name}, dt = {float(d['scan_dt']):g}")
        ax.loglog(d["eps_values"], d["scan_sp_fine"][:, column], "^:", ms=3, color=colour, alpha=0.7,
                  label=f"SP {name}, dt = {float(d['fine_dt']):g}")
        ax.axhline(d["scan_ltp_fine"][column], color=colour, ls=":", label=f"LTP {name}, dt = {float(d['fine_dt']):g}")
    ax.axvline(float(d["scan_h"]) * np.exp(-2 * t), color="0.5", lw=0.8)
    ax.set(xlabel=r"SP width $\varepsilon$ (grey: LTP width $h e^{-2t}$)", ylabel=f"error at $t = {t:g}$")
    ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1)
    label_panel(ax, f"(a) h = {float(d['scan_h']):g}")
    ax = axes[1]
    for column, name, colour in ((0, "L1", "C0"), (1, "Linf", "C3")):
        ax.loglog(d["h_values"], d["sp_errors"][:, column], "o-", color=colour, label=f"SP (eps = h) {name}")
        ax.loglog(d["h_values"], d["ltp_errors"][:, column], "s--", color=colour, label=f"LTP {name}")
    ax.set(xlabel="h", ylabel=f"error at t = {t:g}")
    hide_minor_log_labels(ax)
    ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1)
    label_panel(ax, f"(b) dt = {float(d['dt']):g}, eps = h")
    ax = axes[2]
    for h, errors, marker in zip(d["dt_h"], d["dt_errors"], "os^v"):
        ax.loglog(d["dt_values"], errors[:, 0], marker + "-", ms=4, label=f"LTP L1, h = {h:g}")
    ax.set(xlabel="dt", ylabel=f"L1 error at t = {t:g}")
    ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1)
    label_panel(ax, "(c) error against dt at fixed h")
    suptitle(fig, "SP against LTP errors, W = x^2, data (6.1); the time step")
    save_figure(fig, output.fig3_pdf, output.fig3_png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    data = load_results(snakemake.input.data)  # noqa: F821
    figure2(data, snakemake.output)  # noqa: F821
    figure3(data, snakemake.output)  # noqa: F821
