"""Measures of the long-time behaviour of particle runs (section 6.2): collapse, concentration, peaks.

- :func:`collapse_times`: whether a shrinking size (the smallest particle width, the spread of
  the centres) collapses in finite time, from the inverse of its logarithmic shrink rate,
  g(t) = -1 / (d log s / dt). For s ~ (T - t)^beta, g = (T - t)/beta falls linearly to 0 at the
  collapse time T; for exponential shrinking g is constant, for algebraic shrinking (s ~ t^-p) it
  grows. A line fitted to g over a window gives a slope (negative: finite-time collapse) and,
  when negative, the extrapolated collapse time, which does not depend on where the run stops.
- :func:`side_concentration`: on each side of x = 0, the width of the smallest interval holding a
  fraction of that side's mass, and the mass within a radius of the side's densest particle.
  Dirac masses forming: width to 0, mass near the peak to the side's mass; an L1 profile: both
  settle.
- :func:`shrink_rate_ratios`: whether such a width keeps shrinking at least exponentially (or algebraically):
  its shrink rate (or local exponent) over each window against that over the window before.
- :func:`peak_count`: local maxima of a sampled density standing out from their surroundings.
- :func:`l1_distance`: the L1 distance between two particle reconstructions (2.27), for the steadiness of a
  profile: its change over a time window.
"""

from __future__ import annotations

import math

import numpy as np

from ..validation import finite_array, finite_number, in_interval, instance, integer_at_least, positive, same_length
from .solver import MAX_STEPS, Particles, Simulation

#: A shrink rate (per unit time) and a slope of g below these are zero up to rounding.
RATE_ZERO = 1e-12
SLOPE_ZERO = 1e-9
#: A centre within SIDE_ROUNDING times the largest |centre| of x = 0 sits at 0 up to rounding: on neither side.
#: (The particle at 0 of a symmetric run drifts by rounding alone, 7e-16 in 6000 steps; the grid steps are 1e-3
#: and more of a support of size 1.)
SIDE_ROUNDING = 1e-12


def shrink_rate_inverse(times, sizes) -> np.ndarray:
    """g(t) = -1 / (d log s / dt) at every recorded time (centred differences)."""
    times = finite_array("times", times)
    sizes = finite_array("sizes", sizes)
    same_length(times=times, sizes=sizes)
    if times.size < 3 or np.any(np.diff(times) <= 0):
        raise ValueError("times must be increasing, with at least three records")
    if np.any(sizes <= 0):
        raise ValueError("sizes must be positive")
    rate = -np.gradient(np.log(sizes), times)
    moving = np.abs(rate) > RATE_ZERO
    return np.where(moving, 1.0 / np.where(moving, rate, 1.0), np.inf)


def collapse_times(times, sizes, windows) -> tuple[np.ndarray, np.ndarray]:
    """Slope of g(t) and extrapolated collapse time (``inf`` unless the slope is negative) for
    every window, given as fractions (start, end) of the run's duration."""
    times = finite_array("times", times)
    g = shrink_rate_inverse(times, sizes)
    windows = in_interval("windows", finite_array("windows", windows, ndim=2), 0.0, 1.0)
    if windows.shape[1] != 2:
        raise ValueError(f"windows must be pairs (start, end), got shape {windows.shape}")
    span = times[-1] - times[0]
    slopes, collapse = [], []
    for start, end in windows:
        inside = (times >= times[0] + start * span - 1e-12) & (times <= times[0] + end * span + 1e-12)
        if inside.sum() < 3 or not np.all(np.isfinite(g[inside])):
            raise ValueError(f"windows: the window ({start}, {end}) holds fewer than 3 records of the times where "
                             f"g is finite (the sizes shrink or grow there)")
        slope, intercept = np.polyfit(times[inside], g[inside], 1)
        slope = 0.0 if abs(slope) <= SLOPE_ZERO else slope  # exponential shrinking: 0 up to rounding
        slopes.append(slope)
        collapse.append(-intercept / slope if slope < 0 else math.inf)
    return np.array(slopes), np.array(collapse)


