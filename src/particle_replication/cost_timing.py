"""The sticky cost study's runs (sections 5.1.1 and 5.2.1), counted and timed in several processes.

Every kernel counts its operations as it makes them (the hull's tests, pops, pushes and writes, the rank
step's examined heads and written entries, summed over the steps of the iterated TSPD): the cost claims
are decided on those counts, which no machine changes. The same runs are also timed, for a wall-time check
only. One process's measurement (:func:`measure`) runs each size once untimed (compilation, and the first touch
of its memory), then times the sizes in turn, ``repeats`` rounds over all of them, every run in every round,
keeping each size's best time (:func:`~particle_replication.workflow.interleaved`), under a
:class:`~particle_replication.workflow.LoadGuard`. The kernels are called directly, past the input checks of
the public functions, so that what is measured is the algorithm's.

:func:`replicated` makes that measurement in ``processes`` processes, one after another. On a shared virtual
machine one size can run 20 to 45 % slower in every round of one process and not in the next (an effect of
where that process's memory lies, which no number of rounds removes; config/changes.yaml), so the exponents
of separate processes are the replicates from which the wall-time check tells whether the machine's speed let
it decide (:func:`particle_replication.verdicts.sticky.cost_claims`).

The iterated TSPD allocates NumPy temporaries of up to 32 n bytes per step. glibc serves large blocks by mmap,
whose pages fault on first touch, and raises its mmap threshold (up to 32 MB) each time such a block is freed,
so whether a size pays the page faults depends on what ran before it. Fixing the thresholds at the start of
each process serves every block from the heap, so that all sizes are timed alike.

Run as ``python -m particle_replication.cost_timing``, it reads one measurement's arguments as JSON on stdin and
writes its result as JSON on stdout.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import json
import math
import subprocess
import sys

import numpy as np

from particle_methods import perturbation
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_positions, ranks_kernel
from particle_methods.sticky.spd import hull_positions_kernel
from particle_methods.systems import PSystem
from particle_methods.validation import integer_at_least

from .workflow import LoadGuard, interleaved

#: The timed series, in the order they run: the hull pass (random data, then with no collision), the rank step, the
#: iterated TSPD against n and against its number of steps.
SERIES = ("hull", "hull_free", "rank", "tspd", "steps")


def fixed_allocator() -> bool:
    """Serve every allocation from the heap and never trim it (glibc's mallopt); False elsewhere."""
    name = ctypes.util.find_library("c")
    libc = ctypes.CDLL(name) if name else None
    if libc is None or not hasattr(libc, "mallopt"):
        return False
    m_trim_threshold, m_mmap_threshold = -1, -3
    large = 2**30
    return bool(libc.mallopt(m_mmap_threshold, large)) and bool(libc.mallopt(m_trim_threshold, large))


def measure(p, ulps: int = 0, seed: int = 0) -> dict:
    """One process's measurement with the cost section ``p`` of the config (its sizes, ``tspd_steps``,
    ``steps_n`` and ``repeats``), the initial data nudged by ``ulps`` (:mod:`particle_methods.perturbation`):
    {"times": name -> best seconds per size, "operations": name -> counted operations per size, "readings": the
    load guard's, "allocator": whether every block came from the heap}."""
    repeats = integer_at_least("repeats", p["repeats"], 1)
    allocator = fixed_allocator()
    rng = np.random.default_rng(0)
    system = PSystem()
    series = {name: [] for name in SERIES}  # the runs of each

    def add(name, function, *args):
        function(*args)  # untimed: compiles the kernel, and touches the memory of this size first
        series[name].append(lambda: function(*args)[1])  # the operations it counted

    with perturbation.nudge(ulps, seed):
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
        timed = interleaved([run for runs in series.values() for run in runs], repeats, guard, repeat_below=math.inf)
    seconds, counted = iter(timed.best), iter(timed.results)
    times = {name: [next(seconds) for _ in runs] for name, runs in series.items()}
    operations = {name: [int(next(counted)) for _ in runs] for name, runs in series.items()}
    return {"times": times, "operations": operations, "readings": guard.readings(), "allocator": allocator}


def replicated(p, processes, ulps: int = 0, seed: int = 0) -> list[dict]:
    """:func:`measure` in ``processes`` processes, one after another: this one first, then each in a fresh
    interpreter (``python -m particle_replication.cost_timing``), so that no two share their memory. Every
    process runs the same data (the same sizes, draws and nudge) and must count the same operations."""
    processes = integer_at_least("processes", processes, 1)
    request = json.dumps({"p": p, "ulps": ulps, "seed": seed})
    made = [measure(p, ulps, seed)]
    for _ in range(processes - 1):
        result = subprocess.run([sys.executable, "-m", __name__], input=request, capture_output=True, text=True,
                                check=False)
        if result.returncode:
            raise RuntimeError(f"a timing process failed:\n{result.stderr[-3000:]}")
        made.append(json.loads(result.stdout))
        if made[-1]["operations"] != made[0]["operations"]:
            raise RuntimeError(f"two processes counted different operations on the same data: "
                               f"{made[0]['operations']} and {made[-1]['operations']}")
    return made


if __name__ == "__main__":
    json.dump(measure(**json.loads(sys.stdin.read())), sys.stdout)
