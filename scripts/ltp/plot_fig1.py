"""Figure 1: the hat shape (2.12) and its bi-orthogonal kernel (after (2.18))."""

import numpy as np

from particle_methods.ltp import HAT, hat_biorthogonal_kernel
from particle_replication.plotting import new_figure, save_figure
from particle_replication.workflow import logged


def run(p, output):
    s = np.linspace(-1.5, 1.5, p["points"])
    fig, ax = new_figure(1, 1, width=6, height=2.6)
    ax.plot(s, HAT(s), "-", color="C0", label="hat shape phi (2.12)")
    ax.plot(s, hat_biorthogonal_kernel(s), ":", color="C3", lw=2, label="bi-orthogonal kernel phi~")
    ax.axhline(0, color="0.6", lw=0.6)
    ax.set(xlabel="s", ylabel="value")
    ax.legend(loc="upper right")
    ax.set_title("Piecewise affine shape and its bi-orthogonal kernel; both vanish outside [-1, 1]")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output)  # noqa: F821
