"""Instruments for the estimates of sections 3 and 4 (Proposition 3.2, (3.3), Lemma 4.2, Remark 4.3,
(4.5), (4.6), Corollary 4.6).

Scalar laws (section 3). The proof of Proposition 3.2 compares the SPD of n particles started at x
with the SPD of 2n particles started at the duplicated configuration x^ (x^_{2k-1} = x^_{2k} = x_k,
:func:`duplicated`); (3.3) bounds the L1 distance of their CDFs by t L_LC / (2n). Proposition 3.2
itself needs the entropy solution u_inf[x] from the discrete data H*mu_0[x]; it is exact here for
Burgers' flux (every atom opens into a fan, :class:`~particle_methods.sticky.exact.BurgersSolution`
of :func:`empirical_atoms`) and for the cubic flux of :func:`cubic_flux` from one atom
(:class:`CubicDiracSolution`, a shock followed by a fan).

Diagonal systems (section 4). :func:`psystem_constants` evaluates the constants L_C, L_USH, L_LC of
assumptions (C), (USH), (LC) and m = ceil(2 L_C / L_USH) of (4.5) for the p-system of section 5.2.2
in closed form. :func:`collision_record` runs the iterated TSPD step by step and starts the exact
MSPD (:func:`~particle_methods.sticky.multitype_events.mspd_exact`) from every iterate y for one step
Delta: a pair (alpha:i, beta:j), alpha < beta, is in R(y) when y^alpha_i < y^beta_j and has collided
by Delta when the lower type is no longer behind, z^alpha_i >= z^beta_j (by (USH) a pair meets once
and the lower type then leads), which gives N_Delta(y) of (4.3) and the count of (4.5) pair by pair.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..norms import w1_between_samples
from ..systems import PSystem, checked_system
from ..validation import (
    ParameterTypeError,
    finite_number,
    finite_values,
    in_interval,
    instance,
    integer_at_least,
    nonnegative,
    positive,
    real_array,
    sorted_array,
)
from .measures import Atoms, QuantileMeasure, checked_measure
from .mspd import MAX_STEPS, checked_configuration, mspd_positions
from .multitype_events import mspd_exact
from .spd import MAX_POSITIONS, spd_positions, velocities_from_flux

#: Largest d(d-1)/2 n^2 pair counters :func:`collision_record` keeps (80 MB of int64).
MAX_PAIRS = 10**7

#: Level at which the lower convex envelope of :func:`cubic_flux` on [0, 1] leaves its chord from 0 for
#: the flux itself: the tangency (Lambda(w) - Lambda(0)) / w = lambda(w), i.e. 2 w^2 / 3 = w / 2.
CUBIC_TANGENT = 0.75

#: L_LC of assumption (LC) for :func:`cubic_flux`: lambda(u) = u^2 - u has lambda' = 2u - 1 in [-1, 1].
CUBIC_LIPSCHITZ = 1.0


def cubic_speed(u):
    """lambda(u) = u^2 - u, the derivative of :func:`cubic_flux`. It trusts its caller's checks."""
    return u * u - u


def cubic_flux(u):
    """Lambda(u) = u^3/3 - u^2/2 on [0, 1]: concave on [0, 1/2], convex on [1/2, 1], so that the SPD holds
    clusters (shocks) and lone particles (fans) at once (neither Remark 3.3 case)."""
    u = in_interval("u", u, 0.0, 1.0)
    return u**3 / 3.0 - u**2 / 2.0


class CubicDiracSolution(QuantileMeasure):
    """Entropy solution at time t of (1.1) with :func:`cubic_flux` from delta_a (the Riemann problem 0 | 1).

    Since u jumps up, the solution follows the lower convex envelope of Lambda on [0, 1]: its chord from 0
    to the tangency level w* = 3/4 (:data:`CUBIC_TANGENT`), a shock of speed lambda(w*) = -3/16 carrying
    the mass w*, then Lambda itself, a fan with lambda(u) = (x - a)/t for u in [w*, 1]. Its quantile is
    X(w) = a + t lambda(max(w, w*)), and G(w) = a w + t (lambda(w*) min(w, w*) + Lambda(max(w, w*)) -
    Lambda(w*)).
    """

    def __init__(self, position: float, t: float):
        self.position = finite_number("position", position)
        self.t = nonnegative("t", t)

    def _quantile(self, w):
        return self.position + self.t * cubic_speed(np.maximum(w, CUBIC_TANGENT))

    def _quantile_integral(self, w):
        top = np.maximum(w, CUBIC_TANGENT)
        shock = cubic_speed(CUBIC_TANGENT) * np.minimum(w, CUBIC_TANGENT)
        fan = (top**3 - CUBIC_TANGENT**3) / 3.0 - (top**2 - CUBIC_TANGENT**2) / 2.0
        return self.position * w + self.t * (shock + fan)

    def _cdf(self, x):
        if self.t == 0.0:
            return np.where(x >= self.position, 1.0, 0.0)
        y = (x - self.position) / self.t
        inside = 0.5 * (1.0 + np.sqrt(np.maximum(1.0 + 4.0 * y, 0.0)))  # the root >= 1/2 of w^2 - w = y
        return np.where(y < cubic_speed(CUBIC_TANGENT), 0.0, np.where(y >= 0.0, 1.0, inside))


