"""The SLURM profile for real: a target of the quick pipeline submitted as a SLURM job, where a cluster answers.

It needs a SLURM cluster with an idle node (on one machine: `bash benchmarks/slurm/start_local_cluster.sh`, see
docs/running.md) and snakemake-executor-plugin-slurm; elsewhere (CI) it is skipped, saying why.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
# A small job of the quick run that computes nothing numerical (no kernel to compile): its SLURM job is mostly
# the scheduler's and Snakemake's start.
TARGET = "results/versions.md"
SOURCES = shutil.ignore_patterns(".git", ".snakemake", "results", "figures", "logs", "runs", "executed", "build",
                                 "ms.pdf", "supplement.pdf", "__pycache__", ".hypothesis", ".pytest_cache")


def idle_nodes():
    """The nodes SLURM reports idle, or the reason there are none to run on."""
    if shutil.which("sinfo") is None:
        return [], "no SLURM here (sinfo is not installed): start one with benchmarks/slurm/start_local_cluster.sh"
    result = subprocess.run(["sinfo", "-h", "-N", "-o", "%N %t"], capture_output=True, text=True, timeout=30)
    if result.returncode != 0:
        return [], f"no SLURM controller answers sinfo: {result.stderr.strip()}"
    nodes = [line.split()[0] for line in result.stdout.splitlines() if line.split()[1:] == ["idle"]]
    return nodes, "" if nodes else f"no SLURM node is idle (sinfo: {result.stdout.strip() or 'no nodes'})"


def test_a_target_submitted_through_the_profile_lands_where_the_local_run_puts_it(tmp_path):
    pytest.importorskip("snakemake_executor_plugin_slurm", reason="snakemake-executor-plugin-slurm is not installed")
    nodes, reason = idle_nodes()
    if not nodes:
        pytest.skip(reason)
    checkout = tmp_path / "checkout"
    shutil.copytree(ROOT, checkout, ignore=SOURCES)
    # run as a user runs it, from the checkout without --directory: the output root comes from the configuration
    command = [sys.executable, "-m", "snakemake", "--profile", "profiles/slurm",
               "--slurm-init-seconds-before-status-checks", "2", TARGET, "--configfile", "config/quick.yaml"]
    environment = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(checkout / "src"),
                                                                             os.environ.get("PYTHONPATH")]))}
    result = subprocess.run(command, cwd=checkout, env=environment, capture_output=True, text=True, timeout=600)
    output = result.stdout + result.stderr
    assert result.returncode == 0, output[-3000:]
    assert re.search(r"submitted with SLURM jobid \d+", output), output[-3000:]
    assert (checkout / "runs" / "quick" / TARGET).is_file(), output[-3000:]
    # neither the output root applied twice (the job parses the workflow again) nor the full run's root
    assert not (checkout / "runs" / "quick" / "runs").exists()
    assert not (checkout / "results").exists()
