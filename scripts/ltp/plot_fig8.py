"""Figure 8: SP against LTP end states (densities and particle sizes)."""

from particle_methods.plotting import label_panel, new_figure, save_figure
from particle_methods.workflow import load_results, logged


def run(d, output):
    fig, axes = new_figure(1, 3, width=15, height=4.2)
    axes[0].plot(d["grid"], d["sp_density"], "-", color="C3")
    axes[0].set(xlabel="x", ylabel="density", title="")
    label_panel(axes[0], "(a) SP method (fixed width eps)")
    axes[1].plot(d["grid"], d["ltp_density"], ":", color="C0", lw=1.5)
    axes[1].set(xlabel="x", ylabel="density")
    label_panel(axes[1], "(b) LTP method")
    axes[2].semilogy(d["sp_centres"], d["sp_widths"], "-", color="C3", label="SP")
    axes[2].semilogy(d["ltp_centres"], d["ltp_widths"], ":o", ms=2, color="C0", label="LTP")
    axes[2].set(xlabel="particle centre x_k", ylabel="particle size h_k")
    axes[2].legend()
    label_panel(axes[2], "(c) particle sizes")
    fig.suptitle(f"End state for W = {d['label']}, data (6.2)")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
