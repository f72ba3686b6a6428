"""The commands the documentation shows stay runnable: every `snakemake ...` command of the README, docs/,
CONTRIBUTING, the READMEs of config/, benchmarks/ and paper/, the Snakefile and the config files' comments
parses with Snakemake's own parser, its targets come before `--configfile` (which takes every later word as a
file) and are rules or files of the workflow, and every `python -m ...` command's module and subcommand
answer --help. Fast: nothing is planned or run."""

import re
import runpy
import shlex
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCUMENTS = [ROOT / "README.md", ROOT / "CONTRIBUTING.md", ROOT / "Snakefile", *sorted((ROOT / "docs").glob("*.md")),
             *(ROOT / d / "README.md" for d in ("config", "benchmarks", "paper")),
             *sorted((ROOT / "config").glob("*.yaml"))]


def commands(program: str) -> list[tuple[str, str]]:
    """(document, command) for every command of ``program`` in a code block, a comment or an inline span."""
    found = []
    for path in DOCUMENTS:
        text = path.read_text().replace("\\\n#", "").replace("\\\n", "")
        for line in re.findall(rf"(?:^|[`#] ?|&& ){program} ([^`#\n]*)", text, flags=re.MULTILINE):
            line = line.strip().rstrip(".;,)")
            if line and (program != "snakemake" or ("<" not in line and "..." not in line)):
                found.append((path.name, line))
    return found


def rules() -> set[str]:
    from particle_replication import registry

    names = {name for path in [ROOT / "Snakefile", *(ROOT / "rules").glob("*.smk")]
             for name in re.findall(r"^rule (\w+):", path.read_text(), flags=re.MULTILINE)}
    names |= {entry.rule for entry in registry.RESULTS}
    names |= {plot.rule(paper.id) for paper in registry.PAPERS.values() for plot in paper.plots}
    return names | set(registry.PAPERS)


def test_snakemake_commands_parse_with_targets_first():
    from snakemake.cli import get_argument_parser

    found = commands("snakemake")
    assert len(found) >= 10, found
    known = rules()
    for document, line in found:
        try:
            args = get_argument_parser().parse_args(shlex.split(line))
        except SystemExit:
            pytest.fail(f"{document}: `snakemake {line}` does not parse")
        for path in args.configfile or []:
            assert path.suffix == ".yaml" and (ROOT / path).is_file(), f"{document}: `snakemake {line}`: {path}"
        for target in args.targets:
            assert target in known or "/" in target, f"{document}: `snakemake {line}`: unknown target {target}"


MODULES = sorted({line.split()[0] for _, line in commands("python -m")
                  if re.fullmatch(r"[a-z_]+(\.[a-z_]+)*", line.split()[0])} - {"pytest"})


@pytest.mark.parametrize("module", MODULES)
def test_python_modules_answer_help(module, monkeypatch, capsys):
    subcommands = {line.split()[1] for _, line in commands("python -m") if line.split()[0] == module
                   and len(line.split()) > 1 and re.fullmatch(r"[a-z]+", line.split()[1])}
    for sub in [None, *sorted(subcommands)]:
        monkeypatch.setattr(sys, "argv", [module, *([sub] if sub else []), "--help"])
        try:
            runpy.run_module(module, run_name="__main__")
        except SystemExit as stop:
            assert stop.code in (0, None), f"python -m {module} {sub or ''} --help"
