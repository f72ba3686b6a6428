"""Section 5.1.1 and 5.2.1: the cost of the compiled kernels against the problem size.

Each size runs once untimed, then is timed ``repeats`` times and the best time kept (the least
disturbed by the machine) when a run is shorter than REPEAT_BELOW (0.2 s), else once; the rule runs
alone on the cores it asks for. The kernels are called directly, past the input
checks of the public functions, so that the time measured is the algorithm's.

The iterated TSPD allocates NumPy temporaries of up to 32 n bytes per step. glibc serves large
blocks by mmap, whose pages fault on first touch, and raises its mmap threshold (up to 32 MB) each
time such a block is freed, so whether a size pays the page faults depended on what ran before it:
a window of 1e5..1e6 measured 1.27 in one run (1e6 was page-faulting, the smaller sizes were not)
and about 0.07 us per particle and step at every size when run alone (measured 2026-11-23). Fixing
the thresholds at the start serves every block from the heap, so that all sizes are timed alike.
"""

import ctypes
import ctypes.util

import numpy as np

from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_positions, ranks_kernel
from particle_methods.sticky.spd import hull_positions_kernel
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results, timed


def fixed_allocator():
    """Serve every allocation from the heap and never trim it (glibc's mallopt); False elsewhere."""
    name = ctypes.util.find_library("c")
    libc = ctypes.CDLL(name) if name else None
    if libc is None or not hasattr(libc, "mallopt"):
        return False
    m_trim_threshold, m_mmap_threshold = -1, -3
    large = 2**30
    return bool(libc.mallopt(m_mmap_threshold, large)) and bool(libc.mallopt(m_trim_threshold, large))


def best_time(function, args, repeats):
    """Seconds of ``function(*args)`` after one untimed call (compilation, first touch of the
    memory): the best of ``repeats`` runs below REPEAT_BELOW seconds, else one run
    (:func:`particle_replication.workflow.timed`, the rule of every timed study)."""
    function(*args)
    return timed(lambda: function(*args), repeats)[0]


def run(p, output):
    progress("heap-only allocator: " + ("yes" if fixed_allocator() else "no (not glibc): timings include page faults"))
    rng = np.random.default_rng(0)
    repeats = p["repeats"]
    hull, free = [], []
    for n in p["hull_n"]:
        x = np.sort(rng.normal(size=n))
        out = np.empty(n)
        hull.append(best_time(hull_positions_kernel, (x, rng.normal(size=n), 1.0, out), repeats))
        # Increasing velocities: no collision, every point stays on the hull (the stack grows to n).
        free.append(best_time(hull_positions_kernel, (x, np.sort(rng.normal(size=n)), 1.0, out), repeats))
        progress(f"hull pass, n = {n}: {hull[-1]:.3g} s random, {free[-1]:.3g} s without collision")
    ranks = []
    for n in p["rank_n"]:
        x = np.sort(rng.normal(size=(2, n)), axis=1)
        ranks.append(best_time(ranks_kernel, (x,), repeats))
        progress(f"rank step (d = 2), n = {n}: {ranks[-1]:.3g} s")
    system = PSystem()
    tspd = []
    for n in p["tspd_n"]:
        x0 = psystem_initial_configuration("rarefaction", 0.1, n)
        tspd.append(best_time(mspd_positions, (x0, system, 0.01, p["tspd_steps"]), repeats))
        progress(f"iterated TSPD, n = {n}, {p['tspd_steps']} steps: {tspd[-1]:.3g} s")
    steps = []
    x0 = psystem_initial_configuration("rarefaction", 0.1, p["steps_n"])
    for count in p["steps_values"]:
        steps.append(best_time(mspd_positions, (x0, system, 0.001, count), repeats))
        progress(f"iterated TSPD, n = {p['steps_n']}, {count} steps: {steps[-1]:.3g} s")
    save_results(output, hull_n=np.asarray(p["hull_n"]), hull_times=np.array(hull), hull_free_times=np.array(free),
                 rank_n=np.asarray(p["rank_n"]), rank_times=np.array(ranks),
                 tspd_n=np.asarray(p["tspd_n"]), tspd_times=np.array(tspd), tspd_steps=p["tspd_steps"],
                 steps_values=np.asarray(p["steps_values"]), steps_times=np.array(steps), steps_n=p["steps_n"])


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
