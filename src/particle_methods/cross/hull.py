"""Exact entropy solution of the 1D aggregation equation with K = |x|/2 from any sum of polynomial bumps.

In mass coordinates (sticky paper, section 2; Brenier and Grenier) the level w of F moves at the speed
lambda(w) = M/2 - w (M the total mass), so before any collision it sits at the free-flight position

    Y_t(w) = X_0(w) + t (M/2 - w),    X_0 the quantile of rho0.

The entropy solution's quantile X_t is the derivative of the greatest convex minorant of
Psi_t(w) = int_0^w Y_t (the continuous Brenier-Grenier hull; Lax-Oleinik for the concave flux
M F/2 - F^2/2). Its Legendre transform gives the CDF and its antiderivative directly:

    A(t, x) = int_{-inf}^x F(t, .) = max_{0 <= w <= M} (x w - Psi_t(w)),   F(t, x) = the largest maximiser.

Along a bump's levels, parametrised by the initial position a (w = F_0(a)), Y_t(a) = a + t (M/2 - F_0(a))
has the slope 1 - t rho0(a): it increases except where t rho0 > 1, an interval around the top of each
bump (closed form for c (1 - s^2)^p). A maximiser lies on a piece where Y_t increases, at the root of
Y_t = x (or at a piece's end): the maximum over the few pieces is exact up to one monotone root per piece
(the safeguarded Newton iteration of :func:`~particle_methods.cross.profiles.monotone_root`, compiled with the free
flight and the maximum into one kernel). Aggregates (Dirac masses) are the jumps of F: the
x at which the best piece of a higher level overtakes the best of the lower ones, found by Brent's
method on x (the difference of the two maxima grows with x at the rate of the jump in w), with the masses
and levels on either side. Everything is exact up to rounding: F_0 and int s rho0 are polynomials, evaluated by the
stable recurrence of :class:`~particle_methods.blob.initial.Data1D` and in closed form.

The data of issue 29, ``two_bumps``, 2 (1 - ((x + 0.4)/0.3)^2)_+^2 + (1 - ((x - 0.5)/0.25)^2)_+^2 (mass
0.9067, not normalised), blows up in its left bump at t = 1/2 and in its right one at t = 1; the two
aggregates move towards each other and merge. Each bump is symmetric and one aggregate before the merger, so
every aggregate's position and the merger time follow from the conservation of each bump's centre of mass.

The data of issue 44, ``skewed_bumps`` (:data:`SKEWED_BUMPS`), are made so that they do not: a skewed bump whose
aggregate forms at its peak, off its centre of mass, and meets the other bump's aggregate while part of its mass is
still outside (the facts are listed there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..blob.initial import Data1D, power_mass_kernel
from ..jit import njit
from ..validation import (
    ParameterTypeError,
    finite_number,
    finite_result,
    finite_values,
    in_interval,
    instance,
    integer_at_least,
    nonnegative,
    one_of,
    positive,
)
from .profiles import MAX_ITERATIONS, limited, rtsafe_start_kernel, rtsafe_steps_kernel

#: Iterations of Brent's method allowed for an aggregate's position (it converges to rounding in about 10).
POSITION_STEPS = 80
#: Latest time: the positions are found to the rounding of a bracket of width about t M (1e-10 at t = 1e6).
MAX_TIME = 1e6
#: Largest work of one call, in squared bump counts summed over the solutions it builds: a solution with b bumps
#: finds each of its up to 2 b - 1 boundaries by Brent's method over the up to 2 b pieces, so it costs about b^2
#: units of 0.04 to 0.2 ms with the compiled kernels (two_bumps: 1 to 2 ms; 20 bumps 20 to 45 ms; 40 bumps 70 to
#: 160 ms), and 2000 units take well under a second (a minute before the kernels of issue 47, when the limit was
#: set). The pipeline's calls build one solution of two bumps at a time.
MAX_HULL_WORK = 2000
#: A jump of F smaller than this share of the mass is no aggregate (two pieces that meet continuously).
JUMP_SHARE = 1e-13
#: ... and at a gap of the data, where Brent's x may stop inside the upper piece (a false jump of up to about
#: sqrt(rounding / rho) rho, 1e-8 of the mass): the tails of two bumps that first touch are one aggregate only once it
#: holds this share of the mass.
GAP_JUMP_SHARE = 1e-6


def _positions(a) -> np.ndarray:
    """Finite positions ``a``, at most :data:`~particle_methods.cross.profiles.MAX_POINTS` of them."""
    return limited("a", finite_values("a", a))


@dataclass(frozen=True)
class Bump:
    """height (1 - s^2)_+^power with s = (x - centre)/radius left of the centre and (x - centre)/right_radius right
    of it (right_radius defaults to radius: the symmetric bump). Power 0 is the indicator of
    [centre - radius, centre + right_radius]; for power >= 1 the two halves meet with zero slope at the peak
    ``centre`` (the bump is C^1 there and at its ends), and the mass is height (radius + right_radius) M_1 / 2, M_1
    the unit bump's mass int_{-1}^1 (1 - u^2)^power du. A skewed bump's centre of mass is not its peak: it lies
    (right_radius - radius) / ((power + 1) M_1) to the right of it."""

    height: float
    centre: float
    radius: float
    power: int
    right_radius: float | None = None

    def __post_init__(self):
        positive("height", self.height)
        finite_number("centre", self.centre)
        positive("radius", self.radius)
        if self.right_radius is None:
            object.__setattr__(self, "right_radius", self.radius)
        positive("right_radius", self.right_radius)
        unit = Data1D("unit bump", self.power)
        object.__setattr__(self, "unit", unit)
        # The unit bump's mass and its moment from the left end to the peak, once: every level of a root iteration
        # needs them.
        object.__setattr__(self, "_unit_mass", unit.mass)
        object.__setattr__(self, "_unit_moment_at_peak", unit.moment_from_left(0.0))

    @property
    def left_end(self) -> float:
        return self.centre - self.radius

    @property
    def right_end(self) -> float:
        return self.centre + self.right_radius

    @property
    def mass(self) -> float:
        # (height/2) (radius + right_radius) is height radius to the last bit when the two radii agree.
        return self.height * 0.5 * (self.radius + self.right_radius) * self._unit_mass

    def scaled(self, a):
        """s = (a - centre)/radius left of the centre, (a - centre)/right_radius from it on (``a`` finite)."""
        with np.errstate(over="ignore"):  # an overflow is reported just below
            s = self._scaled(_positions(a))
        return finite_result("s", s, "a is too far from the centre: (a - centre)/radius overflows")

    def density(self, a):
        """The bump's density at the finite positions ``a``."""
        with np.errstate(over="ignore"):  # (far from the centre s overflows to +-inf, where the density is 0)
            return self._density(_positions(a))

    def left_integrals(self, a):
        """:meth:`_left_integrals` at the finite positions ``a``."""
        with np.errstate(over="ignore"):  # (far from the centre s overflows to +-inf: clipped to +-1)
            return self._left_integrals(_positions(a))

    # The unchecked versions, for the positions of this module's own root iterations (inside the bump's support).

    def _scaled(self, a):
        offset = np.asarray(a, dtype=np.float64) - self.centre
        return offset / np.where(offset < 0.0, self.radius, self.right_radius)

    def _density(self, a):
        # (s clipped to [-2, 2], where the bump is 0 beyond +-1: far positions overflow s to +-inf)
        return self.height * self.unit._density(np.clip(self._scaled(a), -2.0, 2.0))

    def _left_integrals(self, a):
        """(int_{-inf}^a of the bump, int_{-inf}^a x times the bump), with s = scaled(a), r = radius and
        k = right_radius/r right of the centre (k = 1 left of it), m_1(s) = int_0^s (1 - u^2)^p du and
        I(s) = int_{-1}^s u (1 - u^2)^p du: c r (M_1/2 + k m_1(s)) and
        c r (centre (M_1/2 + k m_1(s)) + r (k^2 I(s) + (1 - k^2) I(0))) (the right half is the unit bump
        stretched by right_radius: its mass and first moment about the centre scale by k and k^2). For the
        symmetric bump k = 1 and the two are c r (M_1/2 + m_1(s)) and c r (centre (M_1/2 + m_1(s)) + r I(s))."""
        s = np.clip(self._scaled(a), -1.0, 1.0)
        stretch = np.where(s > 0.0, self.right_radius / self.radius, 1.0)
        left = 0.5 * self._unit_mass + stretch * self.unit._mass_from_origin(s)
        square = stretch * stretch
        moment = square * self.unit._moment_from_left(s) + (1.0 - square) * self._unit_moment_at_peak
        scale = self.height * self.radius
        return scale * left, scale * (self.centre * left + self.radius * moment)

    def dense_interval(self, t: float):
        """The a where t rho0(a) > 1, as (low, high), or None:
        (1 - s^2)^p > 1/(c t) for |s| < sqrt(1 - (c t)^(-1/p)), scaled by each side's radius."""
        ct = self.height * nonnegative("t", t)
        if ct <= 1.0:
            return None
        half = 1.0 if self.power == 0 else math.sqrt(-math.expm1(-math.log(ct) / self.power))
        return self.centre - half * self.radius, self.centre + half * self.right_radius


