"""LaTeX snippets for the replication report, written by the pipeline from its own outputs.

``write_snippets(claims, rates, versions, config, outdir, expected)`` writes:

- ``claims_<paper>.tex``: each paper's claims table, every kind with its statement (a longtable, for the
  supplement);
- ``paperclaims_<paper>.tex``: the paper's own claims of each paper, one line each: id, source, published,
  measured, verdict, margin (a longtable, for the report);
- ``measured.tex``: ``\\measured{<claim id>}``, ``\\published{<claim id>}``, ``\\tol{<claim id>}``,
  ``\\status{<claim id>}`` and ``\\margin{<claim id>}`` (in units of its spread over the robustness run's
  variants) for any claim;
- ``fragile.tex``: the verdicts within ``margin_min`` spreads of their threshold, or the statement that none is;
- ``failures.tex``: the failing claims of every paper in one table, with the cause and reason of each
  (from the expected verdicts, :data:`particle_replication.claims.CAUSES`);
- ``changes.tex``: the rules changed after a run in which they failed, with the failing values
  (``config/changes.yaml``, :func:`particle_replication.claims.read_changes`);
- ``parameters.tex``: ``\\param{<dotted config key>}`` for every configuration value;
- ``configuration.tex``: the whole configuration of the run, one line per key (an appendix);
- ``summary.tex``: ``\\claimcount{<paper>.pass}``, ``.fail`` and ``.all`` over every kind, and
  ``\\claimcount{<paper>.<kind>.pass}`` (``.fail``, ``.all``) per kind, with ``all`` for the
  three papers together (``\\claimcount{all.paper.pass}`` is the headline), and
  ``\\claimcount{cause.<cause>}`` for the failures of each cause;
- ``rates.tex``: every fitted rate, its pairwise slopes and the fit over every window (an appendix);
- ``versions.tex``: the software versions table (a tabular);
- ``commit.tex``: ``\\builtfrom``, the commit the run was made from and its date.
- ``further_figures.tex``: the registry's figures of ours that neither document places by hand, with the
  registry's captions (a section of the supplement; empty when there is none).

The article (``paper/ms.tex``) types no parameter or measured value of its own: it uses these
macros.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from .claims import (
    KINDS,
    cause_counts,
    failures_with_causes,
    fragile,
    read_changes,
    read_claims,
    read_verdicts,
    window_dependent,
)
from .environment import CPU_NOT_RECORDED, recorded_cpu
from .paths import REPOSITORY, read_yaml
from .rates import read_rates

_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
            "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "|": r"$|$", "<": r"$<$",
            ">": r"$>$"}


_CLAIM_TABLE_HEAD = (
    "\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{3.3cm}>{\\raggedright\\scriptsize}p{1.6cm}"
    ">{\\raggedright}p{5.0cm}>{\\raggedright}p{1.35cm}>{\\raggedright}p{1.4cm}>{\\raggedright}p{1.25cm}"
    ">{\\raggedright\\arraybackslash}p{1.1cm}@{}}\n"
    "\\toprule id & kind, source & claim & published & measured & tolerance & status, margin \\\\ \\midrule \\endhead\n"
    "\\bottomrule \\endlastfoot\n"
)
_FAILURE_TABLE_HEAD = (
    "\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{3.6cm}>{\\raggedright\\scriptsize}p{1.2cm}"
    ">{\\raggedright\\scriptsize}p{1.7cm}>{\\raggedright}p{1.4cm}>{\\raggedright}p{1.4cm}"
    ">{\\raggedright\\arraybackslash}p{5.2cm}@{}}\n"
    "\\toprule id & kind & cause & published & measured & reason \\\\ \\midrule \\endhead\n"
    "\\bottomrule \\endlastfoot\n"
)
_CHANGE_TABLE_HEAD = (
    "\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{3.8cm}>{\\raggedright\\scriptsize}p{2.6cm}"
    ">{\\raggedright\\scriptsize}p{4.4cm}>{\\raggedright\\arraybackslash\\scriptsize}p{3.6cm}@{}}\n"
    "\\toprule claims & failing value & change & why \\\\ \\midrule \\endhead\n"
    "\\bottomrule \\endlastfoot\n"
)
_SYMBOLS = {"<=": r"\ensuremath{\le}", ">=": r"\ensuremath{\ge}", "+-": r"\ensuremath{\pm}"}
_TOKEN = re.compile(r"(<=|>=|\+-|(?<![\w.^])-?\d+(?:\.\d+)?(?:e[+-]?\d+)?(?![\w.]))")


def tex(text) -> str:
    """Escape LaTeX special characters in plain text."""
    return "".join(_SPECIAL.get(character, character) for character in str(text))


def number(x: float | int) -> str:
    """A number in LaTeX math: integers exactly, floats to four significant digits with powers of ten
    written as such."""
    text = str(x) if isinstance(x, int) else f"{x:.4g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        power = f"10^{{{int(exponent)}}}"
        text = power if mantissa == "1" else f"{mantissa}\\times {power}"
    return f"\\ensuremath{{{text}}}"


def _parse(text: str) -> float | int:
    return float(text) if any(mark in text for mark in ".e") else int(text)


def cell(text) -> str:
    """A cell of the claims table in LaTeX: numbers through :func:`number`, ``<=``, ``>=`` and ``+-``
    as symbols, everything else escaped."""
    parts = _TOKEN.split(str(text))
    return "".join(_SYMBOLS.get(part) or (number(_parse(part)) if index % 2 else tex(part))
                   for index, part in enumerate(parts))


def _flatten(tree, prefix=""):
    """(dotted key, text) for every value of a configuration tree; a list of scalars is one comma-separated
    value."""
    if isinstance(tree, dict):
        for key, value in tree.items():
            yield from _flatten(value, f"{prefix}{key}.")
    elif isinstance(tree, list) and all(not isinstance(v, (dict, list)) for v in tree):
        yield prefix[:-1], ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in tree)
    elif isinstance(tree, list):
        for index, value in enumerate(tree):
            yield from _flatten(value, f"{prefix}{index}.")
    else:
        yield prefix[:-1], f"{tree:.6g}" if isinstance(tree, float) else str(tree)


def _case_fields(tree, prefix=""):
    """(dotted key, text) for each scalar field common to a list of cases, over the cases
    (``ltp.fig6.cases.b``: "1.1, 1.5, 2.5"), so that a text lists them without knowing how many a
    configuration has."""
    if isinstance(tree, dict):
        for key, value in tree.items():
            yield from _case_fields(value, f"{prefix}{key}.")
    elif isinstance(tree, list) and tree and all(isinstance(value, dict) for value in tree):
        for field in sorted(set.intersection(*(set(value) for value in tree))):
            values = [value[field] for value in tree]
            if all(not isinstance(value, (dict, list)) for value in values):
                yield from _flatten(values, f"{prefix}{field}.")


def _breakable(identifier: str) -> str:
    """A dotted identifier in LaTeX, with line breaks allowed after its dots and underscores."""
    return tex(identifier).replace(".", ".\\allowbreak{}").replace("\\_", "\\_\\allowbreak{}")


def _claims_table(claims) -> str:
    """A longtable of claims: id, figure, statement, published, measured, tolerance, status with its margin (in
    spreads; and, for a claim decided on a fitted slope, on how many windows of resolutions the verdict is the
    same)."""
    rows = []
    for claim in claims:
        status = {"fail": r"\textbf{fail}", "abstain": "abstains"}.get(claim.status, claim.status)
        if claim.margin not in ("", "-"):
            status += f"\\newline{{\\scriptsize margin {cell(claim.margin)}}}"
        if claim.windows:
            status += f"\\newline{{\\scriptsize same on {claim.windows}}}"
        cells = [f"\\texttt{{{_breakable(claim.id)}}}", f"\\textit{{{claim.kind}}}: {tex(claim.source)}",
                 tex(claim.claim), cell(claim.published),
                 cell(claim.measured), cell(claim.tolerance), status]
        rows.append(" & ".join(cells) + " \\\\\n")
    return _CLAIM_TABLE_HEAD + "".join(rows) + "\\end{longtable}\n"


_PAPER_CLAIM_TABLE_HEAD = (
    "\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{4.6cm}>{\\raggedright\\scriptsize}p{3.4cm}"
    ">{\\raggedright}p{2.3cm}>{\\raggedright}p{2.3cm}>{\\raggedright}p{0.8cm}"
    ">{\\raggedright\\arraybackslash}p{1.5cm}@{}}\n"
    "\\toprule id & source & published & measured & verdict & margin \\\\ \\midrule \\endhead\n"
    "\\bottomrule \\endlastfoot\n"
)


def _paper_claims_table(claims) -> str:
    """A longtable of a paper's own claims, one line each: id, source, published, measured, verdict, margin (in
    spreads over the robustness run's variants)."""
    rows = []
    for claim in claims:
        status = {"fail": r"\textbf{fail}", "abstain": "abstains"}.get(claim.status, claim.status)
        cells = [f"\\texttt{{{_breakable(claim.id.split('.', 1)[1])}}}", tex(claim.source), cell(claim.published),
                 cell(claim.measured), status, cell(claim.margin or "-")]
        rows.append(" & ".join(cells) + " \\\\\n")
    return _PAPER_CLAIM_TABLE_HEAD + "".join(rows) + "\\end{longtable}\n"


