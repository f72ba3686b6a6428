"""One registry per paper: every figure (its plot job, script, data, caption, title) and every
result file (its writer and its keys, in :mod:`.results`).

The Snakemake rules that draw the figures are generated from it (``rules/figures.smk``), and so
are the lists of figures of the targets, the notebooks' inputs, the pipeline test's expectations
and the README's figure map (``python -m particle_replication.registry`` prints it; a test keeps
the README in step). The result files' keys are checked against it when they are written and
read (:func:`particle_replication.workflow.save_results`, :func:`~.workflow.load_results`).

Adding a figure: a :class:`~.records.Plot` in the paper's module, its script, and the values
its caption reads in ``config/config.yaml``; a new result file adds a :class:`~.records.Result`
in :mod:`.results` and its data rule in ``rules/<paper>.smk``.
"""

from __future__ import annotations

from . import blob, cross, ltp, sticky
from .records import Figure, Paper, Plot, Result
from .results import RESULTS, result

PAPERS: dict[str, Paper] = {paper.id: paper for paper in (sticky.PAPER, ltp.PAPER, blob.PAPER, cross.PAPER)}

__all__ = ["PAPERS", "RESULTS", "Figure", "Paper", "Plot", "Result", "figure_map", "figure_outputs", "result"]


def figure_outputs(paper: str | None = None) -> list[str]:
    """Every figure file (PDF and PNG) of one paper, or of all of them."""
    papers = PAPERS.values() if paper is None else [_paper(paper)]
    return [path for entry in papers for path in entry.outputs()]


def figure_map() -> str:
    """The README's figure map: every figure, what it shows, the result files it is drawn from and
    the scripts that write and draw them, as a Markdown table."""
    writers = {entry.path: entry.writer for entry in RESULTS}
    rows = ["| paper | figure | shows | drawn from (written by) | plot rule |", "|---|---|---|---|---|"]
    for paper in PAPERS.values():
        for plot in paper.plots:
            sources = ", ".join(f"`{path.removeprefix('results/')}` ({writers[path]})" for path in plot.data.values())
            for figure in plot.figures:
                label = figure.label.replace("|", "\\|")
                name = f"{figure.name} (ours)" if figure.ours else figure.name
                rows.append(f"| {paper.id} | {name} | {label} | {sources or '-'} | `{plot.rule(paper.id)}` |")
    return "\n".join(rows)


def _paper(paper: str) -> Paper:
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {sorted(PAPERS)}, got {paper!r}")
    return PAPERS[paper]