@dataclass(frozen=True)
class BumpData:
    """A density made of bumps with disjoint supports, sorted left to right."""

    name: str
    bumps: tuple[Bump, ...]

    def __post_init__(self):
        instance("name", self.name, str)
        if not isinstance(self.bumps, tuple) or not self.bumps or not all(isinstance(b, Bump) for b in self.bumps):
            raise ParameterTypeError("bumps must be a non-empty tuple of Bump")
        ends = [(b.left_end, b.right_end) for b in self.bumps]
        if any(right > left for (_, right), (left, _) in zip(ends, ends[1:])):
            raise ValueError("bumps must be sorted left to right with disjoint supports")
        masses = np.array([b.mass for b in self.bumps])
        object.__setattr__(self, "_before", np.concatenate(([0.0], np.cumsum(masses)[:-1])))
        object.__setattr__(self, "_moments_before", np.concatenate(
            ([0.0], np.cumsum([b._left_integrals(b.right_end)[1] for b in self.bumps])[:-1])))
        # What the compiled kernels need of each bump, one row per bump (the columns _HEIGHT to _MOMENTS_BEFORE), and
        # the powers.
        object.__setattr__(self, "_table", np.array(
            [[b.height, b.centre, b.radius, b.right_radius, b._unit_mass, float(b._unit_moment_at_peak), before,
              moment] for b, before, moment in zip(self.bumps, self._before, self._moments_before)]))
        object.__setattr__(self, "_powers", np.array([b.power for b in self.bumps], dtype=np.int64))

    @property
    def mass(self) -> float:
        return float(sum(b.mass for b in self.bumps))

    @property
    def support(self) -> tuple[float, float]:
        return self.bumps[0].left_end, self.bumps[-1].right_end

    @property
    def peak(self) -> float:
        return max(b.height for b in self.bumps)

    def density(self, x):
        x = limited("x", finite_values("x", x))
        return sum(b._density(x) for b in self.bumps)

    def cdf(self, x):
        """F_0(x) = int_{-inf}^x rho0, exact: the bumps' masses before x plus the part of the bump holding x."""
        x = limited("x", finite_values("x", x))
        value = np.zeros(x.shape)
        for index, bump in enumerate(self.bumps):
            value = np.where(x >= bump.left_end, self._before[index] + bump._left_integrals(x)[0], value)
        return value

    def in_bump(self, index: int, a):
        """(F_0(a), int_{-inf}^a s rho0(s) ds) for a in the support of bump ``index``."""
        index = integer_at_least("index", index, 0, len(self.bumps) - 1)
        with np.errstate(over="ignore"):  # (far from the centre s overflows to +-inf: clipped to +-1)
            return self._in_bump(index, _positions(a))

    def _in_bump(self, index: int, a):
        """:meth:`in_bump` unchecked, for the positions of this module's own root iterations."""
        mass, moment = self.bumps[index]._left_integrals(a)
        return self._before[index] + mass, self._moments_before[index] + moment


