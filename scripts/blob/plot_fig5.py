"""Figure 5: log-log L1_h errors with fitted orders (2D Newtonian kernel)."""

import numpy as np

from particle_methods.convergence import fit_order, pairwise_orders
from particle_replication.plotting import label_h_axis, label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

TITLES = {"regular, blob": "A. regular, blob $m = 4$", "regular, particle": "B. regular, particle",
          "disk, blob": "C. disk, blob $m = 4$"}
#: Labelled ticks of h per panel at most: more (the overlay config/fig5-extended.yaml has 7) run into each other.
MOST_H_LABELS = 5


def run(d, t, output):
    labels = list(d["labels"])
    fig, axes = new_figure(1, len(labels), width=2.4 * len(labels), height=2.9, sharey=True)
    k = int(d["fit_points"])
    h = d["h_values"]
    for index, (ax, label) in enumerate(zip(np.atleast_1d(axes), labels)):
        for part, style, offset in (("trajectory", "o-", -9), ("density", "s--", 5)):
            errors = d[f"case{index}_{part}"]
            if np.all(np.isnan(errors)):
                continue
            (line,) = ax.loglog(h, errors, style, ms=3.5, label=f"{part} {fit_order(h[-k:], errors[-k:]):.2f}")
            # the pairwise order of each step, at the middle of its segment
            for (h0, h1), (e0, e1), value in zip(zip(h[:-1], h[1:]), zip(errors[:-1], errors[1:]),
                                                 pairwise_orders(h, errors)):
                ax.annotate(f"{value:.2f}", (np.sqrt(h0 * h1), np.sqrt(e0 * e1)), xytext=(0, offset),
                            textcoords="offset points", ha="center", fontsize="small", color=line.get_color())
        ax.set(xlabel="$h$")
        label_h_axis(ax, h, most=MOST_H_LABELS)
        ax.tick_params(axis="x", labelsize="small")
        ax.legend(loc="upper left", handlelength=1.8, labelspacing=0.25, borderaxespad=0.3)
        label_panel(ax, TITLES.get(label, label))
    first = np.atleast_1d(axes)[0]
    low, high = first.get_ylim()
    first.set_ylim(low, high * (high / low) ** 0.4)   # room for the legends above the data
    first.set_ylabel(f"$L^1_h$ error at $t = {t:g}$")
    suptitle(fig, rf"2D, $K = \log|x|/(2\pi)$, $\delta = h^{{{float(d['q']):g}}}$; legends: orders fitted on the {k} "
                 "finest $h$; small numbers: pairwise orders")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), float(snakemake.params.t),  # noqa: F821
        snakemake.output)  # noqa: F821
