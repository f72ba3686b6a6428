"""The pair sums of the build before issue 14, kept here as the reference the benchmarks compare with.

One generic loop for every kernel: each pair i < j evaluated once through the kernel's term list
(``profile_forces_kernel``: a branch per term kind, scalar ``math.exp`` and ``math.erf``), dealt to 16
round-robin accumulators over ``prange``. The package now takes vectorised paths where it has
them (see ``particle_methods.blob.pair_sums.pair_sums``).
"""

import math

import numpy as np
from numba import njit, prange

from particle_methods.blob.kernels import profile_forces_kernel

ACCUMULATORS = 16


@njit(parallel=True, cache=True, error_model="numpy")
def reference_pair_sums(positions, masses, kinds, coefficients, parameters, tables, steps):
    n, dimension = positions.shape
    velocities = np.zeros((ACCUMULATORS, n, dimension))
    divergences = np.zeros((ACCUMULATORS, n))
    for c in prange(ACCUMULATORS):
        diff = np.empty(dimension)
        _, self_lap = profile_forces_kernel(kinds, coefficients, parameters, 0.0, dimension, tables, steps)
        for i in range(c, n, ACCUMULATORS):
            divergences[c, i] -= masses[i] * self_lap
            for j in range(i + 1, n):
                r2 = 0.0
                for axis in range(dimension):
                    diff[axis] = positions[i, axis] - positions[j, axis]
                    r2 += diff[axis] * diff[axis]
                g, lap = profile_forces_kernel(kinds, coefficients, parameters, math.sqrt(r2), dimension, tables, steps)
                for axis in range(dimension):
                    velocities[c, i, axis] -= masses[j] * g * diff[axis]
                    velocities[c, j, axis] += masses[i] * g * diff[axis]
                divergences[c, i] -= masses[j] * lap
                divergences[c, j] -= masses[i] * lap
    velocity = np.zeros((n, dimension))
    divergence = np.zeros(n)
    for c in range(ACCUMULATORS):
        velocity += velocities[c]
        divergence += divergences[c]
    return velocity, divergence
