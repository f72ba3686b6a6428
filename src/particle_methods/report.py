"""LaTeX snippets for the replication report, written by the pipeline from its own outputs.

``python -m particle_methods.report CLAIMS VERSIONS CONFIG OUTDIR`` writes:

- ``claims_<paper>.tex``: each paper's claims table (a longtable);
- ``measured.tex``: ``\\measured{<claim id>}`` and ``\\status{<claim id>}`` for any claim;
- ``parameters.tex``: ``\\param{<dotted config key>}`` for every configuration value;
- ``summary.tex``: ``\\claimcount{<paper>}{pass|fail|all}``;
- ``versions.tex``: the software versions table (a tabular).

The article (``paper/ms.tex``) types no number of its own: it uses these macros.
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
    "\\begin{longtable}{>{\\raggedright\\scriptsize}p{3.9cm}>{\\raggedright}p{1.1cm}>{\\raggedright}p{5.2cm}"
    ">{\\raggedright}p{1.5cm}>{\\raggedright}p{1.4cm}>{\\raggedright}p{1.2cm}l}\n"
    "\\toprule id & figure & claim & published & measured & tolerance & status \\\\ \\midrule \\endhead\n"
)


def tex(text) -> str:
    """Escape LaTeX special characters in plain text."""
    return "".join(_SPECIAL.get(character, character) for character in str(text))


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
        measured.append(_define("measured", claim.id, tex(claim.measured)))
        measured.append(_define("status", claim.id, claim.status))
    (outdir / "measured.tex").write_text("".join(measured))
    summary = []
    for paper in papers:
        rows = [claim for claim in claims if claim.paper == paper]
        failed = sum(claim.status == "fail" for claim in rows)
        summary += [_define("claimcount", f"{paper}.all", str(len(rows))),
                    _define("claimcount", f"{paper}.fail", str(failed)),
                    _define("claimcount", f"{paper}.pass", str(len(rows) - failed))]
        lines = []
        for claim in rows:
            status = r"\textbf{fail}" if claim.status == "fail" else "pass"
            identifier = tex(claim.id).replace(".", ".\\allowbreak{}")
            lines.append(f"\\texttt{{{identifier}}} & {tex(claim.figure)} & {tex(claim.claim)} & "
                         f"{tex(claim.published)} & {tex(claim.measured)} & {tex(claim.tolerance)} & {status} \\\\\n")
        table = _CLAIM_TABLE_HEAD + "".join(lines) + "\\bottomrule\n\\end{longtable}\n"
        (outdir / f"claims_{paper}.tex").write_text(table)
    (outdir / "summary.tex").write_text("".join(summary))
    if not isinstance(config, dict):
        config = yaml.safe_load(Path(config).read_text())
    (outdir / "parameters.tex").write_text("".join(_define("param", key, tex(value))
                                                   for key, value in _flatten(config)))
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
