"""Entropy admissibility of a sticky-particle state: the exact test of Remark 3.3.

The SPD with the velocities of section 1.1.3 carries the piecewise constant function

    u_n(t, x) = sum_{k : phi_k(t) <= x} m_k,        m_k = 1/n for the equal masses of section 1.1.3,

(the empirical CDF of section 1.1.3). With particles sorted by position and levels c_0 = 0 and
c_k = m_1 + ... + m_k, a cluster holding the particles a..b at position y is an upward jump of u
from u_- = c_{a-1} to u_+ = c_b. Such a function is a weak solution of (1.1),
d_t u + d_x Lambda(u) = 0, when every jump moves at its Rankine-Hugoniot speed

    sigma = (Lambda(u_+) - Lambda(u_-)) / (u_+ - u_-),                                   (RH)

and the weak solution is the entropy solution when every jump also satisfies Oleinik's condition

    (Lambda(u) - Lambda(u_-)) / (u - u_-)  >=  sigma  >=  (Lambda(u_+) - Lambda(u)) / (u_+ - u)
    for every u strictly between u_- and u_+,                                            (E)

that is (for u_- < u_+, the only jumps a CDF has) the graph of Lambda lies on or above its chord
from u_- to u_+. The SPD gives (RH) by construction: a cluster moves at the mean of its particles'
velocities n (Lambda(c_k) - Lambda(c_{k-1})) (conservation of momentum, section 1.1.2), a telescoping
sum equal to sigma. For a concave flux (E) holds for every upward jump, so u_n[x] is the entropy
solution with the discretised data for every n, x and t (Remark 3.3, with [5, Lemma 3.3]); for a
convex flux such as Burgers' (5.1) the graph lies below every chord, every upward jump is a
rarefaction and (E) fails (the SPD is then not entropic: the t/(4n) of Remark 3.3, Figure 2).

:func:`admissibility_violation` measures both conditions on a state (positions, velocities,
masses) and :func:`spd_state` gives the SPD's state at time t. The measure makes no use of the
flux's shape: it evaluates (E) at the levels inside each cluster and at ``points`` states evenly
spaced inside every level interval (c_{k-1}, c_k), so a single-particle cluster of Burgers' flux
(a jump of 1/n with no level inside) is seen too. Sampling can miss a violation confined between
two sampled states of a flux with wiggles finer than the sampling; it never reports one where
(E) holds, up to rounding: the difference quotients of (E) carry errors of about
eps max|Lambda| / (distance from the sampled state to u_- or u_+), that is
eps max|Lambda| n (points + 1) for equal masses.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    finite_values,
    integer_at_least,
    nonnegative,
    same_length,
)
from .spd import MAX_POSITIONS, checked_masses, spd_positions

#: States sampled inside each level interval (c_{k-1}, c_k) when the caller gives none.
DEFAULT_POINTS = 4

#: Most states per level interval: a larger number would only multiply the work.
MAX_POINTS = 1000


@dataclass(frozen=True)
class Admissibility:
    """The violations of (RH) and (E) by one state, both relative to ``speed_scale``."""

    rankine_hugoniot: float
    """Largest |w_k - sigma| over the particles, w_k a particle's velocity and sigma the (RH) speed of the
    jump its cluster carries, over ``speed_scale``."""
    entropy: float
    """Largest violation of (E) over the jumps and the sampled states, max(sigma - (Lambda(u) -
    Lambda(u_-)) / (u - u_-), (Lambda(u_+) - Lambda(u)) / (u_+ - u) - sigma, 0), over ``speed_scale``."""
    speed_scale: float
    """Largest |speed| compared: the velocities, the (RH) speeds and the difference quotients of (E)."""
    clusters: int
    """Number of clusters (jumps of u)."""

    @property
    def largest(self) -> float:
        """The largest violation, relative to ``speed_scale``: 0 for the entropy solution, up to rounding."""
        return max(self.rankine_hugoniot, self.entropy)

    def __post_init__(self):
        for name in ("rankine_hugoniot", "entropy", "speed_scale"):
            nonnegative(name, getattr(self, name))
        integer_at_least("clusters", self.clusters, 0)


def flux_values(flux, states: np.ndarray, name: str = "states") -> np.ndarray:
    """Lambda at ``states`` (named ``name`` in a refusal of the flux), checked: finite, one value per state."""
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    states = finite_values("states", states)
    try:
        values = flux(states)
    except (ValueError, TypeError) as error:  # the flux's own refusal (u^2/2 overflows): say at which states
        kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
        raise kind(f"flux refused {name}: {error}") from None
    values = finite_values("flux values", values)
    if values.size != states.size:
        raise ValueError(f"flux must return one value per state ({states.size}), got {values.size}")
    return values.ravel()


def checked_sampling(n: int, flux, points: int, fewest_points: int) -> int:
    """Refuse what a test of n particles against ``flux`` sampled at ``points`` states per level interval
    cannot take (a flux that is not callable, too many particles or sampled states); returns ``points``."""
    integer_at_least("number of particles n", n, 1, MAX_POSITIONS)
    fewest_points = integer_at_least("fewest_points", fewest_points, 0, MAX_POINTS)
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    points = integer_at_least("points", points, 0, MAX_POINTS)
    if points < fewest_points:
        raise ValueError(f"points must be at least fewest_points = {fewest_points}, got {points}")
    if n * (points + 1) > MAX_POSITIONS:
        raise ValueError(f"{n} particles with points = {points} give {n * (points + 1):.3g} sampled states, more "
                         f"than MAX_POSITIONS = {MAX_POSITIONS:.0e}: lower points")
    return points


def mass_levels(masses, particles, order) -> tuple[np.ndarray, np.ndarray]:
    """The masses (checked: finite, positive, one per particle of ``particles``) in the sorted ``order``, and
    the levels 0 = c_0 < c_1 < ... < c_n of their partial sums (unscaled: Lambda(c_k) depends on them)."""
    masses = finite_array("masses", masses)
    n = same_length(particles=finite_array("particles", particles), masses=masses)
    if not masses.min() > 0:
        raise ValueError(f"masses must be positive, got {masses.min()} at index {int(masses.argmin())}")
    try:
        order = np.asarray(order)
    except ValueError:  # ragged
        raise ParameterTypeError(f"order must be an array of integers, got {order!r:.80}") from None
    if order.dtype.kind not in "iu" or order.shape != (n,):
        raise ParameterTypeError(f"order must hold one integer index per particle ({n}), got {order!r:.80}")
    if order.min() < 0 or order.max() >= n or np.bincount(order, minlength=n).max() != 1:
        raise ValueError(f"order must be a permutation of 0 .. {n - 1}, got {order!r:.80}")
    masses = masses[order]
    with np.errstate(over="ignore"):
        levels = finite_result("the total of the masses", np.concatenate(([0.0], np.cumsum(masses))),
                               "the masses are too large")
    return masses, levels


def admissibility_violation(positions, velocities, flux, masses=None, points: int = DEFAULT_POINTS) -> Admissibility:
    """Violations of (RH) and (E) by the state ``positions``, ``velocities``, ``masses`` for the flux Lambda.

    Parameters
    ----------
    positions : positions of the n particles at time t, in any order (particles that crossed sort
        into the ranks they occupy; the function u they carry depends only on where the mass sits).
        Equal positions form one cluster.
    velocities : velocity of each particle at time t, in the order of ``positions``.
    flux : the flux Lambda of (1.1), a callable on arrays of states u.
    masses : the jump of u at each particle, positive, in the order of ``positions``; None for 1/n each
        (section 1.1.3: u_n is then the CDF of a probability measure, with levels k/n).
    points : states sampled strictly inside each level interval (c_{k-1}, c_k), at least 1.

    Returns the violations of both conditions relative to the largest speed compared
    (:class:`Admissibility`); :attr:`Admissibility.largest` is 0 up to rounding exactly when every
    cluster moves at the (RH) speed of its jump and every jump satisfies (E) at the sampled states.
    """
    positions = finite_array("positions", positions)
    velocities = finite_array("velocities", velocities)
    n = same_length(positions=positions, velocities=velocities)
    points = checked_sampling(n, flux, points, 1)
    order = np.argsort(positions, kind="stable")
    y, w = positions[order], velocities[order]
    starts = np.flatnonzero(np.concatenate(([True], y[1:] > y[:-1])))
    ends = np.append(starts[1:], n)  # one past each cluster's last particle
    if masses is None:
        levels = np.arange(n + 1) / n  # the levels of velocities_from_flux, so the same flux values
        cluster_mass = (ends - starts) / n
    else:
        sorted_masses, levels = mass_levels(masses, positions, order)
        cluster_mass = np.add.reduceat(sorted_masses, starts)
    level_values = flux_values(flux, levels, "the levels of the masses (their partial sums)")
    lower, upper = levels[starts], levels[ends]
    with np.errstate(over="ignore", invalid="ignore"):
        sigma = finite_result("a Rankine-Hugoniot speed (Lambda(u_+) - Lambda(u_-)) / (u_+ - u_-)",
                              (level_values[ends] - level_values[starts]) / cluster_mass,
                              "the flux values are too large, or differ too much across a small mass")

    # The states of (E): `points` inside each level interval, and the level closing it unless that
    # level closes the cluster too (u_+ itself is not strictly inside the jump).
    cluster = np.repeat(np.arange(starts.size), ends - starts)
    fractions = np.arange(1, points + 1) / (points + 1)
    inside = levels[:-1, None] + fractions[None, :] * np.diff(levels)[:, None]
    closing = np.ones(n, dtype=bool)
    closing[ends - 1] = False
    states = np.concatenate((inside.ravel(), levels[1:][closing]))
    owner = np.concatenate((np.repeat(cluster, points), cluster[closing]))
    lo, hi = lower[owner], upper[owner]
    strict = (states > lo) & (states < hi)  # a state rounded onto u_- or u_+ is no state of (E)
    states, owner, lo, hi = states[strict], owner[strict], lo[strict], hi[strict]
    values = flux_values(flux, states) if states.size else np.zeros(0)
    with np.errstate(over="ignore", invalid="ignore"):
        from_left = (values - level_values[starts][owner]) / (states - lo)
        to_right = (level_values[ends][owner] - values) / (hi - states)
        finite_result("a difference quotient of (E)", np.concatenate((from_left, to_right)),
                      "the flux values are too large, or differ too much across a small mass")

    speeds = np.abs(np.concatenate((w, sigma, from_left, to_right)))
    scale = float(speeds.max())
    if scale == 0.0:  # every speed compared is 0: both conditions hold exactly
        return Admissibility(0.0, 0.0, 0.0, int(starts.size))
    # Relative differences of numbers of size at most 1: no overflow whatever the speeds.
    s = sigma / scale
    rankine_hugoniot = float(np.abs(w / scale - s[cluster]).max())
    entropy = 0.0
    if states.size:
        entropy = float(max(0.0, np.max(s[owner] - from_left / scale), np.max(to_right / scale - s[owner])))
    return Admissibility(rankine_hugoniot, entropy, scale, int(starts.size))


def spd_state(x, v, t: float, masses=None) -> tuple[np.ndarray, np.ndarray]:
    """(positions, velocities) of the SPD at time ``t``: the state :func:`admissibility_violation` takes.

    The positions are :func:`~particle_methods.sticky.spd.spd_positions` (arguments as there). Each
    particle moves with its cluster (a run of equal positions), at the mass-weighted mean of the
    initial velocities of the cluster's particles: mass and momentum are conserved at collisions
    (section 1.1.2). With the velocities of section 1.1.3 that mean is the (RH) speed of the cluster's
    jump; the velocity at a collision time is the velocity just after it.
    """
    positions = spd_positions(x, v, t, masses)
    v = np.asarray(v, dtype=float)  # checked by spd_positions
    n = positions.size
    weights = np.ones(n) if masses is None else checked_masses(masses, positions)  # scaled below 1
    starts = np.flatnonzero(np.concatenate(([True], positions[1:] > positions[:-1])))
    sizes = np.diff(np.append(starts, n))
    # Weights of each particle within its cluster (summing to 1): the partial sums of weight * v stay
    # below max |v|, so the mean cannot overflow.
    share = weights / np.repeat(np.add.reduceat(weights, starts), sizes)
    velocities = np.repeat(np.add.reduceat(share * v, starts), sizes)
    return positions, velocities
