"""Figures 1-3: (A) trajectories, (B) densities, (C) zoom near the blow-up, (D) L1_h errors with orders.

The particle method (Figure 2) has no density for the Newtonian kernel (Delta K is a Dirac mass), so
its figure has three panels, as the paper's Figure 2 compares trajectories and their errors only:
(A) trajectories over the whole time span, (B) the zoom near t = 1 (no bending, unlike the blob
method) and (C) the trajectory errors against h.
"""

import numpy as np

from particle_methods.convergence import fit_order
from particle_replication.plotting import label_h_axis, label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

TRAJECTORIES_SHOWN = 26


def trajectories(ax, d, every, lw):
    ax.plot(d["exact_paths"][:, ::every], d["exact_times"], "k-", lw=lw)
    ax.plot(d["positions"][:, ::every], d["times"], "--", color="C3", lw=lw)
    ax.set(xlabel="$x$", ylabel="$t$")


def run(d, title, error_t, output):
    has_density = bool(np.isfinite(d["densities"]).any())
    method = str(d["method"])
    fig, axes = new_figure(2, 2, width=6.6, height=5.4)
    if has_density:
        ax_a, ax_b, ax_c, ax_d = axes.flat
    else:
        # No density panel: the trajectories take the whole left column.
        grid = axes[0, 0].get_gridspec()
        for ax in axes[:, 0]:
            ax.remove()
        ax_a, ax_c, ax_d, ax_b = fig.add_subplot(grid[:, 0]), axes[0, 1], axes[1, 1], None
    letters = iter("ABCD")

    every = max(1, d["positions"].shape[1] // TRAJECTORIES_SHOWN)
    trajectories(ax_a, d, every, 0.7)
    ax_a.plot([], [], "k-", label="exact")
    ax_a.plot([], [], "--", color="C3", label=f"{method} method")
    start, end = float(d["times"].min()), float(d["times"].max())
    ax_a.set_ylim(start, end + 0.18 * (end - start))  # a band above the last time for the legend
    ax_a.legend(loc="upper center", ncol=2, framealpha=0.9)
    label_panel(ax_a, f"{next(letters)}. trajectories, $h = {float(d['h']):g}$")

    if has_density:
        alpha = d["positions"][0]
        for t, index, exact, colour in zip(d["density_times"], d["density_index"], d["exact_densities"],
                                            ("C0", "C1", "C2")):
            x_exact = d["exact_paths"][int(np.argmin(np.abs(d["exact_times"] - t)))]
            ax_b.plot(x_exact, exact, "-", color=colour, label=f"$t = {t:g}$")
            ax_b.plot(d["positions"][index], d["densities"][index], "o--", ms=2, color=colour, lw=0.8)
        ax_b.plot([], [], "k-", label="exact")
        ax_b.plot([], [], "ko--", ms=2, lw=0.8, label=method)
        ax_b.set(xlabel="$x$", ylabel="density along trajectories", xlim=(alpha.min(), alpha.max()))
        ax_b.legend(loc="upper right")
        label_panel(ax_b, f"{next(letters)}. densities")

    x0, x1, t0, t1 = d["zoom"]
    trajectories(ax_c, d, 1, 0.6)
    ax_c.set(xlim=(x0, x1), ylim=(t0, t1))
    ax_c.locator_params(axis="x", nbins=5)
    label_panel(ax_c, f"{next(letters)}. zoom near $t = 1$")

    k = int(d["fit_points"])
    h = d["h_values"]
    series = [("trajectory_errors", "trajectories", "o-")]
    if has_density:
        series.append(("density_errors", "density", "s-"))
    for key, name, style in series:
        order = fit_order(h[-k:], d[key][-k:])
        ax_d.loglog(h, d[key], style, ms=4, label=f"{name}: order {order:.2f}")
    if method == "blob":
        slope = int(d["order"]) * float(d["q"])
        reference = d["trajectory_errors"][-1] * (h / h[-1]) ** slope
        ax_d.loglog(h, reference, "k:", label=f"slope $mq = {slope:.1f}$")
    ax_d.set(xlabel="$h$", ylabel=f"$L^1_h$ error at $t = {error_t:g}$")
    label_h_axis(ax_d, h)
    ax_d.tick_params(axis="x", labelsize="small")
    low, high = ax_d.get_ylim()
    ax_d.set_ylim(low, high * (high / low) ** 0.35)   # room for the legend above the data
    ax_d.legend(loc="upper left")
    label_panel(ax_d, f"{next(letters)}. errors against $h$")
    suptitle(fig, title)
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.title,  # noqa: F821
        float(snakemake.params.error_t), snakemake.output)  # noqa: F821
