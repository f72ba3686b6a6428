"""A method's aggregates against the exact ones: where they sit and when they merge (data 'two_bumps', :mod:`.hull`).

Every output of :mod:`.methods` is read as point masses on the line: the SPD, particle and blob methods' particles,
the LTP and SP particles' centres and weights, and the jumps of a finite-volume F at the cell edges
(:func:`cell_atoms`). An exact aggregate holds the levels [c, c + m] of the cumulative mass
(``HullSolution.aggregates``: positions, masses, lower levels c); a method's version of it is the mean of its
quantile X_h(w) over those levels,

    centre = (1/m) int_c^{c+m} X_h(w) dw,

which is the aggregate's position when the method holds it as one point mass, changes continuously with the
method's masses (part of an atom counts for the part of its levels inside [c, c + m]) and needs no threshold. The
merger of two aggregates is read the same way for every method: the first time the centres of the two exact
aggregates' levels (taken before the merger) come within the method's own length, the width over which its
clusters are smoothed (the blob's delta, SP's eps, a finite-volume cell); any fixed multiple of it gives the same
order in h. The SPD's clusters are true point masses, so its merger is the time its two heavy clusters become one
(:func:`spd_merger`).
"""

from __future__ import annotations

import numpy as np

from ..finite_volume.grids import MAX_CELLS
from ..finite_volume.scalar import MAX_CELL_STEPS
from ..sticky.spd import spd_positions
from ..validation import (
    finite_array,
    finite_result,
    finite_values,
    instance,
    integer_at_least,
    nonnegative,
    positive,
    same_length,
    sorted_array,
)
from . import methods
from .hull import HullSolution, bump_data

#: Most readings of the gap one :func:`godunov_merger` call takes (a run of the scheme and the centres of two level
#: ranges each, about 2 ms on 64 cells): (high - low) / (chunk steps) + chunk. The pipeline's settings take about 300.
MAX_GAP_READINGS = 10**4


def level_ranges(solution: HullSolution) -> np.ndarray:
    """The levels [c, c + m] of the exact aggregates of ``solution``: shape (aggregates, 2)."""
    instance("solution", solution, HullSolution)
    _, masses, lowers = solution.aggregates
    return np.column_stack((lowers, lowers + masses))


def _ranges(ranges) -> np.ndarray:
    ranges = finite_values("ranges", ranges)
    if ranges.ndim != 2 or ranges.shape[1] != 2:
        raise ValueError(f"ranges must be of shape (r, 2), got {ranges.shape}")
    return ranges


def _atoms(positions, masses):
    x = finite_values("positions", positions)
    m = finite_array("masses", masses)
    if x.ndim not in (1, 2) or x.shape[-1] != m.size or m.ndim != 1 or m.size == 0:
        raise ValueError(f"positions must be of shape (n,) or (times, n) with n = len(masses) > 0, got {x.shape} "
                         f"and {m.shape}")
    if np.any(m < 0):
        raise ValueError("masses must be non-negative")
    return x, m


def level_centres(positions, masses, ranges) -> np.ndarray:
    """Mean of the quantile of sum_k masses[k] delta_{positions[k]} over each level range [lo, hi] of ``ranges``
    (shape (r, 2), 0 <= lo < hi): one value per range, or per time and range if ``positions`` holds one row per
    time (shape (times, n)). A range beyond the atoms' total mass has no quantile there: ValueError."""
    x, m = _atoms(positions, masses)
    ranges = _ranges(ranges)
    rows = np.atleast_2d(x)
    out = np.empty((rows.shape[0], ranges.shape[0]))
    for j, level_range in enumerate(ranges):
        out[:, j] = _level_means(rows, rows, m, level_range)
    finite_result("the centres", out, "positions or masses too large: the quantile's integral overflows")
    return out if x.ndim == 2 else out[0]


