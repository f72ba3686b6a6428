"""Numba settings for every compiled kernel of the package, set in one place."""

from __future__ import annotations

import functools
import hashlib
import os
import types
from pathlib import Path

import numba
from numba.core import sigutils
from numba.core.compiler_lock import global_compiler_lock

try:
    import fcntl
except ImportError:  # not POSIX: each process compiles for itself
    fcntl = None

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


#: The lock files this process holds, one per kernel being compiled (a kernel's compilation compiles the kernels
#: it calls, each under its own lock).
_HELD: set[str] = set()


def _compiled_once(dispatcher):
    """``dispatcher`` (a cached numba kernel), compiled by one process at a time: the first compilation of a
    signature holds a lock file beside the kernel's cache index (``<index>.lock``, ``fcntl.flock``), so that
    another process asking for the same kernel waits, then loads what the first one cached instead of
    compiling it again. Pipeline jobs and test workers that start together compiled the same kernels at
    once: in a cold quick run, 14 kernels were compiled in two jobs or more, and the lock took the compile
    time from 103 to 64 s of CPU (benchmarks/README.md). numba's own compiler lock is taken first, so
    threads of one process queue there and never hold one file lock each while waiting for the other's.
    Without a cache (``NUMBA_DISABLE_JIT``) or without ``fcntl`` (not POSIX), ``dispatcher`` is returned as
    it is."""
    index = getattr(getattr(getattr(dispatcher, "_cache", None), "_cache_file", None), "_index_path", None)
    if fcntl is None or index is None:
        return dispatcher
    compile_signature, lock = dispatcher.compile, f"{index}.lock"

    @functools.wraps(compile_signature)
    def compile_once(sig):
        arguments, _ = sigutils.normalize_signature(sig)
        if tuple(arguments) in dispatcher.overloads:
            return compile_signature(sig)
        with global_compiler_lock:
            if lock in _HELD:
                return compile_signature(sig)
            try:
                handle = open(lock, "a")  # closed by the with block below, after the lock is released
            except OSError:  # a cache directory we cannot write to: numba caches nothing there either
                return compile_signature(sig)
            with handle:
                try:
                    fcntl.flock(handle, fcntl.LOCK_EX)
                except OSError:  # a file system without locks: compile without one
                    return compile_signature(sig)
                _HELD.add(lock)
                try:
                    return compile_signature(sig)
                finally:
                    _HELD.discard(lock)
                    fcntl.flock(handle, fcntl.LOCK_UN)

    dispatcher.compile = compile_once
    return dispatcher


def njit(function=None, **overrides):
    """``numba.njit`` with the package's options, compiled by one process at a time
    (:func:`_compiled_once`); usable bare or with overrides."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: _compiled_once(numba.njit(**options)(f))
    return _compiled_once(numba.njit(**options)(function))


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
