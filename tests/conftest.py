"""Shared fixtures, and the priority of the pytest-xdist workers."""

import os

import numpy as np
import pytest

_LOWERED = []


def pytest_collection_modifyitems(items):
    """The pipeline module's tests first (a stable sort), so that under pytest-xdist one worker starts the quick
    run at once, before it runs any other test (see :func:`pytest_runtest_setup`)."""
    items.sort(key=lambda item: item.get_closest_marker("pipeline") is None)


def pytest_runtest_setup(item):
    """Under pytest-xdist a worker lowers its priority (nice 10) before its first test outside the pipeline
    module: the quick run's timed jobs (sticky cost, beyond, cross) then keep their cores while unit tests run
    beside them. The pipeline module is collected first (:func:`pytest_collection_modifyitems`), so the worker
    that runs it starts its quick run before any unit test and keeps the normal priority for it."""
    if os.environ.get("PYTEST_XDIST_WORKER") and item.get_closest_marker("pipeline") is None and not _LOWERED:
        os.nice(10)
        _LOWERED.append(True)


def pytest_report_header(config):
    """A warning in the header where the machine's SLURM would slow every Snakemake start (tests/ci_tools.py)."""
    import ci_tools

    warning = ci_tools.slurm_wait_warning()
    return [f"warning: {warning}"] if warning else []


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)
