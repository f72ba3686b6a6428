"""The long-time measures of section 6.2: collapse (Figure 5), concentration (Figures 6-7), peaks
(Figure 8)."""

import math

import numpy as np

from particle_methods.ltp.measures import collapse_times, shrink_rate_inverse
from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.workflow import load_results, logged


def run(inputs, p, output):
    d5, d6, d7, d8 = (load_results(path) for path in (inputs.fig5, inputs.fig6, inputs.fig7, inputs.fig8))
    fig, axes = new_figure(2, 2, width=12, height=8.5)
    ax = axes[0, 0]
    windows = [tuple(w) for w in p["fig5"]["collapse"]["windows"]]
    for i, label in enumerate(d5["labels"]):
        times, sizes = d5[f"case{i}_times"], d5[f"case{i}_widths"].min(axis=1)
        g = shrink_rate_inverse(times, sizes)
        slopes, collapse = collapse_times(times, sizes, windows)
        end = f"collapse at t = {collapse[-1]:.3g}" if math.isfinite(collapse[-1]) else "no collapse"
        ax.plot(times, g, color=f"C{i}", label=f"W = {label}:\n{end}")  # two lines: the legend fits the panel
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set(xlabel="t", ylabel="g = -1 / (d log h_min / dt)")
    ax.legend(fontsize="small")
    label_panel(ax, "(a) Figure 5: g falls to 0 at a collapse")
    series = [(f"Fig 6, W = {label}", d6[f"case{i}_times"], d6[f"case{i}_concentration_widths"],
               d6[f"case{i}_concentration_masses"]) for i, label in enumerate(d6["labels"])
              if f"case{i}_concentration_widths" in d6]
    series.append(("Fig 7, data (6.3)", d7["record_times"], d7["concentration_widths"], d7["concentration_masses"]))
    q = p["concentration"]
    for i, (label, times, widths, masses) in enumerate(series):
        axes[0, 1].semilogy(times, widths.max(axis=1), color=f"C{i}", label=label)
        axes[1, 0].plot(times, masses.sum(axis=1), color=f"C{i}", label=label)
    axes[0, 1].set(xlabel="t", ylabel=f"width holding {q['fraction']:g}\nof a side's mass")
    axes[0, 1].legend(fontsize="small")
    label_panel(axes[0, 1], "(b) Figures 6-7: concentration widths")
    axes[1, 0].set(xlabel="t", ylabel=f"mass within {q['radius']:g}\nof the two peaks", ylim=(0, 1.05))
    # the series and colours of (b): a legend here would cover the rising curves
    axes[1, 0].text(0.98, 0.3, "lines as in (b)", transform=axes[1, 0].transAxes, ha="right", fontsize="small")
    label_panel(axes[1, 0], "(c) Figures 6-7: mass near the peaks")
    ax = axes[1, 1]
    spread = ax.twinx()
    for method, colour in (("sp", "C3"), ("ltp", "C0")):
        times = d8[f"{method}_times"]
        ax.plot(times, d8[f"{method}_oscillation"], "-", color=colour, label=f"{method.upper()}: excess variation")
        spread.plot(times, np.ptp(d8[f"{method}_centres"], axis=1), ":", color=colour,
                    label=f"{method.upper()}: spread of the centres")
        steady = float(d8[f"{method}_steady"])
        if math.isfinite(steady):
            ax.axvline(steady, color=colour, ls="--", lw=1, label=f"{method.upper()} steady from t = {steady:g}")
    ax.axhline(float(p["fig8"]["oscillation"]), color="0.4", lw=0.8, label="oscillation threshold")
    ax.set(xlabel="t", ylabel="TV / (2 (max left\n+ max right)) - 1")
    spread.set(ylabel="max x_k - min x_k", ylim=(0, None))
    lines = ax.get_legend_handles_labels()
    more = spread.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize="small", loc="lower left", bbox_to_anchor=(0.08, 0.02))
    label_panel(ax, f"(d) Figure 8, W = {d8['label']}")
    suptitle(fig, "LTP paper, section 6.2: the long-time behaviour measured")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.input, snakemake.params.cfg, snakemake.output)  # noqa: F821