TWO_BUMPS = BumpData("two bumps 2 (1 - ((x + 0.4)/0.3)^2)_+^2 + (1 - ((x - 0.5)/0.25)^2)_+^2",
                     (Bump(2.0, -0.4, 0.3, 2), Bump(1.0, 0.5, 0.25, 2)))
#: A skewed bump 1.3 (1 - s^2)_+^2 peaked at -0.1 (radius 0.8 on the left, 0.1 on the right: support [-0.9, 0])
#: and the symmetric 1.8 (1 - ((x - 0.25)/0.2)^2)_+^2 on [0.05, 0.45]. Facts of the exact solution (this module,
#: checked in tests/cross/test_cross_hull.py against a discrete hull and the SPD):
#:
#: - masses 0.624 (skewed), 0.384, total M = 1.008; the skewed bump's centre of mass starts at -0.31875 (its peak
#:   is 0.21875 to the right of it) and moves at M/2 - 0.624/2 = 0.192 until the merger;
#: - blow-ups at 1/1.8 = 0.5556 (right bump, at x = 0.25 + 0.5556 (M/2 - 0.624 - 0.192) = 0.0767) and
#:   1/1.3 = 0.7692 (skewed bump, at its peak's free flight x = -0.1390);
#: - the skewed bump's aggregate forms 0.0321 to the right of the centre-of-mass path and, at first, moves 0.2425
#:   slower than it (the mean velocity of the levels absorbed at the peak against that of the whole bump); the
#:   offset is 0.0148 at t = 0.9, 0.0083 at t = 1 and 0.0040 at the merger;
#: - alone, each bump would be one aggregate once its farthest end reaches its centre of mass: at
#:   2 (0.58125)/0.624 = 1.8630 (skewed, left end) and 2 (0.2)/0.384 = 1.0417 (right bump);
#: - the two aggregates merge at t = 1.1205477 (x = -0.09961), when the skewed bump's aggregate holds 0.57367 of
#:   its 0.624: 0.05033 of its mass (its left tail) is still outside.
SKEWED_BUMPS = BumpData("skewed bumps 1.3 (1 - s^2)_+^2 on [-0.9, 0] peaked at -0.1 + 1.8 (1 - ((x - 0.25)/0.2)^2)_+^2",
                        (Bump(1.3, -0.1, 0.8, 2, right_radius=0.1), Bump(1.8, 0.25, 0.2, 2)))
