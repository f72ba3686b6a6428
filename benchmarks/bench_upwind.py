"""Time the upwind scheme for the diagonal system (1.7) (finite_volume.upwind_diagonal) on the p-system cases: the
Python time loop (any diagonal system) against the compiled one of a PSystem, on one thread and on ``--threads``.

    python benchmarks/bench_upwind.py [--sizes 4000 16000 64000] [--python-limit 60] [--repeats 3] [--threads 2]

Both p-system cases of the pipeline (config sticky.psystem: rarefaction x0 = 0.1, shocks x0 = -4; nu = 0.5,
kappa = 5) at t = 2 on [-30, 30] with cfl 0.9 (sticky.beyond), from the exact cell averages of
``psystem_initial_cells``, side by side in one run:
  - python:   ``upwind_diagonal`` on a system that delegates ``speed_primitive`` to the PSystem (not a PSystem
              itself, so it takes the Python path: the primitive called from Python at every step);
  - compiled: ``upwind_diagonal`` on the PSystem (the time loop compiled, the primitive evaluated by NumPy);
at each of ``--sizes`` cells. Each row: the best wall time of ``--repeats`` runs (one run from 16000 cells on),
the ratio, the time per type-cell update, the steps of both paths and the largest difference of the results
relative to the largest |w|; then the compiled path with its primitive split among ``--threads`` threads (the
pipeline's upwind references take every core), its speed-up over one thread and whether its result is the same to
the last bit. The Python path is skipped at a size where its time extrapolated from the previous
size (x 16: cells and steps both scale with the size) exceeds ``--python-limit`` seconds (0: never run).

Measured before the change (2026-12-02, same machine): the Python path took 2.7 s on 16,000 cells and 42 s on
64,000 cells. With it (one run, rarefaction / shocks): python 2.13 / 1.95 s and 34.6 / 33.2 s, compiled 0.37 /
0.29 s and 4.8 / 4.8 s on 16,000 and 64,000 cells (37 against 5 ns per type-cell update), the same steps (1799,
7196) and the same numbers to the last bit.
"""

import argparse
import time

import numpy as np
from timing import print_cpu

from particle_methods.finite_volume.psystem import upwind_diagonal
from particle_methods.sticky.cases import psystem_initial_cells
from particle_methods.systems import PSystem

CASES = {"rarefaction": 0.1, "shocks": -4.0}
SYSTEM = PSystem(nu=0.5, kappa=5.0)
T, DOMAIN, CFL = 2.0, (-30.0, 30.0), 0.9


class PythonPath:
    """The PSystem's primitive behind an object that is not a PSystem: upwind_diagonal's Python time loop."""

    d = SYSTEM.d

    def speed_primitive(self, gamma, levels):
        return SYSTEM.speed_primitive(gamma, levels)


def timed(system, w0, edges, repeats, threads=1):
    """(best seconds of ``repeats`` runs, result, steps)."""
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        w, steps = upwind_diagonal(system, w0, edges, T, CFL, return_steps=True, threads=threads)
        best = min(best, time.perf_counter() - start)
    return best, w, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[4000, 16000, 64000])
    parser.add_argument("--python-limit", type=float, default=60.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    print_cpu()
    small = np.linspace(*DOMAIN, 101)
    upwind_diagonal(SYSTEM, psystem_initial_cells("shocks", CASES["shocks"], small), small, T, CFL)  # compile or load
    print(f"{'case':12} {'cells':>6} {'python [s]':>11} {'compiled [s]':>13} {'ratio':>7} {'python ns':>10} "
          f"{'compiled ns':>12} {'steps':>12} {'max |diff|/max|w|':>18} {f'{args.threads} threads [s]':>14} "
          f"{'speed-up':>9} {'same bits':>10}")
    for case, x0 in CASES.items():
        estimate, previous = 0.0, None  # the Python path's time expected at the next size
        for cells in sorted(args.sizes):
            edges = np.linspace(*DOMAIN, cells + 1)
            w0 = psystem_initial_cells(case, x0, edges)
            repeats = args.repeats if cells < 16000 else 1
            compiled_s, compiled, steps = timed(SYSTEM, w0, edges, repeats)
            if previous is not None:
                estimate = previous[1] * (cells / previous[0]) ** 2
            if estimate < args.python_limit:  # --python-limit 0: the compiled path alone
                python_s, python, python_steps = timed(PythonPath(), w0, edges, repeats)
                difference = np.abs(compiled - python).max() / np.abs(python).max()
                previous = cells, python_s
            else:
                print(f"(python path skipped at {cells} cells: about {estimate:.0f} s expected)")
                python_s = python_steps = difference = np.nan
            threaded_s, threaded, _ = timed(SYSTEM, w0, edges, repeats, args.threads)
            updates = 2 * cells * steps
            print(f"{case:12} {cells:6d} {python_s:11.3f} {compiled_s:13.3f} {python_s / compiled_s:7.2f} "
                  f"{python_s / updates * 1e9:10.1f} {compiled_s / updates * 1e9:12.1f} "
                  f"{f'{python_steps}/{steps}':>12} {difference:18.2e} {threaded_s:14.3f} "
                  f"{compiled_s / threaded_s:9.2f} {str(np.array_equal(threaded, compiled)):>10}", flush=True)


if __name__ == "__main__":
    main()