def side_concentration(centres, weights, peak_values, fraction: float, radius: float):
    """(widths, masses) on the sides x < 0 and x > 0.

    widths[s]: the smallest interval holding ``fraction`` of side s's mass (particles as points);
    masses[s]: the mass of the particles within ``radius`` of side s's particle with the largest
    ``peak_values`` (the density at the centres), as a fraction of the total mass. A particle at
    x = 0 belongs to neither side, nor does one within rounding of it (:data:`SIDE_ROUNDING`): the
    particle at 0 of a symmetric run moves off it by rounding alone, to either side.
    """
    centres = finite_array("centres", centres)
    weights = finite_array("weights", weights)
    peak_values = finite_array("peak_values", peak_values)
    same_length(centres=centres, weights=weights, peak_values=peak_values)
    fraction = finite_number("fraction", fraction)
    if not 0.0 < fraction <= 1.0:
        raise ValueError(f"fraction must lie in (0, 1], got {fraction}")
    radius = positive("radius", radius)
    total = weights.sum()
    if total <= 0:
        raise ValueError("weights must have a positive sum")
    middle = SIDE_ROUNDING * np.abs(centres).max()
    widths, masses = [], []
    for side in (centres < -middle, centres > middle):
        if not side.any():
            raise ValueError("centres must hold particles on both sides of x = 0")
        order = np.argsort(centres[side])
        x, m = centres[side][order], weights[side][order]
        cumulative = np.concatenate([[0.0], np.cumsum(m)])
        need = fraction * cumulative[-1] * (1 - 1e-12)
        # for every first particle i, the first j with mass(i..j) >= need
        last = np.searchsorted(cumulative, cumulative[:-1] + need, side="left") - 1
        valid = last < x.size
        widths.append(float((x[last[valid]] - x[np.flatnonzero(valid)]).min()))
        peak = centres[side][np.argmax(peak_values[side])]
        masses.append(float(weights[side][np.abs(centres[side] - peak) <= radius].sum() / total))
    return np.array(widths), np.array(masses)


def peak_count(density, prominence: float = 0.05) -> int:
    """Local maxima of a sampled density whose prominence is at least ``prominence`` times their
    own height."""
    from scipy.signal import find_peaks  # here: scipy.signal takes 0.8 s to import, which most jobs never need

    density = finite_array("density", density)
    prominence = positive("prominence", prominence)
    peaks, properties = find_peaks(density, prominence=0.0)
    with np.errstate(over="ignore"):  # a threshold beyond the double range is inf: no peak counts
        return int(np.sum(properties["prominences"] >= prominence * density[peaks]))


def excess_variation(x, density) -> float:
    """TV(rho) / (2 (max over x < 0 + max over x > 0)) - 1 for a density sampled at increasing x that
    vanishes at both ends: 0 (or below, with a valley between) for one peak on each side, positive
    when ripples add variation. A small bump adds variation in proportion to its height only."""
    x = finite_array("x", x)
    density = finite_array("density", density)
    same_length(x=x, density=density)
    if np.any(np.diff(x) <= 0):
        raise ValueError("x must be increasing")
    left, right = density[x < 0], density[x > 0]
    if left.size == 0 or right.size == 0 or left.max() <= 0 or right.max() <= 0:
        raise ValueError("the density needs mass on both sides of x = 0")
    variation = np.abs(np.diff(density)).sum() + density[0] + density[-1]
    return float(variation / (2 * (left.max() + right.max())) - 1.0)


