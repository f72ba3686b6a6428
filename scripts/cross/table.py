"""The report's table of the comparison: per method and case, the W1 error at the largest size and
the wall time to the target error, on the CPU the study recorded when it timed the runs."""

from particle_replication.report import tex
from particle_replication.verdicts import cross as v
from particle_replication.workflow import load_results, logged


def latex_number(value: float) -> str:
    if value != value:
        return "--"
    if value == float("inf"):
        return "$\\infty$"
    mantissa, exponent = f"{value:.2e}".split("e")
    return f"${mantissa}\\times 10^{{{int(exponent)}}}$"


def work_precision_table(d, cfg) -> str:
    """LaTeX rows: per method and case, the W1 error at the largest size and the wall time to the target
    (an asterisk marks an extrapolation from the two largest runs), and a last row naming the CPU the times were
    measured on (the study's record, ``particle_replication.environment.cpu``)."""
    table = v.fastest_table(d, cfg["target_error"], cfg["min_timed_seconds"])
    keys = list(table)
    head = " & ".join(f"({data}, $t = {t:g}$)" for data, t in keys)
    lines = ["\\begin{tabular}{@{}l" + "r" * len(keys) + "@{}}\\toprule", f"method & {head} \\\\ \\midrule"]
    for method in map(str, d["methods"]):
        cells = []
        for data, t in keys:
            if method not in table[(data, t)]:
                cells.append("--")
                continue
            _, _, errors, _ = v.series(d, data, t, method)
            seconds, extrapolated = table[(data, t)][method]
            cells.append(f"{latex_number(errors[-1])} / {latex_number(seconds)}{'*' if extrapolated else ''}")
        lines.append(f"{method} & " + " & ".join(cells) + " \\\\")
    lines.append("\\midrule")
    lines.append(f"\\multicolumn{{{len(keys) + 1}}}{{@{{}}l}}{{wall times measured on {tex(str(d['cpu']))}}} \\\\")
    lines.append("\\bottomrule\\end{tabular}")
    return "\n".join(lines) + "\n"


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    with open(snakemake.output[0], "w") as handle:  # noqa: F821
        handle.write(work_precision_table(load_results(snakemake.input.study), snakemake.params.cfg))  # noqa: F821
