"""Checked claims: a published statement, the value we measure, a tolerance, a verdict.

Every paper's pipeline writes its claims with :func:`write_claims`; the report
step merges them into ``results/claims.csv`` (columns :data:`COLUMNS`) and a
Markdown table; ``python -m particle_methods.claims verify`` exits non-zero when
any claim fails.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from dataclasses import asdict, dataclass
from pathlib import Path

COLUMNS = ("id", "paper", "figure", "claim", "published", "measured", "tolerance", "status")


@dataclass(frozen=True)
class Claim:
    """One row of the claims table."""

    id: str
    paper: str
    figure: str
    claim: str
    published: str
    measured: str
    tolerance: str
    status: str

    def __post_init__(self):
        if self.status not in ("pass", "fail"):
            raise ValueError(f"status must be 'pass' or 'fail', got {self.status!r}")
        if not self.id.startswith(f"{self.paper}."):
            raise ValueError(f"claim id {self.id!r} must start with the paper id {self.paper!r}")


def _number(value: float) -> str:
    return f"{value:.6g}"


def _verdict(ok: bool, measured: float) -> str:
    return "pass" if ok and math.isfinite(measured) else "fail"


def close_to(id, paper, figure, claim, published: float, measured: float, tolerance: float) -> Claim:
    """Pass when |measured - published| <= tolerance."""
    ok = abs(measured - published) <= tolerance
    return Claim(id, paper, figure, claim, _number(published), _number(measured),
                 f"+-{_number(tolerance)}", _verdict(ok, measured))


def relatively_close_to(id, paper, figure, claim, published: float, measured: float,
                        tolerance: float) -> Claim:
    """Pass when |measured - published| <= tolerance * |published|."""
    ok = abs(measured - published) <= tolerance * abs(published)
    return Claim(id, paper, figure, claim, _number(published), _number(measured),
                 f"rel {_number(tolerance)}", _verdict(ok, measured))


def at_most(id, paper, figure, claim, bound: float, measured: float, published: str | None = None) -> Claim:
    """Pass when measured <= bound."""
    return Claim(id, paper, figure, claim, published or f"<= {_number(bound)}", _number(measured),
                 f"<= {_number(bound)}", _verdict(measured <= bound, measured))


def at_least(id, paper, figure, claim, bound: float, measured: float, published: str | None = None) -> Claim:
    """Pass when measured >= bound."""
    return Claim(id, paper, figure, claim, published or f">= {_number(bound)}", _number(measured),
                 f">= {_number(bound)}", _verdict(measured >= bound, measured))


def write_claims(path, claims) -> None:
    """Write claims to a CSV file with the columns of the repository-wide table."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    ids = [claim.id for claim in claims]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        raise ValueError(f"duplicate claim ids: {duplicates}")
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


def summary_line(claims) -> str:
    """'n claims checked: p pass, f fail.'"""
    failed = sum(claim.status == "fail" for claim in claims)
    return f"{len(claims)} claims checked: {len(claims) - failed} pass, {failed} fail."


def markdown_table(claims, heading: bool = True) -> str:
    """Markdown rendering: a title and a summary line (unless ``heading`` is false), then one row
    per claim."""
    lines = ["# Checked claims", "", summary_line(claims), ""] if heading else []
    lines += [
        "| id | figure | claim | published | measured | tolerance | status |",
        "|---|---|---|---|---|---|---|",
    ]
    for claim in claims:
        status = "**fail**" if claim.status == "fail" else "pass"
        text = claim.claim.replace("|", "\\|")
        lines.append(f"| `{claim.id}` | {claim.figure} | {text} | {claim.published} | "
                     f"{claim.measured} | {claim.tolerance} | {status} |")
    return "\n".join(lines) + "\n"


def merge(sources, csv_path, markdown_path) -> list[Claim]:
    """Concatenate per-paper claim files into the repository table and its Markdown."""
    claims = [claim for source in sources for claim in read_claims(source)]
    write_claims(csv_path, claims)
    markdown_path = Path(markdown_path)
    temporary = markdown_path.with_suffix(".tmp")
    temporary.write_text(markdown_table(claims))
    temporary.replace(markdown_path)
    return claims


def verify(path) -> int:
    """Print failing claims; return the process exit code (1 when any claim fails)."""
    claims = read_claims(path)
    failed = [claim for claim in claims if claim.status == "fail"]
    for claim in failed:
        print(f"FAIL {claim.id}: {claim.claim} (published {claim.published}, "
              f"measured {claim.measured}, tolerance {claim.tolerance})")
    print(f"{len(claims) - len(failed)} of {len(claims)} claims pass")
    return 1 if failed else 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_methods.claims", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    merge_parser = sub.add_parser("merge", help="merge per-paper claim files")
    merge_parser.add_argument("sources", nargs="+")
    merge_parser.add_argument("--csv", required=True)
    merge_parser.add_argument("--markdown", required=True)
    verify_parser = sub.add_parser("verify", help="exit 1 when a claim fails")
    verify_parser.add_argument("path")
    args = parser.parse_args(argv)
    if args.command == "merge":
        merge(args.sources, args.csv, args.markdown)
        return 0
    return verify(args.path)


if __name__ == "__main__":
    sys.exit(main())
