"""Helpers for the pipeline scripts: logging to the rule's log, atomic result files checked where they are read
and at the start of every run, and the owners of Snakemake's locks."""

from __future__ import annotations

import ast
import atexit
import contextlib
import functools
import json
import math
import os
import socket
import sys
import time
import traceback
import zipfile
import zlib
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import NamedTuple

import numpy as np

from .registry import result


@contextlib.contextmanager
def logged(log_path, threads: int = 1, nudge=None):
    """Send stdout and stderr to ``log_path``, run the compiled kernels and numerical libraries on
    the job's ``threads`` (:func:`particle_methods.threads.use_threads`, clamped to what the
    process may use), and report the threads and the wall time. A data job passes the configuration's
    ``nudge`` ({ulps, seed}): its initial data are then moved by that many units in the last place
    (:mod:`particle_methods.perturbation`; 0 ulps: unchanged), as the robustness run's nudged variants ask.
    Yields the threads used."""
    # Imported here, not with the module: they load numba, which the workflow's start (every Snakemake run parses
    # this module) and the plot jobs do not need.
    from particle_methods import perturbation
    from particle_methods.threads import available, use_threads

    log_path = Path(log_path)
    log_path.parent.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    used = use_threads(threads)
    ulps, seed = (0, 0) if nudge is None else (nudge["ulps"], nudge["seed"])
    with log_path.open("w") as log, contextlib.redirect_stdout(log), contextlib.redirect_stderr(log), \
            perturbation.nudge(ulps, seed):
        print(f"threads: {used} (the job's {threads}, at most {available()} in this process)", flush=True)
        if ulps:
            print(f"initial data nudged by up to {ulps} units in the last place (seed {seed})", flush=True)
        try:
            yield used
        except BaseException:
            traceback.print_exc()
            raise
        print(f"wall time: {time.perf_counter() - start:.2f} s", flush=True)


def progress(message: str) -> None:
    """One line of progress in the rule's log."""
    print(message, file=sys.stdout, flush=True)


#: Runs longer than this many seconds are timed once: a repeat would only cost budget. Below it the
#: timer's resolution, an interrupt or a cache left cold by the previous run is a visible share of a run.
REPEAT_BELOW = 0.2

#: Most rounds of :func:`interleaved`: each round of runs shorter than REPEAT_BELOW costs up to that long per run.
MAX_REPEATS = 100


class Timings(NamedTuple):
    """What :func:`interleaved` measured of each run: its best time, its first round's result, its slowest time
    and how many times it was timed (1 for a run timed in the first round only)."""

    best: list
    results: list
    slowest: list
    count: list


def interleaved(runs, repeats: int, guard=None, repeat_below: float = REPEAT_BELOW) -> Timings:
    """The :class:`Timings` of the callables ``runs``, timed in ``repeats`` rounds over all of them, so that a
    passing disturbance of the machine hits every size alike rather than one; a run longer than
    ``repeat_below`` seconds (:data:`REPEAT_BELOW`; ``math.inf`` times every run in every round) is timed in the
    first round only. Its results are those of the first round; ``guard`` (a :class:`LoadGuard`) samples the
    load before every run. Compile and warm the kernels first: the first round is timed too. At most
    :data:`MAX_REPEATS` rounds."""
    if isinstance(repeats, bool) or not isinstance(repeats, int) or not 1 <= repeats <= MAX_REPEATS:
        raise ValueError(f"repeats must be an integer from 1 to MAX_REPEATS = {MAX_REPEATS}, got {repeats!r}")
    if isinstance(repeat_below, bool) or not isinstance(repeat_below, (int, float)) or not repeat_below > 0:
        raise ValueError(f"repeat_below must be a positive number of seconds, got {repeat_below!r}")
    best, slowest, results, count = [math.inf] * len(runs), [0.0] * len(runs), [None] * len(runs), [0] * len(runs)
    for round_ in range(repeats):
        for i, run in enumerate(runs):
            if round_ and best[i] >= repeat_below:
                continue
            if guard is not None:
                guard.sample()
            start = time.perf_counter()
            result = run()
            seconds = time.perf_counter() - start
            best[i], slowest[i], count[i] = min(best[i], seconds), max(slowest[i], seconds), count[i] + 1
            if not round_:
                results[i] = result
    return Timings(best, results, slowest, count)


#: A single-threaded timed run that got less than this share of a core's time was slowed by another process.
CPU_SHARE_MIN = 0.9


