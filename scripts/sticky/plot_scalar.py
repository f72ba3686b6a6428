"""Figures 2 and 3: (a) trajectories, (b) u(t, x), (c) profiles, (d) log L1 error against p."""

import matplotlib as mpl
import numpy as np

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def run(d, case, title, output):
    fig, axes = new_figure(2, 2, width=11, height=7.2)
    ax = axes[0, 0]
    ax.plot(d["trajectories"], d["trajectory_times"], color="C0", lw=0.8)
    ax.set(xlabel="x", ylabel="t")
    label_panel(ax, f"(a) trajectories of {d['trajectories'].shape[1]} particles")

    ax = axes[0, 1]
    mesh = ax.pcolormesh(d["field_x"], d["field_times"], d["field"], shading="auto", vmin=0, vmax=1,
                         rasterized=True)
    fig.colorbar(mesh, ax=ax, label="u(t, x)")
    ax.set(xlabel="x", ylabel="t")
    label_panel(ax, "(b) u(t, x) in the space-time plane (SPD)")

    ax = axes[1, 0]
    # Times by colour (a colour bar, as in panel (d)) rather than a legend that would cover the curves.
    times = d["profile_times"]
    profile_norm = mpl.colors.Normalize(times.min(), times.max())
    profile_cmap = mpl.colors.ListedColormap(mpl.colormaps["viridis"](np.linspace(0.0, 0.9, 256)))
    for t, particle, exact in zip(times, d["profile_particle_cdf"], d["profile_exact_cdf"]):
        ax.step(d["field_x"], particle, where="post", color=profile_cmap(profile_norm(t)))
        ax.plot(d["field_x"], exact, "--", color="k", lw=0.7)
    fig.colorbar(mpl.cm.ScalarMappable(norm=profile_norm, cmap=profile_cmap), ax=ax,
                 label=f"time t ({', '.join(f'{t:g}' for t in times[:3])}, ..., {times[-1]:g})")
    ax.set(xlabel="x", ylabel="u(t, x)")
    label_panel(ax, "(c) profiles: SPD, exact (dashed)")

    ax = axes[1, 1]
    norm = mpl.colors.Normalize(d["error_times"].min(), d["error_times"].max())
    # Plasma without its palest yellow, which is hard to see on white.
    cmap = mpl.colors.ListedColormap(mpl.colormaps["plasma"](np.linspace(0.0, 0.9, 256)))
    for t, errors in zip(d["error_times"], d["errors"]):
        ax.plot(d["error_p"], np.log(errors), "o-", ms=3, color=cmap(norm(t)))
    fig.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="time t")
    if case == "burgers_two_atoms":
        p = d["error_p"].astype(float)
        ax.plot(p, np.log(d["errors"][0, 0]) - np.log(2) * (p - p[0]) - 0.5, "k:",
                label="slope -log 2 (order 1/n)")
        ax.legend(loc="lower left")
    ax.set(xlabel="p  (n = 2^p particles)", ylabel="log L1 error")
    label_panel(ax, "(d) L1 error of the SPD")
    suptitle(fig, title)
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.case, snakemake.params.title,  # noqa: F821
        snakemake.output)  # noqa: F821