def _failures_table(rows) -> str:
    """A longtable of the failing claims (:func:`particle_replication.claims.failures_with_causes`):
    id, kind, cause, published, measured, reason."""
    lines = []
    for claim, verdict in rows:
        cells = [f"\\texttt{{{_breakable(claim.id)}}}", tex(claim.kind), tex(verdict.cause), cell(claim.published),
                 cell(claim.measured), tex(verdict.reason)]
        lines.append(" & ".join(cells) + " \\\\\n")
    return _FAILURE_TABLE_HEAD + "".join(lines) + "\\end{longtable}\n"


def _windows_table(claims) -> str:
    """A longtable of the claims whose verdict changes with the window of resolutions: id, kind, verdict,
    windows with that verdict, measured (the deciding window)."""
    head = ("\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{5.2cm}>{\\raggedright}p{1.4cm}>{\\raggedright}p{1.2cm}"
            ">{\\raggedright}p{2.6cm}>{\\raggedright\\arraybackslash}p{2.4cm}@{}}\n"
            "\\toprule id & kind & verdict & same verdict on & measured \\\\ \\midrule \\endhead\n"
            "\\bottomrule \\endlastfoot\n")
    lines = [" & ".join([f"\\texttt{{{_breakable(claim.id)}}}", tex(claim.kind), claim.status,
                         f"{claim.windows} windows", cell(claim.measured)]) + " \\\\\n" for claim in claims]
    return head + "".join(lines) + "\\end{longtable}\n"


