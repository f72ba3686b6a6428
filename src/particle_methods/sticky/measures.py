"""Probability measures on the real line, described through their quantile functions.

A measure m with CDF F = H*m is represented by three vectorised functions:
``cdf`` (F, right-continuous), ``quantile`` (the pseudo-inverse (1.5),
F^{-1}(v) = inf{x : F(x) >= v}) and ``quantile_integral`` (the antiderivative
G(v) = int_0^v F^{-1}(s) ds, finite when m has a first moment). Exact W1 distances
(:mod:`particle_methods.norms`) and the discretisations (2.1) and (1.9) only need
these three functions, so every measure below gives them in closed form.
"""

from __future__ import annotations

from abc import ABC, abstractmethod

import numpy as np

from ..perturbation import nudged
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    in_interval,
    integer_at_least,
    positive,
    sorted_array,
)
from .spd import MAX_POSITIONS

_BISECTION_STEPS = 64


class QuantileMeasure(ABC):
    """Probability measure given by its quantile function and its antiderivative.

    Subclasses implement ``_quantile`` and ``_quantile_integral`` (and ``_cdf`` when they have
    a closed form) on checked arguments; the public methods check the arguments and refuse a
    result that is not finite, such as F^{-1}(0) = -inf for a support unbounded below.
    """

    def quantile(self, w):
        """Pseudo-inverse F^{-1}(w) of (1.5) for w in [0, 1]."""
        w = in_interval("w", w, 0.0, 1.0)
        return finite_result("the quantile F^{-1}(w)", self._quantile(w),
                             "w is 0 or 1 at an unbounded end of the support, or the measure's scale overflows")

    def quantile_integral(self, w):
        """G(w) = int_0^w F^{-1}(s) ds for w in [0, 1]."""
        w = in_interval("w", w, 0.0, 1.0)
        return finite_result("the quantile integral G(w)", self._quantile_integral(w),
                             "the measure's scale overflows")

    def cdf(self, x):
        """F(x), right-continuous, at finite x."""
        x = in_interval("x", x, -np.inf, np.inf)  # any finite real array
        return finite_result("the CDF F(x)", self._cdf(x), "the measure's parameters are too extreme")

    @abstractmethod
    def _quantile(self, w):
        """F^{-1}(w) at a float array w in [0, 1]."""

    @abstractmethod
    def _quantile_integral(self, w):
        """G(w) at a float array w in [0, 1]."""

    def _cdf(self, x):
        """F(x) = sup{w : F^{-1}(w) <= x}, by bisection on the monotone quantile.

        Sixty-four halvings of [0, 1] reach the resolution of double precision;
        subclasses with a closed-form CDF override this.
        """
        low = np.zeros_like(x)
        high = np.ones_like(x)
        for _ in range(_BISECTION_STEPS):
            middle = 0.5 * (low + high)
            below = self._quantile(middle) <= x
            low = np.where(below, middle, low)
            high = np.where(below, high, middle)
        return low


def checked_measure(name: str, measure) -> QuantileMeasure:
    """``measure`` itself if it is a :class:`QuantileMeasure`, else a ParameterTypeError naming it."""
    if not isinstance(measure, QuantileMeasure):
        raise ParameterTypeError(f"{name} must be a QuantileMeasure, got {type(measure).__name__}")
    return measure


class Atoms(QuantileMeasure):
    """Discrete measure sum_j p_j delta_{a_j} (equal weights by default): (5.2), delta_0."""

    def __init__(self, positions, weights=None):
        self.positions = sorted_array("positions", positions)
        if self.positions.size == 0:
            raise ValueError("positions must contain at least one atom")
        if np.any(np.diff(self.positions) == 0):
            raise ValueError("positions must be distinct")
        if weights is None:
            weights = np.full(self.positions.size, 1.0 / self.positions.size)
        self.weights = finite_array("weights", weights)
        if self.weights.shape != self.positions.shape or np.any(self.weights <= 0):
            raise ValueError("weights must be positive, one per position")
        if not np.isclose(self.weights.sum(), 1.0, rtol=0, atol=1e-12):
            raise ValueError("weights must sum to 1")
        self.levels = np.cumsum(self.weights)
        self.levels[-1] = 1.0
        self.level_starts = self.levels - self.weights
        partial_means = finite_result("a partial sum of p_j a_j", np.cumsum(self.positions * self.weights),
                                      "positions are too large")
        self._integral_starts = np.concatenate(([0.0], partial_means[:-1]))

    def _atom_index(self, w):
        index = np.searchsorted(self.levels, w, side="left")
        return np.minimum(index, self.positions.size - 1)

    def _cdf(self, x):
        index = np.searchsorted(self.positions, x, side="right")
        return np.where(index > 0, self.levels[np.maximum(index - 1, 0)], 0.0)

    def _quantile(self, w):
        return self.positions[self._atom_index(w)]

    def _quantile_integral(self, w):
        j = self._atom_index(w)
        return self._integral_starts[j] + self.positions[j] * (w - self.level_starts[j])


