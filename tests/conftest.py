"""Shared fixtures, and the priority of the pytest-xdist workers."""

import os
from pathlib import Path

import numpy as np
import pytest

_LOWERED = []
TESTS = Path(__file__).resolve().parent


#: The tests that compile most of the numerics' kernels: the papers' folders and the census of every public callable.
COMPILING = ("blob", "cross", "ltp", "sticky", "test_census.py")


def collection_rank(item) -> int:
    """Where a test runs in the order: the pipeline module's tests first (0), then the tests of the replication layer
    and the shared code (1), then those that compile most kernels (2, :data:`COMPILING`)."""
    if item.get_closest_marker("pipeline") is not None:
        return 0
    return 2 if Path(item.path).relative_to(TESTS).parts[0] in COMPILING else 1


def pytest_collection_modifyitems(items):
    """A stable sort by :func:`collection_rank`. Under pytest-xdist one worker starts the quick run at once, before
    it runs any other test (see :func:`pytest_runtest_setup`). The other runs the light tests beside it and reaches
    the compiling ones last: the quick run's scratch copy shares this checkout's numba caches
    (tests/test_pipeline.py, ``copy_repository``), so by then it has compiled most of their kernels, where the two
    would otherwise compile the same kernels at the same time."""
    items.sort(key=collection_rank)


def pytest_runtest_setup(item):
    """Under pytest-xdist a worker lowers its priority (nice 10) before its first test outside the pipeline
    module: the quick run's timed jobs (sticky cost, beyond, cross) then keep their cores while unit tests run
    beside them. The pipeline module is collected first (:func:`pytest_collection_modifyitems`), so the worker
    that runs it starts its quick run before any unit test and keeps the normal priority for it."""
    if os.environ.get("PYTEST_XDIST_WORKER") and item.get_closest_marker("pipeline") is None and not _LOWERED:
        os.nice(10)
        _LOWERED.append(True)


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)
