"""Configuration checks and helpers shared by every rule file."""

import os
from pathlib import Path

from snakemake.utils import validate

from particle_replication import registry
from particle_replication.configuration import check_configuration
from particle_replication.workflow import code_inputs as workflow_code_inputs

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


def code_inputs(path):
    """Modules of the two packages that ``path`` imports, directly or through each other, but for
    the registry (see :func:`imports`)."""
    return [source(module) for module in workflow_code_inputs(path, PACKAGES)]


def imports(script):
    """Modules of the two packages that scripts/<script> imports, directly or through each other.

    Rules list them among their inputs, so editing a module reruns exactly the
    results computed with it; the list is read from the import statements, so it
    cannot drift from the code. The registry is left out: what it gives a job reaches the
    job as its params, inputs and script, which Snakemake tracks (see its docstring).
    """
    return code_inputs(ROOT / "scripts" / script)


# The report's caption of a figure: its plot job's caption param (see report/caption.rst).
CAPTION = str(ROOT / "report" / "caption.rst")