def _changes_table(changes) -> str:
    """A longtable of the rules changed after a failing run (:func:`particle_replication.claims.read_changes`)."""
    lines = []
    for change in changes:
        ids = ", ".join(f"\\texttt{{{_breakable(i)}}}" for i in change.claims)
        lines.append(" & ".join([ids, tex(change.failing), tex(change.change), tex(change.why)]) + " \\\\\n")
    return _CHANGE_TABLE_HEAD + "".join(lines) + "\\end{longtable}\n"


def _define(family: str, key: str, value: str) -> str:
    return f"\\expandafter\\def\\csname {family}@{key}\\endcsname{{{value}}}\n"


def _counts(prefix: str, rows) -> list[str]:
    failed = sum(claim.status == "fail" for claim in rows)
    return [_define("claimcount", f"{prefix}.all", str(len(rows))),
            _define("claimcount", f"{prefix}.fail", str(failed)),
            _define("claimcount", f"{prefix}.pass", str(len(rows) - failed))]


def _rate_table(rate) -> str:
    """One fitted rate: slopes over every window (rows: first point, columns: last point); the
    deciding window in bold."""
    count = len(rate.values)
    first = count - rate.window
    head = "".join(f" & {number(value)}" for value in rate.values[1:])
    rows = []
    for i in range(count - 1):
        cells = []
        for j in range(1, count):
            value = rate.slopes[i][j]
            text = "" if value is None else f"{value:.3f}"
            cells.append(f"\\textbf{{{text}}}" if (i, j) == (first, count - 1) else text)
        rows.append(f"{number(rate.values[i])} & " + " & ".join(cells) + " \\\\\n")
    label = f" ({tex(rate.label)})" if rate.label else ""
    return ("\\noindent\\texttt{" + _breakable(rate.claim) + "}" + label + ": slope of " + tex(rate.quantity)
            + f"; window of the {rate.window} finest ({tex(rate.resolution)}).\\par\\nopagebreak\n"
            + "{\\scriptsize\\begin{tabular}{@{}r" + "r" * (count - 1) + "@{}}\\toprule "
            + f"first {tex(rate.resolution)} $\\backslash$ last" + head + " \\\\ \\midrule\n" + "".join(rows)
            + "\\bottomrule\\end{tabular}}\\par\\medskip\n")


