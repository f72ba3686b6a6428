"""Figures 4 to 7: MSPD trajectories (4, 6) and w-, w+, u, v in the space-time plane (5, 7)."""

from particle_methods.systems import MINUS, PLUS
from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def trajectories(d, title, output):
    fig, ax = new_figure(1, 1, width=7, height=3.8)
    path = d["trajectories"]
    ax.plot(path[:, MINUS], d["times"], color="tab:blue", lw=0.9)
    ax.plot(path[:, PLUS], d["times"], color="tab:red", lw=0.9)
    ax.plot([], [], color="tab:blue", label="type - (w-)")
    ax.plot([], [], color="tab:red", label="type + (w+)")
    if title.startswith("p-system with shocks"):
        ax.axhline(d["trajectories_end"], color="k", ls="--", lw=0.8,
                   label=f"w+ >= w- and no cluster from t = {float(d['trajectories_end']):.3g}")
    ax.set(xlabel="x", ylabel="t")
    # Legend outside the axes, below them, so that it covers no trajectory.
    fig.legend(loc="outside lower center", ncol=3)
    step = d["times"][1] - d["times"][0]
    ax.set_title(f"{title}: {path.shape[-1]} particles per type, iterated TSPD, Delta = {step:g}")
    save_figure(fig, output.pdf, output.png)


def fields(d, title, output):
    fig, axes = new_figure(2, 2, width=11, height=6.6)
    panels = [("w_minus", "(a) w-"), ("w_plus", "(b) w+"), ("u", "(c) specific volume u"), ("v", "(d) velocity v")]
    for ax, (key, label) in zip(axes.flat, panels):
        mesh = ax.pcolormesh(d["field_x"], d["times"], d[key], shading="auto", rasterized=True)
        fig.colorbar(mesh, ax=ax, label=label.split(" ", 1)[1])
        ax.set(xlabel="x", ylabel="t")
        label_panel(ax, label)
        if title.startswith("p-system with shocks"):
            ax.axhline(d["field_end"], color="w", ls="--", lw=0.8)
    n = d["field_path"].shape[-1]
    end = (f"; dashed: w+ >= w- and no cluster from t = {float(d['field_end']):.3g}"
           if title.startswith("p-system with shocks") else "")
    suptitle(fig, f"{title}: iterated TSPD with n = {n} per type, Delta = {d['times'][1] - d['times'][0]:g}{end}")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    data = load_results(snakemake.input.data)  # noqa: F821
    draw = {"trajectories": trajectories, "fields": fields}[snakemake.params.kind]  # noqa: F821
    draw(data, snakemake.params.title, snakemake.output)  # noqa: F821
