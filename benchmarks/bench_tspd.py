"""Iterated TSPD on the p-system: the compiled steps against the Python loop, side by side.

    python benchmarks/bench_tspd.py

For the data of section 5.2.2 (both cases) with L = n steps of t/n up to t = 2, as the cost study of
section 5.2 runs them, times mspd_positions for a PSystem (its compiled steps, mspd._tspd_psystem_kernel)
and for a PSystem subclass (the Python loop over _tspd_step, the path of any other diagonal system), checks
that both give the same positions to the bit, and prints the ratio.
"""

import numpy as np
from timing import best_time, print_cpu

from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.systems import PSystem


class PythonLoop(PSystem):
    """A subclass, which mspd_positions runs through its Python loop."""


def main():
    print_cpu()
    compiled, python = PSystem(), PythonLoop()
    print(f"{'case':>12} {'n':>6} {'compiled [s]':>13} {'Python [s]':>11} {'ratio':>6}")
    for case, x0 in (("rarefaction", 0.1), ("shocks", -4.0)):
        for n in (100, 400, 1600, 6400):
            x = psystem_initial_configuration(case, x0, n)
            fast, a = best_time(lambda x=x, n=n: mspd_positions(x, compiled, 2.0 / n, n))
            slow, b = best_time(lambda x=x, n=n: mspd_positions(x, python, 2.0 / n, n), repeats=1 if n > 1600 else 3)
            assert np.array_equal(a, b), "the compiled steps must give the Python loop's positions"
            print(f"{case:>12} {n:>6} {fast:>13.4g} {slow:>11.4g} {slow / fast:>6.2f}")


if __name__ == "__main__":
    main()