def _fragile_table(claims, margin_min: float) -> str:
    """The fragile verdicts (:func:`particle_replication.claims.fragile`) as a table, or why none is listed."""
    if all(claim.margin in ("", "-") for claim in claims):
        return "No spreads are recorded for this run's configuration, so no margin is known.\n"
    rows = fragile(claims, margin_min)
    if not rows:
        return f"No verdict lies within {number(margin_min)} spreads of its threshold.\n"
    head = ("\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{6.2cm}>{\\raggedright}p{1.6cm}>{\\raggedright}p{1.6cm}"
            ">{\\raggedright\\arraybackslash}p{2.4cm}@{}}\n"
            "\\toprule id & kind & verdict & margin (spreads) \\\\ \\midrule \\endhead\n\\bottomrule \\endlastfoot\n")
    lines = [" & ".join([f"\\texttt{{{_breakable(claim.id)}}}", tex(claim.kind), claim.status, cell(claim.margin)])
             + " \\\\\n" for claim in rows]
    return head + "".join(lines) + "\\end{longtable}\n"


#: A figure placed by hand in the report or its supplement: ``\fig{<paper>/<name>.pdf}`` or ``\ourfig{k}{...}``.
_PLACED = re.compile(r"\\(?:our)?fig(?:\[[0-9.]+\])?(?:\{\d+\})?\{([a-z]+/[a-z0-9_]+)\.pdf\}")


def placed_figures(*documents) -> set[str]:
    """``<paper>/<name>`` of every figure the LaTeX ``documents`` (texts) place by hand."""
    return {match for document in documents for match in _PLACED.findall(document)}


def further_figures(config: dict, placed: set[str]) -> str:
    """LaTeX for the supplement: every registered figure of ours that no document places by hand (``placed``,
    :func:`placed_figures`), numbered as the report numbers ours (A<k>, the registry's
    :attr:`~particle_replication.registry.Paper.numbers`), with the registry's caption of the run's ``config``;
    empty when there is none. A new figure of ours thus reaches the supplement without an edit of it, until the
    text discusses it."""
    from .registry import PAPERS

    if not isinstance(config, dict):
        raise TypeError(f"config must be the run's configuration (a dict), got {type(config).__name__}")
    sections = []
    for paper in PAPERS.values():
        figures = [figure for figure in paper.figures if figure.ours and f"{paper.id}/{figure.name}" not in placed]
        if figures:
            sections.append(f"\\paperfigures{{{paper.name}}}\n" + "".join(
                f"\\ourfig{{{paper.numbers[figure.name].removeprefix('A')}}}{{{paper.id}/{figure.name}.pdf}}"
                f"{{{tex(figure.caption(config[paper.id]))}}}\n" for figure in figures))
    if not sections:
        return ""
    return ("\\section{Further figures}\\label{app:further}\nOur figures that the text above does not discuss yet, "
            "with the captions of the registry.\n\n" + "\n".join(sections))