class LoadGuard:
    """Whether timed work had the machine to itself, measured while it runs (``with LoadGuard() as guard:``).

    Two readings: the share of a core the process got (its CPU time over the wall time; a single-threaded
    kernel with a core of its own gets all of it), and the processes the kernel shared the machine with,
    sampled from the run queue (``/proc/loadavg``; the one-minute load average elsewhere) at every
    :meth:`sample`. The timing is disturbed (:func:`disturbance` of its :meth:`readings`) when the share falls
    below :data:`CPU_SHARE_MIN` (single-threaded work only: ``threads`` = 1) or the other runnable processes, on
    average, left no core idle beside the timed work's threads (at least cores - threads of them, and at least
    half a process): a process
    on the other core shares the caches and the memory bandwidth, and moved a quick run's time exponent from
    1.1 to 0.79 while the tests ran beside it. A wall-time check then abstains.
    """

    def __init__(self, threads: int = 1):
        self.threads = threads
        self.others: list[float] = []
        self.cpu_share = math.nan
        self.cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1

    def sample(self) -> None:
        """Read how many other processes are runnable now."""
        try:
            running = int(Path("/proc/loadavg").read_text().split()[3].split("/")[0]) - 1  # ourselves aside
        except (OSError, IndexError, ValueError):
            running = os.getloadavg()[0] - 1.0 if hasattr(os, "getloadavg") else 0.0
        self.others.append(float(max(running, 0)))

    def __enter__(self):
        self.sample()
        self._cpu, self._wall = time.process_time(), time.perf_counter()
        return self

    def __exit__(self, *exc):
        wall = time.perf_counter() - self._wall
        self.cpu_share = (time.process_time() - self._cpu) / wall if wall > 0 else math.nan
        self.sample()
        return False

    @property
    def load(self) -> float:
        """The other runnable processes, on average over the samples."""
        return float(np.mean(self.others)) if self.others else math.nan

    def readings(self) -> dict:
        """The readings, to save beside the times: ``cpu_share``, ``load``, ``cores`` and ``threads``."""
        return {"cpu_share": self.cpu_share, "load": self.load, "cores": self.cores, "threads": self.threads}


def disturbance(readings) -> str:
    """Why a timing was disturbed, or '' if it was not: the rule of :meth:`LoadGuard.loaded` applied to its
    readings (a mapping with the keys of :meth:`LoadGuard.readings`, such as the result file they were saved in)."""
    cpu_share, load = float(readings["cpu_share"]), float(readings["load"])
    cores, threads = int(readings["cores"]), int(readings["threads"])
    reasons = []
    if threads == 1 and not cpu_share >= CPU_SHARE_MIN:
        reasons.append(f"the timed kernels got {cpu_share:.2f} of a core (at least {CPU_SHARE_MIN:g} alone)")
    if not load < max(cores - threads, 0.5):
        reasons.append(f"{load:.2g} other processes were runnable on average, beside {threads} timed thread(s) on "
                       f"{cores} cores")
    return " and ".join(reasons)


def save_results(path, **arrays) -> None:
    """Write ``arrays`` to an ``.npz`` file through a temporary file of this process's own, so that an
    interrupted run never leaves a truncated result behind and two jobs writing one result (a killed run's job
    still running beside its rerun) never write into one file. The zip file numpy writes records the CRC-32 of
    every array, which :func:`load_results` and :func:`damaged_results` check. A file the registry knows
    (:mod:`particle_replication.registry`) must hold exactly its declared keys."""
    _check_keys(path, arrays)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f"{path.name}.{socket.gethostname()}.{os.getpid()}.tmp")
    try:
        with temporary.open("wb") as handle:
            np.savez(handle, **arrays)
        os.replace(temporary, path)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise


def load_results(path, expect: dict | None = None) -> dict:
    """Load an ``.npz`` result file into a plain dictionary of arrays, checking every array against the CRC-32
    recorded when it was written (a truncated or altered file raises a ValueError naming it; the next Snakemake
    run rebuilds it, :func:`damaged_results`) and a registered file's keys against the registry (a file written
    by older code fails here, not later). ``expect`` maps keys to the values a job that reads an intermediate
    file requires of it (its case, its grid): a file that holds other values, made for another configuration,
    raises a ValueError naming the key."""
    if problem := damaged(path):
        raise ValueError(f"{path} is damaged ({problem}): the next snakemake run rebuilds it")
    with np.load(path) as data:
        _check_keys(path, data.files)
        results = {key: data[key] for key in data.files}
    for key, value in (expect or {}).items():
        if key not in results:
            raise ValueError(f"{path} holds no {key}, which its reader requires: rerun its rule")
        if not np.array_equal(results[key], np.asarray(value)):
            raise ValueError(f"{path} holds {key} = {results[key]!r}, not the {np.asarray(value)!r} of this "
                             "configuration: rerun its rule")
    return results


