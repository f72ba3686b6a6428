"""Configuration checks and helpers shared by every rule file."""

import importlib.util
import os
import sys
from pathlib import Path

import jsonschema
from snakemake.exceptions import WorkflowError
from snakemake.utils import update_config

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
from particle_replication.paths import read_yaml
from particle_replication.workflow import code_inputs as workflow_code_inputs
from particle_replication.workflow import (
    damaged_results,
    missing_inputs,
    record_lock_owner,
    stale_locks,
)

PACKAGE = ROOT / "src" / "particle_methods"  # the numerics
REPLICATION = ROOT / "src" / "particle_replication"  # claims, verdicts, the pipeline's support
PACKAGES = [PACKAGE, REPLICATION]

# Software of every rule under `--software-deployment-method conda`. Its post-deploy script
# installs the package from this clone, which it finds through PARTICLE_METHODS_SOURCE: set
# here for the processes Snakemake starts (never read by the workflow, so no envvars entry).
ENVIRONMENT = "../envs/particle-methods.yaml"
os.environ.update(PARTICLE_METHODS_SOURCE=str(ROOT))


# The full run's configuration, with what --configfile and --config give laid over it, as Snakemake's `configfile`
# does, and checked against its schema as snakemake.utils.validate does (the schema sets no defaults): both files
# read through libyaml (read_yaml), where Snakemake's pure-Python reader took about half a second of every start.
CONFIG_FILE = ROOT / "config" / "config.yaml"
workflow.configfiles.append(str(CONFIG_FILE))
update_config(config, read_yaml(CONFIG_FILE))
update_config(config, workflow.config_settings.overwrite_config)
try:
    jsonschema.Draft202012Validator(read_yaml(ROOT / "config" / "schema.yaml")).validate(config)
except jsonschema.ValidationError as error:
    raise WorkflowError("Error validating config file.", error)
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


def claims_steps():
    """Every table of the claims (the repository's and each paper's) with the files it is computed from."""
    steps = {}
    for paper in registry.PAPERS.values():
        for table in ("claims.csv", "rates.json"):
            steps[f"results/{paper.id}/{table}"] = list(paper.claim_inputs().values())
    for table in ("claims.csv", "claims.md", "rates.json"):
        steps[f"results/{table}"] = [
            f"results/{paper}/{name}"
            for paper in registry.PAPERS
            for name in ("claims.csv", "rates.json")
        ]
    return steps


def rebuild_what_is_not_current():
    """At the start of every run, in its output root (after `workdir:`), the results Snakemake would take as
    up to date although they are not, marked for rebuilding by setting their time to 1970 (older than the
    code that computes them, so Snakemake reruns their jobs and all that depends on them): a damaged result
    (truncated or altered, its time kept or not; :func:`damaged_results`), and a claims table computed from a
    result that is gone (Snakemake does not rebuild a missing file whose dependants exist). Returns the damaged
    results, for verify to refuse them."""
    if not workflow.is_main_process:  # a job of a cluster run parses the workflow again
        return {}
    damaged = damaged_results("results")
    missing = missing_inputs(claims_steps())
    for path, problem in damaged.items():
        print(f"{path} is damaged ({problem}): its job reruns.", file=sys.stderr)
    for table, gone in missing.items():
        print(
            f"{table} was computed from {', '.join(gone)}, which no longer exist: it is rebuilt.",
            file=sys.stderr,
        )
    for path in [*damaged, *missing]:
        os.utime(path, ns=(0, 0))
    return damaged


LOCKS = Path(".snakemake") / "locks"


def remove_stale_locks():
    """Remove the locks of a Snakemake run of this output root that was killed (SIGKILL, a lost session: a run
    that ends removes its own), saying so, so that running the same command again resumes it; stop while jobs
    of the killed run still write their outputs. Only locks whose owner our onstart recorded are judged
    (:func:`stale_locks`): Snakemake's lock files do not name their run."""
    if not workflow.is_main_process:
        return
    stale, running = stale_locks(LOCKS)
    if running:
        raise WorkflowError(
            "A Snakemake run of this directory was killed while its jobs go on writing their outputs: "
            + ", ".join(
                f"process {pid} is gone, its process group {group} still runs"
                for pid, group in running.items()
            )
            + ". Wait for them to end, or end them with "
            + " ".join(f"`kill -- -{group}`" for group in running.values())
            + ", then run the same command again."
        )
    for lock in stale:
        lock.unlink(missing_ok=True)
        Path(f"{lock}.owner").unlink(missing_ok=True)
        print(
            f"Removed {lock}, the lock of a Snakemake run that was killed (its process is gone); "
            "the jobs it left unfinished are rerun.",
            file=sys.stderr,
        )


onstart:
    # Snakemake's file persistence knows the lock files this run holds; another backend records no owner.
    record_lock_owner(getattr(workflow.persistence, "_lockfile", {}).values())


def current_claims_table(wildcards):
    """No file: verify's refusal, before any job runs, of a claims table not built from the current results,
    naming what is missing (a claims table or a result it is computed from) or damaged
    (rebuild_what_is_not_current). Snakemake would take such a table as up to date; what it sees
    out of date (a newer result, changed code or parameters) it rebuilds before verify judges."""
    steps = claims_steps()
    files = dict.fromkeys([*steps, *(path for inputs in steps.values() for path in inputs)])
    problems = [f"{path} is missing" for path in files if not os.path.exists(path)]
    problems += [f"{path} is damaged ({problem})" for path, problem in DAMAGED.items()]
    if problems:
        raise WorkflowError(
            "verify judges only a claims table built from the current results, and "
            + "; ".join(problems)
            + ". Run the pipeline first (snakemake --cores 2, with the same --configfile): it rebuilds them."
        )
    return []