def level_spreads(positions, masses, ranges, targets) -> np.ndarray:
    """Mean distance (1/m) int_c^{c+m} |X_h(w) - x_a| dw of the quantile of sum_k masses[k] delta_{positions[k]}
    from ``targets`` x_a over each level range [c, c + m] of ``ranges``: the W1 distance, per unit mass, between the
    method's mass on an exact aggregate's levels and the aggregate (0 when the method holds those levels at x_a; a
    wrong position, or part of those levels held elsewhere, raises it; mass the method gathers from other levels onto
    x_a does not, which W1 over all levels sees). One value per range (``positions`` of shape
    (n,)) or per time and range (shape (times, n)); ``targets`` one value per range."""
    x, m = _atoms(positions, masses)
    ranges = _ranges(ranges)
    targets = finite_values("targets", targets)
    if targets.shape != (ranges.shape[0],):
        raise ValueError(f"targets must hold one position per level range ({ranges.shape[0]}), got {targets.shape}")
    rows = np.atleast_2d(x)
    out = np.empty((rows.shape[0], ranges.shape[0]))
    for j, target in enumerate(targets):
        out[:, j] = _level_means(np.abs(rows - target), rows, m, ranges[j])
    finite_result("the spreads", out, "positions or targets too large: their distances overflow")
    return out if x.ndim == 2 else out[0]


def _level_means(values, rows, masses, level_range):
    """Mean over the levels [lo, hi] of ``values`` carried by the atoms of ``rows`` (sorted by position)."""
    lo, hi = level_range
    if not 0.0 <= lo < hi:
        raise ValueError(f"ranges must hold levels 0 <= lo < hi, got {list(level_range)}")
    order = np.argsort(rows, axis=1, kind="stable")
    levels = np.concatenate((np.zeros((rows.shape[0], 1)), np.cumsum(masses[order], axis=1)), axis=1)
    # (a range may end at the total mass, which the running sum of n masses reaches only to n rounding errors)
    if hi > levels[:, -1].min() * (1.0 + max(1e-12, 4.0 * masses.size * np.finfo(float).eps)):
        raise ValueError(f"ranges reach above the total mass {float(levels[0, -1])!r} of the masses: "
                         f"{[float(level) for level in level_range]}")
    overlap = np.clip(np.minimum(levels[:, 1:], hi) - np.maximum(levels[:, :-1], lo), 0.0, None)
    with np.errstate(over="ignore", invalid="ignore"):
        return np.sum(overlap * np.take_along_axis(values, order, axis=1), axis=1) / (hi - lo)


def two_body_gap(order: int) -> float:
    """The blob method's gap at the exact merger, over delta, of two point masses that hold all the mass M (both
    bumps collapsed), with no fitted parameter. With K_delta = K * psi_delta, K = |x|/2 and psi of (4.1) a mixture
    sum_i a_i G_{s_i}, their gap g obeys g' = -(M/2) f(g/delta), f(u) = sum_i a_i erf(u/s_i), against g' = -M/2
    for the exact aggregates (f -> 1 beyond a few delta, so the two gaps agree long before the merger). In
    u = g/delta and tau = (M/2)(t* - t)/delta the exact gap is tau and the blob's solves du/dtau = f(u); matching
    them far from the merger gives u(t*) = u*, the root of u* = int_{u*}^inf (1/f(u) - 1) du (0.2933 for m = 4),
    the same at every h and M."""
    from scipy.integrate import quad
    from scipy.optimize import brentq
    from scipy.special import erf

    from ..blob.mollifiers import mollifier

    psi = mollifier(order, 1)

    def f(u):
        return sum(a * erf(u / s) for a, s in zip(psi.weights, psi.widths))

    # Beyond u = 40 s_max, 1/f - 1 is below 1e-300: the integral ends there.
    end = 40.0 * max(psi.widths)

    def excess(u):
        return quad(lambda v: 1.0 / f(v) - 1.0, u, end, limit=200, epsabs=1e-15, epsrel=1e-13)[0] - u

    return float(brentq(excess, 1e-3, 5.0, xtol=1e-15, rtol=4.0 * np.finfo(float).eps))


