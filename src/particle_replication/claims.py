"""Checked claims: a statement, where it comes from, the value we measure, a tolerance, a verdict.

Every row has a ``kind``:

- ``paper``: a statement the paper makes; ``published`` holds its value or words and
  ``source`` where the paper makes it (figure, remark, lemma, theorem, section);
- ``derived``: a consequence we derive from the paper's theory (the report gives the
  derivation), for example a blow-up time or a stationary ring radius;
- ``check``: our own consistency checks and diagnostics (integrator accuracy, reference
  convergence, conservation, reruns with other parameters).

Every paper's pipeline writes its claims with :func:`write_claims`; the report step merges them
into ``results/claims.csv`` (columns :data:`COLUMNS`) and a Markdown table. ``verify`` compares
the verdicts with the expected ones kept in a committed file (``config/verdicts.yaml``): a claim
that genuinely fails is expected to fail, with its cause (:data:`CAUSES`) and a one-line reason, so
a run is judged by whether its verdicts changed, not by whether all of them pass.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import inspect
import math
import re
import sys
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import NamedTuple

import numpy as np
import yaml

from particle_methods.validation import ParameterTypeError

from .paths import read_yaml
from .rates import Recorder, merge_rates
from .workflow import load_results

COLUMNS = ("id", "paper", "kind", "source", "figure", "claim", "published", "measured", "tolerance", "status", "value",
           "windows", "distance", "margin")
#: ``status`` of a claim: decided (pass, fail), or a wall-time check that did not decide because the machine was
#: loaded or its speed moved more than the check can tell (:func:`abstain`), which ``verify`` reports but never
#: counts as a difference.
STATUSES = ("pass", "fail", "abstain")
KINDS = ("paper", "derived", "check")
KIND_NAMES = {"paper": "paper claims", "derived": "derived claims", "check": "checks"}
#: Why an expected failure fails. A failure decided by our own instrument (a coarse reference, a grid,
#: a timing) has no cause: it is a defect to fix, marked ``defect`` until it is fixed.
CAUSES = {
    "contradicts": "our measurement contradicts what the paper states",
    "pre-asymptotic": "the statement concerns a limit our resolutions do not reach (the reason says where it holds)",
    "our-inference": "a claim we derived failed: our derivation was wrong (the reason says what)",
    "defect": "no cause of the paper's: our own reference, grid or timing decides the verdict, a defect to fix",
}

ROUNDING = 1e-9
"""The one rounding tolerance of every paper's claims, relative: a quantity that equals another in exact
arithmetic (an identity exact by construction) may differ from it by ``ROUNDING * scale``, the scale being
that of the quantity compared (1 for ratios and relative gaps; the positions' extent, the mass or the time
for absolute ones). A tolerance that decides a paper's statement belongs in the config instead. An identity
is compared at the scale of its operands, never as a ratio to a small quantity: a gap relative to W1 = t/(4n)
multiplies the rounding of positions of size t by n, and the robustness run's nudged data moved such gaps to
within a spread of the tolerance. The value sits far above rounding at the scale of the operands and at least
30 times below the smallest plausible wrong outcome (a centre of mass drifting at O(h^2) in LTP: 3e-8 at
h = 0.005)."""


@dataclass(frozen=True)
class Claim:
    """One row of the claims table."""

    id: str
    paper: str
    kind: str
    source: str
    figure: str
    claim: str
    published: str
    measured: str
    tolerance: str
    status: str
    #: The measured value to full precision (``repr``), for comparisons between builds.
    value: str = ""
    #: For a claim decided on a fitted slope: on how many windows of consecutive resolutions (of the deciding
    #: window's length) the same rule gives the same verdict, "k of K" (:func:`claim`); empty otherwise.
    windows: str = ""
    #: The signed distance of the measured value from the threshold (``repr``): positive on the passing side,
    #: negative on the failing side, -inf for a value not measured (:func:`signed_distance`).
    distance: str = ""
    #: The distance in units of the spread the robustness run measured for this claim (:func:`margin_text`),
    #: filled in when the papers' tables are merged; empty in a paper's own table.
    margin: str = ""

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"status must be one of {', '.join(STATUSES)}, got {self.status!r}")
        if self.status == "abstain" and self.kind != "check":
            raise ValueError(f"only a check may abstain: {self.id!r} is a {self.kind} claim")
        if self.kind not in KINDS:
            raise ValueError(f"kind of {self.id!r} must be one of {', '.join(KINDS)}, got {self.kind!r}")
        if not self.source.strip():
            raise ValueError(f"claim {self.id!r} needs a source: where the paper states it or what it checks")
        if not self.id.startswith(f"{self.paper}."):
            raise ValueError(f"claim id {self.id!r} must start with the paper id {self.paper!r}")
        window_counts(self)  # "k of K" or empty


def _number(value: float) -> str:
    return f"{value:.6g}"


def _measured_text(measured: float) -> str:
    """The measured value as the tables print it: a number, or "not measured" for a non-finite value (a run
    that never settles, a fit on too few points), which fails its claim."""
    return _number(measured) if math.isfinite(measured) else "not measured"


def signed_distance(room: float, measured: float) -> float:
    """The distance of a measured value from its threshold, ``room`` (positive: on the passing side), or -inf
    for a value not measured (non-finite)."""
    return float(room) if math.isfinite(measured) and not math.isnan(room) else -math.inf


def _decided(id, paper, kind, source, figure, claim, published: str, measured: float, tolerance: str,
             room: float) -> Claim:
    """A claim decided by the sign of ``room``, its signed distance from the threshold (pass when >= 0)."""
    distance = signed_distance(room, measured)
    return Claim(id, paper, kind, source, figure, claim, published, _measured_text(measured), tolerance,
                 "pass" if distance >= 0 else "fail", repr(float(measured)), distance=repr(distance))


def close_to(id, paper, figure, claim, published: float, measured: float, tolerance: float, *, kind: str,
             source: str) -> Claim:
    """Pass when |measured - published| <= tolerance."""
    return _decided(id, paper, kind, source, figure, claim, _number(published), measured, f"+-{_number(tolerance)}",
                    tolerance - abs(measured - published))


def relatively_close_to(id, paper, figure, claim, published: float, measured: float, tolerance: float, *,
                        kind: str, source: str) -> Claim:
    """Pass when |measured - published| <= tolerance * |published|."""
    return _decided(id, paper, kind, source, figure, claim, _number(published), measured, f"rel {_number(tolerance)}",
                    tolerance * abs(published) - abs(measured - published))


def at_most(id, paper, figure, claim, tolerance: float, measured: float, published: str | None = None, *,
            kind: str, source: str) -> Claim:
    """Pass when measured <= tolerance (the bound)."""
    return _decided(id, paper, kind, source, figure, claim, published or f"<= {_number(tolerance)}", measured,
                    f"<= {_number(tolerance)}", tolerance - measured)


def at_least(id, paper, figure, claim, tolerance: float, measured: float, published: str | None = None, *,
             kind: str, source: str) -> Claim:
    """Pass when measured >= tolerance (the bound)."""
    return _decided(id, paper, kind, source, figure, claim, published or f">= {_number(tolerance)}", measured,
                    f">= {_number(tolerance)}", measured - tolerance)


def between(id, paper, figure, claim, lower: float, upper: float, measured: float, published: str | None = None, *,
            kind: str, source: str) -> Claim:
    """Pass when lower <= measured <= upper."""
    if not lower <= upper:
        raise ValueError(f"between: lower {lower} must not exceed upper {upper}")
    band = f"[{_number(lower)}, {_number(upper)}]"
    return _decided(id, paper, kind, source, figure, claim, published or f"in {band}", measured, f"in {band}",
                    min(measured - lower, upper - measured))


def abstain(made: Claim, why: str) -> Claim:
    """``made``, a check decided on wall time, turned into an abstention: the machine was loaded while it was
    timed, or its speed moved more than the check can tell, so its value decides nothing (``why`` is appended to
    the claim's text)."""
    return dataclasses.replace(made, status="abstain", claim=f"{made.claim}; abstains: {why}")


COMPARISONS = (close_to, relatively_close_to, at_most, at_least, between)

#: A non-finite number written into a claim's text as a word of its own ("inf", "-inf", "nan"), not part of a
#: name (u_inf, Linf).
_NON_FINITE = re.compile(r"(?<![A-Za-z0-9_.])(-?inf|nan)(?![A-Za-z0-9_])")


def in_words(text: str) -> str:
    """``text`` with every non-finite number written as what it means: a time never reached within the run
    ("t = inf", "time inf") as "never", the exponent p = inf of a norm as "infinity", anything else as "not
    measured". No table prints a non-finite value as a number."""
    text = re.sub(r"\b(t|time) = inf\b(?![A-Za-z0-9_])", r"\1 = never", text)
    text = re.sub(r"\bsteady time inf\b", "steady time never", text)
    text = re.sub(r"\bp = inf\b", "p = infinity", text)
    return _NON_FINITE.sub("not measured", text)


def claim(paper: str, compare, name: str, kind: str, source: str, figure: str, text: str, *args, **kwargs) -> Claim:
    """The one constructor of every claim: ``<paper>.<name>``, its kind (:data:`KINDS`), its source in the
    paper, the figure it concerns and its statement ``text``, decided by ``compare`` (one of
    :data:`COMPARISONS`). Each paper binds its id once: ``claim = functools.partial(claims.claim, PAPER)``.

    The convention is keywords, the same for every comparison: ``measured=`` the value we measure,
    ``tolerance=`` what it is held to (the distance allowed from ``published`` for :func:`close_to` and
    :func:`relatively_close_to`, the bound of :func:`at_most` and :func:`at_least`, the band (lower, upper) of
    :func:`between`) and ``published=`` the paper's value or words (optional for a bound or a band)::

        claim(c.close_to, "fig2d.order", kind="paper", source="Figure 2 (d)", figure="2d",
              text="order of the L1 error", published=1.0, measured=slope, tolerance=rules["order_tolerance"])

    When the measured value is a fitted slope (:class:`~particle_replication.rates.Slope`, as
    :meth:`Recorder.add <particle_replication.rates.Recorder.add>` returns it, or its negation or the
    difference of two), the same rule also decides every window of consecutive resolutions of the deciding
    window's length, and the row says on how many the verdict is the deciding window's: ``windows`` =
    "k of K". A bound that is a fitted slope on as many windows takes its value on the same window."""
    if compare not in COMPARISONS:
        raise ParameterTypeError(f"compare must be one of {', '.join(f.__name__ for f in COMPARISONS)}, got "
                                 f"{compare!r}")
    if compare is between and "tolerance" in kwargs:
        band = kwargs.pop("tolerance")
        if not isinstance(band, (tuple, list)) or len(band) != 2:
            raise ParameterTypeError(f"tolerance of between must be a band (lower, upper), got {band!r}")
        kwargs["lower"], kwargs["upper"] = band
    arguments = inspect.signature(compare).bind(f"{paper}.{name}", paper, figure, in_words(text), *args, kind=kind,
                                                source=source, **kwargs).arguments
    made = compare(**arguments)
    windows = getattr(arguments["measured"], "windows", None)
    if windows is None:
        return made
    # A bound that is itself a fitted slope on as many windows (one rate above another) moves with the measure.
    moving = {key: value.windows for key, value in arguments.items()
              if len(getattr(value, "windows", ())) == len(windows)}
    same = sum(compare(**{**arguments, **{key: values[i] for key, values in moving.items()}}).status == made.status
               for i in range(len(windows)))
    return dataclasses.replace(made, windows=f"{same} of {len(windows)}")


def window_counts(claim: Claim) -> tuple[int, int] | None:
    """(k, K) of the claim's ``windows``, None for a claim not decided on a fitted slope; a ValueError unless
    it reads "k of K" with 0 <= k <= K, K > 0."""
    if not claim.windows:
        return None
    held, _, total = claim.windows.partition(" of ")
    if not (held.isdigit() and total.isdigit() and int(held) <= int(total) and int(total) > 0):
        raise ValueError(f"windows of {claim.id!r} must be 'k of K' with 0 <= k <= K, K > 0, got {claim.windows!r}")
    return int(held), int(total)


def window_dependent(claims) -> list[Claim]:
    """The claims decided on a fitted slope whose verdict changes with the window (k < K)."""
    return [claim for claim in claims if (pair := window_counts(claim)) is not None and pair[0] < pair[1]]


def farthest_from_centre(values, band) -> float:
    """The value farthest from the middle of ``band`` (lower, upper): the one that decides whether all lie in
    it, itself (a fitted :class:`~particle_replication.rates.Slope` keeps its windows, so that the claim shows on
    how many windows its verdict holds); NaN for no value (a claim on nothing fails)."""
    values = list(values)
    if not values:
        return math.nan
    distances = np.abs(np.asarray(values, dtype=float) - 0.5 * (band[0] + band[1]))
    chosen = values[int(np.argmax(distances))]
    return chosen if isinstance(chosen, float) and not isinstance(chosen, bool) else float(chosen)


class Catalogue:
    """The kind and source of every claim of one paper, looked up by the claim's name.

    ``catalogue.claim(close_to, "fig2.order", figure, text, ...)`` builds the claim
    ``<paper>.fig2.order`` with the kind and source of its entry; a name without an entry is an
    error, so no claim reaches the table without them.
    """

    def __init__(self, paper: str, kinds: dict[str, tuple[str, str]]):
        self.paper, self.kinds = paper, dict(kinds)
        unknown = sorted(name for name, (kind, _) in self.kinds.items() if kind not in KINDS)
        if unknown:
            raise ValueError(f"kinds of {unknown} must be one of {', '.join(KINDS)}")

    def kind_and_source(self, name: str) -> tuple[str, str]:
        if name not in self.kinds:
            raise ValueError(f"claim {self.paper}.{name} has no kind and source: add it to the paper's table")
        return self.kinds[name]

    def claim(self, compare, name, figure, text, *args, **kwargs) -> Claim:
        """:func:`claim` with the kind and source of the entry ``name``."""
        kind, source = self.kind_and_source(name)
        return claim(self.paper, compare, name, kind, source, figure, text, *args, **kwargs)


class Tolerances(dict):
    """A ``claims`` section of the config (the tolerances no figure's section holds) that records which keys
    the measures read: the schema types a new tolerance without listing it (a number or a band), and
    :func:`measure_paper` refuses a key no claim read (a misspelt name) instead."""

    def __init__(self, values, where: str):
        super().__init__(values)
        self.where, self.read = where, set()

    def __getitem__(self, key):
        self.read.add(key)
        return super().__getitem__(key)

    def get(self, key, default=None):
        self.read.add(key)
        return super().get(key, default)

    def unread(self) -> list[str]:
        return [f"{self.where}.{key}" for key in self if key not in self.read]


def tracked(cfg, where: str):
    """``cfg`` with every ``claims`` section, at any depth, a :class:`Tolerances` (the rest copied as it is)."""
    if not isinstance(cfg, dict):
        return cfg
    return {key: Tolerances(value, f"{where}.{key}") if key == "claims" and isinstance(value, dict)
            else tracked(value, f"{where}.{key}") for key, value in cfg.items()}


def unread_tolerances(cfg) -> list[str]:
    """The keys of the :class:`Tolerances` in ``cfg`` that nothing read."""
    if isinstance(cfg, Tolerances):
        return cfg.unread()
    return [key for value in cfg.values() for key in unread_tolerances(value)] if isinstance(cfg, dict) else []


def measure_paper(inputs, cfg, output, measure, log=None) -> None:
    """A paper's claims job: load its result files (``inputs``, by file stem; the ``code`` inputs
    aside), measure them with ``measure(results, cfg, recorder)`` (a verdict module's ``claims``),
    and write the claims table to ``output.claims`` and every fitted rate to ``output.rates``.
    A tolerance of a ``claims`` section of ``cfg`` (the paper's section) that no measure reads stops the job:
    a misspelt or forgotten key, which the schema, typing new tolerances generically, lets through."""
    recorder = Recorder(log)
    results = {name: load_results(path) for name, path in inputs.items() if name != "code"}
    cfg = tracked(cfg, measure.__module__.rpartition(".")[2])  # the verdict module is named after its paper
    made = measure(results, cfg, recorder)
    unread = unread_tolerances(cfg)
    if unread:
        raise ValueError(f"tolerances no claim reads (misspelt, or left from a removed claim): {unread}")
    write_claims(output.claims, made, log=log)
    recorder.write(output.rates)


def write_claims(path, claims, log=None) -> None:
    """Write claims to a CSV file with the columns of the repository-wide table; ``log`` (a
    callable taking one line, e.g. a rule's progress) also receives one line per verdict."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    ids = [claim.id for claim in claims]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        raise ValueError(f"duplicate claim ids: {duplicates}")
    for claim in claims if log is not None else ():
        log(f"{claim.status:4} {claim.id} [{claim.kind}]: measured {claim.measured} ({claim.tolerance})")
    temporary = path.with_suffix(path.suffix + ".tmp")
    with temporary.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=COLUMNS)
        writer.writeheader()
        for claim in claims:
            writer.writerow(asdict(claim))
    temporary.replace(path)


def read_claims(path) -> list[Claim]:
    """Read a claims CSV written by :func:`write_claims`."""
    with Path(path).open(newline="") as handle:
        reader = csv.DictReader(handle)
        if tuple(reader.fieldnames or ()) != COLUMNS:
            raise ValueError(f"{path} must have the columns {','.join(COLUMNS)}")
        return [Claim(**row) for row in reader]


def counts(claims) -> dict[str, tuple[int, int]]:
    """kind -> (passing, decided), for every kind present (a check that abstained is not decided)."""
    out = {}
    for kind in KINDS:
        rows = [claim for claim in claims if claim.kind == kind and claim.status != "abstain"]
        if rows or any(claim.kind == kind for claim in claims):
            out[kind] = (sum(claim.status == "pass" for claim in rows), len(rows))
    return out


def summary_line(claims) -> str:
    """'Paper claims reproduced: p of q. Also derived claims passing: ...; checks passing: ...' (each kind counted
    apart; abstentions named); without paper claims (the cross part), 'No claim of a paper. Derived claims
    passing: ...'."""
    tally = counts(claims)
    passed, total = tally.get("paper", (0, 0))
    others = "; ".join(f"{KIND_NAMES[kind]} passing: {p} of {n}" for kind, (p, n) in tally.items() if kind != "paper")
    abstained = sum(claim.status == "abstain" for claim in claims)
    if total:
        line = f"Paper claims reproduced: {passed} of {total}." + (f" Also {others}." if others else "")
    else:
        line = "No claim of a paper." + (f" {others[0].upper()}{others[1:]}." if others else "")
    return line + (f" {abstained} wall-time checks abstained (a loaded machine, or its speed moving more than "
                   f"the check can tell)." if abstained else "")


class Spread(NamedTuple):
    """What the robustness run measured of a claim over its variants: the spread (largest minus smallest) of its
    signed distance from the threshold and of its measured value, and its smallest margin over them (the
    distance in units of that spread; inf where the spread is 0) (:mod:`particle_replication.robustness`)."""

    distance: float
    value: float
    margin: float = math.inf
    kind: str = "paper"


def read_spreads(path, run: str) -> dict[str, Spread]:
    """The spreads recorded for a run (``full``, ``quick``) in a spreads file (``config/spreads.yaml``, written
    from a robustness run's ``results/robustness/spreads.yaml``): claim id -> :class:`Spread`; empty when the file
    has no section for the run."""
    data = read_yaml(path) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{path}: a spreads file maps runs to {{claim id: {{distance, value}}}}")
    section = data.get(run) or {}
    spreads = {}
    for i, entry in section.items():
        if not isinstance(entry, dict) or set(entry) != set(Spread._fields):
            raise ValueError(f"{path} [{run}]: the spread of {i} needs exactly the keys {list(Spread._fields)}")
        values = [float(entry[key]) for key in Spread._fields[:3]]
        if any(not v >= 0 for v in values) or entry["kind"] not in KINDS:
            raise ValueError(f"{path} [{run}]: the spreads of {i} must be non-negative numbers and its kind one of "
                             f"{', '.join(KINDS)}, got {entry}")
        spreads[i] = Spread(*values, entry["kind"])
    return spreads


def margin_of(distance: float, spread: float) -> float:
    """A signed distance from a threshold in units of its spread: inf where the spread is 0 (every variant gave
    the same distance, a value not measured included: the verdict is exact), 0 where the distance is not
    measured or the spread is infinite (some variants measured it, others not)."""
    if spread == 0:
        return math.inf
    if not (math.isfinite(distance) and math.isfinite(spread)):
        return 0.0
    return abs(distance) / spread


def margin(claim: Claim, spread: Spread | None) -> float | None:
    """The claim's distance from its threshold in units of its recorded spread (:func:`margin_of`), None without
    a recorded spread."""
    if spread is None or not claim.distance:
        return None
    return margin_of(float(claim.distance), spread.distance)


def margin_text(value: float | None) -> str:
    """How the tables print a margin: 'exact', a number of spreads, or '-' (no spread recorded)."""
    if value is None:
        return "-"
    return "exact" if value == math.inf else f"{value:.3g}"


def with_margins(claims, spreads) -> list[Claim]:
    """The claims with their ``margin`` column filled in from the recorded spreads."""
    return [dataclasses.replace(claim, margin=margin_text(margin(claim, spreads.get(claim.id)))) for claim in claims]


def fragile(claims, margin_min: float) -> list[Claim]:
    """The decided claims whose margin is below ``margin_min`` spreads (a margin not recorded is not listed)."""
    return [claim for claim in claims if claim.status != "abstain" and claim.margin not in ("", "-", "exact")
            and float(claim.margin) < margin_min]


def markdown_table(claims, heading: bool = True) -> str:
    """Markdown rendering: a title and the summary line (unless ``heading`` is false), then one row
    per claim, paper claims first (a ``|`` in any cell escaped, so that the table keeps its columns)."""
    lines = ["# Checked claims", "", summary_line(claims), ""] if heading else []
    lines += [
        "| id | kind | source | claim | published | measured | tolerance | status | margin (spreads) | "
        "same verdict on windows |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for claim in sorted(claims, key=lambda claim: KINDS.index(claim.kind)):
        status = {"fail": "**fail**", "abstain": "abstains"}.get(claim.status, claim.status)
        cells = [claim.source, claim.claim, claim.published, claim.measured, claim.tolerance]
        source, text, published, measured, tolerance = (cell.replace("|", "\\|") for cell in cells)
        lines.append(f"| `{claim.id}` | {claim.kind} | {source} | {text} | {published} | "
                     f"{measured} | {tolerance} | {status} | {claim.margin} | {claim.windows} |")
    return "\n".join(lines) + "\n"


def merge(sources, csv_path, markdown_path, expected_path=None, run: str = "full", spreads_path=None,
          margin_min: float = 10.0) -> list[Claim]:
    """Concatenate per-paper claim files into the repository table and its Markdown; with the expected
    verdicts, the Markdown also lists the failures by cause; with the recorded spreads (``spreads_path``), every
    claim gets its margin and the Markdown lists the fragile verdicts (margin below ``margin_min``)."""
    claims = [claim for source in sources for claim in read_claims(source)]
    spreads = read_spreads(spreads_path, run) if spreads_path is not None else {}
    claims = with_margins(claims, spreads)
    write_claims(csv_path, claims)
    markdown_path = Path(markdown_path)
    temporary = markdown_path.with_suffix(".tmp")
    causes = "" if expected_path is None else "\n" + failures_by_cause(claims, read_verdicts(expected_path, run))
    temporary.write_text(markdown_table(claims) + causes + "\n" + fragile_section(claims, spreads, margin_min))
    temporary.replace(markdown_path)
    return claims


def fragile_section(claims, spreads, margin_min: float) -> str:
    """Markdown: the fragile verdicts (margin below ``margin_min`` spreads), or why there are none to list."""
    if not spreads:
        return ("## Fragile verdicts\n\nNo spreads are recorded for this run's configuration, so no margin is "
                "known.\n")
    rows = fragile(claims, margin_min)
    lines = ["## Fragile verdicts", "", f"{len(rows)} verdicts lie within {margin_min:g} spreads of their threshold "
             "(the spread: over the variants of the robustness run).", ""]
    if rows:
        lines += ["| id | kind | status | margin |", "|---|---|---|---|"]
        lines += [f"| `{claim.id}` | {claim.kind} | {claim.status} | {claim.margin} |" for claim in rows]
    return "\n".join(lines) + "\n"


class Expected(NamedTuple):
    """The expected verdict of a claim: its status and, for a failure, why (reason) and its cause."""

    status: str
    reason: str = ""
    cause: str = ""


#: The expected verdict of a claim that ``config/verdicts.yaml`` does not list.
PASSING = Expected("pass")


def _statuses(path, where: str, data) -> dict[str, Expected]:
    """``pass`` (a list of claim ids) and ``fail`` (id: {cause, reason}) of one part of the file."""
    passing, failing = data.get("pass") or [], data.get("fail") or {}
    if not isinstance(passing, list) or not isinstance(failing, dict):
        raise ValueError(f"{path}{where}: 'pass' must be a list of claim ids and 'fail' a mapping id: "
                         "{cause, reason}")
    both = sorted(set(passing) & set(failing))
    repeated = sorted({i for i in passing if passing.count(i) > 1})
    if both or repeated:
        raise ValueError(f"{path}{where}: claim ids listed twice: {both + repeated}")
    failures = {}
    for i, entry in failing.items():
        if not isinstance(entry, dict) or set(entry) != {"cause", "reason"}:
            raise ValueError(f"{path}{where}: the expected failure {i} needs a cause and a one-line reason "
                             "({cause: ..., reason: ...})")
        if entry["cause"] not in CAUSES:
            raise ValueError(f"{path}{where}: the cause of {i} must be one of {sorted(CAUSES)}, got {entry['cause']!r}")
        if not isinstance(entry["reason"], str) or not entry["reason"].strip():
            raise ValueError(f"{path}{where}: every expected failure needs a one-line reason: {i}")
        failures[i] = Expected("fail", entry["reason"], entry["cause"])
    return {**{i: Expected("pass") for i in passing}, **failures}


def read_verdicts(path, run: str = "full") -> dict[str, Expected]:
    """Expected verdicts of a run: claim id -> :class:`Expected` (status, reason, cause).

    The file holds the full run's verdicts under two keys: ``pass``, a list of claim ids, and
    ``fail``, a mapping from claim id to its cause (one of :data:`CAUSES`) and a one-line reason.
    Another run (``quick``) has a section of its own with the same two keys, holding only the
    verdicts that differ from the full run's.
    Measured values are never recorded there, only statuses. A claim listed nowhere is expected to pass
    (:data:`PASSING`): only an expected failure has to be written down; a listed pass guards against the
    claim vanishing (``verify`` reports it MISSING).
    """
    data = read_yaml(path) or {}
    if not isinstance(data, dict) or not {"pass", "fail"} & set(data):
        raise ValueError(f"{path}: expected verdicts need the keys 'pass' (a list) and 'fail' (id: {{cause, reason}})")
    sections = set(data) - {"pass", "fail"}
    if any(not isinstance(data[name], dict) or set(data[name]) - {"pass", "fail"} for name in sections):
        raise ValueError(f"{path}: expected verdicts need the keys 'pass' (a list) and 'fail' (id: {{cause, reason}}), "
                         f"and a section per run ({sorted(sections)}) with the same two keys")
    verdicts = _statuses(path, "", data)
    if run == "full":
        return verdicts
    if run not in sections:
        raise ValueError(f"{path}: no section for the run {run!r} (sections: {sorted(sections)})")
    differences = _statuses(path, f" [{run}]", data[run])
    same = sorted(i for i, verdict in differences.items() if verdict == verdicts.get(i, PASSING))
    if same:
        raise ValueError(f"{path} [{run}]: entries equal to the full run's (keep only differences): {same}")
    return {**verdicts, **differences}


class Change(NamedTuple):
    """A rule changed after a run in which it failed: the claims it decides, the failing value seen,
    what changed and why."""

    claims: tuple[str, ...]
    failing: str
    change: str
    why: str


def read_changes(path, known=None) -> list[Change]:
    """The register of rules changed after a failing run (``config/changes.yaml``): a list ``changes``
    of entries with the keys of :class:`Change`. With ``known`` (claim ids), every claim an entry names
    must be among them, so that the register cannot name a claim that no longer exists."""
    data = read_yaml(path) or {}
    entries = data.get("changes") if isinstance(data, dict) else None
    if not isinstance(entries, list) or not entries:
        raise ValueError(f"{path}: expected a non-empty list 'changes'")
    changes = []
    for index, entry in enumerate(entries):
        if not isinstance(entry, dict) or set(entry) != set(Change._fields):
            raise ValueError(f"{path}: change {index} needs exactly the keys {list(Change._fields)}")
        texts = [entry[key] for key in Change._fields[1:]]
        if not all(isinstance(text, str) and text.strip() for text in texts):
            raise ValueError(f"{path}: change {index}: failing, change and why must be non-empty texts")
        ids = entry["claims"]
        if not isinstance(ids, list) or not ids or not all(isinstance(i, str) for i in ids):
            raise ValueError(f"{path}: change {index}: claims must be a non-empty list of claim ids")
        unknown = sorted(set(ids) - set(known)) if known is not None else []
        if unknown:
            raise ValueError(f"{path}: change {index} names claims that do not exist: {unknown}")
        changes.append(Change(tuple(ids), *texts))
    return changes


def verify(claims_path, verdicts_path, run: str | None = "full", margin_min: float = 10.0,
           differing: tuple[str, ...] = (), write=print, brief: bool = False) -> int:
    """Print (through ``write``) the paper claims (``brief``: only those that fail), the fragile verdicts, then
    every difference from the expected verdicts; return the exit code.

    Non-zero when a verdict differs from the expected one (a claim the file does not list is expected to pass)
    or when a listed claim is missing. A check that abstained (a loaded machine, or a speed that moved more than
    the check can tell) is listed, never a difference.
    ``run`` None: the configuration is none of the repository's runs (``differing``: the keys in which it
    differs), so no verdict is expected of it: the summary is printed and nothing compared.
    """
    claims = read_claims(claims_path)
    write(summary_line(claims))
    for claim in claims:
        if claim.kind == "paper" and not (brief and claim.status == "pass"):
            write(f"  {claim.status:4} {claim.id} ({claim.source}): published {claim.published}, "
                  f"measured {claim.measured}, margin {claim.margin or '-'}")
    for claim in claims:
        if claim.status == "abstain":
            write(f"ABSTAINED {claim.id}: {claim.claim.rpartition('abstains: ')[2]}")
    shaky = fragile(claims, margin_min)
    for claim in shaky:
        write(f"FRAGILE {claim.id} ({claim.kind}, {claim.status}): {claim.margin} spreads from its threshold")
    if shaky:
        write(f"{len(shaky)} fragile verdicts (within {margin_min:g} spreads of their threshold)")
    if run is None:
        write("Nothing compared: this configuration is none of the repository's runs (it differs in "
              f"{', '.join(differing) or 'its settings'}), so no verdict is expected of it.")
        return 0
    expected = read_verdicts(verdicts_path, run)
    problems = []
    for claim in claims:
        if claim.status == "abstain":
            continue
        verdict = expected.get(claim.id, PASSING)
        if verdict.status != claim.status:
            reason = verdict.reason or ("" if claim.id in expected else f"not listed in {verdicts_path}")
            problems.append(f"CHANGED {claim.id}: expected {verdict.status}"
                            f"{f' ({reason})' if reason else ''}, got {claim.status} (measured {claim.measured}, "
                            f"tolerance {claim.tolerance})")
    present = {claim.id for claim in claims}
    problems += [f"MISSING {i}: expected {verdict.status}, not in {claims_path}"
                 for i, verdict in expected.items() if i not in present]
    for problem in problems:
        write(problem)
    write(f"{len(problems)} differences from the expected verdicts (expected: {cause_line(expected)}; each with "
          f"its reason in {verdicts_path})")
    return 1 if problems else 0


def cause_counts(expected) -> dict[str, int]:
    """cause -> number of failures, for every cause (0 where none), and 'unexpected' if any."""
    tally = {cause: sum(verdict.cause == cause for verdict in expected.values()) for cause in [*CAUSES, "unexpected"]}
    return {cause: count for cause, count in tally.items() if cause in CAUSES or count}


def cause_line(expected) -> str:
    """'14 failures: 3 contradict the paper, ...' for a set of verdicts (passes are not counted)."""
    tally = cause_counts(expected)
    words = {"contradicts": "contradict the paper", "pre-asymptotic": "pre-asymptotic",
             "our-inference": "our inference was wrong", "defect": "defects of ours to fix",
             "unexpected": "not expected"}
    return (f"{sum(tally.values())} failures: "
            + ", ".join(f"{count} {words[cause]}" for cause, count in tally.items()))


def failures_with_causes(claims, expected) -> list[tuple[Claim, Expected]]:
    """The failing claims with their expected verdicts, in the order of :data:`CAUSES`; a failure
    that is not expected gets the cause 'unexpected' (last)."""
    unexpected = Expected("fail", "not expected: snakemake verify reports it", "unexpected")
    rows = [(claim, expected[claim.id] if claim.id in expected and expected[claim.id].status == "fail"
             else unexpected) for claim in claims if claim.status == "fail"]
    order = [*CAUSES, "unexpected"]
    return sorted(rows, key=lambda row: order.index(row[1].cause))


def failures_by_cause(claims, expected) -> str:
    """Markdown: the failing claims with their cause and reason, counted per cause."""
    rows = failures_with_causes(claims, expected)
    lines = ["## Failures by cause", "", cause_line({claim.id: verdict for claim, verdict in rows}), "",
             "| id | kind | cause | reason |", "|---|---|---|---|"]
    for claim, verdict in rows:
        reason = verdict.reason.replace("|", "\\|")
        lines.append(f"| `{claim.id}` | {claim.kind} | {verdict.cause} | {reason} |")
    return "\n".join(lines) + "\n"


def read_values(path) -> tuple[dict[str, float], dict[str, str]]:
    """A reference of measured values: (claim id -> value, claim id -> reason it is exempt).

    The YAML file has ``values`` (id: full-precision value, written by :func:`write_values`) and
    ``exempt`` (id: one-line reason its value may change between builds: a wall-clock time, or a
    quantity at the level of rounding or of the integrator's tolerance).
    """
    data = read_yaml(path) or {}
    if not isinstance(data, dict) or set(data) != {"values", "exempt"}:
        raise ValueError(f"{path}: a reference of values needs the keys 'values' and 'exempt'")
    values, exempt = data["values"] or {}, data["exempt"] or {}
    missing_reason = sorted(i for i, reason in exempt.items() if not isinstance(reason, str) or not reason.strip())
    if missing_reason:
        raise ValueError(f"{path}: every exempt claim needs a one-line reason: {missing_reason}")
    return {i: float(v) for i, v in values.items()}, dict(exempt)


#: The first line of a reference of values: the command that rewrites it.
VALUES_HEADER = ("# Written by `python -m particle_replication.claims values <run>/results/claims.csv --reference "
                 "<this file>` (the quick run: runs/quick/results/claims.csv); the exemptions are kept.\n")


def write_values(claims_path, path) -> None:
    """Record the measured values of a claims table as the reference, keeping the file's exemptions."""
    exempt = read_values(path)[1] if Path(path).exists() else {}
    values = {claim.id: claim.value for claim in read_claims(claims_path)}
    Path(path).write_text(VALUES_HEADER + yaml.safe_dump({"exempt": exempt, "values": values}, sort_keys=False,
                                                         width=120))


def value_differences(claims, reference_path, relative: float = 1e-9, spreads=None,
                      factor: float = 10.0) -> list[str]:
    """Every claim whose measured value moved by more than its tolerance from the reference, or that is new or
    missing; exempt claims are skipped. The tolerance is ``relative`` times the reference value, or ``factor``
    times the value's spread over the robustness run's variants where that is larger (``spreads``: claim id ->
    :class:`Spread`): a value that rounding, threads or another CPU move is pinned as far as they move it."""
    values, exempt = read_values(reference_path)
    spreads = spreads or {}
    problems = []
    present = set()
    for claim in claims:
        present.add(claim.id)
        if claim.id in exempt:
            continue
        if claim.id not in values:
            problems.append(f"NEW {claim.id}: no reference value in {reference_path}")
            continue
        new, old = float(claim.value), values[claim.id]
        spread = spreads[claim.id].value if claim.id in spreads else 0.0
        tolerance = max(relative * abs(old), factor * spread)
        # Not measured in both (NaN): the same outcome; NaN on one side only: moved.
        same = (new == old or (math.isnan(new) and math.isnan(old))
                or (math.isfinite(new) and abs(new - old) <= tolerance))
        if not same:
            problems.append(f"MOVED {claim.id}: {old!r} -> {new!r} (tolerance {tolerance:.3g})")
    problems += [f"MISSING {i}" for i in values if i not in present and i not in exempt]
    return problems


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_replication.claims", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    merge_parser = sub.add_parser("merge", help="merge per-paper claim files")
    merge_parser.add_argument("sources", nargs="+")
    merge_parser.add_argument("--csv", required=True)
    merge_parser.add_argument("--markdown", required=True)
    merge_parser.add_argument("--rates", nargs="*", default=[], help="per-paper rate tables to merge")
    merge_parser.add_argument("--rates-output", help="merged rate tables (JSON)")
    merge_parser.add_argument("--expected", help="YAML file of expected verdicts (for the failures by cause)")
    merge_parser.add_argument("--run", default="full", help="the run whose verdicts to use (full, or a section)")
    merge_parser.add_argument("--spreads", help="YAML file of the spreads recorded by a robustness run (margins)")
    merge_parser.add_argument("--margin-min", type=float, default=10.0, help="margins below this are fragile")
    verify_parser = sub.add_parser("verify", help="exit 1 when a verdict differs from the expected ones")
    verify_parser.add_argument("path")
    verify_parser.add_argument("--expected", required=True, help="YAML file of expected verdicts")
    verify_parser.add_argument("--run", default="full", help="the run whose verdicts to use (full, or a section)")
    verify_parser.add_argument("--margin-min", type=float, default=10.0, help="margins below this are fragile")
    verify_parser.add_argument("--differs", nargs="*", default=None,
                               help="the configuration is none of the repository's runs: the keys in which it differs "
                                    "(nothing is compared)")
    verify_parser.add_argument("--report", help="also write what is printed to this file")
    verify_parser.add_argument("--brief", action="store_true", help="list only the paper claims that fail")
    values_parser = sub.add_parser("values", help="record a claims table's measured values as the reference")
    values_parser.add_argument("path")
    values_parser.add_argument("--reference", required=True, help="YAML file of reference values")
    args = parser.parse_args(argv)
    if args.command == "values":
        write_values(args.path, args.reference)
        return 0
    if args.command == "merge":
        merge(args.sources, args.csv, args.markdown, args.expected, args.run, args.spreads, args.margin_min)
        if args.rates_output:
            merge_rates(args.rates, args.rates_output)
        return 0
    lines = []

    def write(line):
        print(line, flush=True)
        lines.append(line)

    run = None if args.differs is not None else args.run
    code = verify(args.path, args.expected, run, args.margin_min, tuple(args.differs or ()), write, args.brief)
    if args.report:
        Path(args.report).write_text("\n".join(lines) + "\n")
    return code


if __name__ == "__main__":
    sys.exit(main())
