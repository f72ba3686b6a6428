"""Beyond the paper: the exact MSPD's limit against two finite-volume schemes (``beyond_limits``)
and the work-precision diagrams of the cost argument of section 5.2 (``beyond_cost``)."""

import numpy as np

from particle_methods.sticky.cases import empirical_cdf
from particle_methods.systems import MINUS, PLUS
from particle_replication.plotting import hide_minor_log_labels, label_panel, new_figure, save_figure, suptitle
from particle_replication.verdicts.sticky import SCALAR_NAMES, exponent_window
from particle_replication.workflow import load_results, logged

METHODS = {  # key in the results, label, colour, marker
    "spd": ("SPD", "C0", "o"),
    "godunov": ("Godunov", "C3", "D"),
    "tspd": ("iterated TSPD, L = n", "C1", "s"),
    "exact": ("exact MSPD", "C4", "^"),
    "upwind": ("upwind for (1.7)", "C2", "v"),
}


def cell_centres(domain, cells):
    edges = np.linspace(*domain, cells + 1)
    return (edges[1:] + edges[:-1]) / 2


def limits(d, p, output):
    fig, axes = new_figure(1, 3, width=11, height=5.2, squeeze=False)
    centres = cell_centres(p["domain"], int(d["reference_cells"]))
    centres_up = cell_centres(p["domain"], int(d["upwind_reference_cells"]))
    for j, case in enumerate(map(str, d["cases"])):
        ax = axes[0, j]
        for gamma, name, style in ((MINUS, "w-", "-"), (PLUS, "w+", "--")):
            ax.plot(centres, empirical_cdf(d[f"{case}_mspd"][gamma], centres), style, color="C4", lw=1.6,
                    label=f"{name} exact MSPD")
            ax.plot(centres, d[f"{case}_hll_w"][gamma], style, color="C3", lw=1.0, label=f"{name} HLL (conservative)")
            ax.plot(centres_up, d[f"{case}_upwind_w"][gamma], style, color="C2", lw=0.8,
                    label=f"{name} upwind for (1.7)")
        ax.set(xlim=(-12, 12), xlabel="x", ylabel="Riemann invariant" if j == 0 else "")  # (b) shares (a)'s
        label_panel(ax, f"({'ab'[j]}) {case}, t = {float(d['t']):g}")
    ax = axes[0, 2]
    n = d["limit_n"]
    for j, case in enumerate(map(str, d["cases"])):
        colour = f"C{j}"
        ax.plot(n, d[f"{case}_limit_to_hll"], "o-", color=colour, label=f"{case}: to HLL")
        ax.plot(n, d[f"{case}_limit_to_upwind"], "s--", color=colour, mfc="none", label=f"{case}: to upwind (1.7)")
        ax.axhline(float(d[f"{case}_hll_gap"]), color=colour, lw=0.7, ls=":")
        ax.axhline(float(d[f"{case}_upwind_gap"]), color=colour, lw=0.7, ls="-.")
    ax.plot(n, 2.0 / n, "k:", lw=0.7, label="slope -1")
    ax.plot([], [], color="0.4", lw=0.7, ls=":", label="HLL to its half resolution")
    ax.plot([], [], color="0.4", lw=0.7, ls="-.", label="upwind to its half resolution")
    ax.set(xscale="log", yscale="log", xlabel="n per type", ylabel=r"$W_1^{(d)}$ distance")
    # Ticks at the particle counts run, without the log axis's minor labels (which ran into each other).
    ax.set_xticks(n, [f"{int(count)}" for count in n])
    hide_minor_log_labels(ax)
    label_panel(ax, "(c) exact MSPD to the schemes")
    # One legend under the three panels: the curves of (a, b), then the distances of (c); three columns, so that it
    # is no wider than the panels (four made the figure a third wider, and printed it that much smaller).
    handles, labels = axes[0, 0].get_legend_handles_labels()
    more = ax.get_legend_handles_labels()
    fig.legend(handles + more[0], labels + more[1], loc="outside lower center", ncol=3, fontsize="small")
    suptitle(fig, "Which limit? Exact MSPD, conservative HLL and nonconservative upwind on the p-system")
    save_figure(fig, output.pdf, output.png)


def cost(d, p, output):
    """Error against operations and wall time; the runs each cost exponent is fitted on are filled, the others
    hollow (on the p-system, those whose pairwise exponents the reference's own error blurs: exponent_window,
    the rule of the claims)."""
    panels = [(name, label, ("spd", "godunov")) for name, label in SCALAR_NAMES.items()]
    panels += [(str(case), f"p-system, {case}", ("tspd", "exact", "upwind")) for case in d["cases"]]
    fig, axes = new_figure(len(panels), 2, width=8.5, height=2.3 * len(panels) + 0.8, squeeze=False)
    for j, (name, label, methods) in enumerate(panels):
        reference_error = float(d[f"{name}_reference_error"]) if name in d["cases"] else 0.0
        for row, (column, xlabel) in enumerate(((1, "operations"), (2, "wall time (s), after JIT warm-up"))):
            ax = axes[j, row]
            for method in methods:
                runs = d[f"{name}_{method}"]
                text, colour, marker = METHODS[method]
                ax.plot(runs[column], runs[0], "-", color=colour, lw=1)
                fitted = np.zeros(runs.shape[1], dtype=bool)
                window = exponent_window(runs[0], runs[1], reference_error, p["window"], p["exponent_uncertainty"])
                fitted[window] = True
                ax.plot(runs[column][fitted], runs[0][fitted], marker, color=colour, ms=4, label=text)
                ax.plot(runs[column][~fitted], runs[0][~fitted], marker, color=colour, ms=4, mfc="white")
            ax.set(xscale="log", yscale="log", xlabel=xlabel, ylabel="W1 error")
            if row == 0:  # error ~ work^(-1/slope): slope 1 for O(1/eps), 2 for O(eps^-2)
                (left, right), (bottom, top) = ax.get_xlim(), ax.get_ylim()
                work = np.geomspace(left, right, 3)
                for slope in (1, 2):
                    ax.plot(work, top * (work / left) ** (-1.0 / slope), "k:", lw=0.7)
                ax.set(xlim=(left, right), ylim=(bottom, top))
            label_panel(ax, f"({'abcdefgh'[2 * j + row]}) {label}")
    legend = {}
    for ax in axes[:, 0]:
        legend.update(zip(*ax.get_legend_handles_labels()[::-1]))
    legend["not in the fit"] = ax.plot([], [], "o", color="0.4", mfc="white", ms=4)[0]
    fig.legend(list(legend.values()), list(legend), loc="outside lower center", ncol=4, fontsize="small")
    suptitle(fig, "Error against cost: particles (hull, TSPD, exact events) and finite volumes (cell updates)")
    save_figure(fig, output.pdf, output.png)


def run(d, p, figure, output):
    if figure == "beyond_limits":
        limits(d, p, output)
    else:
        cost(d, p, output)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.cfg, snakemake.params.figure,  # noqa: F821
        snakemake.output)  # noqa: F821
