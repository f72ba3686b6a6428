"""What the notebooks show: a figure of the pipeline next to the claims checked on it.

The notebooks (``notebooks/<paper>.py``) read the pipeline's outputs through
:mod:`particle_replication.paths`, so they show the run in ``PARTICLE_METHODS_WORKDIR``.
"""

from __future__ import annotations

import re

from IPython.display import Image, Markdown, display

from .claims import Claim, markdown_table, read_claims, summary_line
from .paths import FIGURES, RESULTS
from .registry import PAPERS

#: The figures this session has shown, paper -> figure names (:func:`show_remaining_figures` shows the rest).
SHOWN: dict[str, set[str]] = {}


def figures_of(claim: Claim) -> set[int]:
    """Figure numbers a claim refers to: '2d' and '2, 3d' name figures, 'Remark 3.3' does not."""
    return {int(match) for part in claim.figure.split(",") for match in re.findall(r"^\s*(\d+)(?![\d.-])", part)}


def paper_claims(paper: str) -> list[Claim]:
    """The claims of one paper, as the pipeline measured them."""
    return read_claims(RESULTS / paper / "claims.csv")


def show_figure(paper: str, figure: int | str) -> None:
    """Display a figure of ``paper``, by the paper's number (``2`` for ``fig2``) or by its name in
    the registry (``"long_time"``), under its label as the report prints it (Figure Blob 4, and ours
    numbered apart: Figure Blob A1, :attr:`particle_replication.registry.Paper.numbers`), and the table of the
    claims checked on a numbered figure."""
    if isinstance(figure, bool) or not isinstance(figure, int | str):
        raise TypeError(f"figure must be a figure number or name, got {figure!r}")
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {sorted(PAPERS)}, got {paper!r}")
    entry = PAPERS[paper]
    name = f"fig{figure}" if isinstance(figure, int) else figure
    ours = next((f.ours for f in entry.figures if f.name == name), False)
    display(Markdown(f"**{entry.label(name)}**" + (", a study of ours, not a figure of the paper" if ours else "")))
    display(Image(filename=str(FIGURES / paper / name) + ".png"))
    SHOWN.setdefault(paper, set()).add(name)
    if not isinstance(figure, int):
        return
    claims = [claim for claim in paper_claims(paper) if figure in figures_of(claim)]
    if claims:
        display(Markdown(markdown_table(claims, heading=False)))


def show_remaining_figures(paper: str) -> None:
    """Display every registered figure of ``paper`` that :func:`show_figure` has not shown in this session,
    each under its label: a figure added to the registry appears in the notebook before the tour discusses it."""
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {sorted(PAPERS)}, got {paper!r}")
    for figure in PAPERS[paper].figures:
        if figure.name not in SHOWN.get(paper, set()):
            show_figure(paper, int(figure.name[3:]) if re.fullmatch(r"fig\d+", figure.name) else figure.name)


def show_other_claims(paper: str) -> None:
    """Display the claims of ``paper`` that refer to no figure (lemmas, remarks, sections)."""
    display(Markdown(markdown_table([claim for claim in paper_claims(paper) if not figures_of(claim)],
                                    heading=False)))


def summary(paper: str) -> str:
    """The counts of one part's claims, kind by kind (:func:`particle_replication.claims.summary_line`): 'Paper
    claims reproduced: p of q. Also derived claims passing: ...; checks passing: ...'."""
    return summary_line(paper_claims(paper))
