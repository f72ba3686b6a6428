"""Numba settings for every compiled kernel of the package, set in one place."""

from __future__ import annotations

import os

import numba

# numba's threading layer is GNU OpenMP here (no TBB): its threads spin at every barrier before they sleep.
# With two processes on two cores, a spinning thread holds the core the other process's thread needs, and
# a parallel call of a fraction of a millisecond took 24 ms (a time slice; benchmarks/bench_threads.py).
# Passive threads sleep at once. Read when the OpenMP library starts, at the first parallel call; a value
# the user set is kept.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

#: Options passed to :func:`numba.njit` for every kernel. ``cache=True`` keeps the
#: compiled machine code on disk so that pipeline steps do not pay the JIT again.
JIT_OPTIONS = {"cache": True, "nogil": True, "error_model": "numpy"}


def njit(function=None, **overrides):
    """``numba.njit`` with the package's options; usable bare or with overrides."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: numba.njit(**options)(f)
    return numba.njit(**options)(function)
