"""Figures 7 and 8: trajectories (grey) and end states (dots), particle method above, blob method below."""


from particle_methods.plotting import new_figure, save_figure
from particle_methods.workflow import load_results, logged

KERNEL_TITLES = {
    "quartic_log": "|x|^4/4 - log|x|/(2 pi)", "quartic_power": "|x|^4/4 - |x|^1.5/1.5",
    "septic_power": "|x|^7/7 - |x|^1.5/1.5", "morse_1": "e^{-|x|} - 2 e^{-|x|/2}",
    "morse_2": "2 e^{-|x|} - 2 e^{-|x|/2}",
}


def run(d, title, output):
    labels = list(d["labels"])
    fig, axes = new_figure(2, len(labels), width=4.3 * len(labels), height=8.6)
    for column, label in enumerate(labels):
        kernel, data = label.split("|")
        t_max = d[f"case{column}_times"][-1]
        for row, method in enumerate(("particle", "blob")):
            ax = axes[row, column]
            paths = d[f"case{column}_{method}"]
            ax.plot(paths[:, :, 0], paths[:, :, 1], color="0.75", lw=0.4)
            ax.plot(paths[-1, :, 0], paths[-1, :, 1], "o", ms=2.5, color="C3" if method == "blob" else "C0")
            ax.set(xlabel="x", ylabel="y", aspect="equal")
            ax.set_title(f"{method}: K = {KERNEL_TITLES[kernel]}\n{data} data, t = {t_max:g}", fontsize=9)
    fig.suptitle(f"{title} (h = {float(d['h']):.3g}, delta = {float(d['delta']):g})")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.title, snakemake.output)  # noqa: F821
