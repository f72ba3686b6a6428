"""Exact solution of the Riemann problem for the p-system of section 5.2.2, in one genuinely nonlinear half.

The p-system u_t - v_x = 0, v_t + p(u)_x = 0 has the characteristic speeds -c(u) (1-waves)
and +c(u) (2-waves), c = sqrt(-p'). Along a 1-rarefaction w^- = v - g(u) is constant and
along a 2-rarefaction w^+ = v + g(u) is (the invariants of (5.7)). A shock joining q_a
(left) to q_b (right) satisfies Rankine-Hugoniot, s (u_b - u_a) = -(v_b - v_a) and
s (v_b - v_a) = p(u_b) - p(u_a), hence s^2 = -[p]/[u].

c peaks at u = nu/2 and is strictly monotone on each half [0, nu/2] and [nu/2, nu]: the
system is genuinely nonlinear there, and Lax's theory applies (Smoller, Shock Waves and
Reaction-Diffusion Equations, chapter 17). With sigma = +1 on the lower half (c increasing)
and -1 on the upper one, a 1-wave from u_L to u_* is a shock when sigma (u_* - u_L) > 0
(Lax's condition c(u_L) < |s| < c(u_*), |s| being a root mean square of c between the two
states) and a rarefaction otherwise; a 2-wave from u_* to u_R is a shock when
sigma (u_* - u_R) > 0. The 1-wave curve through the left state increases in u and the 2-wave
curve through the right state decreases, so their crossing, the middle state, is unique; it
is found by bracketing over the half.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..systems import PSystem
from ..validation import ParameterTypeError, finite_number, finite_values, instance, positive
from .grids import checked_edges


def _state(name: str, state, system: PSystem) -> tuple[float, float]:
    try:
        u, v = state
    except (TypeError, ValueError):
        raise ParameterTypeError(f"{name} must be a pair (u, v), got {state!r}") from None
    u = finite_number(f"{name} u", u)
    v = finite_number(f"{name} v", v)
    if not 0.0 <= u <= system.nu:
        raise ValueError(f"{name} u must lie in [0, nu] = [0, {system.nu}], got {u}")
    return u, v


@dataclass(frozen=True)
class Wave:
    """One wave of the solution: a shock (equal edges) or a rarefaction fan, by the speeds of its two edges."""

    family: int
    left_edge: float
    right_edge: float

    def __post_init__(self):
        if isinstance(self.family, bool) or self.family not in (1, 2):
            raise ValueError(f"family must be 1 or 2, got {self.family!r}")
        object.__setattr__(self, "left_edge", finite_number("left_edge", self.left_edge))
        object.__setattr__(self, "right_edge", finite_number("right_edge", self.right_edge))

    @property
    def shock(self) -> bool:
        return self.left_edge == self.right_edge


class PSystemRiemann:
    """Entropy solution of the Riemann problem (u, v)(0, x) = ``left`` for x < 0, ``right`` for x > 0.

    Both states and the middle state must lie in one half, u <= nu/2 or u >= nu/2, where the
    system is genuinely nonlinear; otherwise a ValueError. The solution is self-similar:
    :meth:`state` gives it at x/t and :meth:`cell_averages` averages it exactly over cells.
    """

    def __init__(self, system: PSystem, left, right):
        self.system = instance("system", system, PSystem)
        self.left = _state("left", left, self.system)
        self.right = _state("right", right, self.system)
        middle = 0.5 * self.system.nu
        volumes = (self.left[0], self.right[0])
        if max(volumes) <= middle:
            self.sigma, bracket = 1.0, (0.0, middle)
        elif min(volumes) >= middle:
            self.sigma, bracket = -1.0, (middle, self.system.nu)
        else:
            raise ValueError(f"left u = {volumes[0]} and right u = {volumes[1]} lie on both sides of nu/2 = {middle}, "
                             "where the system is not genuinely nonlinear: both must be <= nu/2 or both >= nu/2")
        gap = [self._first_curve(u) - self._second_curve(u) for u in bracket]
        if gap[0] > 0.0 or gap[1] < 0.0:
            raise ValueError(f"the middle state of left = {self.left} and right = {self.right} leaves the half "
                             f"[{bracket[0]}, {bracket[1]}] of u where the system is genuinely nonlinear")
        from scipy import optimize

        u_star = optimize.brentq(lambda u: self._first_curve(u) - self._second_curve(u), *bracket,
                                 xtol=np.finfo(np.float64).tiny, rtol=4.0 * np.finfo(np.float64).eps, maxiter=400)
        self.middle = (u_star, self._first_curve(u_star))
        self.waves = (self._wave(1, self.left[0], u_star), self._wave(2, u_star, self.right[0]))

    def _shock_jump(self, u_a: float, u_b: float) -> float:
        """sign(u_b - u_a) sqrt(-(p(u_b) - p(u_a)) (u_b - u_a)) = |s| (u_b - u_a) across a shock."""
        product = -(float(self.system.pressure(u_b)) - float(self.system.pressure(u_a))) * (u_b - u_a)
        return math.copysign(math.sqrt(max(product, 0.0)), u_b - u_a)

    def _first_curve(self, u: float) -> float:
        """v on the 1-wave curve through the left state: increasing in u."""
        u_left, v_left = self.left
        if self.sigma * (u - u_left) > 0.0:
            return v_left + self._shock_jump(u_left, u)
        return v_left - float(self.system.g(u_left)) + float(self.system.g(u))  # w^- = w^-_L

    def _second_curve(self, u: float) -> float:
        """v on the 2-wave curve through the right state: decreasing in u."""
        u_right, v_right = self.right
        if self.sigma * (u - u_right) > 0.0:
            return v_right + self._shock_jump(u, u_right)
        return v_right + float(self.system.g(u_right)) - float(self.system.g(u))  # w^+ = w^+_R

    def _wave(self, family: int, u_a: float, u_b: float) -> Wave:
        sign = -1.0 if family == 1 else 1.0
        shock = self.sigma * ((u_b - u_a) if family == 1 else (u_a - u_b)) > 0.0
        if shock:
            speed = sign * abs(self._shock_jump(u_a, u_b) / (u_b - u_a))
            return Wave(family, speed, speed)
        left_edge, right_edge = (sign * float(self.system.sound_speed(u)) for u in (u_a, u_b))
        return Wave(family, left_edge, right_edge)

    def _fan_volume(self, xi: np.ndarray) -> np.ndarray:
        """u in a fan, where c(u) = |xi|: c^{-1} on the half, kappa (u/nu - 1/2) = -+ sqrt((A/|xi|)^2 - 1)."""
        ratio = np.maximum(self.system.speed_scale / np.abs(xi), 1.0)
        offset = self.sigma * np.sqrt((ratio - 1.0) * (ratio + 1.0)) / self.system.kappa
        return np.clip(self.system.nu * (0.5 - offset), 0.0, self.system.nu)

    def _pieces(self):
        """(start, end, kind, data) of the constant states and fans, left to right; start/end are speeds."""
        states = (self.left, self.middle, self.right)
        pieces = []
        start = -np.inf
        for k, wave in enumerate(self.waves):
            pieces.append((start, wave.left_edge, "constant", states[k]))
            if not wave.shock:
                pieces.append((wave.left_edge, wave.right_edge, "fan", wave.family))
            start = wave.right_edge
        pieces.append((start, np.inf, "constant", states[2]))
        return pieces

    def _fan_state(self, family: int, xi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = self._fan_volume(xi)
        if family == 1:
            return u, self.left[1] - float(self.system.g(self.left[0])) + self.system.g(u)
        return u, self.right[1] + float(self.system.g(self.right[0])) - self.system.g(u)

    def state(self, xi):
        """(u, v) at x/t = ``xi`` (any shape); at a shock, the state on its right."""
        xi = finite_values("xi", xi)
        u, v = np.empty_like(xi), np.empty_like(xi)
        for start, end, kind, data in self._pieces():
            inside = (xi >= start) & (xi < end) if end < np.inf else xi >= start
            if kind == "constant":
                u[inside], v[inside] = data
            else:
                u[inside], v[inside] = self._fan_state(data, xi[inside])
        return u, v

    def _fan_integrals(self, family: int, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """int_lo^hi (u, v)(xi) dxi inside a fan of the given family, in closed form.

        With y = |xi| = c(u) and r = A/y >= 1 (A the speed scale), u = nu/2 - sigma (nu/kappa)
        sqrt(r^2 - 1) and g(u) = -sigma acosh(r)/(2a). Antiderivatives in y:
        int sqrt(A^2/y^2 - 1) dy = sqrt(A^2 - y^2) - A acosh(A/y) and
        int acosh(A/y) dy = y acosh(A/y) + A asin(y/A).
        """
        a, big = self.system.a, self.system.speed_scale
        sign = -1.0 if family == 1 else 1.0  # xi = sign * y

        def antiderivatives(xi):
            y = np.clip(np.abs(xi), 0.0, big)
            arc = np.arccosh(np.maximum(big / np.maximum(y, np.finfo(np.float64).tiny), 1.0))
            root = np.sqrt(np.maximum((big - y) * (big + y), 0.0))
            volume = 0.5 * self.system.nu * y - self.sigma * (self.system.nu / self.system.kappa) * (root - big * arc)
            g = -self.sigma * (y * arc + big * np.arcsin(y / big)) / (2.0 * a)
            if family == 1:
                velocity = (self.left[1] - float(self.system.g(self.left[0]))) * y + g
            else:
                velocity = (self.right[1] + float(self.system.g(self.right[0]))) * y - g
            # d/dxi F(sign xi) = sign F'(y): the xi-antiderivative of f(y(xi)) is sign * F(y).
            return sign * volume, sign * velocity

        upper, lower = antiderivatives(hi), antiderivatives(lo)
        return upper[0] - lower[0], upper[1] - lower[1]

    def cell_averages(self, x_edges, t) -> tuple[np.ndarray, np.ndarray]:
        """Exact averages of (u, v)(t, .) over the cells of the strictly increasing ``x_edges``, for t > 0."""
        edges = checked_edges(x_edges)
        t = positive("t", t)
        with np.errstate(over="ignore"):
            xi = edges / t
        if not np.all(np.isfinite(xi)):
            raise ValueError(f"t = {t:g} is too small for these x_edges: x / t overflows (the averages would be NaN)")
        a_end, b_end = xi[:-1], xi[1:]
        sums_u, sums_v = np.zeros(a_end.size), np.zeros(a_end.size)
        for start, end, kind, data in self._pieces():
            lo, hi = np.clip(a_end, start, end), np.clip(b_end, start, end)
            if kind == "constant":
                sums_u += data[0] * (hi - lo)
                sums_v += data[1] * (hi - lo)
            else:
                du, dv = self._fan_integrals(data, lo, hi)
                sums_u += du
                sums_v += dv
        width = b_end - a_end
        return sums_u / width, sums_v / width
