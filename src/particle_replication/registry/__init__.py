"""One registry per paper (:mod:`.sticky`, :mod:`.ltp`, :mod:`.blob`, :mod:`.cross`): every result
file (its writer, its keys, the parameters of the job that computes it) and every figure (its plot
script, the result files it reads, its caption and title).

The Snakemake rules that compute the results and draw the figures are generated from it
(``rules/registry.smk``), and so are the lists of figures of the targets, the notebooks' inputs,
the pipeline test's expectations and the README's figure map (``python -m
particle_replication.registry`` prints it; a test keeps the README in step). The result files'
keys are checked against it when they are written and read
(:func:`particle_replication.workflow.save_results`, :func:`~.workflow.load_results`).

The registry holds names, texts and the functions that pick a job's parameters out of the config;
what it gives a job reaches it as the rule's params, input files and script, which Snakemake tracks.
So the registry's modules are not among the rules' code inputs: editing a caption reruns the plot
jobs of that figure's batch (:attr:`~.records.Paper.plot_batches`), not the computations.

Adding a figure: a :class:`~.records.Result` with its :class:`~.records.Job` and a
:class:`~.records.Plot` in the paper's module, the data and plot scripts, and the values they read
in ``config/config.yaml``.
"""

from __future__ import annotations

from fnmatch import fnmatchcase
from pathlib import PurePath

from . import blob, cross, ltp, sticky
from .records import Figure, Job, Paper, Plot, Result

PAPERS: dict[str, Paper] = {paper.id: paper for paper in (sticky.PAPER, ltp.PAPER, blob.PAPER, cross.PAPER)}
RESULTS: tuple[Result, ...] = tuple(entry for paper in PAPERS.values() for entry in paper.results)

__all__ = ["PAPERS", "RESULTS", "Figure", "Job", "Paper", "Plot", "Result", "figure_map", "figure_outputs", "result"]


def figure_outputs(paper: str | None = None) -> list[str]:
    """Every figure file (PDF and PNG) of one paper, or of all of them."""
    papers = PAPERS.values() if paper is None else [_paper(paper)]
    return [path for entry in papers for path in entry.outputs()]


def result(path) -> Result | None:
    """The entry of a result file (its path ending in a declared path), or None for a file the
    registry does not know (a scratch file, a test's own)."""
    path = PurePath(path).as_posix()
    for entry in RESULTS:
        if fnmatchcase(path, entry.path) or fnmatchcase(path, f"*/{entry.path}"):
            return entry
    return None


def figure_map(config=None) -> str:
    """The README's figure map for a configuration (the full run's, ``config/config.yaml``, by default):
    every figure, by its number as the report prints it (:attr:`~.records.Paper.numbers`: the paper's, or A1,
    A2, ... for ours) and its file's name, what it shows, the rules that compute its data (with their scripts)
    and the rule that draws it, as a Markdown table."""
    if config is None:
        from ..paths import REPOSITORY, read_yaml

        config = read_yaml(REPOSITORY / "config" / "config.yaml")
    entries = {entry.path: entry for entry in RESULTS}
    rows = ["| paper | figure | shows | data rule (script) | plot rule |", "|---|---|---|---|---|"]
    for paper in PAPERS.values():
        for plot in paper.plots:
            sources = ", ".join(_computed_by(entries[path]) for path in plot.data.values()) or "-"
            for figure in plot.figures:
                label = figure.describe(config[paper.id]).replace("|", "\\|")
                name = f"{paper.numbers[figure.name]} (`{figure.name}`)"
                rows.append(f"| {paper.id} | {name} | {label} | {sources} | `{plot.rule(paper.id)}` |")
    return "\n".join(rows)


def _computed_by(entry: Result) -> str:
    return f"`{entry.rule}` ({entry.writer})"


def _paper(paper: str) -> Paper:
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {sorted(PAPERS)}, got {paper!r}")
    return PAPERS[paper]
