"""What the registry records: a figure, the plot job that draws it, a result file and its keys,
a paper's whole entry. Captions, titles and plot parameters are functions of the paper's section
of the configuration, so that a figure's text follows the values it was computed with."""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from fnmatch import fnmatchcase

Section = Mapping  # one paper's section of the configuration (config[paper])


def _nothing(section: Section) -> dict:
    return {}


@dataclass(frozen=True)
class Figure:
    """One figure: ``figures/<paper>/<name>.{pdf,png}``.

    ``label`` is the line of the README's figure map (a text, or a function of the section when it names
    parameters), ``caption`` the Snakemake report's caption, ``title`` the figure's own heading (None when
    the plot script composes it from its data), and ``ours`` marks a figure of our own studies, not of the
    paper.
    """

    name: str
    label: str | Callable[[Section], str]
    caption: Callable[[Section], str]
    title: Callable[[Section], str] | None = None
    ours: bool = False

    def describe(self, section: Section) -> str:
        """The figure map's line for the paper's ``section`` of a configuration."""
        return self.label(section) if callable(self.label) else self.label


@dataclass(frozen=True)
class Plot:
    """One plot job: ``scripts/<paper>/<script>`` draws ``figures`` from the result files ``data``
    (input names to paths under the run's root), with ``params`` from the paper's section."""

    script: str
    figures: tuple[Figure, ...]
    data: Mapping[str, str] = field(default_factory=dict)
    params: Callable[[Section], dict] = _nothing

    def __post_init__(self):
        if len({figure.ours for figure in self.figures}) != 1:
            raise ValueError(f"{self.script}: a plot job draws figures of the paper or ours, not both: {self.names}")

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(figure.name for figure in self.figures)

    @property
    def key(self) -> str:
        """The plot job's name within its paper (its figures' names joined): its log, and the prefix of its inputs
        in its batch's rule."""
        return "_".join(self.names)

    @property
    def ours(self) -> bool:
        """Whether its figures are of our own studies."""
        return self.figures[0].ours

    def rule(self, paper: str) -> str:
        """Name of the generated Snakemake rule that runs it: one per paper for the paper's figures, ``plot_<paper>``,
        and one for ours, ``plot_<paper>_ours`` (:attr:`Paper.plot_batches`)."""
        return f"plot_{paper}_ours" if self.ours else f"plot_{paper}"


@dataclass(frozen=True)
class Job:
    """How a result file is computed: its data rule runs the result's writer with ``params`` from
    the paper's section, reading the result files ``inputs`` (input names to paths), on one thread
    or, for a timing study that must not share the cores, on ``threads="all"``; or on what a function of the
    paper's section gives, for a job whose size decides whether it can use more threads than one."""

    about: str
    params: Callable[[Section], dict]
    inputs: Mapping[str, str] = field(default_factory=dict)
    threads: int | str | Callable[[Section], int | str] = 1

    def threads_in(self, section: Section) -> int | str:
        """The job's threads under the paper's ``section``: 1, another count, or "all" (every core of the run)."""
        threads = self.threads(section) if callable(self.threads) else self.threads
        if threads != "all" and not (isinstance(threads, int) and not isinstance(threads, bool) and threads >= 1):
            raise ValueError(f"{self.about}: threads must be a positive integer or 'all', got {threads!r}")
        return threads