def _positions(name: str, x) -> np.ndarray:
    """A configuration of one type: a non-empty sorted finite 1D array of at most MAX_POSITIONS / 2 positions
    (its duplicate must fit too)."""
    x = sorted_array(name, x)
    integer_at_least(f"the number of positions of {name}", x.size, 1, MAX_POSITIONS // 2)
    return x


def empirical_atoms(x) -> Atoms:
    """The empirical measure mu_0[x] = (1/n) sum_k delta_{x_k} of a configuration, as :class:`Atoms` (equal
    positions merged into one atom of their total mass): the discrete data H*mu_0[x] of u_inf[x]."""
    x = _positions("x", x)
    positions, counts = np.unique(x, return_counts=True)
    return Atoms(positions, counts / x.size)


def duplicated(x) -> np.ndarray:
    """x^ of the proofs of Propositions 3.2 and 4.5: every particle of a configuration (a sorted row, or one
    sorted row per type) doubled, x^_{2k-1} = x^_{2k} = x_k; the empirical measures do not change (4.9)."""
    x = real_array("x", x)
    rows = sorted_array("x", x, ndim=max(x.ndim, 1))
    if rows.ndim > 2 or rows.size == 0:
        raise ValueError(f"x must be a non-empty configuration (n,) or (d, n), got shape {rows.shape}")
    integer_at_least("the number of positions of x", rows.size, 1, MAX_POSITIONS // 2)
    return np.repeat(rows, 2, axis=-1)


def sampled_configuration(measures, n: int, rng) -> np.ndarray:
    """A random configuration (d, n): for each measure m^gamma, n independent draws F^{-1}(U), U uniform on
    (0, 1) (exact quantiles), sorted. W1(mu_0[x(n)], m) -> 0 almost surely when m has a first moment, so
    such sequences satisfy (4.12) of Corollary 4.6 without being the discretisations (1.9) or (4.7)."""
    instance("measures", measures, (list, tuple))
    measures = [checked_measure("measures[gamma]", m) for m in measures]
    if not measures:
        raise ValueError("measures must hold at least one measure (one per type)")
    n = integer_at_least("n", n, 1, MAX_POSITIONS // len(measures))
    instance("rng", rng, np.random.Generator)
    # Integers 1 .. 2^53 - 1 over 2^53: uniform on the multiples of 2^-53 in (0, 1), never 0 or 1, where
    # the quantile of an unbounded law is infinite.
    levels = rng.integers(1, 2**53, size=(len(measures), n)) / 2.0**53
    return np.sort([m.quantile(w) for m, w in zip(measures, levels)], axis=-1)


class _SystemConstantsFields(NamedTuple):
    d: int
    speed_bound: float
    """L_C = max_gamma sup |lambda^gamma| over [0, 1]^d (assumption (C))."""
    hyperbolicity: float
    """L_USH = min_gamma (inf lambda^gamma - sup lambda^{gamma+1}) (assumption (USH))."""
    lipschitz: float
    """L_LC, the smallest constant of assumption (LC) for the l1 distance on [0, 1]^d."""
    crossings_bound: int
    """m = ceil(2 L_C / L_USH) of (4.5)."""


class SystemConstants(_SystemConstantsFields):
    """The constants of section 4 for one diagonal system (the fields of :class:`_SystemConstantsFields`),
    checked: d >= 1 types, finite L_C >= 0, L_USH and L_LC >= 0, an integer m >= 0."""

    __slots__ = ()

    def __new__(cls, d, speed_bound, hyperbolicity, lipschitz, crossings_bound):
        return super().__new__(cls, integer_at_least("d", d, 1, MAX_POSITIONS),
                               nonnegative("speed_bound", speed_bound), finite_number("hyperbolicity", hyperbolicity),
                               nonnegative("lipschitz", lipschitz),
                               integer_at_least("crossings_bound", crossings_bound, 0, 2**63))

    @property
    def constant_over_stability(self) -> float:
        """C / L_1 of (4.6): d (d - 1) L_LC m, the constant C for the smallest L_1 = 1 of Proposition 1.5."""
        return self.d * (self.d - 1) * self.lipschitz * self.crossings_bound


def psystem_constants(system: PSystem) -> SystemConstants:
    """L_C, L_USH, L_LC and m for the p-system of section 5.2.2, in closed form.

    lambda^{+-} = -+ A / cosh(a s), s = w^+ - w^- in [-1, 1], A the speed scale, a = asinh(kappa/2):
    |lambda| is largest at s = 0 (L_C = A) and smallest at |s| = 1, where cosh(a) = sqrt(1 + kappa^2/4),
    so L_USH = 2 A / cosh(a) (the value 2 l of (5.8)) and 2 L_C / L_USH = cosh(a). Both partial
    derivatives have the magnitude A a f(a |s|), f(y) = sinh(y) / cosh(y)^2, which rises up to y = asinh(1)
    (f = 1/2) and falls after: L_LC = A a f(min(a, asinh(1))), that is kappa / (4 nu) when kappa >= 2.
    """
    instance("system", system, PSystem)
    a, scale = system.a, system.speed_scale
    peak = min(a, math.asinh(1.0))
    cosh_a = math.sqrt(1.0 + 0.25 * system.kappa**2)
    return SystemConstants(d=system.d, speed_bound=scale, hyperbolicity=2.0 * scale / cosh_a,
                           lipschitz=scale * a * math.sinh(peak) / math.cosh(peak) ** 2,
                           crossings_bound=math.ceil(cosh_a))


class _CollisionRecordFields(NamedTuple):
    collisions: np.ndarray
    """N_Delta(y_{l-1}) of (4.3), l = 1..L: pairs of R(y_{l-1}) that collide within Delta in the MSPD from it."""
    step_distances: np.ndarray
    """||Phi_Delta(y_{l-1}) - Phi~_Delta(y_{l-1})||_1, l = 1..L: the left-hand side of Lemma 4.2."""
    pair_counts: np.ndarray
    """(d(d-1)/2, n, n): for each pair (alpha:i, beta:j), alpha < beta (type pairs in the order (0, 1), (0, 2),
    ..., (d-2, d-1)), the number of steps l counted in (4.5)."""
    smallest_shrink: float
    """Smallest (y^beta_j - y^alpha_i) - (z^beta_j - z^alpha_i) over the steps and pairs, z = Phi~_Delta(y): by
    Remark 4.3 at least L_USH Delta."""
    largest_collision_gap: float
    """Largest y^beta_j - y^alpha_i over the pairs counted in N_Delta(y), over the steps (-inf if none): by
    Remark 4.3 at most 2 L_C Delta."""
    mspd_distances: np.ndarray
    """||Phi(x; l Delta) - Phi~_Delta^l(x)||_1, l = 0..L: the left-hand side of (4.1) on the grid."""
    extent: float
    """Largest |position| of the iterates and of the MSPD: the scale of the positions."""


def _counts(name: str, values) -> np.ndarray:
    """Finite non-negative counts or distances, any shape, in their own dtype (integer counts stay integers)."""
    checked = finite_values(name, values)
    if checked.size and checked.min() < 0:
        raise ValueError(f"{name} must be non-negative, got {checked.min()}")
    return np.asarray(values) if np.asarray(values).dtype.kind in "iu" else checked


class CollisionRecord(_CollisionRecordFields):
    """The iterated TSPD y_0 = x, y_l = Phi~_Delta(y_{l-1}) against the exact MSPD, step by step (the fields of
    :class:`_CollisionRecordFields`), checked: finite non-negative counts and distances, a finite smallest shrink
    (+inf only with no type pair), a finite largest collision gap (-inf only if no pair collided)."""

    __slots__ = ()

    def __new__(cls, collisions, step_distances, pair_counts, smallest_shrink, largest_collision_gap, mspd_distances,
                extent):
        collisions = _counts("collisions", collisions)
        pair_counts = _counts("pair_counts", pair_counts)
        if not (smallest_shrink == math.inf and pair_counts.size == 0):
            smallest_shrink = finite_number("smallest_shrink", smallest_shrink)
        if not (largest_collision_gap == -math.inf and not collisions.any()):
            largest_collision_gap = finite_number("largest_collision_gap", largest_collision_gap)
        return super().__new__(cls, collisions, _counts("step_distances", step_distances), pair_counts,
                               smallest_shrink, largest_collision_gap, _counts("mspd_distances", mspd_distances),
                               nonnegative("extent", extent))


def _type_pairs(d: int):
    return [(alpha, beta) for alpha in range(d) for beta in range(alpha + 1, d)]


def _rows_distance(a: np.ndarray, b: np.ndarray) -> float:
    """(1/n) sum |a - b| over two configurations (d, n) with sorted rows: the normalised L1 distance of
    section 1.2.2, equal to W1^(d) of (1.10) (what :func:`~particle_methods.sticky.cases.configuration_distance`
    computes for any sizes), without its checks: called twice per step on the solvers' own output."""
    return float(np.abs(a - b).sum() / a.shape[-1])


def collision_record(x0, system, delta: float, steps: int) -> CollisionRecord:
    """Lemma 4.2, Remark 4.3, (4.5) and (4.1) on the iterated TSPD from ``x0`` (shape (d, n)), ``steps``
    steps of length ``delta``: from each iterate y the exact MSPD z = Phi_Delta(y) and the TSPD step
    Phi~_Delta(y), and the exact MSPD from x0 at the grid times (module docstring)."""
    x0 = checked_configuration("x0", x0, system)
    d = checked_system(system)
    delta = positive("delta", delta)
    steps = integer_at_least("steps", steps, 1, MAX_STEPS)
    if not math.isfinite(delta * steps):
        raise ValueError(f"delta * steps, the last time, overflows: delta = {delta:.3g} is too large")
    n = x0.shape[1]
    pairs = _type_pairs(d)
    if len(pairs) * n * n > MAX_PAIRS:
        raise ValueError(f"{len(pairs)} type pairs of n = {n} particles need {len(pairs) * n * n:.3g} pair counters, "
                         f"more than MAX_PAIRS = {MAX_PAIRS:.0e}")
    if (steps + 1) * x0.size > MAX_POSITIONS:
        raise ValueError(f"{steps + 1} grid times of {x0.size} particles exceed MAX_POSITIONS = {MAX_POSITIONS:.0e}")
    exact_path = mspd_exact(x0, system, delta * np.arange(steps + 1))
    counts = np.zeros((len(pairs), n, n), dtype=np.int64)
    collisions = np.zeros(steps, dtype=np.int64)
    step_distances = np.empty(steps)
    mspd_distances = np.empty(steps + 1)
    shrink, window, extent = math.inf, -math.inf, float(np.abs(exact_path).max())
    y = x0
    for step in range(steps):
        mspd_distances[step] = _rows_distance(exact_path[step], y)
        z = mspd_exact(y, system, [delta])[0]
        following = mspd_positions(y, system, delta, 1)
        for p, (alpha, beta) in enumerate(pairs):
            gap = y[beta][None, :] - y[alpha][:, None]
            collided = (gap > 0) & (z[beta][None, :] - z[alpha][:, None] <= 0)
            counts[p] += collided
            collisions[step] += int(collided.sum())
            if collided.any():
                window = max(window, float(gap[collided].max()))
            shrink = min(shrink, float((gap - (following[beta][None, :] - following[alpha][:, None])).min()))
        step_distances[step] = _rows_distance(z, following)
        extent = max(extent, float(np.abs(z).max()), float(np.abs(following).max()))
        y = following
    mspd_distances[steps] = _rows_distance(exact_path[steps], y)
    return CollisionRecord(collisions, step_distances, counts, shrink, window, mspd_distances, extent)


def doubling_distance(flux, x, t: float) -> float:
    """||u_n[x](t) - u_2n[x^](t)||_L1 of (3.3): the W1 distance between the SPD of n particles from x and that
    of 2n particles from the duplicated configuration x^, each with the velocities of section 1.1.3."""
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    x = _positions("x", x)
    t = nonnegative("t", t)
    n = x.size
    return w1_between_samples(spd_positions(x, velocities_from_flux(flux, n), t),
                              spd_positions(duplicated(x), velocities_from_flux(flux, 2 * n), t))
