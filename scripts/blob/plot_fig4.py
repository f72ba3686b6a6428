"""Figure 4: L1_h errors at t = 0.5; rows K = -|x|/2 and |x|^3/3, columns particle, m = 4, m = 6."""

import numpy as np

from particle_methods.convergence import fit_order
from particle_methods.plotting import hide_minor_log_labels, new_figure, save_figure
from particle_methods.workflow import load_results, logged

ROWS = {"newtonian_repulsive": "K = (-Delta)^{-1} = -|x|/2", "cubic": "K = |x|^3/3"}
COLUMNS = (("particle", "particle method"), ("blob4", "blob, m = 4"), ("blob6", "blob, m = 6"))


def run(d, output):
    kernels = list(d["kernels"])
    fig, axes = new_figure(len(kernels), 3, width=13, height=4 * len(kernels), sharey="row")
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
                ax.loglog(h, errors, style, ms=4, label=f"{part}: order {order:.2f}")
            ax.set(xlabel="h", title=f"{ROWS[kernel]}, {title}")
            hide_minor_log_labels(ax)
            ax.legend(loc="lower right")
        axes[row, 0].set_ylabel("L1_h error at t = 0.5")
    fig.suptitle(f"Errors for data (4.5), delta = h^{float(d['q']):g}")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