class Laplace(QuantileMeasure):
    """Two-sided exponential law m(dx) = exp(-|x - loc|)/2 dx, equation (5.4)."""

    def __init__(self, loc: float = 0.0):
        self.loc = finite_number("loc", loc)

    def _cdf(self, x):
        z = x - self.loc
        return np.where(z < 0, 0.5 * np.exp(np.minimum(z, 0.0)), 1.0 - 0.5 * np.exp(-np.maximum(z, 0.0)))

    def _quantile(self, w):
        with np.errstate(divide="ignore"):
            return self.loc + np.where(w < 0.5, np.log(2.0 * w), -np.log(2.0 * (1.0 - w)))

    def _quantile_integral(self, w):
        from scipy import special

        left = special.xlogy(w, 2.0 * w) - w
        right = special.xlogy(1.0 - w, 2.0 * (1.0 - w)) - (1.0 - w)
        return self.loc * w + np.where(w <= 0.5, left, right)


class Uniform(QuantileMeasure):
    """Uniform law on [a, b]."""

    def __init__(self, a: float = 0.0, b: float = 1.0):
        self.a = finite_number("a", a)
        self.b = finite_number("b", b)
        if self.b <= self.a:
            raise ValueError(f"b must exceed a, got a={self.a}, b={self.b}")
        if not np.isfinite(self.b - self.a):
            raise ValueError(f"b - a must be finite, got a={self.a}, b={self.b}")

    def _cdf(self, x):
        return np.clip((x - self.a) / (self.b - self.a), 0.0, 1.0)

    def _quantile(self, w):
        return self.a + (self.b - self.a) * w

    def _quantile_integral(self, w):
        return self.a * w + 0.5 * (self.b - self.a) * w**2


class TruncatedExponential(QuantileMeasure):
    """Density exp(-x)/(1 - exp(-b)) on [0, b]: positive but not constant (Lemma 2.1 (iv))."""

    MIN_B = 1e-4
    """Smallest b: G(w) = (s log s - s + 1)/(1 - e^-b) cancels to an absolute error near 1e-16/b,
    against values of order b, so below 1e-4 fewer than 8 digits are left."""

    def __init__(self, b: float = 1.0):
        self.b = positive("b", b)
        if self.b < self.MIN_B:
            raise ValueError(f"b must be at least {self.MIN_B:g} (G(w) loses its digits to cancellation below), "
                             f"got {self.b}")
        self._mass = -np.expm1(-self.b)

    def _cdf(self, x):
        return -np.expm1(-np.clip(x, 0.0, self.b)) / self._mass

    def _quantile(self, w):
        return -np.log1p(-self._mass * w)

    def _quantile_integral(self, w):
        from scipy import special

        s = 1.0 - self._mass * w
        return (special.xlogy(s, s) - s + 1.0) / self._mass


class Pareto(QuantileMeasure):
    """Heavy tail F(x) = 1 - x^{-alpha} on [1, inf), alpha > 1 (end of section 2)."""

    def __init__(self, alpha: float):
        self.alpha = positive("alpha", alpha)
        if self.alpha <= 1:
            raise ValueError(f"alpha must exceed 1 for a finite first moment, got {self.alpha}")

    def _cdf(self, x):
        return 1.0 - np.maximum(x, 1.0) ** (-self.alpha)

    def _quantile(self, w):
        with np.errstate(divide="ignore"):
            return (1.0 - w) ** (-1.0 / self.alpha)

    def _quantile_integral(self, w):
        power = 1.0 - 1.0 / self.alpha
        return (1.0 - (1.0 - w) ** power) / power


