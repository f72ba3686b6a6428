"""The software a run used: Python and each dependency's version, for the report."""

from __future__ import annotations

import argparse
import platform
import sys
from importlib import metadata

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


def markdown() -> str:
    lines = ["# Software versions", "", f"Platform: {platform.platform()}", "", "| package | version |", "|---|---|"]
    lines += [f"| {name} | {version} |" for name, version in versions().items()]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_methods.environment", description=__doc__)
    parser.add_argument("output", help="Markdown file to write")
    args = parser.parse_args(argv)
    with open(args.output, "w") as handle:
        handle.write(markdown())
    return 0


if __name__ == "__main__":
    sys.exit(main())
