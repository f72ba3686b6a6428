"""Checks of the LTP inputs: the arrays a compiled kernel reads, values of any shape, object types.

The compiled loops of :mod:`.kernels` index their arrays without bounds checks, so every array
reaches them through these checks: particles (2.23) with one centre, weight and width h_k > 0
each, a piecewise cubic shape (2.12), (2.13) with one row of four coefficients per piece, and
the power terms of a potential with exponents of at least 1.
"""

from __future__ import annotations

import numpy as np

from ..validation import finite_array, integer_at_least, same_length, sorted_array

#: Most particles one call may use: the pair sums cost (particles)^2 per time step, and the
#: repository's finest grid (h = 0.0025 on [-1, 1]) has 803 particles.
MAX_PARTICLES = 10_000
#: Most power terms of one potential (section 6's have one or two; each term is a loop over the pairs).
MAX_TERMS = 100


def particle_arrays(centres, weights, widths) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centres x_k, weights omega_k and widths h_k > 0 of 1 to MAX_PARTICLES particles (2.23)."""
    centres, weights, widths = (np.ascontiguousarray(finite_array(name, values)) for name, values in
                                (("centres", centres), ("weights", weights), ("widths", widths)))
    count = same_length(centres=centres, weights=weights, widths=widths)
    integer_at_least("the number of particles", count, 1, MAX_PARTICLES)
    if np.any(widths <= 0):
        raise ValueError("widths must be positive")
    return centres, weights, widths


def piece_arrays(breaks, coefficients, name: str = "coefficients") -> tuple[np.ndarray, np.ndarray]:
    """Breaks -r = s_0 < ... < s_J = r of a shape and its (J, 4) cubic coefficients (called ``name`` in the
    messages: the kernels call them ``pieces``)."""
    breaks = np.ascontiguousarray(sorted_array("breaks", breaks))
    if breaks.size < 2 or np.any(np.diff(breaks) <= 0) or breaks[0] != -breaks[-1]:
        raise ValueError(f"breaks must increase strictly from -r to r, got {breaks}")
    coefficients = np.ascontiguousarray(finite_array(name, coefficients, ndim=2))
    if coefficients.shape != (breaks.size - 1, 4):
        raise ValueError(f"{name} must have shape ({breaks.size - 1}, 4), one cubic per piece, "
                         f"got {coefficients.shape}")
    return breaks, coefficients


def exponent_array(exponents) -> np.ndarray:
    """Exponents a_j >= 1 of the power terms of a potential (see :func:`power_arrays`), at least one."""
    exponents = np.ascontiguousarray(finite_array("exponents", exponents))
    integer_at_least("the number of exponents (terms of the potential)", exponents.size, 1, MAX_TERMS)
    if np.any(exponents < 1.0):
        raise ValueError(f"exponents must all be at least 1 (a = 1 is the Newtonian |x|; below 1 W' is unbounded "
                         f"at 0), got {exponents}")
    return exponents


def power_arrays(coefficients, exponents) -> tuple[np.ndarray, np.ndarray]:
    """Coefficients c_j and exponents a_j >= 1 of W = sum_j c_j |x|^a_j / a_j, at least one term.

    a_j > 1 gives W' continuous and W'' locally integrable; a_j = 1 is the Newtonian c|x|, with W' = c sign(x)
    bounded and W'' = 2c delta a Dirac mass (the kernels convolve it exactly). Below 1, W' is unbounded at 0.
    """
    coefficients = np.ascontiguousarray(finite_array("coefficients", coefficients))
    exponents = exponent_array(exponents)
    same_length(coefficients=coefficients, exponents=exponents)
    return coefficients, exponents