def cell_atoms(edges, values, mass: float):
    """(positions, masses) of the point masses whose cumulative mass is the finite-volume F: values[i] on
    [edges[i], edges[i+1]), 0 left of the grid and ``mass`` right of it, so a jump at every edge."""
    edges = finite_array("edges", edges)
    values = finite_array("values", values)
    mass = positive("mass", mass)
    if edges.size != values.size + 1 or values.size == 0:
        raise ValueError(f"edges must hold one more value than values (at least one), got {edges.size} and "
                         f"{values.size}")
    jumps = np.diff(np.concatenate(([0.0], values, [mass])))
    if np.any(jumps < -1e-12 * mass):
        raise ValueError("values must be non-decreasing from 0 to mass (a cumulative mass)")
    return edges, np.maximum(jumps, 0.0)


def first_within(times, gaps, threshold: float) -> float:
    """First time at which ``gaps`` (sampled at the increasing ``times``) falls to ``threshold``, linearly
    interpolated between the two samples around it. ValueError if it never does, or already did at the first
    sample (no crossing to locate)."""
    t = finite_array("times", times)
    g = finite_array("gaps", gaps)
    same_length(times=t, gaps=g)
    threshold = positive("threshold", threshold)
    if t.size < 2 or np.any(t[1:] <= t[:-1]):
        raise ValueError("times must be increasing, at least two")
    below = np.flatnonzero(g <= threshold)
    if below.size == 0 or below[0] == 0:
        raise ValueError(f"gaps must fall to the threshold {threshold!r} after the first sample, got {g[[0, -1]]} "
                         "at the first and last")
    i = below[0]
    # The share of the step at which the gap reaches the threshold, in [0, 1) (the gap falls by more than its
    # excess), with the three values scaled by a power of two (exactly) so that their differences cannot overflow.
    scale = np.ldexp(1.0, -max(int(np.frexp(max(abs(g[i - 1]), abs(g[i])))[1]), 0))
    share = (g[i - 1] * scale - threshold * scale) / (g[i - 1] * scale - g[i] * scale)
    crossing = (1.0 - share) * t[i - 1] + share * t[i]
    return finite_result("the crossing time", float(crossing), "times too large: their interpolation overflows")


def gap_path(positions, masses, ranges) -> np.ndarray:
    """Distance between the centres (:func:`level_centres`) of the two level ranges at each row of ``positions``."""
    ranges = _ranges(ranges)
    if ranges.shape[0] != 2:
        raise ValueError(f"a merger needs two level ranges, got {ranges.shape[0]}")
    x, m = _atoms(positions, masses)
    centres = level_centres(np.atleast_2d(x), m, ranges)
    return np.abs(centres[:, 1] - centres[:, 0])


def heavy_clusters(positions, masses, share: float) -> np.ndarray:
    """Positions, increasing, of the clusters (particles at one position) holding at least ``share`` of the mass."""
    x, m = _atoms(positions, masses)
    if x.ndim != 1:
        raise ValueError(f"positions must be one-dimensional, got shape {x.shape}")
    share = positive("share", share)
    values, index = np.unique(x, return_inverse=True)
    totals = np.bincount(index.ravel(), weights=m)
    with np.errstate(over="ignore"):  # (a share beyond the double range: no cluster holds it)
        return values[totals >= share * m.sum()]


def spd_merger(x0, velocities, masses, low: float, high: float, share: float) -> float:
    """Time at which the SPD's heavy clusters (:func:`heavy_clusters`) drop from two to one, by bisection to
    rounding; ValueError if [low, high] holds no such drop."""
    low, high = nonnegative("low", low), nonnegative("high", high)
    if not low < high:
        raise ValueError(f"need low < high, got {low} and {high}")
    # Checked here, so that the errors name this function's parameters, not spd_positions' x and v.
    x0 = sorted_array("x0", x0)
    velocities = finite_array("velocities", velocities)
    same_length(x0=x0, velocities=velocities)
    _atoms(x0, masses)
    share = positive("share", share)
    count = lambda t: heavy_clusters(spd_positions(x0, velocities, t, masses=masses), masses, share).size  # noqa: E731
    if not (count(low) >= 2 and count(high) == 1):
        raise ValueError(f"low = {low} and high = {high} must bracket a drop from two heavy clusters (holding share = "
                         f"{share} of the masses each) to one in the SPD of x0 and velocities")
    while True:
        middle = 0.5 * (low + high)
        if middle in (low, high):
            return high
        low, high = (middle, high) if count(middle) >= 2 else (low, middle)


