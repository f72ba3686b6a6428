"""The tools CI installs beside the tests (``.ci/run``): the LaTeX toolchain and headless Chromium; and the check
that the machine's SLURM, if any, does not slow every Snakemake start of the tests.

``.ci/run`` installs them in the background while the tests run, and writes the install's outcome
(``installed`` or ``failed``) to the file that ``PARTICLE_METHODS_TOOLS_STATUS`` names once it ends. Elsewhere
the variable is unset, and the tools are whatever the machine has.
"""

from __future__ import annotations

import importlib.util
import os
import shutil
import subprocess
import time
from pathlib import Path

#: The variable naming the install's status file.
VARIABLE = "PARTICLE_METHODS_TOOLS_STATUS"


def installing(environ=os.environ) -> bool:
    """Whether CI's install of the tools is still running (its status file not yet written)."""
    status = environ.get(VARIABLE)
    return bool(status) and not Path(status).exists()


def wait(environ=os.environ, timeout: float = 1200.0, poll: float = 1.0) -> str | None:
    """Wait for CI's install of the tools to end; returns its outcome (``installed`` or ``failed``), or None where no
    install was started. Raises TimeoutError after ``timeout`` seconds."""
    status = environ.get(VARIABLE)
    if not status:
        return None
    deadline = time.monotonic() + timeout
    while not Path(status).exists():
        if time.monotonic() > deadline:
            raise TimeoutError(f"the tools' install ({VARIABLE}={status}) did not end within {timeout:.0f} s")
        time.sleep(poll)
    return Path(status).read_text().strip()


def slurm_wait_warning(path: str | None = None) -> str | None:
    """Why every Snakemake start of the tests will be slow, or None: where the SLURM executor plugin is installed
    and SLURM's ``scontrol`` is on ``path`` but no controller answers ``scontrol ping`` (which answers at once), the
    plugin's own ``scontrol show config`` at each start waits about 9 s (docs/running.md)."""
    if importlib.util.find_spec("snakemake_executor_plugin_slurm") is None:
        return None
    scontrol = shutil.which("scontrol", path=path)
    if scontrol is None:
        return None
    try:
        answered = subprocess.run([scontrol, "ping"], capture_output=True, timeout=20).returncode == 0
    except subprocess.TimeoutExpired:
        answered = False
    if answered:
        return None
    return ("SLURM's commands are installed but no controller answers `scontrol ping`: each of the tests' Snakemake "
            "starts waits about 9 s for the SLURM plugin's `scontrol show config` (about 5 minutes in all). Start "
            "the controller (benchmarks/slurm/start_local_cluster.sh) or uninstall snakemake-executor-plugin-slurm "
            "(docs/running.md).")