#: Data that only the hull solves (asymmetric); the symmetric data of :mod:`.profiles` are bumps too.
BUMP_DATA = {"two_bumps": TWO_BUMPS, "skewed_bumps": SKEWED_BUMPS}


def check_hull_work(data: BumpData, solutions: int, name: str = "data") -> None:
    """Refuse ``solutions`` exact solutions of ``data`` (a :class:`BumpData`) beyond :data:`MAX_HULL_WORK` (b^2 units
    each, b bumps); ``name`` is the caller's parameter that asks for them, which the errors name."""
    instance("data", data, BumpData)
    solutions = integer_at_least(name, solutions, 0)
    work = solutions * len(data.bumps) ** 2
    if work > MAX_HULL_WORK:
        raise ValueError(f"{name} ask for {solutions} exact solution(s) of {len(data.bumps)} bumps, {work} units of "
                         f"(bumps)^2, more than MAX_HULL_WORK = {MAX_HULL_WORK} (the hull's work is quadratic in the "
                         "number of bumps): use fewer bumps or times")


def bump_data(data) -> BumpData:
    """``data`` itself, or the data named by it: 'two_bumps', 'skewed_bumps', or a symmetric polynomial datum of
    :data:`~particle_methods.blob.initial.DATA_1D` ('smooth20', 'indicator', 'smooth10') as one bump."""
    if isinstance(data, BumpData):
        return data
    if isinstance(data, Data1D):
        return BumpData(data.name, (Bump(1.0, 0.0, 1.0, data.power),))
    if isinstance(data, str):
        from ..blob.initial import DATA_1D  # the symmetric data, as single bumps

        choices = {**BUMP_DATA, **{name: BumpData(d.name, (Bump(1.0, 0.0, 1.0, d.power),))
                                   for name, d in DATA_1D.items()}}
        return one_of("initial data", data, choices)
    raise ParameterTypeError(f"data must be a data name, a Data1D or a BumpData, got {data!r}")


@dataclass(frozen=True)
class _Piece:
    """Levels [w0, w1] of one bump, at positions [a0, a1], on which Y_t increases."""

    bump: int
    a0: float
    a1: float


# --- compiled kernels -------------------------------------------------------------------------------
# The root iterations of the hull called NumPy thousands of times on arrays of a few points (Brent's method on
# 1-point arrays, the bisections of the W1 distances), where the time was the dispatch of each operation (issue 47).
# These kernels compute the same numbers with the same floating-point operations, in the same order, point by
# point: Bump._left_integrals, Bump._density, the free flight and the maximum over the pieces
# (tests/cross/test_cross_hull.py compares them bit for bit with the NumPy versions); the root iteration's start and
# steps are monotone_root's own kernels.

