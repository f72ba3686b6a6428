"""K = -|x|/2: the density error of the blob method split into quadrature and regularisation parts."""


from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def run(d, output):
    fig, axes = new_figure(1, 2, width=12, height=4.6)
    h, base = 1.0 / d["inverse_h"], int(d["base_count"])
    for ax, m in zip(axes, (4, 6)):
        ax.loglog(h, d[f"m{m}_total"], "ko-", label="blob run: density error")
        ax.loglog(h, d[f"m{m}_quadrature"], "s--", color="C0", label="quadrature part")
        ax.loglog(h, d[f"m{m}_regularisation"], "^--", color="C3", label="regularisation part")
        ax.loglog(h, d[f"m{m}_combined"], ":", color="0.4", label="sum of the parts")
        guide = d[f"m{m}_regularisation"][base - 1] * (h / h[base - 1]) ** (m * float(d["q"]))
        ax.loglog(h, guide, "-", color="C3", lw=0.6, alpha=0.6, label=f"slope m q = {m * float(d['q']):g}")
        ax.axvspan(h[-1] / 1.2, h[base - 1] / 1.2, color="0.9", zorder=0, label="beyond the paper's h")
        ax.set(xlabel="h", ylabel=f"L1_h density error at t = {float(d['t']):g}")
        ax.legend(fontsize="small", loc="lower right")
        label_panel(ax, f"({'ab'[m == 6]}) m = {m}")
    suptitle(fig, r"$K = -|x|/2$: where the density error comes from")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.output)  # noqa: F821
