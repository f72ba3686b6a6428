"""Limits on the work of one call, and the input checks particular to the blob package.

Every public function of :mod:`particle_methods.blob` checks its inputs with these and with
:mod:`particle_methods.validation` before a compiled sum sees them, and checks its results.
The limits refuse work that would not finish in reasonable time; each lies well above the
repository's own runs (``blob:`` in config/config.yaml, config/fig5-extended.yaml).
"""

from __future__ import annotations

import numpy as np

from ..validation import real_array

#: Particles of one ODE solve (grid points, or particles and tracers in ``mass_defect``). The direct
#: pair sums cost O(N^2) per right-hand side: 20,069 particles (h = 1/80 in 2D) take about 1 s per
#: evaluation; the 1D runs have at most 2,561.
MAX_PARTICLES = 25_000
#: Particles of one ODE solve with the 2D Newtonian kernel, raw or mollified by (4.2), whose sums take
#: the fast multipole method, about O(N) per right-hand side: Figure 5 extended to h = 1/320 has 321,645
#: particles and takes 2 to 5 s per evaluation on one core (benchmarks/README.md).
MAX_FMM_PARTICLES = 400_000
#: Largest final time of a run. The paper's runs end by t = 400 (Figure 8, our choice); the
#: solver's step count grows with t (about one step per time unit for the repulsive 1D kernel).
MAX_TIME = 1.0e4
#: Right-hand sides of one ODE solve, a guard against a solver that stalls (stiff or non-smooth
#: systems): the repository's runs need at most about 5,600 (Figures 7 and 8). Below 100
#: particles 100,000 evaluations take about 5 s.
MAX_EVALUATIONS = 100_000
#: Values a run stores, output times x particles x (d + 1): 160 MB.
MAX_STORED = 20_000_000
#: Smallest delta / h of a 2D blob run with delta given: below it the blobs barely overlap, the
#: self term m_i Delta K_delta(0) ~ rho h^2 / delta^2 of the density equation dominates and the
#: densities grow like exp(rho t h^2 / delta^2). With delta = h^q (1/2 < q < 1, h <= 1),
#: delta / h >= 1; Figures 7 and 8 take delta = 0.32, h = 1/9.
MIN_DELTA_OVER_H = 0.5
#: table_points x table_radius / delta of a tabulated 2D kernel: the radial quadrature costs about
#: 2.5 microseconds per unit (4 s at 8001 points and radius / delta = 200). Figure 6's cubic kernel
#: on the star patch, the largest, needs 4.3e5.
MAX_TABLE_WORK = 4.0e6
#: Largest power n of 1D data (1 - x^2)^n: the exact mass m(x) sums monomials of size up to
#: 2^n / n, losing n log10(2) digits (1e-8 relative at n = 30); the paper's data have n = 10, 20.
MAX_DATA_POWER = 30


def output_times(times) -> np.ndarray:
    """Output times of a run: a non-empty, strictly increasing array in [0, MAX_TIME]."""
    times = real_array("times", times)
    if times.ndim != 1 or times.size == 0:
        raise ValueError(f"times must be a non-empty 1-dimensional array, got shape {times.shape}")
    if not np.all(np.isfinite(times)):
        raise ValueError("times contains NaN or infinite values")
    if times[0] < 0 or np.any(np.diff(times) <= 0):
        raise ValueError(f"times must be non-negative and strictly increasing, got {times}")
    if times[-1] > MAX_TIME:
        raise ValueError(f"times must end by MAX_TIME = {MAX_TIME:g} (a limit on the work of one run), "
                         f"got {times[-1]:g}")
    return times
