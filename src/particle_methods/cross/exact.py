"""Exact solution of the 1D aggregation equation with the attractive Newtonian kernel K = |x|/2.

With v = -K' * rho = (M - 2F)/2, the cumulative mass F(t, x) = int_{-inf}^x rho solves the scalar
conservation law

    F_t + (M F/2 - F^2/2)_x = 0,

whose flux is concave (with u = F/M and tau = M t it is (5.3) of the sticky paper,
u_tau + (u(1 - u)/2)_x = 0). Its entropy solution is written in mass coordinates: the level w of F
travels at the speed lambda(w) = M/2 - w, so from a symmetric density non-increasing in |x| the
level w <= M/2 sits at

    X_t(w) = a - t m(a),   a = F0^{-1}(w),   m(a) = int_0^a rho0,

the characteristic of the blob paper's section 4.1 (X(alpha, t) = alpha - t m(alpha)), until it
reaches 0. Its speed t m(a) grows more slowly than |a| once rho0(a) < 1/t, so the level a stays
off 0 exactly when |a| > a0(t), the positive root of a = t m(a) (a0 = 0 before the blow-up time
1/max rho0; a0 = radius once t M/2 reaches the radius of a compact support). The levels
w0 = F0(-a0) < w < M - w0 sit in a Dirac mass at 0 of mass 2 m(a0): the stationary shock of
the concave flux, symmetric about M/2. This is the greatest convex minorant (Brenier-Grenier) of
int (X_0 + t lambda) in the symmetric case: on [w0, M - w0] the mean of X_0 + t lambda is 0, and
it touches at w0 where X_0(w0) + t lambda(w0) = 0. By symmetry X_t(M - w) = -X_t(w).

Everything W1 needs is then exact up to the rounding of one monotone root per point
(:func:`~particle_methods.cross.profiles.monotone_root`): the CDF F(t, x), the quantile X_t(w)
and its antiderivative int_0^w X_t = int_{-R}^{a} s rho0(s) ds + t (M w/2 - w^2/2) for w <= w0.
"""

from __future__ import annotations

import math

import numpy as np

from ..validation import finite_result, finite_values, in_interval, nonnegative
from .hull import BUMP_DATA, BumpData, HullSolution
from .profiles import MAX_ITERATIONS, Profile, limited, monotone_root, profile


def _collapse_radius(shape: Profile, t: float) -> float:
    """a0(t): the largest |a| whose level has reached 0 by time t (0 before the blow-up)."""
    # Full collapse first: for the indicator (4.4) t M/2 = radius and t max rho0 = 1 at once (t = 1),
    # when every level reaches 0 together; tested the other way round, a0 would be 0 and the Dirac
    # mass of the whole data reported as 0.
    if t * shape.mass / 2.0 >= shape.radius:
        return shape.radius
    if t * shape.peak <= 1.0:
        return 0.0
    # g(a) = t m(a) - a is concave (rho0 non-increasing), positive just above 0 and negative at
    # min(radius, t M/2): bisect to the last ulp.
    low, high = 0.0, min(shape.radius, t * shape.mass / 2.0)
    for _ in range(MAX_ITERATIONS):
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if t * float(shape.mass_from_origin(middle)) - middle > 0.0:
            low = middle
        else:
            high = middle
    return high