#: Columns of BumpData._table, one row per bump.
_HEIGHT, _CENTRE, _RADIUS, _RIGHT_RADIUS, _UNIT_MASS, _UNIT_MOMENT_AT_PEAK, _BEFORE, _MOMENTS_BEFORE = range(8)


@njit
def _power(base, exponent):
    """base ** exponent as NumPy raises a float array to an integer: a square by one product, else libm's pow (with
    a float exponent: numba's pow of an integer exponent multiplies, which differs in the last bits). On AVX-512 CPUs
    NumPy's power is SVML's, whose last bits may differ from libm's (tests/cross/test_cross_hull.py then compares the
    kernels with the NumPy formulas to rounding)."""
    return base * base if exponent == 2 else math.pow(base, float(exponent))


@njit
def _flight(a, w, t, mass):
    """The free flight Y_t = a + t (M/2 - w) of the level w from a (module docstring)."""
    return a + t * (0.5 * mass - w)


@njit
def _psi(w, moment, t, mass):
    """Psi_t(w) = int_0^w Y_t = int_{-inf}^a s rho0 + t (M w/2 - w^2/2) (module docstring)."""
    return moment + t * (0.5 * mass * w - 0.5 * w * w)


@njit
def _levels_kernel(table, powers, index, t, mass, a, w, psi, y):
    """HullSolution._levels: (w, Psi_t(w), Y_t(w)) at the positions a of bump ``index``, into w, psi and y."""
    _in_bump_kernel(table, powers, index, a, w, psi)
    for j in range(a.size):
        psi[j] = _psi(w[j], psi[j], t, mass)
        y[j] = _flight(a[j], w[j], t, mass)


@njit
def _scaled_at(table, index, a):
    """Bump._scaled at one position a."""
    offset = a - table[index, _CENTRE]
    return offset / (table[index, _RADIUS] if offset < 0.0 else table[index, _RIGHT_RADIUS])


@njit
def _in_bump_kernel(table, powers, index, a, w, moment):
    """BumpData._in_bump (Bump._left_integrals, the unit bump's mass m_1 by power_mass_kernel) at the positions a,
    into w and moment."""
    s = np.empty(a.size)
    for j in range(a.size):
        s[j] = min(max(_scaled_at(table, index, a[j]), -1.0), 1.0)
    unit_mass = np.empty(a.size)
    power_mass_kernel(s, powers[index], unit_mass)
    height, centre, radius = table[index, _HEIGHT], table[index, _CENTRE], table[index, _RADIUS]
    scale = height * radius
    exponent = powers[index] + 1
    for j in range(a.size):
        stretch = table[index, _RIGHT_RADIUS] / radius if s[j] > 0.0 else 1.0
        left = 0.5 * table[index, _UNIT_MASS] + stretch * unit_mass[j]
        square = stretch * stretch
        unit_moment = -_power(max(1.0 - s[j] * s[j], 0.0), exponent) / (2.0 * exponent)
        bump_moment = square * unit_moment + (1.0 - square) * table[index, _UNIT_MOMENT_AT_PEAK]
        w[j] = table[index, _BEFORE] + scale * left
        moment[j] = table[index, _MOMENTS_BEFORE] + scale * (centre * left + radius * bump_moment)


@njit
def _density_at(table, powers, index, a):
    """Bump._density at one position a."""
    s = min(max(_scaled_at(table, index, a), -2.0), 2.0)
    unit = _power(max(1.0 - s * s, 0.0), powers[index]) if abs(s) <= 1.0 else 0.0
    return table[index, _HEIGHT] * unit


