"""Numba settings for every compiled kernel of the package, set in one place."""

from __future__ import annotations

import functools
import hashlib
import os
import types
from pathlib import Path

import numba

# numba's threading layer is GNU OpenMP here (no TBB): its threads spin at every barrier before they sleep.
# With two processes on two cores, a spinning thread holds the core the other process's thread needs, and
# a parallel call of a fraction of a millisecond took 24 ms (a time slice; benchmarks/bench_threads.py).
# Passive threads sleep at once. Read when the OpenMP library starts, at the first parallel call; a value
# the user set is kept.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

#: Where the package's numba caches are stamped with the sources they were compiled from.
SOURCES_STAMP = Path(__file__).parent / "__pycache__" / "numba-sources.sha256"


def sources_digest(root: Path = Path(__file__).parent) -> str:
    """SHA-256 of every Python source of the package (paths and contents)."""
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def clear_stale_caches(root: Path = Path(__file__).parent, stamp: Path = SOURCES_STAMP) -> bool:
    """Remove the package's numba caches (``__pycache__/*.nbi``, ``*.nbc``) if any source changed since
    they were written; returns whether it did.

    numba keys a cached kernel by the modification time and size of the file that defines it only: a
    kernel that calls a compiled function of another module keeps its old machine code when only that
    module changes (a flux formula edited in ``sticky/exact.py`` left ``finite_volume``'s cached scheme
    unchanged). One digest of all sources makes any edit recompile everything once."""
    digest = sources_digest(root)
    try:
        if stamp.read_text() == digest:
            return False
    except OSError:
        pass
    for cache in [*root.rglob("__pycache__/*.nbi"), *root.rglob("__pycache__/*.nbc")]:
        cache.unlink(missing_ok=True)
    try:
        stamp.parent.mkdir(exist_ok=True)
        temporary = stamp.with_name(f"{stamp.name}.{os.getpid()}")
        temporary.write_text(digest)
        temporary.replace(stamp)
    except OSError:  # a read-only installation: numba then keeps its caches elsewhere
        pass
    return True


clear_stale_caches()

#: Options passed to :func:`numba.njit` for every kernel. ``cache=True`` keeps the
#: compiled machine code on disk so that pipeline steps do not pay the JIT again.
JIT_OPTIONS = {"cache": True, "nogil": True, "error_model": "numpy"}

#: Overrides for a kernel that allocates nothing (``@njit(**NO_RUNTIME)``): compiled without numba's runtime
#: (NRT, numba's private option ``_nrt``), it keeps no reference counts. With the runtime, every array passed
#: to a helper is counted in and out by atomic operations: half the time of the MSPD's event loop
#: (``sticky/multitype_events.py``, 2.4 times faster without). Such a kernel cannot create an array
#: (``np.empty``, nor a copy between slices, which may need a temporary): its caller passes every one.
NO_RUNTIME = {"_nrt": False}


def njit(function=None, **overrides):
    """``numba.njit`` with the package's options; usable bare or with overrides."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: numba.njit(**options)(f)
    return numba.njit(**options)(function)


def njit_threaded(function):
    """A kernel whose outer loop is a ``prange``, compiled twice from the same source: with
    ``parallel=True``, run when numba has more than one thread, and without it (the ``prange`` runs as a
    ``range``), run on one thread. The serial variant compiles about twice as fast, costs no thread launch
    per call, and is all that a one-thread pipeline job ever compiles. Both variants compute the same
    numbers: the kernels give every thread fixed accumulators summed in a fixed order.

    The serial variant is a copy of the function named ``<name>_serial``, so that numba files its cache
    apart from the parallel one (numba keys a cache by the function's qualified name and line)."""
    parallel = njit(parallel=True)(function)
    copy = types.FunctionType(function.__code__.replace(co_name=f"{function.__name__}_serial"), function.__globals__,
                              f"{function.__name__}_serial", function.__defaults__, function.__closure__)
    copy.__qualname__ = f"{function.__qualname__}_serial"
    copy.__module__ = function.__module__
    serial = njit(copy)

    @functools.wraps(function)
    def kernel(*arguments):
        return (parallel if numba.get_num_threads() > 1 else serial)(*arguments)

    kernel.parallel, kernel.serial = parallel, serial
    return kernel