def shrink_rate_ratios(times, sizes, window: float, since: float, floor: float, algebraic: bool = False):
    """Whether a size keeps shrinking at least exponentially (or, with ``algebraic``, at least algebraically),
    window after window, from ``since`` on.

    The shrink rate over the window ending at a recorded t is r(t) = log(s(t - window)/s(t))/window
    (s(t - window) at the latest record not after it). For every recorded t with t - 2 window >= since,
    the ratio r(t)/max(r(t - window), floor) compares the rate with the one a window earlier: 1 for
    exponential shrinking, above 1 when it speeds up, exp(-mu window) for a size settling at rate mu to a
    positive limit, and about 0 for a settled size (its rate below ``floor``, the rate of a size the caller
    calls steady, > 0). With ``algebraic`` the window's log-shrink is divided by log(t/(t - window)) instead of
    the window: the local exponent p of s ~ t^-p, so that the ratio is 1 for algebraic shrinking, above 1 for
    exponential shrinking (its exponent grows like t), and tends to 0 for a size settling to a positive limit
    (the floor is the same log-shrink per window). Unlike a shrink factor over the end of the run, no ratio
    depends on where the run stops: a longer run adds ratios. Returns (t, ratios), one per such record.
    """
    times = finite_array("times", times)
    sizes = finite_array("sizes", sizes)
    same_length(times=times, sizes=sizes)
    window = positive("window", window)
    since = finite_number("since", since)
    floor = positive("floor", floor)
    instance("algebraic", algebraic, bool)
    if np.any(sizes <= 0):
        raise ValueError("sizes must be positive")
    if np.any(np.diff(times) <= 0):
        raise ValueError("times must be increasing")

    def earlier(t):  # the latest record <= t (to rounding), -1 before the first
        return np.searchsorted(times, t + 1e-9 * window, side="right") - 1

    ends = np.flatnonzero(times - 2.0 * window >= since - 1e-9 * window)
    if ends.size == 0:
        raise ValueError(f"no recorded time two windows (window = {window:g}) after since = {since:g}")
    middle = earlier(times[ends] - window)
    first = earlier(times[middle] - window)
    if np.any(first < 0):
        raise ValueError("`since` lies before the first record")
    if algebraic and times[first].min() <= 0:
        raise ValueError("the algebraic reading needs `since` after t = 0 (it divides by log(t / (t - window)))")
    rate = np.log(sizes[middle] / sizes[ends]) / window
    before = np.maximum(np.log(sizes[first] / sizes[middle]) / window, floor)
    if algebraic:  # the same log-shrinks (and floor), per unit of log t instead of t
        exponent = rate / np.log(times[ends] / times[middle])
        return times[ends], exponent / (before / np.log(times[middle] / times[first]))
    return times[ends], rate / before


def concentration_series(simulation, fraction: float, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`side_concentration` at every recorded step of a :class:`~.solver.Simulation`, the
    densest particle found from the density at the centres: arrays of shape (records, 2)."""
    instance("simulation", simulation, Simulation)
    widths, masses = [], []
    for index in range(simulation.steps.size):
        particles = simulation.at(index)
        w, m = side_concentration(particles.centres, particles.weights, particles.density(particles.centres),
                                  fraction, radius)
        widths.append(w)
        masses.append(m)
    return np.array(widths), np.array(masses)


#: Gauss-Legendre nodes per part of :func:`l1_distance` (exact for the difference of two cubics), and parts per
#: polynomial piece (the kink of |.| where the difference changes sign inside a part costs a share of about the
#: part's length squared: 1e-4 relative with 8 parts, against 1e-2 with one).
L1_NODES = 3
L1_PARTS = 8
_L1_NODES, _L1_WEIGHTS = np.polynomial.legendre.leggauss(L1_NODES)


def l1_distance(first, second) -> float:
    """int |rho_a - rho_b| for two :class:`~.solver.Particles` reconstructions (2.27): every piece between
    consecutive shape breaks of either, where both are polynomials, is cut into L1_PARTS parts integrated by
    Gauss-Legendre (exact for the difference, up to the kink of |.| where it changes sign inside a part)."""
    instance("first", first, Particles)
    instance("second", second, Particles)
    breaks = np.union1d(first.breaks, second.breaks)
    points = np.append(breaks[:-1, None] + np.diff(breaks)[:, None] * np.arange(L1_PARTS) / L1_PARTS, breaks[-1])
    a, b = points[:-1], points[1:]
    nodes = (0.5 * (a + b)[:, None] + 0.5 * (b - a)[:, None] * _L1_NODES).ravel()
    difference = np.abs(first.density(nodes) - second.density(nodes)).reshape(a.size, L1_NODES)
    return float(np.sum(0.5 * (b - a) * (difference @ _L1_WEIGHTS)))


def profile_changes(simulation, window: float, every: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """(t, ||rho_h(t) - rho_h(t')||_L1) at every ``every``-th record t of a :class:`~.solver.Simulation` with a
    record t' at or before t - ``window`` (t' the latest such): how much the profile moves over one window."""
    instance("simulation", simulation, Simulation)
    window = positive("window", window)
    every = integer_at_least("every", every, 1, MAX_STEPS + 1)  # a run records at most MAX_STEPS + 1 times
    times = simulation.times
    earlier = np.searchsorted(times, times - window + 1e-9 * window, side="right") - 1
    usable = np.flatnonzero(earlier >= 0)
    usable = usable[usable % every == 0]
    return times[usable], np.array([l1_distance(simulation.at(int(i)), simulation.at(int(earlier[i])))
                                    for i in usable])