def write_snippets(claims_csv, rates_json, versions_md, config, outdir, expected, changes, documents=None) -> None:
    """Write every snippet to ``outdir``; ``config`` is the run's configuration (dict or YAML path),
    ``expected`` its expected verdicts (:func:`particle_replication.claims.read_verdicts`), which give
    the failures their causes, ``changes`` the rules changed after a failing run
    (:func:`particle_replication.claims.read_changes`), and ``documents`` the paths of the report's LaTeX sources
    (by default the repository's ``paper/ms.tex`` and ``paper/supplement.tex``), whose figures placed by hand
    :func:`further_figures` leaves out."""
    if not isinstance(config, dict):
        config = read_yaml(config)
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    claims = read_claims(claims_csv)
    papers = sorted({claim.paper for claim in claims})
    measured = []
    for claim in claims:
        measured.append(_define("measured", claim.id, cell(claim.measured)))
        measured.append(_define("published", claim.id, cell(claim.published)))
        measured.append(_define("tolerance", claim.id, cell(claim.tolerance)))
        measured.append(_define("status", claim.id, claim.status))
        measured.append(_define("margin", claim.id, cell(claim.margin or "-")))
    (outdir / "measured.tex").write_text("".join(measured))
    if documents is None:
        documents = [REPOSITORY / "paper" / f"{name}.tex" for name in ("ms", "supplement")]
    (outdir / "further_figures.tex").write_text(
        further_figures(config, placed_figures(*(Path(document).read_text() for document in documents))))
    summary = []
    for paper in [*papers, "all"]:
        rows = [claim for claim in claims if paper in (claim.paper, "all")]
        summary += _counts(paper, rows)
        for kind in KINDS:
            summary += _counts(f"{paper}.{kind}", [claim for claim in rows if claim.kind == kind])
        if paper != "all":
            (outdir / f"claims_{paper}.tex").write_text(_claims_table(rows))
            own = [claim for claim in rows if claim.kind == "paper"]
            (outdir / f"paperclaims_{paper}.tex").write_text(
                _paper_claims_table(own) if own else "This study states no claim of a paper.\n")
    failures = failures_with_causes(claims, expected)
    (outdir / "failures.tex").write_text(_failures_table(failures) if failures else "No claim fails.\n")
    (outdir / "changes.tex").write_text(_changes_table(changes))
    dependent = window_dependent(claims)
    (outdir / "windows.tex").write_text(_windows_table(dependent) if dependent else
                                        "Every verdict decided on a fitted slope is the same on every window.\n")
    summary.append(_define("claimcount", "windows.fitted", str(sum(bool(claim.windows) for claim in claims))))
    summary.append(_define("claimcount", "windows.dependent", str(len(dependent))))
    margin_min = config["robustness"]["margin_min"]
    (outdir / "fragile.tex").write_text(_fragile_table(claims, margin_min))
    summary.append(_define("claimcount", "fragile", str(len(fragile(claims, margin_min)))))
    summary.append(_define("claimcount", "abstained", str(sum(claim.status == "abstain" for claim in claims))))
    tally = cause_counts({claim.id: verdict for claim, verdict in failures})
    summary += [_define("claimcount", f"cause.{cause}", str(count)) for cause, count in tally.items()]
    (outdir / "summary.tex").write_text("".join(summary))
    (outdir / "rates.tex").write_text("".join(_rate_table(rate) for rate in read_rates(rates_json)))
    parameters = list(_flatten(config))
    (outdir / "parameters.tex").write_text("".join(_define("param", key, cell(text))
                                                   for key, text in [*parameters, *_case_fields(config)]))
    (outdir / "configuration.tex").write_text("".join(
        f"\\noindent\\texttt{{{_breakable(key)}}} = {cell(text)}\\par\n" for key, text in parameters))
    versions = Path(versions_md).read_text()
    lines = versions.splitlines()
    fields = dict(line.split(": ", 1) for line in lines if line.startswith(("Commit", "Modified")))
    modified = " (with uncommitted changes)" if fields.get("Modified since the commit") == "yes" else ""
    hash_, date = fields.get("Commit", "unknown"), fields.get("Commit date", "unknown")[:10]
    built = (f"Built from commit \\texttt{{{tex(hash_)}}}{modified} of {tex(date)}" if hash_ != "unknown"
             else "Built outside a git clone (commit unknown)")
    cpu = recorded_cpu(versions)
    ran_on = cpu if cpu == CPU_NOT_RECORDED else f"run on {cpu}"
    (outdir / "commit.tex").write_text(f"\\newcommand{{\\builtfrom}}{{{built}}}\n"
                                       f"\\newcommand{{\\builton}}{{{tex(ran_on)}}}\n")
    rows = [line for line in lines if re.match(r"\| [^-]", line)][1:]
    table = "".join(f"{tex(cells[1].strip())} & {tex(cells[2].strip())} \\\\\n"
                    for cells in (row.split("|") for row in rows))
    (outdir / "versions.tex").write_text("\\begin{tabular}{ll}\\toprule package & version \\\\ \\midrule\n" + table
                                         + "\\bottomrule\n\\end{tabular}\n")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_replication.report", description=__doc__)
    parser.add_argument("claims")
    parser.add_argument("rates")
    parser.add_argument("versions")
    parser.add_argument("config")
    parser.add_argument("outdir")
    parser.add_argument("--expected", required=True, help="YAML file of expected verdicts (the failures' causes)")
    parser.add_argument("--run", default="full", help="the run whose verdicts to use (full, or a section)")
    parser.add_argument("--changes", required=True, help="YAML file of the rules changed after a failing run")
    args = parser.parse_args(argv)
    expected = read_verdicts(args.expected, args.run)
    write_snippets(args.claims, args.rates, args.versions, args.config, args.outdir, expected,
                   read_changes(args.changes, expected))
    return 0


if __name__ == "__main__":
    sys.exit(main())
