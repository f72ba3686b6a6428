"""The README's results: generated from a full run, never typed.

``python -m particle_replication.readme`` prints the block the README holds between its results markers, from
the run's claims table (``results/claims.csv``: the counts, the margins), its software record
(``results/versions.md``: the commit, its date, the CPU it ran on), its times (its benchmark files and job
graph: :func:`~particle_replication.pipeline_times.run_times`) and the expected verdicts
(``config/verdicts.yaml``: each failure's cause and reason); ``--write`` puts it into README.md. The tests keep
the block in step with the expected verdicts (tests/test_readme.py).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from .claims import CAUSES, KINDS, counts, fragile, read_claims, read_verdicts
from .environment import recorded_cpu
from .paths import REPOSITORY, read_yaml
from .pipeline_times import RunTimes, run_times

START = ("<!-- results: generated from the full run by `python -m particle_replication.readme --write`; "
         "tests/test_readme.py keeps it in step with config/verdicts.yaml -->")
END = "<!-- end of the results -->"
#: How the README counts the failures of each cause: (one, several).
CAUSE_WORDS = {"contradicts": ("contradicts the paper", "contradict the paper"),
               "pre-asymptotic": ("is pre-asymptotic", "are pre-asymptotic"),
               "our-inference": ("is an inference of ours that was wrong", "are inferences of ours that were wrong"),
               "defect": ("is a defect of ours", "are defects of ours")}


def cause_sentence(causes: dict[str, int]) -> str:
    """'Of the 8 failures, 2 contradict the paper, 4 are pre-asymptotic, ...' for the failures per cause."""
    return (f"Of the {sum(causes.values())} failures, "
            + ", ".join(f"{count} {CAUSE_WORDS[cause][count != 1]}" for cause, count in causes.items()
                        if cause in CAUSE_WORDS) + ".")


def _field(versions: str, name: str) -> str:
    found = re.search(rf"^{name}: (.+)$", versions, flags=re.MULTILINE)
    return found.group(1).strip() if found else "unknown"


def times_sentence(times: RunTimes) -> str:
    """What the run cost: its span, whether it compiled its kernels, its summed job time and its lower bound."""
    compiled = {True: "compiling every kernel itself, as a fresh clone does",
                False: "with kernels an earlier run had compiled",
                None: "whether it compiled its kernels itself is not recorded"}[times.cold]
    took = (f"It took {times.span:.0f} s on {times.cores} cores from its first job's start to its last job's end, "
            f"{compiled}; its jobs" if times.span is not None else
            "Its jobs were run by several invocations of Snakemake (its span is not measured); they")
    return (f"{took} took {times.jobs:.0f} s together, and no schedule on {times.cores} cores "
            f"finishes them in less than {times.bound:.0f} s (the critical path {times.path:.0f} s, the core-seconds "
            f"{times.core_seconds:.0f} / {times.cores}). Another machine's times differ: `benchmarks/README.md` "
            "names the CPU of every measurement.")


def results_block(claims, expected, versions: str, margin_min: float, robustness: str = "",
                  times: RunTimes | None = None) -> str:
    """The README's results paragraph and table of failures for a run's ``claims`` (with their margins), its
    ``expected`` verdicts (claim id -> :class:`~particle_replication.claims.Expected`), its versions record,
    its robustness report (``results/robustness.md``, or '' if the run has none) and its times (None: not
    measured)."""
    tally = counts(claims)
    paper, derived, check = (tally.get(kind, (0, 0)) for kind in KINDS)
    abstained = sum(claim.status == "abstain" for claim in claims)
    failing = [claim for claim in claims if claim.status == "fail"]
    causes = {cause: sum(expected[claim.id].cause == cause for claim in failing if claim.id in expected)
              for cause in CAUSES}
    shaky = [claim for claim in fragile(claims, margin_min) if claim.kind in ("paper", "derived")]
    run = (f"At the last full run (commit {_field(versions, 'Commit')[:7]} of {_field(versions, 'Commit date')[:10]}, "
           f"on {recorded_cpu(versions)})")
    lines = [
        f"{run}, {paper[0]} of the papers' {paper[1]} claims are reproduced; {derived[0]} of {derived[1]} claims we "
        f"derive from their theory and {check[0]} of our {check[1]} checks pass"
        + (f" ({abstained} wall-time check{'s' if abstained > 1 else ''} abstained: the machine was loaded or its "
           f"speed moved more than the check can tell)"
           if abstained else "") + ". "
        "Every verdict is compared with the expected one in `config/verdicts.yaml`, at the end of the run and by "
        "`snakemake verify`; each expected failure carries its cause and reason (a pre-asymptotic one: the paper's "
        "limit lies beyond our resolutions; a defect: our own instrument decides the verdict), and the report "
        "(`paper/ms.pdf`) gives the evidence. " + cause_sentence(causes)
        + (" " + times_sentence(times) if times else ""),
        "",
        "| claim | kind | cause | why |",
        "|---|---|---|---|",
    ]
    order = list(CAUSES)
    for claim in sorted(failing, key=lambda c: order.index(expected[c.id].cause) if c.id in expected else len(order)):
        verdict = expected.get(claim.id)
        cause, reason = (verdict.cause, verdict.reason) if verdict else ("unexpected", "not expected")
        lines.append(f"| `{claim.id}` | {claim.kind} | {cause} | {reason.replace('|', chr(92) + '|')} |")
    lines += [
        "",
        "Each verdict's margin, its distance from its threshold in units of its spread over the variants of the "
        "robustness run (threads, BLAS kernels, SIMD dispatch, CPU target, ulp-nudged data, a loaded machine), is "
        f"in the claims table; a margin below {margin_min:g} is fragile. "
        + (f"The robustness run: {_robustness_line(robustness)} " if robustness else "")
        + (f"Fragile paper or derived claims: {', '.join(f'`{claim.id}` ({claim.margin})' for claim in shaky)}."
           if shaky else "No paper or derived claim is fragile."),
    ]
    return "\n".join(lines)


def _robustness_line(report: str) -> str:
    """The robustness report's count of variants and of verdicts that differ ('10 variants beside the run itself;
    0 verdicts differ.')."""
    found = re.search(r"^\d+ variants beside the run itself; \d+ verdicts differ\.$", report, flags=re.MULTILINE)
    if not found:
        raise ValueError("the robustness report has lost its count of variants and differences")
    return found.group(0)