class TruncatedPareto(QuantileMeasure):
    """F(x) = (1 - x^{-alpha}) / (1 - R^{-alpha}) on [1, R], any alpha > 0 (Lemma 2.1 (i)).

    For alpha <= 1 the untruncated law has no first moment; widening R shows the discretisation
    error growing without bound, as section 1.1.4 argues (W1 = +inf for such m).
    """

    def __init__(self, alpha: float, upper: float):
        self.alpha = positive("alpha", alpha)
        self.upper = finite_number("upper", upper)
        if self.upper <= 1.0:
            raise ValueError(f"upper must exceed 1, got {self.upper}")
        self._tail = self.upper ** (-self.alpha)
        if self._tail == 1.0:
            raise ValueError(f"alpha log(upper) must exceed double precision, got alpha={self.alpha}, "
                             f"upper={self.upper}: the law is numerically the point mass at 1")

    def _remaining(self, w):
        """1 - (1 - R^-alpha) w, written to keep its digits as w -> 1."""
        return (1.0 - w) + w * self._tail

    def _cdf(self, x):
        x = np.clip(x, 1.0, self.upper)
        return -np.expm1(-self.alpha * np.log(x)) / (1.0 - self._tail)

    def _quantile(self, w):
        with np.errstate(divide="ignore", over="ignore"):
            return self._remaining(w) ** (-1.0 / self.alpha)

    def _quantile_integral(self, w):
        remaining, mass = self._remaining(w), 1.0 - self._tail
        with np.errstate(divide="ignore"):
            if self.alpha == 1.0:
                return -np.log(remaining) / mass
            power = 1.0 - 1.0 / self.alpha
            return -np.expm1(power * np.log(remaining)) / (mass * power)


class Weibull(QuantileMeasure):
    """Light tail F(x) = 1 - exp(-x^alpha) on [0, inf), alpha > 0 (end of section 2)."""

    MIN_ALPHA = 1 / 170
    """Smallest alpha: below it the mean Gamma(1 + 1/alpha) overflows."""

    def __init__(self, alpha: float):
        self.alpha = positive("alpha", alpha)
        if self.alpha < self.MIN_ALPHA:
            raise ValueError(f"alpha must be at least 1/170 (the mean Gamma(1 + 1/alpha) overflows below), "
                             f"got {self.alpha}")

    def _cdf(self, x):
        return -np.expm1(-(np.maximum(x, 0.0) ** self.alpha))

    def _quantile(self, w):
        with np.errstate(divide="ignore"):
            return (-np.log1p(-w)) ** (1.0 / self.alpha)

    def _quantile_integral(self, w):
        shape = 1.0 + 1.0 / self.alpha
        with np.errstate(divide="ignore"):
            level = -np.log1p(-w)
        from scipy import special

        return special.gamma(shape) * special.gammainc(shape, level)


def median_quantiles(measure: QuantileMeasure, n: int) -> np.ndarray:
    """Discretisation (2.1): x_k = F^{-1}((2k - 1)/(2n)), k = 1..n, the W1-optimal choice (initial positions:
    moved by the active nudge of :mod:`particle_methods.perturbation`, if any)."""
    measure = checked_measure("measure", measure)
    n = integer_at_least("n", n, 1, MAX_POSITIONS)
    return nudged(measure.quantile((2.0 * np.arange(1, n + 1) - 1.0) / (2.0 * n)), keep_sorted=True)


def averaged_quantiles(measure: QuantileMeasure, n: int) -> np.ndarray:
    """Discretisation (1.9): x_k = (n+1) int_{(2k-1)/(2(n+1))}^{(2k+1)/(2(n+1))} F^{-1}(w) dw (initial
    positions: moved by the active nudge of :mod:`particle_methods.perturbation`, if any)."""
    measure = checked_measure("measure", measure)
    n = integer_at_least("n", n, 1, MAX_POSITIONS)
    edges = (2.0 * np.arange(n + 1) + 1.0) / (2.0 * (n + 1))
    return nudged(finite_result("a position (1.9)", (n + 1) * np.diff(measure.quantile_integral(edges)),
                                "the quantile integral is too large: its differences overflow"), keep_sorted=True)
