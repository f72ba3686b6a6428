"""Figure 5's pairwise orders as a LaTeX table for the report: the run's own, and those of the opt-in
overlay config/fig5-extended.yaml (finer grids, down to the h its rule's parameters name) when its results exist."""

from pathlib import Path

import numpy as np

from particle_methods.convergence import fit_order, pairwise_orders
from particle_replication.report import tex
from particle_replication.workflow import load_results, logged, progress

PARTS = ("trajectory", "density")


def table(d, title) -> str:
    """One tabular: a row per case and quantity, the pairwise order of each step of h, the fit on the finest."""
    h, k = d["h_values"], int(d["fit_points"])
    steps = " & ".join(f"{1 / a:.0f}--{1 / b:.0f}" for a, b in zip(h[:-1], h[1:]))
    rows = []
    for index, label in enumerate(d["labels"]):
        for part in PARTS:
            errors = d[f"case{index}_{part}"]
            if np.all(np.isnan(errors)):
                continue
            cells = " & ".join(f"{value:.2f}" for value in pairwise_orders(h, errors))
            rows.append(f"{tex(str(label))}, {part} & {cells} & {fit_order(h[-k:], errors[-k:]):.2f} \\\\\n")
    columns = "l" + "r" * h.size
    return (f"\\noindent {title}\\par\\nopagebreak\n{{\\footnotesize\\begin{{tabular}}{{@{{}}{columns}@{{}}}}"
            f"\\toprule case & \\multicolumn{{{h.size - 1}}}{{c}}{{pairwise order, $1/h$ from -- to}} & fit \\\\\n"
            f" & {steps} & {k} finest \\\\ \\midrule\n" + "".join(rows) + "\\bottomrule\\end{tabular}}\\par\\medskip\n")


def run(data, extended, extended_finest, output):
    text = table(load_results(data), "This run:")
    if Path(extended).exists() and not Path(extended).samefile(data):
        progress(f"overlay results found: {extended}")
        text += table(load_results(extended), "The overlay \\texttt{config/fig5-extended.yaml}:")
    else:
        text += ("\\noindent The overlay \\texttt{config/fig5-extended.yaml} "
                 f"(to $h = 1/{extended_finest}$) has not been run in this clone.\\par\n")
    temporary = Path(output).with_name(Path(output).name + ".tmp")
    temporary.write_text(text)
    temporary.replace(output)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    params = snakemake.params  # noqa: F821
    run(snakemake.input.data, params.extended, params.extended_finest, snakemake.output[0])  # noqa: F821