def replaced(readme: str, block: str) -> str:
    """``readme`` with the text between its results markers replaced by ``block``."""
    pattern = re.compile(re.escape(START) + r"\n.*?\n" + re.escape(END), flags=re.DOTALL)
    if not pattern.search(readme):
        raise ValueError("README.md has lost its results markers")
    return pattern.sub(lambda _: f"{START}\n{block}\n{END}", readme)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_replication.readme", description=__doc__)
    parser.add_argument("--root", default=".", help="the full run's root (results/ under it)")
    parser.add_argument("--write", action="store_true", help="write the block into README.md")
    args = parser.parse_args(argv)

    config = read_yaml(REPOSITORY / "config" / "config.yaml")
    root = Path(args.root)
    report = root / "results" / "robustness.md"
    block = results_block(read_claims(root / "results" / "claims.csv"),
                          read_verdicts(REPOSITORY / config["verdicts"]),
                          (root / "results" / "versions.md").read_text(), config["robustness"]["margin_min"],
                          report.read_text() if report.exists() else "",
                          run_times(root) if (root / "logs" / "benchmarks").is_dir() else None)
    if args.write:
        readme = REPOSITORY / "README.md"
        readme.write_text(replaced(readme.read_text(), block))
    else:
        print(block)
    return 0


if __name__ == "__main__":
    sys.exit(main())
