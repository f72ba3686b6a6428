"""Figure 5: log-log L1_h errors with fitted orders (2D Newtonian kernel)."""

import numpy as np

from particle_methods.convergence import fit_order
from particle_methods.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure
from particle_methods.workflow import load_results, logged

TITLES = {"regular, blob": "regular data, blob m = 4", "regular, particle": "regular data, particle method",
          "disk, blob": "indicator of the disk, blob m = 4"}


def run(d, output):
    labels = list(d["labels"])
    fig, axes = new_figure(1, len(labels), width=4.5 * len(labels), height=4.2, sharey=True)
    k = int(d["fit_points"])
    h = d["h_values"]
    for index, (ax, label) in enumerate(zip(np.atleast_1d(axes), labels)):
        for part, style in (("trajectory", "o-"), ("density", "s--")):
            errors = d[f"case{index}_{part}"]
            if np.all(np.isnan(errors)):
                continue
            ax.loglog(h, errors, style, label=f"{part}: order {fit_order(h[-k:], errors[-k:]):.2f}")
        ax.set(xlabel="h")
        hide_minor_log_labels(ax)
        ax.legend(loc="lower right")
        label_panel(ax, TITLES.get(label, label))
    np.atleast_1d(axes)[0].set_ylabel("L1_h error at t = 0.5")
    fig.suptitle(f"2D, K = log|x|/(2 pi), delta = h^{float(d['q']):g}")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
