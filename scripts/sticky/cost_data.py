"""Sections 5.1.1 and 5.2.1: the work of the compiled kernels against the problem size.

Every kernel counts its operations as it makes them (the hull's tests, pops, pushes and writes, the rank
step's examined heads and written entries, summed over the steps of the iterated TSPD): the cost claims
are decided on those counts, which no machine changes. The same runs are also timed, for a wall-time check
only: each size runs once untimed (compilation, and the first touch of its memory), then the sizes are timed
in turn, ``repeats`` rounds over all of them, every run in every round, keeping each size's best time
(:func:`~particle_replication.workflow.interleaved`). The runs are kept short (one TSPD step per run at the
largest sizes, under a second), so that each size has many rounds: on a shared virtual machine the speed
drifts by 20 to 45 % over seconds while no other process runs here, and a size timed in one long round took
that drift into the exponent. A :class:`~particle_replication.workflow.LoadGuard`
records whether the timed kernels had a core to themselves, and the CPU is recorded beside the times. The
kernels are called directly, past the input checks of the public functions, so that what is measured is the
algorithm's.

The iterated TSPD allocates NumPy temporaries of up to 32 n bytes per step. glibc serves large
blocks by mmap, whose pages fault on first touch, and raises its mmap threshold (up to 32 MB) each
time such a block is freed, so whether a size pays the page faults depends on what ran before it.
Fixing the thresholds at the start serves every block from the heap, so that all sizes are timed alike.
"""

import ctypes
import ctypes.util
import math

import numpy as np

from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_positions, ranks_kernel
from particle_methods.sticky.spd import hull_positions_kernel
from particle_methods.systems import PSystem
from particle_replication.environment import cpu
from particle_replication.workflow import LoadGuard, interleaved, logged, progress, save_results


def fixed_allocator():
    """Serve every allocation from the heap and never trim it (glibc's mallopt); False elsewhere."""
    name = ctypes.util.find_library("c")
    libc = ctypes.CDLL(name) if name else None
    if libc is None or not hasattr(libc, "mallopt"):
        return False
    m_trim_threshold, m_mmap_threshold = -1, -3
    large = 2**30
    return bool(libc.mallopt(m_mmap_threshold, large)) and bool(libc.mallopt(m_trim_threshold, large))


def run(p, output):
    progress("heap-only allocator: " + ("yes" if fixed_allocator() else "no (not glibc): timings include page faults"))
    rng = np.random.default_rng(0)
    system = PSystem()
    series = {name: [] for name in ("hull", "hull_free", "rank", "tspd", "steps")}  # the runs of each

    def add(name, function, *args):
        function(*args)  # untimed: compiles the kernel, and touches the memory of this size first
        series[name].append(lambda: function(*args)[1])  # the operations it counted

    for n in p["hull_n"]:
        x = np.sort(rng.normal(size=n))
        out = np.empty(n)
        add("hull", hull_positions_kernel, x, rng.normal(size=n), 1.0, out)
        # Increasing velocities: no collision, every point stays on the hull (the stack grows to n).
        add("hull_free", hull_positions_kernel, x, np.sort(rng.normal(size=n)), 1.0, out)
    for n in p["rank_n"]:
        add("rank", ranks_kernel, np.sort(rng.normal(size=(2, n)), axis=1))
    for n in p["tspd_n"]:
        add("tspd", mspd_positions, psystem_initial_configuration("rarefaction", 0.1, n), system, 0.01,
            p["tspd_steps"], True)
    x0 = psystem_initial_configuration("rarefaction", 0.1, p["steps_n"])
    for count in p["steps_values"]:
        add("steps", mspd_positions, x0, system, 0.001, count, True)
    with LoadGuard() as guard:
        seconds, counted = interleaved([run for runs in series.values() for run in runs], p["repeats"], guard,
                                      repeat_below=math.inf)
    seconds, counted = iter(seconds), iter(counted)
    times = {name: np.array([next(seconds) for _ in runs]) for name, runs in series.items()}
    operations = {name: np.array([next(counted) for _ in runs], dtype=np.int64) for name, runs in series.items()}
    for name in series:
        progress(f"{name}: operations {operations[name].tolist()}, best times {np.round(times[name], 5).tolist()} s")
    progress(f"CPU {cpu()}; the timed kernels got {guard.cpu_share:.2f} of a core, {guard.load:.2g} other processes "
             "runnable on average")
    save_results(output, hull_n=np.asarray(p["hull_n"]), hull_operations=operations["hull"],
                 hull_free_operations=operations["hull_free"], hull_times=times["hull"],
                 hull_free_times=times["hull_free"], rank_n=np.asarray(p["rank_n"]), rank_operations=operations["rank"],
                 rank_times=times["rank"], tspd_n=np.asarray(p["tspd_n"]), tspd_operations=operations["tspd"],
                 tspd_times=times["tspd"], tspd_steps=p["tspd_steps"], steps_values=np.asarray(p["steps_values"]),
                 steps_operations=operations["steps"], steps_times=times["steps"], steps_n=p["steps_n"], cpu=cpu(),
                 **guard.readings())


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