class AggregationSolution:
    """Entropy solution at time t of F_t + (M F/2 - F^2/2)_x = 0 from a symmetric profile.

    ``data``: a name ('smooth20' (4.3), 'indicator' (4.4), 'smooth10' (4.5), 'laplace' (5.4)),
    a :class:`~particle_methods.blob.initial.Data1D` or a
    :class:`~particle_methods.cross.profiles.Profile`. Attributes: ``mass`` M, ``t``,
    ``blowup_time`` 1/max rho0, ``collapse_radius`` a0(t), ``level`` w0(t) = F0(-a0) and
    ``dirac_mass`` M - 2 w0, the mass held at 0.
    """

    def __init__(self, data, t: float):
        self.profile = profile(data)
        self.t = nonnegative("t", t)
        shape = self.profile
        self.mass = shape.mass
        self.blowup_time = 1.0 / shape.peak
        if self.t > 0.0 and not math.isfinite(self.t * shape.mass):
            raise ValueError(f"t = {t} is too large")
        self.collapse_radius = _collapse_radius(shape, self.t)
        if self.collapse_radius >= shape.radius:
            self.level = 0.0
        else:
            # (not below 0: M/2 - m(a0) rounds to -ulp(M) when a0 is just short of the radius)
            self.level = max(0.5 * shape.mass - float(shape.mass_from_origin(self.collapse_radius)), 0.0)
        self.dirac_mass = shape.mass - 2.0 * self.level
        #: Left end of the support, -R + t M/2 (-inf for an unbounded support).
        self.left_end = min(-shape.radius + 0.5 * self.t * shape.mass, 0.0)
        #: Where F(t, .) is not smooth: the support's ends and 0.
        self.kinks = np.unique([k for k in (self.left_end, 0.0, -self.left_end) if math.isfinite(k)])

    def _characteristic(self, a):
        return a - self.t * self.profile.mass_from_origin(a)

    def _left_state(self, x):
        """(F(t, x), int_0^{F(t, x)} X_t) at x <= 0 from one root per point: the level a whose
        characteristic sits at x (0 and 0 left of the support; F(t, 0-) = w0 at x = 0)."""
        shape, t = self.profile, self.t
        inside = x > self.left_end
        level, integral = np.zeros_like(x), np.zeros_like(x)
        if np.any(inside):
            xi = x[inside]
            # For a < 0, |m(a)| <= M/2: the characteristic of a lies in [a, a + t M/2]. (The bracket stays
            # finite: x - t M/2 overflows to -inf for x near -1.8e308, and m(-inf), s rho0(s) at -inf are NaN.)
            with np.errstate(over="ignore"):
                low = np.maximum(xi - 0.5 * t * shape.mass, max(-shape.radius, -np.finfo(np.float64).max))
            high = np.minimum(xi, -self.collapse_radius)
            a = monotone_root(self._characteristic, lambda s: 1.0 - t * shape.density(s), xi, low, high)
            # Clipped: M/2 + m(a) may round to -ulp(M) in the left tail, and F must lie in [0, M].
            w = np.clip(0.5 * shape.mass + shape.mass_from_origin(a), 0.0, 0.5 * shape.mass)
            level[inside] = w
            integral[inside] = shape.moment_from_left(a) + t * (0.5 * shape.mass * w - 0.5 * w * w)
        return level, integral

    def cdf(self, x):
        """F(t, x) = int_{-inf}^x rho(t, .), right-continuous (the Dirac mass counts at x = 0)."""
        x = limited("x", finite_values("x", x))
        flat = x.ravel()
        left, _ = self._left_state(-np.abs(flat))
        value = np.where(flat < 0.0, left, self.mass - left)
        return finite_result("F(t, x)", value.reshape(x.shape), "the data overflow")

    def antiderivative(self, x):
        """int_{-inf}^x F(t, .) = x F(t, x) - int_0^{F(t, x)} X_t, from one root per point: by the
        symmetry X_t(M - w) = -X_t(w), the quantile integral at F(t, x) = M - F(t, -x) for x >= 0
        equals the one at F(t, -x)."""
        x = limited("x", finite_values("x", x))
        flat = x.ravel()
        left, integral = self._left_state(-np.abs(flat))
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported just below
            value = flat * np.where(flat < 0.0, left, self.mass - left) - integral
        return finite_result("int F(t, .)", value.reshape(x.shape), "x is too large: x F(t, x) overflows")

    def _left_levels(self, w):
        """min(w, M - w), and whether that level still moves (below w0)."""
        lower = np.minimum(w, self.mass - w)
        return lower, lower < self.level

    def quantile(self, w):
        """X_t(w) = inf{x : F(t, x) >= w} for 0 <= w <= M (0 on the levels of the Dirac mass)."""
        w = limited("w", in_interval("w", w, 0.0, self.mass))
        lower, moving = self._left_levels(w)
        value = np.zeros_like(w)
        a = self.profile.level_position(lower[moving])
        value[moving] = self._characteristic(a)
        value = np.where(w > 0.5 * self.mass, -value, value)
        return finite_result("X_t(w)", value, "w is 0 or M at an unbounded end of the support")

    def quantile_integral(self, w):
        """int_0^w X_t(s) ds for 0 <= w <= M."""
        w = limited("w", in_interval("w", w, 0.0, self.mass))
        lower, _ = self._left_levels(w)
        level = np.minimum(lower, self.level)
        value = np.zeros_like(w)
        positive = level > 0.0
        s = level[positive]
        moment = self.profile.moment_from_left(self.profile.level_position(s))
        value[positive] = moment + self.t * (0.5 * self.mass * s - 0.5 * s * s)
        return finite_result("int_0^w X_t", value, "the data overflow")


def solution(data, t: float):
    """The exact solution at time t: :class:`~particle_methods.cross.hull.HullSolution` for the asymmetric bump data
    ('two_bumps', 'skewed_bumps', a :class:`~particle_methods.cross.hull.BumpData`), :class:`AggregationSolution`
    otherwise."""
    if isinstance(data, BumpData) or (isinstance(data, str) and data in BUMP_DATA):
        return HullSolution(data, t)
    return AggregationSolution(data, t)


def exact_mass_function(data, t: float, x):
    """F(t, x), the mass left of x at time t, of the entropy solution of the aggregation equation
    with K = |x|/2 from ``data`` (a name: 'smooth20', 'indicator', 'smooth10', 'laplace', 'two_bumps',
    'skewed_bumps'; a :class:`~particle_methods.blob.initial.Data1D` or a
    :class:`~particle_methods.cross.hull.BumpData`), before and after the blow-ups and mergers (see
    :func:`solution`)."""
    return solution(data, t).cdf(x)