def godunov_merger(data, cells: int, low: float, high: float, *, cfl: float = 0.9, chunk: int = 16) -> float:
    """Time in [low, high] at which the centres of the two exact aggregates' levels at ``low`` come within one
    cell in Godunov's scheme for F (:mod:`.methods`), on the scheme's own steps: the gap is read every ``chunk``
    steps, then at every step of the chunk in which it fell to one cell (from that chunk's saved state), and the
    crossing interpolated between two steps (:func:`first_within`). ValueError if low and high do not bracket such
    a time (two exact aggregates at low, more than a cell apart; within a cell by high)."""
    cells = integer_at_least("cells", cells, 1, MAX_CELLS)
    chunk = integer_at_least("chunk", chunk, 1, MAX_GAP_READINGS)  # (more steps a chunk: fewer readings than chunk)
    low, high = nonnegative("low", low), nonnegative("high", high)
    if not low < high:
        raise ValueError(f"need low < high, got {low} and {high}")
    with np.errstate(divide="ignore", over="ignore"):  # (a step that underflows to 0 needs infinitely many)
        steps = (high - low) / np.float64(methods.godunov_time_step(np.linspace(-1.0, 1.0, cells + 1),
                                                                    bump_data(data).mass, cfl))
    if steps / chunk + chunk > MAX_GAP_READINGS:
        raise ValueError(f"[low, high] = [{low}, {high}] takes {steps:.3g} steps of the scheme on {cells} cells (cfl "
                         f"= {cfl}), read every chunk = {chunk}: more than MAX_GAP_READINGS = {MAX_GAP_READINGS:.0e} "
                         "readings of the gap; raise cfl or chunk, or narrow [low, high]")
    if (steps + chunk) * cells > MAX_CELL_STEPS:
        raise ValueError(f"[low, high] = [{low}, {high}] takes {steps:.3g} steps of the scheme on {cells} cells (cfl "
                         f"= {cfl}), more than MAX_CELL_STEPS = {MAX_CELL_STEPS:.0e} cell updates; raise cfl, use "
                         "fewer cells or narrow [low, high]")
    solution = HullSolution(data, low)
    ranges = level_ranges(solution)
    if ranges.shape[0] != 2:
        raise ValueError(f"low = {low} must be a time with two aggregates, got {ranges.shape[0]}")
    edges, values = methods.godunov_mass(data, cells, low, cfl=cfl)
    mass, width = solution.mass, edges[1] - edges[0]
    step = methods.godunov_time_step(edges, mass, cfl)
    gap = lambda f: float(gap_path(*cell_atoms(edges, f, mass), ranges)[0])  # noqa: E731
    t, last = low, gap(values)
    if last <= width:
        raise ValueError(f"at low = {low} the aggregates are already within a cell")
    while t < high:
        following = methods.godunov_advance(edges, values, mass, chunk * step, cfl=cfl)
        if gap(following) <= width:
            times, gaps, state = [t], [last], values
            for k in range(1, chunk + 1):
                state = methods.godunov_advance(edges, state, mass, step, cfl=cfl)
                times.append(t + k * step)
                gaps.append(gap(state))
            crossing = first_within(np.array(times), np.array(gaps), width)
            if crossing > high:
                break
            return crossing
        t, values, last = t + chunk * step, following, gap(following)
    raise ValueError(f"the aggregates do not come within a cell (one of cells = {cells}) by high = {high}")
