"""Figure 4: L1_h errors at t = 0.5; rows K = -|x|/2 and |x|^3/3 (or the row label's -log|x|/(2 pi)),
columns particle, m = 4, m = 6."""

import numpy as np

from particle_methods.convergence import fit_order
from particle_replication.plotting import label_h_axis, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

ROWS = {"newtonian_repulsive": r"$K = (-\Delta)^{-1} = -|x|/2$", "cubic": r"$K = |x|^3/3$",
        "log_repulsive": r"$K = -\log|x|/(2\pi)$"}
COLUMNS = (("particle", "particle method"), ("blob4", "blob, $m = 4$"), ("blob6", "blob, $m = 6$"))


def run(d, t, output):
    kernels = list(d["kernels"])
    fig, axes = new_figure(len(kernels), 3, width=7.0, height=2.4 * len(kernels) + 0.4, sharey="row")
    axes = np.atleast_2d(axes)
    k = int(d["fit_points"])
    h = d["h_values"]
    for row, kernel in enumerate(kernels):
        for column, (method, title) in enumerate(COLUMNS):
            ax = axes[row, column]
            for part, style in (("trajectory", "o-"), ("density", "s--")):
                errors = d[f"{kernel}_{method}_{part}"]
                if np.all(np.isnan(errors)):
                    continue
                order = fit_order(h[-k:], errors[-k:])
                ax.loglog(h, errors, style, ms=3.5, label=f"{part} {order:.2f}")
            ax.set_xlabel("$h$", labelpad=1)
            if row == 0:
                ax.set_title(title)
            label_h_axis(ax, h)
            ax.tick_params(axis="x", labelsize="small")
            ax.legend(loc="upper left", handlelength=1.8, labelspacing=0.25, borderaxespad=0.3)
        low, high = axes[row, 0].get_ylim()
        axes[row, 0].set_ylim(low, high * (high / low) ** 0.3)   # room for the legends above the data
        axes[row, 0].set_ylabel(f"{ROWS.get(kernel, kernel)}\n$L^1_h$ error at $t = {t:g}$")
    suptitle(fig, rf"Errors for data (4.5), $\delta = h^{{{float(d['q']):g}}}$; legends: orders fitted on the "
                 f"{k} finest $h$")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), float(snakemake.params.t),  # noqa: F821
        snakemake.output)  # noqa: F821