@dataclass(frozen=True)
class Result:
    """One ``.npz`` result file: its path under the run's root (``results/<paper>/...``), the
    script of ``scripts/<paper>/`` that writes it, its keys as ``fnmatch`` patterns
    (``case*_density``) where the config decides the names, and either its :class:`Job`, from which
    its data rule is generated, or ``hand_rule``, the name of the rule written by hand in
    ``rules/<paper>.smk`` that computes it. The writer and every reader check the file against these
    keys (:func:`check_keys`)."""

    path: str
    writer: str
    keys: tuple[str, ...]
    job: Job | None = None
    hand_rule: str | None = None

    def __post_init__(self):
        if (self.job is None) == (self.hand_rule is None):
            raise ValueError(f"{self.path}: give either job (a generated rule) or hand_rule (a rule written by hand)")

    @property
    def rule(self) -> str:
        """Name of the rule that computes it: the hand-written one, or the generated data_<paper>_<file stem>."""
        if self.hand_rule is not None:
            return self.hand_rule
        return "data_" + self.path.removeprefix("results/").removesuffix(".npz").replace("/", "_")

    def check_keys(self, keys) -> None:
        """Raise KeyError unless ``keys`` are exactly those declared: every key matches a pattern,
        every plain name is present and every pattern matches at least one key."""
        keys = set(keys)
        stray = sorted(key for key in keys if not any(fnmatchcase(key, pattern) for pattern in self.keys))
        missing = [pattern for pattern in self.keys if not any(fnmatchcase(key, pattern) for key in keys)]
        if stray or missing:
            raise KeyError(
                f"{self.path}: keys not declared in the registry {stray}, declared keys "
                f"missing {missing} (particle_replication.registry; a file written by older code: "
                f"rerun the job that writes it)"
            )


@dataclass(frozen=True)
class Paper:
    """A paper's entry: its name in figure labels (``Blob``: Figure Blob 7), its plot jobs, its result files,
    and the result files its notebook (``notebooks/<id>.py``) reads besides its claims table."""

    id: str
    name: str
    plots: tuple[Plot, ...]
    results: tuple[Result, ...]
    notebook: tuple[str, ...]

    @property
    def figures(self) -> tuple[Figure, ...]:
        return tuple(figure for plot in self.plots for figure in plot.figures)

    @property
    def plot_batches(self) -> dict[str, tuple[Plot, ...]]:
        """The plot jobs by the rule that runs them, in registry order: the paper's figures in one process, ours in
        another (a figure of ours may read the slowest results, which the paper's figures need not wait for). A
        process per plot job spent about 2.6 s starting Python, importing matplotlib and warming its fonts and
        formula parser, half of a quick run's plotting (benchmarks/README.md)."""
        batches: dict[str, tuple[Plot, ...]] = {}
        for plot in self.plots:
            batches[plot.rule(self.id)] = (*batches.get(plot.rule(self.id), ()), plot)
        return batches

    @property
    def numbers(self) -> dict[str, str]:
        """Each figure's number, by name: a figure of the paper keeps the paper's (``fig7``: ``7``); ours are
        numbered apart, ``A1``, ``A2``, ... in registry order, so they never shift the paper's numbers. The
        report's ``\\ourfig{k}`` numbers, the README's figure map, the HTML report and the notebooks all
        show these."""
        numbers, ours = {}, 0
        for figure in self.figures:
            if figure.ours:
                ours += 1
                numbers[figure.name] = f"A{ours}"
            else:
                numbered = re.fullmatch(r"fig([1-9]\d*)", figure.name)
                if numbered is None:
                    raise ValueError(f"{self.id}: a figure of the paper is named fig<number>, got {figure.name!r}")
                numbers[figure.name] = numbered.group(1)
        return numbers

    def label(self, figure: str) -> str:
        """A figure's label, as the report prints it: ``Figure Blob 7``, ``Figure Blob A1``."""
        if figure not in self.numbers:
            raise ValueError(f"figure must be one of {self.id}'s {sorted(self.numbers)}, got {figure!r}")
        return f"Figure {self.name} {self.numbers[figure]}"

    def claim_inputs(self) -> dict[str, str]:
        """The result files its claims are measured on, by file stem: every registered file but
        those whose names the config decides (patterns)."""
        return {
            entry.path.rsplit("/", 1)[-1].removesuffix(".npz"): entry.path
            for entry in self.results
            if "*" not in entry.path
        }

    def outputs(self) -> list[str]:
        """Every figure file of the paper, PDF and PNG."""
        return [f"figures/{self.id}/{figure.name}.{ext}" for figure in self.figures for ext in ("pdf", "png")]


def listing(values) -> str:
    """Values of a caption: all of them when few, else the first two, an ellipsis and the last."""
    values = [f"{value:g}" for value in values]
    return ", ".join(values if len(values) <= 4 else [*values[:2], "...", values[-1]])


def power(exponent) -> str:
    """|x|^a/a in a caption."""
    return f"|x|^{exponent:g}/{exponent:g}"
