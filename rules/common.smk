"""Configuration checks and helpers shared by every rule file."""

import importlib.util
import os
from pathlib import Path

from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

ROOT = Path(workflow.basedir)


def imported_elsewhere(src):
    """The packages the jobs run (the numerics and the replication layer) that Python would import from
    elsewhere than ``src``, this checkout's sources: a copy or a second clone run in another checkout's
    environment would run that checkout's code while its rules track this one's files."""
    found = {}
    for name in ("particle_methods", "particle_replication"):
        spec = importlib.util.find_spec(name)
        location = Path(spec.origin).resolve().parents[1] if spec and spec.origin else None
        if location != Path(src).resolve():
            found[name] = location or "nowhere (not installed)"
    return found


if elsewhere := imported_elsewhere(ROOT / "src"):
    raise WorkflowError(
        f"This workflow's code is in {ROOT / 'src'}, but Python imports "
        + ", ".join(f"{name} from {where}" for name, where in elsewhere.items())
        + ": the jobs would run another checkout's code. Install this checkout in the environment "
        f'(pip install -e "{ROOT}[pipeline]") or run with PYTHONPATH={ROOT / "src"}.'
    )

from particle_replication import registry
from particle_replication.configuration import check_configuration
from particle_replication.workflow import code_inputs as workflow_code_inputs

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
