"""Time the exact MSPD at one time over the grid of crossings (sticky.mspd_exact_at) against the event loop
(sticky.mspd_exact) on the p-system cases, side by side in one run.

    python benchmarks/bench_mspd_grid.py [--sizes 1600 6400] [--largest 25600] [--repeats 2]

Both p-system cases of the pipeline (rarefaction x0 = 0.1, shocks x0 = -4; nu = 0.5, kappa = 5) at t = 2, as
the cost study's reference (scripts/sticky/beyond_reference.py) runs them. At each of ``--sizes`` particles per
type: the best wall time of the event loop and of ``mspd_exact_at`` (1 + ``--repeats`` runs each, alternating),
their ratio, the method ``mspd_exact_at`` used ("grid", or "events" where particles of one type meet: the
shock case) and whether the two configurations are the same bit for bit. At ``--largest`` (the reference's
size) ``mspd_exact_at`` alone, once: the event loop takes minutes there (the pipeline's job: 220 to 312 s).
"""

import argparse
import time

import numpy as np
from timing import print_cpu

from particle_methods.sticky import mspd_exact, mspd_exact_at
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.systems import PSystem

CASES = {"rarefaction": 0.1, "shocks": -4.0}
SYSTEM = PSystem(nu=0.5, kappa=5.0)
T = 2.0


def best(run, repeats):
    """(best seconds of 1 + repeats calls of run, the last result)."""
    seconds, result = np.inf, None
    for _ in range(1 + repeats):
        start = time.perf_counter()
        result = run()
        seconds = min(seconds, time.perf_counter() - start)
    return seconds, result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[1600, 6400])
    parser.add_argument("--largest", type=int, default=25600)
    parser.add_argument("--repeats", type=int, default=2)
    args = parser.parse_args()
    print_cpu()
    for case, x0 in CASES.items():  # compile or load the caches, outside the timings
        small = psystem_initial_configuration(case, x0, 20)
        mspd_exact(small, SYSTEM, [T]), mspd_exact_at(small, SYSTEM, T)
    print(f"{'case':12} {'n':>6} {'events [s]':>11} {'grid [s]':>9} {'ratio':>7} {'method':>7} {'identical':>10}")
    for case, x0 in CASES.items():
        for n in [*args.sizes, args.largest]:
            x = psystem_initial_configuration(case, x0, n)
            grid_s, (grid, method) = best(lambda x=x: mspd_exact_at(x, SYSTEM, T, return_method=True),
                                          args.repeats if n in args.sizes else 0)
            if n in args.sizes:
                events_s, events = best(lambda x=x: mspd_exact(x, SYSTEM, [T])[0], args.repeats)
                identical = str(np.array_equal(events, grid))
            else:
                events_s, identical = np.nan, "-"
            print(f"{case:12} {n:6d} {events_s:11.3f} {grid_s:9.3f} {events_s / grid_s:7.1f} {method:>7} "
                  f"{identical:>10}", flush=True)


if __name__ == "__main__":
    main()
