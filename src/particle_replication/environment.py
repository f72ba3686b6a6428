"""The software a run used: the repository's commit, Python and each dependency's version.

``python -m particle_replication.environment versions.md`` writes them for the report;
``python -m particle_replication.environment --epoch`` prints the commit time in seconds since 1970,
the SOURCE_DATE_EPOCH that makes two builds of the PDF from one commit byte-identical.
:func:`cpu` is the one description of a CPU that every timing names (the benchmarks, the timing claims, the
report, the README); :func:`recorded_cpu` reads it back from a run's record.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
from importlib import metadata
from pathlib import Path

PACKAGES = ("particle-methods", "numpy", "scipy", "numba", "llvmlite", "matplotlib", "snakemake", "jupytext",
            "jsonschema", "pyyaml")


def versions() -> dict[str, str]:
    """Name -> version of Python and of each package in :data:`PACKAGES` (or 'not installed')."""
    found = {"python": platform.python_version()}
    for name in PACKAGES:
        try:
            found[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            found[name] = "not installed"
    return found


#: Vector extensions, widest first, by the flag /proc/cpuinfo gives them.
VECTOR_FLAGS = (("avx512f", "AVX-512"), ("avx2", "AVX2"), ("avx", "AVX"), ("sse2", "SSE2"))


def cpu() -> str:
    """The CPU a timing was made on: its model, its widest vector extension and the cores this process may use,
    e.g. "AMD EPYC (AVX-512, 2 cores)" (from /proc/cpuinfo; the platform's processor name elsewhere)."""
    model, flags = platform.processor() or platform.machine() or "unknown CPU", set()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            key, _, value = line.partition(":")
            if key.strip() == "model name" and value.strip():
                model = value.strip()
            elif key.strip() == "flags":
                flags = set(value.split())
    except OSError:
        pass
    width = next((name for flag, name in VECTOR_FLAGS if flag in flags), "")
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    return f"{model} ({width + ', ' if width else ''}{cores} cores)"


#: The field of the versions record (:func:`markdown`) that names the CPU, and what is said without it.
CPU_FIELD, CPU_NOT_RECORDED = "CPU", "CPU not recorded"


def recorded_cpu(versions: str) -> str:
    """The CPU a run's versions record (the text of its ``results/versions.md``, :func:`markdown`) names: the
    machine the run was timed on, not the one reading it; :data:`CPU_NOT_RECORDED` if the record has none."""
    if not isinstance(versions, str):
        raise TypeError(f"versions must be the text of a versions record, not {type(versions).__name__}")
    for line in versions.splitlines():
        key, separator, value = line.partition(": ")
        if separator and key.strip() == CPU_FIELD and value.strip():
            return value.strip()
    return CPU_NOT_RECORDED


def repository() -> Path:
    """The clone the run was made from: PARTICLE_METHODS_SOURCE (set by the Snakefile), else this package's."""
    return Path(os.environ.get("PARTICLE_METHODS_SOURCE", Path(__file__).resolve().parents[2]))


def _git(*args) -> str | None:
    try:
        result = subprocess.run(["git", "-C", str(repository()), *args], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    return result.stdout.strip() if result.returncode == 0 else None


def commit() -> dict[str, str]:
    """hash, date (ISO 8601), epoch (seconds) of the checked-out commit, and whether files differ from it.

    Outside a git clone every field is "unknown" and the epoch is 0.
    """
    found = _git("log", "-1", "--format=%H %cI %ct")
    if not found:
        return {"hash": "unknown", "date": "unknown", "epoch": "0", "modified": "unknown"}
    hash_, date, epoch = found.split()
    changes = _git("status", "--porcelain", "--untracked-files=no")
    return {"hash": hash_, "date": date, "epoch": epoch, "modified": "yes" if changes else "no"}


def markdown() -> str:
    state = commit()
    lines = ["# Software versions", "", f"Commit: {state['hash']}", "", f"Commit date: {state['date']}", "",
             f"Modified since the commit: {state['modified']}", "", f"Platform: {platform.platform()}", "",
             f"{CPU_FIELD}: {cpu()}", "",
             "| package | version |", "|---|---|"]
    lines += [f"| {name} | {version} |" for name, version in versions().items()]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_replication.environment", description=__doc__)
    parser.add_argument("output", nargs="?", help="Markdown file to write")
    parser.add_argument("--epoch", action="store_true", help="print the commit time (SOURCE_DATE_EPOCH) and exit")
    args = parser.parse_args(argv)
    if args.epoch:
        print(commit()["epoch"])
        return 0
    if args.output is None:
        parser.error("give the Markdown file to write, or --epoch")
    with open(args.output, "w") as handle:
        handle.write(markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())
