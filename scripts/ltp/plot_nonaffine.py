"""LTP on a flow that is not affine: errors against h; the drift of the centre of mass."""


from particle_replication.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def run(d, output):
    fig, axes = new_figure(1, 2, width=11, height=4.4)
    h = d["h_values"]
    ax = axes[0]
    for column, name, colour in ((0, "L1", "C0"), (1, "Linf", "C3")):
        ax.loglog(h, d["errors"][:, column], "o-", color=colour, label=f"LTP {name}")
    for power, style in ((1, ":"), (2, "--")):
        ax.loglog(h, d["errors"][-1, 0] * (h / h[-1]) ** power, style, color="0.5", label=f"slope {power}")
    ax.set(xlabel="h", ylabel=f"error against h = {float(d['reference_h']):g}")
    hide_minor_log_labels(ax)
    ax.legend(fontsize="small")
    label_panel(ax, f"(a) W = {d['label']}, t = {float(d['t']):g}, dt = {float(d['dt']):g}")
    ax = axes[1]
    ax.loglog(d["centre_h"], d["centre_drift"], "s-", color="C2", label="drift of the centre of mass")
    ax.loglog(d["centre_h"], d["centre_drift"][-1] * (d["centre_h"] / d["centre_h"][-1]) ** 2, "--", color="0.5",
              label="slope 2")
    ax.set(xlabel="h", ylabel="drift at the final time")
    hide_minor_log_labels(ax)
    ax.legend(fontsize="small")
    label_panel(ax, f"(b) W = {d['centre_label']}, data (6.1)")
    suptitle(fig, "LTP beyond the affine case: convergence in h, centre of mass")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
