"""Helpers for the pipeline scripts: logging to the rule's log, atomic result files."""

from __future__ import annotations

import contextlib
import os
import sys
import time
from pathlib import Path

import numpy as np


@contextlib.contextmanager
def logged(log_path):
    """Send stdout and stderr to ``log_path`` and report the wall time at the end."""
    log_path = Path(log_path)
    log_path.parent.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    with log_path.open("w") as log, contextlib.redirect_stdout(log), contextlib.redirect_stderr(log):
        yield
        print(f"wall time: {time.perf_counter() - start:.2f} s", flush=True)


def progress(message: str) -> None:
    """One line of progress in the rule's log."""
    print(message, file=sys.stdout, flush=True)


def save_results(path, **arrays) -> None:
    """Write ``arrays`` to an ``.npz`` file through a temporary name, so that an
    interrupted run never leaves a truncated result behind."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(path.name + ".tmp")
    with temporary.open("wb") as handle:
        np.savez(handle, **arrays)
    os.replace(temporary, path)


def load_results(path) -> dict:
    """Load an ``.npz`` result file into a plain dictionary of arrays."""
    with np.load(path) as data:
        return {key: data[key] for key in data.files}
