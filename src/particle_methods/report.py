"""LaTeX snippets for the replication report, written by the pipeline from its own outputs.

``python -m particle_methods.report CLAIMS VERSIONS CONFIG OUTDIR`` writes:

- ``claims_<paper>.tex``: each paper's claims table (a longtable);
- ``measured.tex``: ``\\measured{<claim id>}``, ``\\published{<claim id>}``, ``\\tol{<claim id>}`` and
  ``\\status{<claim id>}`` for any claim;
- ``failures.tex``: the failing claims of every paper in one table;
- ``parameters.tex``: ``\\param{<dotted config key>}`` for every configuration value;
- ``configuration.tex``: the whole configuration of the run, one line per key (an appendix);
- ``summary.tex``: ``\\claimcount{<paper>.pass}``, ``.fail`` and ``.all``;
- ``versions.tex``: the software versions table (a tabular).

The article (``paper/ms.tex``) types no parameter or measured value of its own: it uses these
macros.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import yaml

from .claims import read_claims

_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
            "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "|": r"$|$", "<": r"$<$",
            ">": r"$>$"}


_CLAIM_TABLE_HEAD = (
    "\\begin{longtable}{@{}>{\\raggedright\\scriptsize}p{3.6cm}>{\\raggedright}p{1.15cm}>{\\raggedright}p{5.35cm}"
    ">{\\raggedright}p{1.4cm}>{\\raggedright}p{1.5cm}>{\\raggedright}p{1.3cm}l@{}}\n"
    "\\toprule id & figure & claim & published & measured & tolerance & status \\\\ \\midrule \\endhead\n"
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


def _breakable(identifier: str) -> str:
    """A dotted identifier in LaTeX, with line breaks allowed after its dots and underscores."""
    return tex(identifier).replace(".", ".\\allowbreak{}").replace("\\_", "\\_\\allowbreak{}")


def _claims_table(claims) -> str:
    """A longtable of claims: id, figure, statement, published, measured, tolerance, status."""
    rows = []
    for claim in claims:
        status = r"\textbf{fail}" if claim.status == "fail" else "pass"
        cells = [f"\\texttt{{{_breakable(claim.id)}}}", tex(claim.figure), tex(claim.claim), cell(claim.published),
                 cell(claim.measured), cell(claim.tolerance), status]
        rows.append(" & ".join(cells) + " \\\\\n")
    return _CLAIM_TABLE_HEAD + "".join(rows) + "\\end{longtable}\n"


def _define(family: str, key: str, value: str) -> str:
    return f"\\expandafter\\def\\csname {family}@{key}\\endcsname{{{value}}}\n"


def write_snippets(claims_csv, versions_md, config, outdir) -> None:
    """Write every snippet to ``outdir``; ``config`` is the run's configuration (dict or YAML path)."""
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
    (outdir / "measured.tex").write_text("".join(measured))
    summary = []
    for paper in papers:
        rows = [claim for claim in claims if claim.paper == paper]
        failed = sum(claim.status == "fail" for claim in rows)
        summary += [_define("claimcount", f"{paper}.all", str(len(rows))),
                    _define("claimcount", f"{paper}.fail", str(failed)),
                    _define("claimcount", f"{paper}.pass", str(len(rows) - failed))]
        (outdir / f"claims_{paper}.tex").write_text(_claims_table(rows))
    failures = [claim for claim in claims if claim.status == "fail"]
    (outdir / "failures.tex").write_text(_claims_table(failures) if failures else "No claim fails.\n")
    (outdir / "summary.tex").write_text("".join(summary))
    if not isinstance(config, dict):
        config = yaml.safe_load(Path(config).read_text())
    parameters = list(_flatten(config))
    (outdir / "parameters.tex").write_text("".join(_define("param", key, cell(text)) for key, text in parameters))
    (outdir / "configuration.tex").write_text("".join(
        f"\\noindent\\texttt{{{_breakable(key)}}} = {cell(text)}\\par\n" for key, text in parameters))
    rows = [line for line in Path(versions_md).read_text().splitlines() if re.match(r"\| [^-]", line)][1:]
    table = "".join(f"{tex(cells[1].strip())} & {tex(cells[2].strip())} \\\\\n"
                    for cells in (row.split("|") for row in rows))
    (outdir / "versions.tex").write_text("\\begin{tabular}{ll}\\toprule package & version \\\\ \\midrule\n" + table
                                         + "\\bottomrule\n\\end{tabular}\n")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_methods.report", description=__doc__)
    parser.add_argument("claims")
    parser.add_argument("versions")
    parser.add_argument("config")
    parser.add_argument("outdir")
    args = parser.parse_args(argv)
    write_snippets(args.claims, args.versions, args.config, args.outdir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
