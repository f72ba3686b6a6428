"""Remark 3.3 with many particles: the Godunov-to-SPD distance on grids finer than the pipeline's.

Remark 3.3 itself is tested exactly by the pipeline (``sticky.remark33.concave``: the SPD against
Hopf's formula for the entropy solution of the same atoms); the Godunov comparison is the check
``sticky.remark33.godunov_refinement``, whose distance falls slowly at n = 256 because a first-order
scheme needs a very fine grid to resolve shocks of strength 1/n. This script continues the refinement
(about three minutes on 2 cores) and prints the distance and the pairwise order per doubling,
which should rise towards 1.

    python benchmarks/remark33_refinement.py [n] [t]
"""

import math
import sys
import time

import numpy as np
from timing import print_cpu

from particle_methods.finite_volume.fluxes import CONCAVE
from particle_methods.finite_volume.grids import cell_averages_of_step_cdf, l1_distance_to_step_cdf
from particle_methods.finite_volume.scalar import godunov
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.spd import spd_positions


def main(n=256, t=1.0, cells_per_unit=(1600, 3200, 6400, 12800, 25600)):
    x, v = SCALAR_CASES["concave_laplace"].initial_state(n)
    positions = spd_positions(x, v, t)
    previous = None
    print_cpu()
    print(f"n = {n}, t = {t:g}\ncells per unit | distance | pairwise order | seconds")
    for count in cells_per_unit:
        left = math.ceil((1.0 - min(x[0], positions[0])) * count)  # a cell edge at x = 0, as in the pipeline
        right = math.ceil((max(x[-1], positions[-1]) + 1.0) * count)
        edges = np.arange(-left, right + 1) / count
        start = time.perf_counter()
        values = godunov(CONCAVE, cell_averages_of_step_cdf(x, edges), edges, t, left=0.0, right=1.0)
        distance = l1_distance_to_step_cdf(values, edges, positions)
        order = "" if previous is None else f"{math.log(previous / distance, 2):.2f}"
        print(f"{count:14d} | {distance:.4e} | {order:>14} | {time.perf_counter() - start:.1f}")
        previous = distance


if __name__ == "__main__":
    main(*(int(sys.argv[1]),) if len(sys.argv) > 1 else (), *(float(sys.argv[2]),) if len(sys.argv) > 2 else ())