@njit
def _root_kernel(table, powers, index, t, mass, flight, target, low, high):
    """monotone_root's iteration (its start and steps: profiles.rtsafe_start_kernel, rtsafe_steps_kernel) for bump
    ``index``: the a in [low, high] with Y_t(a) = target (``flight``; the free flight Y_t = a + t (M/2 - F_0(a)) of
    the sticky paper's section 2, slope 1 - t rho0) or with F_0(a) = target (slope rho0); the bracket is the
    caller's (here, a piece where the function increases)."""
    low, high = low.copy(), high.copy()
    x, before_last, last = rtsafe_start_kernel(low, high)
    active = np.arange(x.size)
    for _ in range(MAX_ITERATIONS):
        if active.size == 0:
            break
        points = np.empty(active.size)
        for k in range(active.size):
            points[k] = x[active[k]]
        w, moment = np.empty(active.size), np.empty(active.size)
        _in_bump_kernel(table, powers, index, points, w, moment)
        value, slope = np.empty(active.size), np.empty(active.size)
        for k in range(active.size):
            xa = points[k]
            if flight:
                value[k] = _flight(xa, w[k], t, mass) - target[active[k]]
                slope[k] = 1.0 - t * _density_at(table, powers, index, xa)
            else:
                value[k] = w[k] - target[active[k]]
                slope[k] = _density_at(table, powers, index, xa)
        active = rtsafe_steps_kernel(x, low, high, before_last, last, active, value, slope)
    return x


@njit
def _best_kernel(table, powers, bumps, starts, ends, t, mass, x, value, level):
    """HullSolution._best: (value, largest maximiser w) of x w - Psi_t(w) over the pieces (bump, start, end), into
    value and level."""
    value[:] = -np.inf
    level[:] = 0.0
    a, w, moment = np.empty(x.size), np.empty(x.size), np.empty(x.size)
    end_levels, end_moments = np.empty(2), np.empty(2)
    for p in range(bumps.size):
        index, a0, a1 = bumps[p], starts[p], ends[p]
        _in_bump_kernel(table, powers, index, np.array([a0, a1]), end_levels, end_moments)
        y0, y1 = _flight(a0, end_levels[0], t, mass), _flight(a1, end_levels[1], t, mass)
        inside = np.empty(x.size, dtype=np.int64)
        count = 0
        for j in range(x.size):
            a[j] = a0 if x[j] <= y0 else a1
            if x[j] > y0 and x[j] < y1:
                inside[count] = j
                count += 1
        if count:
            targets = np.empty(count)
            for k in range(count):
                targets[k] = x[inside[k]]
            roots = _root_kernel(table, powers, index, t, mass, True, targets, np.full(count, a0), np.full(count, a1))
            for k in range(count):
                a[inside[k]] = roots[k]
        _in_bump_kernel(table, powers, index, a, w, moment)
        for j in range(x.size):
            v = x[j] * w[j] - _psi(w[j], moment[j], t, mass)
            if v > value[j] or (v == value[j] and w[j] > level[j]):
                value[j], level[j] = v, w[j]