def damaged(path) -> str:
    """Why the result file ``path`` is damaged, or '' if it is whole: it must be a zip file whose every member
    (an array) reads back with the CRC-32 recorded when it was written. A truncated file has lost its zip
    directory, a changed byte fails its array's CRC; the whole file is read (about 1 GB/s)."""
    if not isinstance(path, str | os.PathLike):
        raise TypeError(f"path must be a path, got {type(path).__name__}")
    try:
        with zipfile.ZipFile(path) as archive:
            if not archive.namelist():
                return "it holds no array"
            if (name := archive.testzip()) is not None:
                return f"the CRC-32 of its array {name.removesuffix('.npy')} does not match"
    except (zipfile.BadZipFile, zipfile.LargeZipFile, OSError, EOFError, ValueError, NotImplementedError,
            RuntimeError, zlib.error) as error:
        return f"{type(error).__name__}: {error}"
    return ""


def damaged_results(root) -> dict[str, str]:
    """Every ``.npz`` file under the directory ``root`` (a run's ``results``) that is damaged, with why
    (:func:`damaged`). The workflow checks them at every start (0.1 s for the 105 MB of the full run's results
    once they are in the page cache, 0.5 s from disk) and reruns the jobs that write them: a file truncated or
    altered with its time kept would otherwise be taken as up to date."""
    root = Path(root)
    if root.exists() and not root.is_dir():
        raise ValueError(f"root must be a directory, got the file {root}")
    return {str(path): problem for path in sorted(root.rglob("*.npz")) if (problem := damaged(path))}


def missing_inputs(steps: Mapping[str, Iterable[str]]) -> dict[str, list[str]]:
    """Of the ``steps`` (each output file with the files it is computed from), the outputs that exist although
    some of their inputs do not, with those inputs. Snakemake takes such an output as up to date (a missing
    input it could rebuild is taken for a temporary file), so a result deleted after its tables were made is
    never rebuilt and the tables stay those of results that are gone."""
    if not isinstance(steps, Mapping):
        raise TypeError(f"steps must map each output to its inputs, got {type(steps).__name__}")
    found = {}
    for output, inputs in steps.items():
        if isinstance(inputs, str):
            raise TypeError(f"the inputs of {output} must be a list of paths, got the string {inputs!r}")
        if os.path.exists(output) and (gone := [path for path in inputs if not os.path.exists(path)]):
            found[output] = gone
    return found


def _check_keys(path, keys) -> None:
    entry = result(path)
    if entry is not None:
        entry.check_keys(keys)


def record_lock_owner(lockfiles) -> None:
    """Write beside each of Snakemake's lock files (``.snakemake/locks/<n>.input.lock`` and ``.output.lock``,
    which name the files a run holds but not the run) the process that holds them: this one, with its start
    time, process group and machine, which :func:`stale_locks` reads (the workflow calls it in ``onstart``)."""
    if isinstance(lockfiles, str | os.PathLike) or not isinstance(lockfiles, Iterable):
        raise TypeError(f"lockfiles must be a list of paths, got {type(lockfiles).__name__}")
    owner = {"pid": os.getpid(), "started": _started(os.getpid()), "group": os.getpgrp(),
             "host": socket.gethostname()}
    for lock in lockfiles:
        Path(f"{lock}.owner").write_text(json.dumps(owner))


def stale_locks(lockdir) -> tuple[list[Path], dict[int, int]]:
    """The lock files in ``lockdir`` whose Snakemake run is gone (killed: a run that ends removes its locks), and
    the runs that are gone while jobs they started still run, by process id with their process group.

    A lock counts only with an owner record (:func:`record_lock_owner`) of this machine; its run is gone when
    no process has its id, or a process has it that started at another time (the id was reused) or is a
    zombie. A run started as its process group's leader (from a shell, or in a session of its own) leaves
    its jobs in that group: while one of them runs, its lock is not stale, as the jobs still write outputs."""
    lockdir = Path(lockdir)
    if lockdir.exists() and not lockdir.is_dir():
        raise ValueError(f"lockdir must be a directory, got the file {lockdir}")
    stale, running = [], {}
    for record in sorted(lockdir.glob("*.lock.owner")):
        try:
            owner = json.loads(record.read_text())
            pid, group, started, host = owner["pid"], owner["group"], owner["started"], owner["host"]
        except (OSError, ValueError, KeyError, TypeError):
            continue  # being written, or not ours: Snakemake's own lock check decides
        lock = record.with_suffix("")
        if host != socket.gethostname() or _alive(pid, started) or not lock.exists():
            continue
        if group == pid and _group_running(group):
            running[pid] = group
        else:
            stale.append(lock)
    return stale, running


