"""Configuration checks and helpers shared by every rule file."""

import os
from pathlib import Path

from snakemake.utils import validate

from particle_replication.configuration import check_configuration
from particle_replication.workflow import module_dependencies

ROOT = Path(workflow.basedir)
PACKAGE = ROOT / "src" / "particle_methods"  # the numerics
REPLICATION = ROOT / "src" / "particle_replication"  # claims, verdicts, the pipeline's support
PACKAGES = [PACKAGE, REPLICATION]

# Software of every rule under `--software-deployment-method conda`. Its post-deploy script
# installs the package from this clone, which it finds through PARTICLE_METHODS_SOURCE: set
# here for the processes Snakemake starts (never read by the workflow, so no envvars entry).
ENVIRONMENT = "../envs/particle-methods.yaml"
os.environ.update(PARTICLE_METHODS_SOURCE=str(ROOT))


validate(config, str(ROOT / "config" / "schema.yaml"))
check_configuration(config)


def source(path):
    """A repository file as an input, relative to the working directory, so that a
    run moved or copied together with its repository has nothing to do."""
    return os.path.relpath(path)


def imports(script):
    """Modules of the two packages that scripts/<script> imports, directly or through each other.

    Rules list them among their inputs, so editing a module reruns exactly the
    results computed with it; the list is read from the import statements, so it
    cannot drift from the code.
    """
    return [source(path) for path in module_dependencies(ROOT / "scripts" / script, PACKAGES)]


CAPTION = str(ROOT / "report" / "caption.rst")


def figure(path_without_suffix):
    """PDF and PNG outputs of one figure; the PNG goes to the Snakemake report with the rule's
    ``params.caption`` as caption, filed under its paper and figure."""
    paper, name = path_without_suffix.split("/")[-2:]
    return {
        "pdf": f"{path_without_suffix}.pdf",
        "png": report(
            f"{path_without_suffix}.png", caption=CAPTION, category=paper, subcategory=name
        ),
    }


def listing(values):
    """Values of a caption: all of them when few, else the first two, an ellipsis and the last."""
    values = [f"{value:g}" for value in values]
    return ", ".join(values if len(values) <= 4 else [*values[:2], "...", values[-1]])


def power(exponent):
    """|x|^a/a in a caption."""
    return f"|x|^{exponent:g}/{exponent:g}"


def _rst(text):
    """Escape the characters reStructuredText would read as markup (|x|, delta_1, a*b)."""
    for character in "|_*":
        text = text.replace(character, f"\\{character}")
    return text


def caption(captions, figure=None):
    """Caption of a figure from a paper's CAPTIONS table (by wildcard when ``figure`` is None)."""
    if figure is not None:
        return _rst(captions[figure])
    return lambda wildcards: _rst(captions[wildcards.figure])