class HullSolution:
    """Entropy solution at time t of F_t + (M F/2 - F^2/2)_x = 0 from bump data (module docstring).

    Attributes ``mass`` M, ``t``, ``aggregates`` (positions, masses, lower levels), the Dirac masses at t.
    Provides what the W1 distances need (:func:`particle_methods.norms.l1_to_step_function`): ``cdf``,
    ``antiderivative``, ``quantile``, ``quantile_integral``.
    """

    def __init__(self, data, t: float):
        self.data = bump_data(data)
        check_hull_work(self.data, 1)
        self.t = nonnegative("t", t)
        if self.t > MAX_TIME:
            raise ValueError(f"t = {t:g} is beyond MAX_TIME = {MAX_TIME:g}: the aggregates' positions are found in a "
                             "bracket of width about t M, to its rounding")
        self.mass = self.data.mass
        self._pieces = self._increasing_pieces()
        self._piece_bumps = np.array([piece.bump for piece in self._pieces], dtype=np.int64)
        self._piece_starts = np.array([piece.a0 for piece in self._pieces])
        self._piece_ends = np.array([piece.a1 for piece in self._pieces])
        self.aggregates = self._find_aggregates()
        positions, masses, levels = self.aggregates
        #: Mass held in Dirac masses at t.
        self.dirac_mass = float(masses.sum())
        #: Where F(t, .) is not smooth: the aggregates (jumps) and the free flight of every piece's ends (the
        #: bumps' ends, where rho0 is only C^1, and the turning points).
        flights = np.concatenate([self._levels(piece, np.array([piece.a0, piece.a1]))[2] for piece in self._pieces])
        self.kinks = np.unique(np.concatenate([positions, flights[np.isfinite(flights)]]))

    # --- free flight along the pieces -------------------------------------------------------------

    def _increasing_pieces(self):
        pieces = []
        for index, bump in enumerate(self.data.bumps):
            low, high = bump.left_end, bump.right_end
            dense = bump.dense_interval(self.t)
            if dense is None:
                pieces.append(_Piece(index, low, high))
            else:
                pieces += [_Piece(index, low, max(low, dense[0])), _Piece(index, min(high, dense[1]), high)]
        return pieces

    def _levels(self, piece, a):
        """(w, Psi_t(w), Y_t(w)) at the positions a of a piece."""
        w, psi, y = np.empty(a.size), np.empty(a.size), np.empty(a.size)
        _levels_kernel(self.data._table, self.data._powers, piece.bump, self.t, self.mass, a, w, psi, y)
        return w, psi, y

    def _best(self, x, start=0, stop=None):
        """(value, largest maximiser w) of x w - Psi_t(w) over the pieces start to stop (ties: the larger w): on each
        piece, at the root of Y_t = x or at an end (a compiled kernel)."""
        value, level = np.empty(x.size), np.empty(x.size)
        _best_kernel(self.data._table, self.data._powers, self._piece_bumps[start:stop], self._piece_starts[start:stop],
                     self._piece_ends[start:stop], self.t, self.mass, x, value, level)
        return value, level

    # --- aggregates ---------------------------------------------------------------------------------

    def _find_aggregates(self):
        """Jumps of F: for each boundary between consecutive pieces, the x where the pieces above overtake
        the pieces below (bisection on x), and the jump in levels there; boundaries at the same x are one
        aggregate."""
        pieces = self._pieces
        low, high = self.data.support
        bracket = (low - self.t * self.mass, high + self.t * self.mass)  # every Y_t lies within
        found = []
        for split in range(1, len(pieces)):

            def overtaking(x, split=split):
                point = np.array([x])
                return float(self._best(point, split)[0][0] - self._best(point, 0, split)[0][0])

            # (Where two pieces meet at one level, the difference is 0 over an interval of x and Brent's method
            # may not settle: any x of it finds no jump.)
            from scipy.optimize import brentq

            x = brentq(overtaking, *bracket, xtol=1e-300, rtol=4.0 * np.finfo(float).eps, maxiter=POSITION_STEPS,
                       disp=False)
            point = np.array([x])
            lower, upper = self._best(point, 0, split)[1][0], self._best(point, split)[1][0]
            # Across a gap of the data (F_0 flat: the level where one bump ends and the next begins), the two sides
            # tie over the interval of x between their ends' free flights, and Brent's x may stop a rounding error
            # inside the upper piece, where F grows continuously: a jump from that level below GAP_JUMP_SHARE is none.
            at_gap = np.any(np.abs(self.data._before[1:] - lower) <= JUMP_SHARE * self.mass)
            if upper - lower > (GAP_JUMP_SHARE if at_gap else JUMP_SHARE) * self.mass:
                found.append((x, float(lower), float(upper)))
        merged = []
        for x, lower, upper in found:
            # Boundaries inside one aggregate find the same two levels; distinct aggregates share none.
            if merged and lower < merged[-1][2] - JUMP_SHARE * self.mass:
                merged[-1] = (merged[-1][0], min(merged[-1][1], lower), max(merged[-1][2], upper))
            else:
                merged.append((x, lower, upper))
        positions = np.array([m[0] for m in merged])
        lowers = np.array([m[1] for m in merged])
        masses = np.array([m[2] - m[1] for m in merged])
        return positions, masses, lowers

    # --- what W1 needs ------------------------------------------------------------------------------

    def antiderivative(self, x):
        """int_{-inf}^x F(t, .) = max_w (x w - Psi_t(w))."""
        x = limited("x", finite_values("x", x))
        value, _ = self._best(x.ravel())
        return finite_result("int F(t, .)", value.reshape(x.shape), "x is too large: x F(t, x) overflows")

    def cdf(self, x):
        """F(t, x), right-continuous: the largest maximiser of x w - Psi_t(w)."""
        x = limited("x", finite_values("x", x))
        _, level = self._best(x.ravel())
        return np.clip(level, 0.0, self.mass).reshape(x.shape)

    def _free_quantile(self, w):
        """(Y_t(w), Psi_t(w)) at levels w off the aggregates: the initial quantile by one root per level."""
        data = self.data
        before = np.append(data._before, self.mass)
        # A level between two bumps' masses (F_0 flat over the gap) belongs to the left one: X_t is left-continuous.
        index = np.clip(np.searchsorted(before, w, side="left") - 1, 0, len(data.bumps) - 1)
        y, psi = np.empty_like(w), np.empty_like(w)
        for b, bump in enumerate(data.bumps):
            mine = index == b
            if not np.any(mine):
                continue
            low, high = bump.left_end, bump.right_end
            level = w[mine]
            a = _root_kernel(data._table, data._powers, b, self.t, self.mass, False, level, np.full(level.size, low),
                             np.full(level.size, high))
            # The bump's first and last levels sit at its ends (F_0 is flat there: a root would be any point of
            # the flat tail to rounding).
            a = np.where(level <= before[b], low, np.where(level >= before[b + 1], high, a))
            piece = _Piece(b, low, high)
            _, psi[mine], y[mine] = self._levels(piece, a)
        return y, psi

    def quantile(self, w):
        """X_t(w) = inf{x : F(t, x) >= w}: the aggregate's position on its levels, the free flight elsewhere."""
        w = limited("w", in_interval("w", w, 0.0, self.mass))
        flat = w.ravel()
        value, _ = self._free_quantile(flat)
        positions, masses, lowers = self.aggregates
        for x, m, lower in zip(positions, masses, lowers):
            value = np.where((flat >= lower) & (flat <= lower + m), x, value)
        return finite_result("X_t(w)", value.reshape(w.shape), "the data overflow")

    def quantile_integral(self, w):
        """int_0^w X_t = the convex minorant of Psi_t at w: Psi_t off the aggregates, linear across each."""
        w = limited("w", in_interval("w", w, 0.0, self.mass))
        flat = w.ravel()
        _, value = self._free_quantile(flat)
        positions, masses, lowers = self.aggregates
        if positions.size:
            _, start = self._free_quantile(lowers)
            for x, m, lower, psi in zip(positions, masses, lowers, start):
                value = np.where((flat > lower) & (flat < lower + m), psi + (flat - lower) * x, value)
        return finite_result("int_0^w X_t", value.reshape(w.shape), "the data overflow")


