"""Time the exact MSPD (sticky.mspd_exact) on the p-system cases: the current code against an older commit
of sticky/multitype_events.py, side by side in one run.

    python benchmarks/bench_mspd_exact.py [--sizes 800 3200] [--largest 20000] [--old-commit b351c67]

Both p-system cases of the pipeline (config sticky.psystem: rarefaction x0 = 0.1, shocks x0 = -4; nu = 0.5,
kappa = 5) at t = 2 (sticky.beyond.t), side by side in one run:
  - old: ``mspd_exact`` as of ``--old-commit``, read with ``git show`` and imported beside the package
         (compiled once in a temporary directory, outside the timings);
  - new: ``particle_methods.sticky.mspd_exact``;
at each of ``--sizes`` particles per type, then the new one alone at ``--largest``. Each row: best wall time of
``--repeats`` runs (one run from 10,000 particles on), the ratio old/new, the peak memory of one run
(resident memory sampled every millisecond from a thread, minus the resident memory before the call; and the
peak of NumPy's allocations by tracemalloc), the events, and the largest position difference old - new
relative to the largest |position|.

Issue 47 (default ``--old-commit`` b351c67, before it): the heap's times beside its ids and a table of the
primitive's values per difference of counts (the same events and positions, bit for bit). On an AMD EPYC
(AVX2, 2 cores, shared with other jobs), old and new alternating in one process (this script runs a size's
repeats of one, then of the other), best of 3 at n = 6400 per type, load average 2.0: rarefaction old
7.35 s, new 4.80 s (1.53 times faster; 1.8e7 crossings), shocks old 4.77 s, new 2.80 s (1.70 times; 1.3e7
crossings); at load 4.3 to 4.6, 1.49 and 1.67 times.

Issue 27 (``--old-commit 2c8f79b``: the velocity table of d (n+1)^d values, which refuses n > 4999, against
the primitive at the ranks each event needs). Measured before that change (2026-12-02, same machine, one run
each): old 0.336 s and 7.60 s (rarefaction, n = 800 and 3200), 0.222 s and 5.12 s (shocks); the table alone
took 2.8 s at n = 3200.
"""

import argparse
import ctypes
import importlib.util
import subprocess
import sys
import tempfile
import threading
import time
import tracemalloc
from pathlib import Path

import numpy as np
from timing import best_time, print_cpu

import particle_methods.sticky  # noqa: F401 (the parent package of the old module)
from particle_methods.sticky import mspd_exact
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.systems import PSystem

CASES = {"rarefaction": 0.1, "shocks": -4.0}
SYSTEM = PSystem(nu=0.5, kappa=5.0)
T = 2.0
OLD_PATH = "src/particle_methods/sticky/multitype_events.py"


def load_old(commit: str):
    """``mspd_exact`` as of ``commit``, imported as particle_methods.sticky.<module> (None if it cannot be)."""
    root = Path(__file__).resolve().parents[1]
    try:
        source = subprocess.run(["git", "show", f"{commit}:{OLD_PATH}"], cwd=root, check=True, capture_output=True,
                                text=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        print(f"old implementation not available ({error}): only the times measured before the change (docstring)")
        return None
    folder = Path(tempfile.gettempdir()) / f"bench_mspd_exact_{commit}"
    folder.mkdir(exist_ok=True)
    path = folder / "multitype_events_old.py"
    if not path.exists() or path.read_text() != source:
        path.write_text(source)
    name = "particle_methods.sticky.multitype_events_old"
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module.mspd_exact


def fixed_mmap_threshold() -> None:
    """Have glibc map every block above 128 kB and unmap it when freed: by default it raises that threshold
    after the old code frees its table, and later arrays then reuse resident heap pages (0 MB measured)."""
    try:
        ctypes.CDLL("libc.so.6").mallopt(-3, 128 * 1024)  # M_MMAP_THRESHOLD
    except (OSError, AttributeError):
        print("mallopt not available: resident peaks may be hidden by reused heap pages")


def resident_bytes() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def peak_memory(function):
    """(result, peak resident memory over the call minus that before it, peak of NumPy's allocations)."""
    before, peak, running = resident_bytes(), [0], [True]

    def sample():
        while running[0]:
            peak[0] = max(peak[0], resident_bytes())
            time.sleep(0.001)

    sampler = threading.Thread(target=sample)
    tracemalloc.start()
    sampler.start()
    try:
        result = function()
    finally:
        running[0] = False
        sampler.join()
        traced = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    return result, max(peak[0], resident_bytes()) - before, traced


def measure(run, x, repeats):
    """(best seconds of 1 + repeats runs, configuration, events, resident peak, traced peak) of run(x): the
    first run is the one whose memory is measured."""
    start = time.perf_counter()
    (state, events), resident, traced = peak_memory(lambda: run(x, SYSTEM, [T], return_events=True))
    seconds = time.perf_counter() - start
    for _ in range(repeats):
        start = time.perf_counter()
        run(x, SYSTEM, [T], return_events=True)
        seconds = min(seconds, time.perf_counter() - start)
    return seconds, state[0], events, resident, traced


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[800, 3200])
    parser.add_argument("--largest", type=int, default=20000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--old-commit", default="b351c67")
    args = parser.parse_args()
    print_cpu()
    fixed_mmap_threshold()
    old = load_old(args.old_commit)
    small = psystem_initial_configuration("shocks", CASES["shocks"], 20)
    for run in (mspd_exact, old):
        if run is not None:
            best_time(lambda run=run: run(small, SYSTEM, [T]), 1)  # compile or load the caches
    print(f"{'case':12} {'n':>6} {'old [s]':>9} {'new [s]':>9} {'old/new':>8} {'old MB':>8} {'new MB':>8} "
          f"{'old np MB':>10} {'new np MB':>10} {'crossings':>10} {'max |diff|/max|x|':>18}")
    for case, x0 in CASES.items():
        for n in [*args.sizes, args.largest]:
            x = psystem_initial_configuration(case, x0, n)
            repeats = args.repeats - 1 if n < 10_000 else 0
            new_s, new_x, events, new_rss, new_np = measure(mspd_exact, x, repeats)
            if old is not None and n in args.sizes:
                old_s, old_x, old_events, old_rss, old_np = measure(old, x, repeats)
                assert old_events == events, (old_events, events)
                difference = np.abs(old_x - new_x).max() / np.abs(old_x).max()
            else:
                old_s = old_rss = old_np = difference = np.nan
            print(f"{case:12} {n:6d} {old_s:9.3f} {new_s:9.3f} {old_s / new_s:8.2f} {old_rss / 1e6:8.1f} "
                  f"{new_rss / 1e6:8.1f} {old_np / 1e6:10.1f} {new_np / 1e6:10.1f} {events.crossings:10.3g} "
                  f"{difference:18.2e}", flush=True)


if __name__ == "__main__":
    main()
