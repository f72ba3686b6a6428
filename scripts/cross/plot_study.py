"""Work-precision diagrams of the cross-method comparison: W1 error against the number of particles
or cells, or against wall time, for every data (rows) and time (columns)."""

import numpy as np

from particle_replication.plotting import label_panel, new_figure, save_figure, suptitle
from particle_replication.verdicts.cross import cases, series
from particle_replication.workflow import load_results, logged

#: W1 at most this (about 1e4 ulps of the unit length: exact to rounding) is drawn on the panel's bottom edge with
#: open markers, so that the axis spans only the measured errors.
EXACT = 1e-12
STYLES = {
    "SPD, equal masses": ("C0", "o", "-"),
    "SPD, grid weights": ("C1", "s", "-"),
    "particle method": ("C2", "^", "--"),
    "Godunov for F": ("C3", "D", "-"),
    "LTP": ("C6", ">", "-"),
    "SP": ("C7", "p", "-"),
}
#: The blob methods, one per mollifier order of the config ("blob, m = <m>"), in the order the study lists them.
BLOB_STYLES = (("C4", "v", "-"), ("C5", "<", "-"), ("C8", "*", "-"), ("C9", "h", "-"))
TITLES = {"smooth20": "(4.3) (1 - x^2)^20", "indicator": "(4.4) indicator of [-1, 1]"}


def run(d, p, figure, output):
    data, times = p["data"], p["times"]
    every = cases(d)
    styles = {**STYLES, **dict(zip([m for m in map(str, d["methods"]) if m.startswith("blob, ")], BLOB_STYLES))}
    fig, axes = new_figure(len(data), len(times), width=11, height=8.5, squeeze=False)
    for i, name in enumerate(data):
        for j, t in enumerate(times):
            ax = axes[i, j]
            drawn = [p["target_error"]]
            for method in map(str, d["methods"]):
                if (name, t, method) not in every:
                    continue
                _, counts, errors, seconds = series(d, name, t, method)
                colour, marker, line = styles.get(method, ("k", "x", "-"))
                # The equal-mass SPD often lies on the grid SPD: smaller markers on top, so both show.
                size, order = (2.5, 3) if method == "SPD, equal masses" else (4.5, 2)
                x = counts if figure == "error_size" else seconds
                exact = errors <= EXACT
                drawn.extend(errors[~exact])
                ax.plot(x[~exact], errors[~exact], line + marker, color=colour, lw=1, ms=size, label=method,
                        zorder=order)
                # On the bottom edge (axes coordinates in y): left out of the layout, which would otherwise
                # measure them before the axis limits are set.
                ax.plot(x[exact], np.zeros(exact.sum()), marker, color=colour, ms=size + 1, ls="none", mfc="none",
                        zorder=order, clip_on=False, transform=ax.get_xaxis_transform())[0].set_in_layout(False)
            ax.axhline(p["target_error"], color="k", lw=0.6, ls=":")
            # Axes fitted to the panel's data (no empty decades).
            ax.set(xscale="log", yscale="log", ylim=(min(drawn) / 3, max(drawn) * 3),
                   xlabel="particles or cells" if figure == "error_size" else "wall time (s), after JIT warm-up",
                   ylabel="W1 error")
            label_panel(ax, f"({'abcd'[i * len(times) + j]}) {TITLES.get(name, name)}, t = {t:g}")
    # One legend below the panels (inside one, it would hide lines).
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=4, fontsize="small")
    suptitle(fig, "K = |x|/2: W1 distance to the exact solution "
                 + ("against size" if figure == "error_size" else "against wall time")
                 + f" (dotted: {p['target_error']:g}; open markers on the bottom edge: exact to rounding, "
                 f"W1 <= {EXACT:g})")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.cfg, snakemake.params.figure,  # noqa: F821
        snakemake.output)  # noqa: F821