def _started(pid: int) -> str | None:
    """The start time of the process ``pid`` (in clock ticks since boot, from /proc) or None where there is no
    /proc or no such process."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[19]
    except (OSError, IndexError):
        return None


def _state(pid: int) -> str | None:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return None


def _alive(pid: int, started: str | None) -> bool:
    """Whether the process ``pid`` that started at ``started`` (:func:`_started`) still runs."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # another user's process has the id
    if _state(pid) == "Z":
        return False
    now = _started(pid)
    return started is None or now is None or now == started


def _group_running(group: int) -> bool:
    """Whether a process of the process group ``group`` runs (zombies aside, where /proc tells them)."""
    proc = Path("/proc")
    if not proc.is_dir():
        try:
            os.killpg(group, 0)
        except ProcessLookupError:
            return False
        except PermissionError:
            pass
        return True
    for stat in proc.glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if fields[2] == str(group) and fields[0] != "Z":
            return True
    return False


def module_dependencies(script, package_dirs) -> list[str]:
    """Source files of the packages that ``script`` imports, directly or through each other.

    ``package_dirs`` is a package directory or a list of them side by side (``src/particle_methods`` and
    ``src/particle_replication``). Rules list these files among their inputs so that editing a module
    reruns exactly the results computed with it. Absolute imports of the packages and relative imports
    inside them are followed; a package's ``__init__.py`` counts only when a name is imported from it
    (its re-exports are then followed too).
    """
    dirs = [Path(d).resolve() for d in ([package_dirs] if isinstance(package_dirs, str | Path) else package_dirs)]
    if not dirs or len({d.parent for d in dirs}) != 1:
        raise ValueError(f"package_dirs must be one or more package directories side by side, got {package_dirs}")
    found: set[Path] = set()
    pending = [Path(script).resolve()]
    scanned = _scan_cache(tuple(dirs))
    while pending:
        path = pending.pop()
        stamp = path.stat()
        key, version = scanned.key(path), [stamp.st_mtime_ns, stamp.st_size]
        entry = scanned.entries.get(key)
        if entry is None or entry[0] != version:
            entry = [version, [scanned.key(f) for f in _direct_dependencies(path, tuple(dirs))]]
            scanned.entries[key] = entry
            scanned.save_later()
        for candidate in map(scanned.path_of, entry[1]):
            if candidate not in found:
                found.add(candidate)
                pending.append(candidate)
    return sorted(str(path) for path in found)


#: Where a checkout keeps the imports its files were found to make, per version of each file, between processes
#: (relative to the checkout, beside Snakemake's own records): :func:`module_dependencies`.
SCAN_CACHE = Path(".snakemake") / "import-scan.json"


class _ScanCache:
    """The imports :func:`_direct_dependencies` found in each file, by path: [[modification time, size], files],
    read from and written to :data:`SCAN_CACHE` of the checkout, so that a Snakemake start parses only the files
    changed since the last one (reading every rule's modules took 0.4 of the 4 s of a start). An entry holds while
    its file keeps its time and size; the whole record holds while the packages hold the same module files (an
    import resolves to a module or a package's ``__init__`` by which files exist). Paths inside the checkout are
    kept relative to it, so that a copied checkout (file times kept) uses the record as it is, and the entries of
    files that no longer exist are dropped when the record is written. A record that cannot be read, or of another
    format, is ignored, one that cannot be written is not kept: the scan is then made anew."""

    #: The record's format: a record of another one is ignored (format 1 kept absolute paths).
    FORMAT = 2

    def __init__(self, dirs: tuple[Path, ...]):
        self.checkout = dirs[0].parent.parent
        self.path = self.checkout / SCAN_CACHE
        self.layout = sorted(str(f.relative_to(dirs[0].parent)) for d in dirs for f in d.rglob("*.py"))
        self.entries: dict[str, list] = {}
        self.pending = False
        try:
            record = json.loads(self.path.read_text())
            if record.get("format") == self.FORMAT and record.get("layout") == self.layout:
                self.entries = record["entries"]
        except (OSError, ValueError, TypeError, KeyError, AttributeError):
            pass

    def key(self, path: Path) -> str:
        """A file's key in the record: its path relative to the checkout, or absolute outside it."""
        return str(path.relative_to(self.checkout)) if path.is_relative_to(self.checkout) else str(path)

    def path_of(self, key: str) -> Path:
        """The file a key names (the inverse of :meth:`key`)."""
        return self.checkout / key

    def save_later(self) -> None:
        """Write the record when the process ends (once, whatever the number of files scanned)."""
        if not self.pending:
            self.pending = True
            atexit.register(self.save)

    def save(self) -> None:
        """Write the record atomically (a temporary file renamed: concurrent starts each leave a whole record)."""
        try:
            self.path.parent.mkdir(exist_ok=True)  # (not the checkout itself, if it is gone)
            temporary = self.path.with_name(f"{self.path.name}.{os.getpid()}.tmp")
            self.entries = {key: entry for key, entry in self.entries.items() if self.path_of(key).is_file()}
            temporary.write_text(json.dumps({"format": self.FORMAT, "layout": self.layout, "entries": self.entries}))
            os.replace(temporary, self.path)
        except OSError:
            pass
        self.pending = False


