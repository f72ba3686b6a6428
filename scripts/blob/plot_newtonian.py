"""Figures 1-3: (A) trajectories, (B) densities, (C) zoom near the blow-up, (D) L1_h errors with orders."""

import numpy as np

from particle_methods.convergence import fit_order
from particle_methods.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure
from particle_methods.workflow import load_results, logged

TRAJECTORIES_SHOWN = 26


def run(d, title, output):
    has_density = bool(np.isfinite(d["densities"]).any())
    fig, axes = new_figure(2, 2, width=11, height=8.5)
    ax_a, ax_b, ax_c, ax_d = axes.flat
    every = max(1, d["positions"].shape[1] // TRAJECTORIES_SHOWN)
    method = str(d["method"])
    for ax in (ax_a, ax_c):
        ax.plot(d["exact_paths"][:, ::every], d["exact_times"], "k-", lw=0.8)
        ax.plot(d["positions"][:, ::every], d["times"], "--", color="C3", lw=0.9)
        ax.plot([], [], "k-", label="exact")
        ax.plot([], [], "--", color="C3", label=f"{method} method")
        ax.set(xlabel="x", ylabel="t")
    ax_a.legend(loc="upper right")
    label_panel(ax_a, f"A. trajectories, h = {float(d['h']):g}")
    x0, x1, t0, t1 = d["zoom"]
    ax_c.set(xlim=(x0, x1), ylim=(t0, t1))
    ax_c.plot(d["positions"], d["times"], "--", color="C3", lw=0.6)
    ax_c.plot(d["exact_paths"], d["exact_times"], "k-", lw=0.6)
    label_panel(ax_c, "C. zoom near the blow-up time t = 1")

    if has_density:
        alpha = d["positions"][0]
        for t, index, exact, colour in zip(d["density_times"], d["density_index"], d["exact_densities"],
                                            ("C0", "C1", "C2")):
            x = d["positions"][index]
            ax_b.plot(d["exact_paths"][int(np.argmin(np.abs(d["exact_times"] - t)))], exact, "-", color=colour,
                      label=f"exact, t = {t:g}")
            ax_b.plot(x, d["densities"][index], "o--", ms=2.5, color=colour, lw=0.8, label=f"{method}, t = {t:g}")
        ax_b.set(xlabel="x", ylabel="density along trajectories", xlim=(alpha.min(), alpha.max()))
        ax_b.legend(fontsize=7)
        label_panel(ax_b, "B. densities")
    else:
        ax_b.axis("off")
        ax_b.text(0.5, 0.5, "particle method: no density\n(Delta K is a Dirac mass)", ha="center", va="center")

    k = int(d["fit_points"])
    h = d["h_values"]
    series = [("trajectory_errors", "trajectories", "o-")] + ([("density_errors", "density", "s-")] if has_density
                                                               else [])
    for key, name, style in series:
        order = fit_order(h[-k:], d[key][-k:])
        ax_d.loglog(h, d[key], style, label=f"{name}: order {order:.2f}")
    if method == "blob":
        reference = d["trajectory_errors"][-1] * (h / h[-1]) ** (4 * float(d["q"]))
        ax_d.loglog(h, reference, "k:", label=f"slope m q = {4 * float(d['q']):.1f}")
    ax_d.set(xlabel="h", ylabel="L1_h error at t = 0.5")
    hide_minor_log_labels(ax_d)
    ax_d.legend()
    label_panel(ax_d, "D. errors against h")
    fig.suptitle(title)
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.title, snakemake.output)  # noqa: F821
