"""Threads of the compiled kernels and of the numerical libraries: one mechanism for the package.

Numba's parallel kernels, BLAS and OpenMP libraries each start a pool of threads as large as the
machine. Two processes sharing the cores then run twice as many busy threads as there are cores, and
each parallel region waits for a thread that is not scheduled: on 2 cores, three short LTP runs took
20x to 126x longer side by side than alone. Hence:

- OpenMP's threads sleep rather than spin while they wait (``OMP_WAIT_POLICY=PASSIVE`` unless set,
  :mod:`particle_methods.jit`): a parallel call under load then costs what it costs alone, not a time
  slice of the other process;
- :func:`use_threads` sets the threads of numba and of every loaded BLAS/OpenMP library at once,
  clamped to what the process may use (``NUMBA_NUM_THREADS`` when the user set it, else the
  cores). Every pipeline script calls it with the rule's ``threads``, through
  :func:`particle_replication.workflow.logged`.
- :func:`pool` holds the package's Python threads (the FMM beside its near field, the NumPy
  evaluations of the p-system's primitive split among threads), one pool per size, started on first use;
- :func:`threads_for` runs a kernel on the current threads only when its problem is at least a
  size where that pays off, and on one thread below it. Each kernel family keeps that size as
  one named constant next to its kernels (``PARALLEL_MIN_...``), measured by
  ``benchmarks/bench_threads.py``; below it a call is a fraction of a millisecond, and waking
  threads costs more than it saves, all the more when another process holds the other core.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import functools
import os

import numba

from .validation import integer_at_least

#: Environment variables read by OpenMP and BLAS libraries when they are loaded.
_LIBRARY_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def available() -> int:
    """The most threads this process may use: ``NUMBA_NUM_THREADS`` if set, else the cores."""
    return int(numba.config.NUMBA_NUM_THREADS)


def use_threads(count) -> int:
    """Run numba's kernels and the BLAS/OpenMP libraries on ``count`` >= 1 threads, at most
    :func:`available`; returns the count used. Libraries loaded later read it from the
    environment; those already loaded are set through threadpoolctl."""
    count = min(integer_at_least("threads", count, 1), available())
    numba.set_num_threads(count)
    for variable in _LIBRARY_VARIABLES:
        os.environ[variable] = str(count)
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=count)
    return count


@contextlib.contextmanager
def numba_threads(count: int):
    """Numba's kernels on ``count`` threads (at least 1, at most the current count) inside the block;
    the previous setting is restored on exit."""
    count = integer_at_least("count", count, 0)
    threads = numba.get_num_threads()
    numba.set_num_threads(max(1, min(count, threads)))
    try:
        yield
    finally:
        numba.set_num_threads(threads)


def threads_for(size, threshold):
    """Numba's current threads for a problem of at least ``threshold`` (particles, targets), one below it
    (a context manager, :func:`numba_threads`); both are non-negative integers."""
    size, threshold = integer_at_least("size", size, 0), integer_at_least("threshold", threshold, 0)
    return numba_threads(numba.get_num_threads() if size >= threshold else 1)


def pool(workers: int) -> concurrent.futures.ThreadPoolExecutor:
    """``workers`` >= 1 threads for work that releases the interpreter's lock (compiled kernels, NumPy's
    ufuncs), started on first use and kept for the process."""
    return _pool(integer_at_least("workers", workers, 1))


@functools.cache
def _pool(workers: int) -> concurrent.futures.ThreadPoolExecutor:
    return concurrent.futures.ThreadPoolExecutor(max_workers=workers, thread_name_prefix="particle-methods")
