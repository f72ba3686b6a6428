"""Figure 4: exact, LTP and SP densities for W = x^2/2, hat (left) and B3 (right)."""

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

NAMES = {"hat": "hat function (2.12)", "b3": "B3-spline (2.13)"}


def run(d, t, dt, output):
    fig, axes = new_figure(1, 2, width=11, height=4.2, sharey=True)
    for ax, shape, label in zip(axes, ("hat", "b3"), ("(a)", "(b)")):
        ltp_l1 = d[f"{shape}_ltp_errors"][0]
        sp_l1 = d[f"{shape}_sp_errors"][0]
        ax.plot(d["grid"], d["exact"], "k-", lw=2, label="exact")
        ax.plot(d["grid"], d[f"{shape}_ltp"], "--", color="C0", label=f"LTP (L1 error {ltp_l1:.2e})")
        ax.plot(d["grid"], d[f"{shape}_sp"], "-", color="C3", lw=0.9, label=f"SP, eps = h (L1 error {sp_l1:.2e})")
        ax.set(xlabel="x", xlim=(-0.8, 0.7))
        ax.legend(loc="upper right")
        label_panel(ax, f"{label} {NAMES[shape]}")
    axes[0].set_ylabel(f"density at t = {t:g}")
    suptitle(fig, f"W = x^2/2, data (6.1), h = {float(d['h']):g}, dt = {dt:g}")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.t, snakemake.params.dt,  # noqa: F821
        snakemake.output)  # noqa: F821
