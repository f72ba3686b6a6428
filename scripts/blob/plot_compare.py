"""Figures 7 and 8: trajectories (grey) and end states (dots), particle method above, blob method below."""

import numpy as np
from matplotlib.ticker import MaxNLocator

from particle_replication.plotting import mathtext, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged

KERNEL_TITLES = {
    "quartic_log": r"$K = |x|^4/4 - \log|x|/(2\pi)$",
    "quartic_power": r"$K = |x|^4/4 - |x|^{3/2}/(3/2)$",
    "septic_power": r"$K = |x|^7/7 - |x|^{3/2}/(3/2)$",
    "morse_1": r"$K = e^{-|x|} - 2e^{-|x|/2}$",
    "morse_2": r"$K = 2e^{-|x|} - 2e^{-|x|/2}$",
}
DATA_TITLES = {"quartic": "data (4.7)", "star": "star patch (4.6)"}


def run(d, title, output):
    labels = list(d["labels"])
    fig, axes = new_figure(2, len(labels), width=2.45 * len(labels), height=5.4)
    for column, label in enumerate(labels):
        kernel, data = label.split("|")
        t_max = d[f"case{column}_times"][-1]
        both = np.concatenate([d[f"case{column}_{method}"].reshape(-1, 2) for method in ("particle", "blob")])
        low, high = both.min(axis=0), both.max(axis=0)
        low, high = low - 0.06 * (high - low), high + 0.06 * (high - low)   # same frame for both methods
        axes[0, column].set_title(f"{KERNEL_TITLES.get(kernel, kernel)}\n{DATA_TITLES.get(data, mathtext(data))}, "
                                  f"$t = {t_max:g}$", fontsize="medium")
        for row, method in enumerate(("particle", "blob")):
            ax = axes[row, column]
            paths = d[f"case{column}_{method}"]
            ax.plot(paths[:, :, 0], paths[:, :, 1], color="0.75", lw=0.4)
            ax.plot(paths[-1, :, 0], paths[-1, :, 1], "o", ms=1.8, color="C3" if method == "blob" else "C0")
            ax.set(xlabel="$x$", aspect="equal", xlim=(low[0], high[0]), ylim=(low[1], high[1]))
            ax.xaxis.set_major_locator(MaxNLocator(5))
            ax.yaxis.set_major_locator(MaxNLocator(5))
            ax.tick_params(labelsize="small")
    axes[0, 0].set_ylabel("particle method\n$y$")
    axes[1, 0].set_ylabel("blob method\n$y$")
    suptitle(fig, f"{mathtext(title)}\n($h = {float(d['h']):.3g}$, $\\delta = {float(d['delta']):g}$)")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.title, snakemake.output)  # noqa: F821
