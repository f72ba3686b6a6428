"""Configuration checks and helpers shared by every rule file."""

from pathlib import Path

from snakemake.utils import validate

from particle_methods.workflow import module_dependencies

ROOT = Path(workflow.basedir)
PACKAGE = ROOT / "src" / "particle_methods"


validate(config, str(ROOT / "config" / "schema.yaml"))


def imports(script):
    """Package modules that scripts/<script> imports, directly or through each other.

    Rules list them among their inputs, so editing a module reruns exactly the
    results computed with it; the list is read from the import statements, so it
    cannot drift from the code.
    """
    return module_dependencies(ROOT / "scripts" / script, PACKAGE)


def figure(path_without_suffix):
    """PDF and PNG outputs of one figure."""
    return {"pdf": f"{path_without_suffix}.pdf", "png": f"{path_without_suffix}.png"}
