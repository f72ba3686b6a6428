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

from .validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    finite_values,
    in_interval,
    integer_at_least,
    positive,
    real_array,
    sorted_array,
)


def _points(name: str, points) -> np.ndarray:
    x = sorted_array(name, points)
    if x.size == 0:
        raise ValueError(f"{name} must contain at least one position")
    return x


def _measure_values(name: str, values, n: int) -> np.ndarray:
    """Values a measure returned for n arguments, checked: real, one per argument, finite."""
    values = real_array(name, values)
    if values.shape != (n,):
        raise ValueError(f"{name} must return one value per point, shape ({n},), got {values.shape}")
    return finite_result(name, values, "the measure returned NaN or infinite values")


def w1_to_measure(measure, points) -> float:
    """W1 distance between ``measure`` and the empirical measure (1/n) sum delta_{x_k}.

    ``measure`` must provide ``cdf(x)`` (right-continuous) and
    ``quantile_integral(w)`` (an antiderivative of the quantile function (1.5)).
    On ((k-1)/n, k/n] the empirical quantile is the constant x_k and the quantile of
    ``measure`` crosses x_k at s_k = F(x_k), so the integral of |F^{-1} - x_k| is
    x_k (s - a) - (G(s) - G(a)) + (G(b) - G(s)) - x_k (b - s) with G the
    antiderivative: exact, with no quadrature.
    """
    methods = ("cdf", "quantile_integral")
    if isinstance(measure, type) or not all(callable(getattr(measure, name, None)) for name in methods):
        raise ParameterTypeError(f"measure must provide methods cdf(x) and quantile_integral(w), got {measure!r}")
    x = _points("points", points)
    n = x.size
    lower = np.arange(n) / n
    upper = np.arange(1, n + 1) / n
    split = np.clip(_measure_values("measure.cdf(points)", measure.cdf(x), n), lower, upper)
    g_lower, g_split, g_upper = (_measure_values("measure.quantile_integral(w)", measure.quantile_integral(w), n)
                                 for w in (lower, split, upper))
    below = x * (split - lower) - (g_split - g_lower)
    above = (g_upper - g_split) - x * (upper - split)
    return finite_result("W1", float(np.sum(below + above)), "the points or the measure's values are too large")


def w1_between_samples(x, y) -> float:
    """W1 distance between two empirical measures with equal masses 1/n and 1/m.

    Both quantile functions are step functions; on each piece of the common
    refinement of the grids k/n and j/m they are constant, so the sum is exact.
    """
    x = _points("x", x)
    y = _points("y", y)
    n, m = x.size, y.size
    breaks = np.union1d(np.arange(n + 1) / n, np.arange(m + 1) / m)
    middles = 0.5 * (breaks[1:] + breaks[:-1])
    ix = np.minimum((middles * n).astype(np.int64), n - 1)
    iy = np.minimum((middles * m).astype(np.int64), m - 1)
    return finite_result("W1", float(np.sum(np.abs(x[ix] - y[iy]) * np.diff(breaks))),
                         "x and y are too far apart: their differences overflow")


def grid_errors(values, reference, x) -> tuple[float, float]:
    """L1 (trapezoidal rule) and L-infinity norms of values - reference on the grid x.

    Use a grid much finer than the features of both functions; the tests check that
    refining it does not move the errors measured in the figures.
    """
    x = sorted_array("x", x)
    if x.size < 2:
        raise ValueError(f"x must contain at least 2 points for the trapezoidal rule, got {x.size}")
    values = finite_array("values", values)
    reference = finite_array("reference", reference)
    if values.shape != x.shape or reference.shape != x.shape:
        raise ValueError(f"values, reference and x must have the same shape, got {values.shape}, {reference.shape} "
                         f"and {x.shape}")
    difference = np.abs(values - reference)
    errors = float(np.trapezoid(difference, x)), float(difference.max())
    return finite_result("the L1 or L-infinity error", errors, "values, reference or x are too large")


def discrete_l1(values, reference, h: float, dimension: int = 1) -> float:
    """Discrete L1_h norm h^d sum_i |values_i - reference_i| of the blob paper (section 4.1).

    For vector quantities (trajectories in 2D) the last axis is the vector and |.| is
    its Euclidean length.
    """
    values = in_interval("values", values, -np.inf, np.inf)  # any finite real array
    reference = in_interval("reference", reference, -np.inf, np.inf)
    try:
        np.broadcast_shapes(values.shape, reference.shape)
    except ValueError:
        raise ValueError(f"values and reference must have broadcastable shapes, got {values.shape} and "
                         f"{reference.shape}") from None
    h = positive("h", h)
    dimension = integer_at_least("dimension", dimension, 1)
    try:
        volume = h**dimension
    except OverflowError:
        raise ValueError(f"h**dimension overflows, h = {h}, dimension = {dimension}") from None
    difference = values - reference
    if difference.ndim > 1 and dimension > 1:
        difference = np.linalg.norm(difference, axis=-1)
    return finite_result("the discrete L1 norm", float(volume * np.abs(difference).sum()),
                         "values, reference or h are too large: the sum overflows")


