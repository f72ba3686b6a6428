"""The tools CI installs beside the tests (``.ci/run``): the LaTeX toolchain and headless Chromium.

``.ci/run`` installs them in the background while the tests run, and writes the install's outcome
(``installed`` or ``failed``) to the file that ``PARTICLE_METHODS_TOOLS_STATUS`` names once it ends. Elsewhere
the variable is unset, and the tools are whatever the machine has.
"""

from __future__ import annotations

import os
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
