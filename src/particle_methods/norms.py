"""Error norms shared by the papers.

For probability measures on the real line the L1 distance between cumulative
distribution functions equals the Wasserstein distance W1 and the L1 distance
between quantile functions, equation (1.6) of Jourdain and Reygner:

    ||H*m - H*m'||_{L1(R)} = W1(m, m') = int_0^1 |F^{-1}(v) - F'^{-1}(v)| dv.

Both functions below integrate that quantile difference exactly, piece by piece,
so the only error is floating-point rounding (far below 1/n).
"""

from __future__ import annotations

import numpy as np

from .validation import sorted_array


def w1_to_measure(measure, points) -> float:
    """W1 distance between ``measure`` and the empirical measure (1/n) sum delta_{x_k}.

    ``measure`` must provide ``cdf(x)`` (right-continuous) and
    ``quantile_integral(w)`` (an antiderivative of the quantile function (1.5)).
    On ((k-1)/n, k/n] the empirical quantile is the constant x_k and the quantile of
    ``measure`` crosses x_k at s_k = F(x_k), so the integral of |F^{-1} - x_k| is
    x_k (s - a) - (G(s) - G(a)) + (G(b) - G(s)) - x_k (b - s) with G the
    antiderivative: exact, with no quadrature.
    """
    x = sorted_array("points", points)
    n = x.size
    if n == 0:
        raise ValueError("points must contain at least one position")
    lower = np.arange(n) / n
    upper = np.arange(1, n + 1) / n
    split = np.clip(measure.cdf(x), lower, upper)
    primitive = measure.quantile_integral
    g_lower, g_split, g_upper = primitive(lower), primitive(split), primitive(upper)
    below = x * (split - lower) - (g_split - g_lower)
    above = (g_upper - g_split) - x * (upper - split)
    return float(np.sum(below + above))


def w1_between_samples(x, y) -> float:
    """W1 distance between two empirical measures with equal masses 1/n and 1/m.

    Both quantile functions are step functions; on each piece of the common
    refinement of the grids k/n and j/m they are constant, so the sum is exact.
    """
    x = sorted_array("x", x)
    y = sorted_array("y", y)
    if x.size == 0 or y.size == 0:
        raise ValueError("x and y must contain at least one position")
    n, m = x.size, y.size
    breaks = np.union1d(np.arange(n + 1) / n, np.arange(m + 1) / m)
    middles = 0.5 * (breaks[1:] + breaks[:-1])
    ix = np.minimum((middles * n).astype(np.int64), n - 1)
    iy = np.minimum((middles * m).astype(np.int64), m - 1)
    return float(np.sum(np.abs(x[ix] - y[iy]) * np.diff(breaks)))


def grid_errors(values, reference, x) -> tuple[float, float]:
    """L1 (trapezoidal rule) and L-infinity norms of values - reference on the grid x.

    Use a grid much finer than the features of both functions; the tests check that
    refining it does not move the errors measured in the figures.
    """
    x = sorted_array("x", x)
    difference = np.abs(np.asarray(values, dtype=np.float64) - np.asarray(reference, dtype=np.float64))
    if difference.shape != x.shape:
        raise ValueError("values, reference and x must have the same shape")
    return float(np.trapezoid(difference, x)), float(difference.max())


def discrete_l1(values, reference, h: float, dimension: int = 1) -> float:
    """Discrete L1_h norm h^d sum_i |values_i - reference_i| of the blob paper (section 4.1).

    For vector quantities (trajectories in 2D) the last axis is the vector and |.| is
    its Euclidean length.
    """
    difference = np.asarray(values, dtype=np.float64) - np.asarray(reference, dtype=np.float64)
    if difference.ndim > 1 and dimension > 1:
        difference = np.linalg.norm(difference, axis=-1)
    return float(h**dimension * np.abs(difference).sum())