def aggregate_paths(data, times):
    """(positions, masses) of the aggregates at each of the ``times``, as lists of arrays (one per time)."""
    data = bump_data(data)
    if isinstance(times, np.ndarray) and times.ndim == 1:  # from the shape, before any copy of the times
        check_hull_work(data, times.size, "times")
    times = finite_values("times", times)
    if times.ndim != 1 or times.size == 0:
        raise ValueError(f"times must be a non-empty 1D array, got shape {times.shape}")
    check_hull_work(data, times.size, "times")
    if times.min() < 0.0 or times.max() > MAX_TIME:
        raise ValueError(f"times must lie in [0, MAX_TIME = {MAX_TIME:g}], got times from {times.min():g} to "
                         f"{times.max():g}")
    solutions = [HullSolution(data, float(t)) for t in times]
    return [s.aggregates[0] for s in solutions], [s.aggregates[1] for s in solutions]


def merger_time(data, low: float, high: float) -> float:
    """The time in [low, high] at which the number of aggregates drops, by bisection to rounding; ``low`` and
    ``high`` must bracket one such drop (more aggregates at ``low`` than at ``high``)."""
    low, high = nonnegative("low", low), nonnegative("high", high)
    if not low < high:
        raise ValueError(f"need low < high, got low = {low} and high = {high}")
    if high > MAX_TIME:
        raise ValueError(f"high = {high:g} is beyond MAX_TIME = {MAX_TIME:g}")
    data = bump_data(data)
    # Two solutions, then one per halving of [low, high] down to the spacing of the doubles at the merger: at least
    # as many as down to their spacing at high.
    halvings = math.ceil(math.log2(high - low) - math.log2(np.spacing(high)))
    check_hull_work(data, 2 + halvings, "low and high")
    count = lambda t: HullSolution(data, t).aggregates[0].size  # noqa: E731
    before, after = count(low), count(high)
    if not before > after:
        raise ValueError(f"low = {low} and high = {high} bracket no merger: {before} aggregates, then {after}")
    while True:
        middle = 0.5 * (low + high)
        if middle in (low, high):
            return high
        if count(middle) > after:
            low = middle
        else:
            high = middle
