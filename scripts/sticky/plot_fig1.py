"""Figure 1: one iteration of the hull algorithm of section 5.1.1 on a small example."""

import numpy as np

from particle_methods.sticky.hull_reference import cumulative_free_positions, hull_vertices
from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import logged


def run(p, output):
    rng = np.random.default_rng(p["seed"])
    x = np.sort(rng.normal(size=p["particles"]))
    v = rng.normal(size=p["particles"])
    q = cumulative_free_positions(x, v, p["t"])
    history = []
    hull_vertices(q, trace=history)
    step = next(s for s in history if s.removed)
    k = np.arange(q.size)
    fig, axes = new_figure(1, 3, width=12, height=3.8, sharey=True)
    panels = [
        ("(a) L before step k", step.before, (), False),
        ("(b) corner removed", step.before, step.removed, True),
        ("(c) L after step k", step.after, (), True),
    ]
    for ax, (title, chain, removed, show_new) in zip(axes, panels):
        ax.plot(k, q, "o", color="0.7", label="Q(k) (free transport)")
        kept = [i for i in chain if i not in removed]
        ax.plot(kept, q[kept], "-o", color="C0", label="hull vertices in L")
        if removed:
            ax.plot(removed, q[list(removed)], "x", color="C3", markersize=10, mew=2, label="removed from L")
            ax.plot([min(removed) - 1, step.k], q[[min(removed) - 1, step.k]], "--", color="C3", lw=1)
        if show_new or step.k in chain:
            ax.plot([step.k], [q[step.k]], "s", color="C2", markersize=8, label=f"new point k = {step.k}")
        ax.set_xlabel("particle index k")
        label_panel(ax, title)
    axes[0].set_ylabel("cumulative sum Q(k)")
    axes[0].legend(loc="best")
    axes[1].legend(loc="upper right")
    suptitle(fig, "Brenier-Grenier hull: Andrew's monotone chain on the cumulative free-transport positions")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output)  # noqa: F821
