"""Configuration checks and helpers shared by every rule file."""

from pathlib import Path

from snakemake.utils import validate

ROOT = Path(workflow.basedir)
PACKAGE = ROOT / "src" / "particle_methods"


validate(config, str(ROOT / "config" / "schema.yaml"))


def code(*modules):
    """Absolute paths of package modules, listed as inputs so that editing one
    reruns exactly the results that depend on it."""
    return [str(PACKAGE / module) for module in modules]


def figure(path_without_suffix):
    """PDF and PNG outputs of one figure."""
    return {"pdf": f"{path_without_suffix}.pdf", "png": f"{path_without_suffix}.png"}