def _checked_measure(measure, methods: tuple[str, ...]) -> float:
    """The mass M of ``measure`` (its ``mass``, 1 if absent) after checking that it provides ``methods``."""
    if isinstance(measure, type) or not all(callable(getattr(measure, name, None)) for name in methods):
        raise ParameterTypeError(f"measure must provide methods {', '.join(f'{name}()' for name in methods)}, got "
                                 f"{measure!r}")
    return positive("measure.mass", getattr(measure, "mass", 1.0))


def check_within_range(name: str, x: np.ndarray, mass: float) -> None:
    """Refuse positions ``x`` whose products x F(x) with values of F up to ``mass`` overflow (and positions that are
    not finite reals, or a mass that is not a finite number, naming them)."""
    x, mass = finite_values(name, x), finite_number("mass", mass)
    with np.errstate(over="ignore"):
        if x.size and not np.isfinite(np.max(np.abs(x)) * mass):
            raise ValueError(f"{name} are too large: {name} times the mass {mass!r} overflow")


def cdf_antiderivative(measure, x, mass=None):
    """A(x) = int_{-inf}^x F = x F(x) - G(F(x)) for the CDF F of ``measure`` (mass M, default its
    ``mass`` or 1): the levels below F(x) sit at X(w) <= x (integration by parts)."""
    own = _checked_measure(measure, ("cdf", "quantile_integral"))
    mass = own if mass is None else positive("mass", mass)
    x = finite_array("x", x)
    if callable(getattr(measure, "antiderivative", None)):  # the measure computes A itself, faster
        return measure.antiderivative(x)
    level = np.clip(measure.cdf(x), 0.0, mass)
    return x * level - measure.quantile_integral(level)


def l1_to_step_function(measure, breaks, values) -> float:
    """Exact int_R |F(x) - S(x)| dx between the CDF F of ``measure`` and a step function S.

    S(x) = values[j] on [breaks[j], breaks[j+1]), 0 left of breaks[0] and values[-1] from
    breaks[-1] on, which must be the total mass M of ``measure`` (within 1e-9 relative, else the
    integral diverges; the tail then uses M). Point masses m_k at sorted x_k give breaks x_k and
    values the partial sums (repeated positions are allowed); piecewise constant finite-volume
    values of F give breaks the cell edges and values (F_0, ..., F_{K-1}, M).

    ``measure`` provides ``cdf``, ``quantile`` (on [0, M]), ``quantile_integral`` (G(w) = int_0^w X)
    and ``mass`` (1 if absent: a probability measure). With A(x) = int_{-inf}^x F = x F(x) - G(F(x)),
    on a piece [a, b) where S = s the integral of |F - s| is A(b) - A(a) - s (b - a) plus twice
    int_a^{x*} (s - F), with x* = X(s) clipped to [a, b] the point where F reaches s:
    exact, no quadrature.
    """
    mass = _checked_measure(measure, ("cdf", "quantile", "quantile_integral"))
    b = sorted_array("breaks", breaks)
    s = finite_array("values", values)
    if b.size == 0:
        raise ValueError("breaks must contain at least one point")
    if s.shape != b.shape:
        raise ValueError(f"values must have one entry per break, shape {b.shape}, got {s.shape}")
    if not abs(s[-1] - mass) <= 1e-9 * mass:
        raise ValueError(f"values[-1] = {s[-1]!r} must be the total mass {mass!r} of the measure: the L1 distance "
                         "is infinite otherwise")
    check_within_range("breaks", b, mass)
    a_values = cdf_antiderivative(measure, b, mass)
    starts, ends, steps = b[:-1], b[1:], s[:-1]
    crossing = np.where(steps <= 0.0, starts, np.where(steps >= mass, ends, 0.0))
    interior = (steps > 0.0) & (steps < mass)
    crossing[interior] = measure.quantile(steps[interior])
    crossing = np.clip(crossing, starts, ends)
    a_crossing = cdf_antiderivative(measure, crossing, mass)
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported just below
        pieces = (a_values[1:] - a_values[:-1]) - steps * (ends - starts)
        pieces += 2.0 * (steps * (crossing - starts) - (a_crossing - a_values[:-1]))
        total = float(np.sum(pieces) + sum(tail_integrals(measure, b[0], b[-1])))
    return finite_result("the L1 distance", total, "breaks or values are too large")


def tail_integrals(measure, left: float, right: float) -> tuple[float, float]:
    """(int_{-inf}^left F, int_right^inf (M - F)) for the CDF F of ``measure`` of mass M (see
    :func:`l1_to_step_function`): A(left), and (G(M) - G(F(right))) - right (M - F(right)), since
    the levels above F(right) sit at X(w) > right."""
    mass = _checked_measure(measure, ("cdf", "quantile_integral"))
    ends = np.array([finite_number("left", left), finite_number("right", right)], dtype=np.float64)
    lower = float(cdf_antiderivative(measure, ends[:1], mass)[0])
    level = np.clip(measure.cdf(ends[1:]), 0.0, mass)
    upper = (measure.quantile_integral(np.array([mass])) - measure.quantile_integral(level)) - ends[1] * (mass - level)
    return lower, float(upper[0])