@functools.cache
def _scan_cache(dirs: tuple[Path, ...]) -> _ScanCache:
    """The record of :class:`_ScanCache` for the packages ``dirs``, read once per process."""
    return _ScanCache(dirs)


def _direct_dependencies(path: Path, dirs: tuple[Path, ...]) -> tuple[Path, ...]:
    """Source files of the packages in ``dirs`` that the file ``path`` imports itself. :func:`module_dependencies`
    parses each version of a file once (:class:`_ScanCache`, within a process and between them): every rule's code
    inputs share the modules, and parsing them again for each of the 75 rules took 4 s of every Snakemake start."""
    root, packages = dirs[0].parent, {d.name for d in dirs}
    tree = ast.parse(path.read_text(), filename=str(path))
    inside = any(path.is_relative_to(d) for d in dirs)
    here = path.relative_to(root).with_suffix("").parts if inside else ()
    files = []
    for node in _import_statements(tree):
        for parts, names in _imported(node, here):
            if parts and parts[0] in packages:
                files.extend(_module_files(root, parts, names))
    return tuple(files)


#: The fields of a statement that hold statements (bodies of functions, classes, branches, loops, handlers, cases).
_BODIES = ("body", "orelse", "finalbody", "handlers", "cases")


def _import_statements(tree: ast.AST):
    """The import statements of a module at any depth (inside functions, classes, branches), found by visiting
    statements only: imports are statements, and skipping the expressions visits a tenth of the nodes of
    ``ast.walk``."""
    pending = [tree]
    while pending:
        node = pending.pop()
        if isinstance(node, ast.Import | ast.ImportFrom):
            yield node
        for field in _BODIES:
            children = getattr(node, field, None)
            if isinstance(children, list):
                pending.extend(children)


def code_inputs(script, package_dirs) -> list[str]:
    """The modules a job's code inputs list: :func:`module_dependencies` of ``script`` but for the
    registry (:mod:`particle_replication.registry` of the checkout ``package_dirs`` belong to, not of the
    imported package: a copy of the repository would otherwise list its registry and replan every job),
    whose captions and parameters reach a job as its params, inputs and script, which Snakemake tracks,
    so that editing a caption reruns only the plot that shows it."""
    modules = module_dependencies(script, package_dirs)  # checks package_dirs: one or more, side by side
    first = package_dirs if isinstance(package_dirs, str | Path) else package_dirs[0]
    registry = (Path(first).resolve().parent / "particle_replication" / "registry")
    return [path for path in modules if not Path(path).is_relative_to(registry)]


def _imported(node, here):
    """(dotted module parts, imported names) for an import statement."""
    if isinstance(node, ast.Import):
        return [(tuple(alias.name.split(".")), ()) for alias in node.names]
    if isinstance(node, ast.ImportFrom):
        if node.level:
            # ``here`` ends with the module's own name (or "__init__"): drop it, then go up.
            base = here[: len(here) - node.level]
            parts = (*base, *(node.module.split(".") if node.module else ()))
        else:
            parts = tuple(node.module.split("."))
        return [(parts, tuple(alias.name for alias in node.names))]
    return []


def _module_files(root: Path, parts, names):
    base = root.joinpath(*parts)
    if base.with_suffix(".py").is_file():
        return [base.with_suffix(".py").resolve()]
    files = [(base / name).with_suffix(".py").resolve() for name in names
             if (base / name).with_suffix(".py").is_file()]
    if len(files) < len(names) and (base / "__init__.py").is_file():
        files.append((base / "__init__.py").resolve())
    return files
