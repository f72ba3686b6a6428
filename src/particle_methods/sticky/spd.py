"""Sticky particle dynamics (SPD) of section 1.1.2, computed by the Brenier-Grenier hull.

Particles of mass 1/n start at sorted positions x_k with velocities v_k, move
freely and stick on collision with conservation of mass and momentum. Brenier and
Grenier observed (section 5.1.1) that the cumulative sums P_t(k/n) of the
positions at time t form the lower convex hull of the cumulative sums Q_t(k/n) of
the free-transport positions x_k + t v_k. The slopes of that hull are the
positions, so one monotone-chain pass gives all of them in O(n) operations.

The kernel keeps the hull as a stack of segments, each stored by its number of
particles and its sum of free positions: the slope of a segment is the common
position of a cluster. Working with segment sums instead of the cumulative sums
Q_t themselves gives the same algorithm (the paper's test compares two slopes)
without the cancellation that large cumulative sums would cause for n = 10^7.

Particles may also carry masses m_k > 0 (for instance grid weights rho0(x_j) h). The remark
of Brenier and Grenier holds for them too: the cumulative mass-weighted sums of positions,
placed at the cumulative masses c_k = m_1 + ... + m_k instead of k/n, form the lower convex
hull of those of the free positions, whose slopes are again the positions. Segments then
keep their mass instead of their number of particles (:func:`_weighted_hull_positions`), and
:func:`velocities_from_levels` gives the velocities of section 1.1.3 at the levels c_k.
"""

from __future__ import annotations

import numpy as np

from ..jit import njit
from ..perturbation import nudged
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    instance,
    integer_at_least,
    nonnegative,
    real_array,
    same_length,
    sorted_array,
)

#: Largest number of positions one call takes or returns: 0.8 GB of float64, and seconds for an
#: O(n) pass. The figures use at most 3 * 10**6 particles (config ``sticky.cost.hull_n``). It also
#: keeps the particle counts of the kernel within its int32 array.
MAX_POSITIONS = 10**8

#: Largest ratio of the largest to the smallest mass. The masses are scaled by a power of two so
#: that the largest lies in [1/2, 1) (exact: the positions depend only on mass ratios); every mass
#: is then at least 2^-501 and a product of two segment masses at least 2^-1002. The merge test
#: compares S_prev M_new = M_prev M_new * (mean position), which loses digits below the normal
#: range 2^-1022: it can then err only between means closer than 2^-1074 / 2^-1002 = 2^-72 ~ 2e-22,
#: an absolute error below rounding for positions of size 1e-6 and more (the sums S lose far less:
#: n 2^-1075 / 2^-501 on a mean).
MAX_MASS_RATIO = 2.0**500

#: The largest double: :func:`check_reach` keeps every sum of the hull passes below it.
LARGEST = float(np.finfo(np.float64).max)


@njit
def hull_positions_kernel(x, v, t, out):
    """Positions at time t of the SPD, written to ``out``; returns (the number of clusters, the operations
    made).

    The stack of hull segments lives in place: segment j keeps its sum of free
    positions in ``out[j]`` (there are never more segments than particles seen)
    and its particle count in ``counts[j]``; the segment being built stays in
    registers. The final pass runs backwards so that each segment's sum is read
    before its particles' slots are overwritten.

    The operations are counted where they are made (section 5.1.1's O(n) is a statement about them): every
    test of the merge condition against a segment on the stack, every merge (a pop), every push, and every
    position written by the final pass.
    """
    n = x.size
    counts = np.empty(n, dtype=np.int32)
    top = -1
    operations = 0
    for k in range(n):
        total = x[k] + t * v[k]
        count = 1
        # Merge while the previous segment is steeper than the new one (a concave corner).
        while top >= 0:
            operations += 1  # a test
            if not out[top] * count > total * counts[top]:
                break
            total += out[top]
            count += counts[top]
            top -= 1
            operations += 1  # a pop
        top += 1
        out[top] = total
        counts[top] = count
        operations += 1  # a push
    end = n
    for segment in range(top, -1, -1):
        start = end - counts[segment]
        position = out[segment] / counts[segment]
        for k in range(start, end):
            out[k] = position
            operations += 1  # a position written
        end = start
    return top + 1, operations


@njit
def _weighted_hull_positions(x, v, masses, t, out):
    """Positions at time t of the SPD of particles with ``masses``, written to ``out``; returns (the number of
    clusters, the operations made), counted as in :func:`hull_positions_kernel`.

    The hull of :func:`hull_positions_kernel` with the abscissae k/n replaced by the cumulative
    masses (section 5.1.1 for masses m_k instead of 1/n): segment j keeps its sum of m_k (x_k + t v_k)
    in ``out[j]``, its mass in ``weights[j]`` and its particle count in ``counts[j]`` (for the
    final pass). The previous segment is merged while its mean free position S_prev / M_prev
    exceeds that of the new one, tested cross-multiplied as S_prev M_new > S_new M_prev; a
    cluster sits at its mass-weighted mean S / M, which conserves mass and momentum.

    Two kernels exist because the unweighted one is the one timed: its segments hold integer
    counts, so it reads x and v only and keeps 12 bytes per segment against 20 here, with no
    multiplication by a mass. The cost study (scripts/sticky/cost_data.py, benchmarks/bench_spd.py)
    times it and the iterated TSPD (:mod:`.mspd`) calls it at every step, so the equal-mass path
    stays as it was, results and speed. (Equal power-of-two masses reproduce it bit for bit.)
    """
    n = x.size
    weights = np.empty(n)
    counts = np.empty(n, dtype=np.int32)
    top = -1
    operations = 0
    for k in range(n):
        mass = masses[k]
        total = mass * (x[k] + t * v[k])
        count = 1
        while top >= 0:
            operations += 1  # a test
            if not out[top] * mass > total * weights[top]:
                break
            total += out[top]
            mass += weights[top]
            count += counts[top]
            top -= 1
            operations += 1  # a pop
        top += 1
        out[top] = total
        weights[top] = mass
        counts[top] = count
        operations += 1  # a push
    end = n
    for segment in range(top, -1, -1):
        start = end - counts[segment]
        position = out[segment] / weights[segment]
        for k in range(start, end):
            out[k] = position
            operations += 1  # a position written
        end = start
    return top + 1, operations


def checked_state(x, v):
    x = sorted_array("x", x)
    v = finite_array("v", v)
    n = same_length(x=x, v=v)
    integer_at_least("number of particles n", n, 1, MAX_POSITIONS)
    return x, v


def checked_masses(masses, x) -> np.ndarray:
    """``masses`` checked (real, finite, positive, one per particle, spread at most
    :data:`MAX_MASS_RATIO`) and scaled by a power of two so that the largest lies in [1/2, 1).

    The scaling is exact and the SPD depends only on mass ratios, so the positions are those of
    the given masses whatever their total; it leaves a total mass of at most n for
    :func:`check_reach`.
    """
    masses = finite_array("masses", masses)
    x = real_array("x", x)
    if x.ndim == 0:
        raise ValueError(f"x must be an array of positions, got {x!r}")
    same_length(x=x, masses=masses)
    smallest, largest = masses.min(), masses.max()
    if not smallest > 0:
        raise ValueError(f"masses must be positive, got {smallest} at index {int(masses.argmin())}")
    if smallest < largest / MAX_MASS_RATIO:
        raise ValueError(f"masses span {largest:.3g} / {smallest:.3g}, more than MAX_MASS_RATIO = 2^500: "
                         "drop the negligible masses")
    return np.ldexp(masses, -int(np.frexp(largest)[1]))


def check_reach(x, speed: float, t: float, time_name: str = "t", velocity_name: str = "v", masses=None,
                position_name: str = "x") -> None:
    """Refuse free positions x + t v that could overflow the sums of the hull.

    With R = max |x| + t |v| and total mass M, a free position and its product with a mass m_k <= 1
    are at most R in magnitude, a segment sum of m_k (x_k + t v_k) is at most M R and the kernel
    multiplies it by a segment mass of at most M, so max(M, 1)^2 R must stay below the largest
    double; then every sum, product, and position (a weighted average of free positions) is
    finite. The unweighted kernel sums free positions and multiplies by particle counts: M = n
    (``masses=None``); the weighted one gets the masses scaled below 1 by
    :func:`checked_masses`, so M <= n there too. ``x`` is sorted along its last axis (one row
    per type), named ``position_name`` in the message, and ``speed`` is max |v|.
    """
    x = real_array(position_name, x)
    if x.ndim == 0:
        raise ValueError(f"{position_name} must be an array of positions, got {x!r}")
    speed = nonnegative(f"speed (max |{velocity_name}|)", speed)
    t = nonnegative(time_name, t)
    n = x.shape[-1]
    if n == 0:
        return
    ends = np.abs(np.stack((x[..., 0], x[..., -1])))  # x is sorted: its ends bound every position
    if not np.all(np.isfinite(ends)):
        raise ValueError(f"{position_name} contains NaN or infinite values")
    total_mass = n if masses is None else float(masses.sum())
    with np.errstate(over="ignore"):
        reach = float(ends.max()) + t * speed
    limit = LARGEST / max(total_mass, 1.0) ** 2
    if not reach <= limit:
        raise ValueError(
            f"{position_name} + {time_name} {velocity_name} may overflow: |{position_name}| + {time_name} "
            f"|{velocity_name}| reaches {reach:.3g}, "
            f"above {limit:.3g} (the largest double / max(M, 1)^2, M = {total_mass:.6g} the total mass in "
            f"particles or in scaled masses); reduce {time_name} or {velocity_name} (the speed max "
            f"|{velocity_name}| is {speed:.3g})"
        )


def _hull(x, v, masses, t: float, out) -> tuple[int, int]:
    """The equal-mass kernel for ``masses=None``, else the weighted one; returns (clusters, operations)."""
    if masses is None:
        return hull_positions_kernel(x, v, t, out)
    return _weighted_hull_positions(x, v, masses, t, out)


def spd_positions(x, v, t: float, masses=None, return_operations: bool = False):
    """Positions phi[v](x; t) of the SPD at time ``t`` (section 5.1.1), in O(n).

    Parameters
    ----------
    x : sorted initial positions (an element of D_n).
    v : initial velocities, one per particle.
    t : time, t >= 0.
    masses : positive masses, one per particle, any total; None for equal masses 1/n. At most
        :data:`MAX_MASS_RATIO` between the largest and the smallest.
    return_operations : also return the operations the hull pass made (counted by the kernel:
        :func:`hull_positions_kernel`).
    """
    # From the shape, before any copy (a zero-stride array holds its 10^9 entries in one).
    for name, values in (("x", x), ("v", v), ("masses", masses)):
        if isinstance(values, np.ndarray) and values.size > MAX_POSITIONS:
            raise ValueError(f"{name} holds {values.size} particles, more than MAX_POSITIONS = {MAX_POSITIONS:.0e}")
    x, v = checked_state(x, v)
    t = nonnegative("t", t)
    masses = None if masses is None else checked_masses(masses, x)
    return_operations = instance("return_operations", return_operations, (bool, np.bool_))
    check_reach(x, np.abs(v).max(), t, masses=masses)
    out = np.empty_like(x)
    _, operations = _hull(x, v, masses, t, out)
    return (out, operations) if return_operations else out


def spd_trajectories(x, v, times, masses=None) -> np.ndarray:
    """SPD positions at each of ``times``: array of shape (len(times), n); ``masses`` as in :func:`spd_positions`.

    The flow needs no time stepping: each row is an independent O(n) hull.
    """
    x, v = checked_state(x, v)
    times = finite_array("times", times)
    if np.any(times < 0):
        raise ValueError("times must be non-negative")
    if times.size * x.size > MAX_POSITIONS:
        raise ValueError(f"{times.size} times of {x.size} particles give {times.size * x.size:.3g} positions, more "
                         f"than MAX_POSITIONS = {MAX_POSITIONS:.0e} in one call: split the times")
    masses = None if masses is None else checked_masses(masses, x)
    if times.size:
        check_reach(x, np.abs(v).max(), times.max(), "times", masses=masses)
    out = np.empty((times.size, x.size))
    for row, t in enumerate(times):
        _hull(x, v, masses, t, out[row])
    return out


def cluster_sizes(positions) -> np.ndarray:
    """Sizes of the clusters (runs of equal positions) of a sorted configuration."""
    positions = sorted_array("positions", positions)
    if positions.size == 0:
        return np.zeros(0, dtype=np.int64)
    starts = np.flatnonzero(np.concatenate(([True], np.diff(positions) > 0)))
    return np.diff(np.append(starts, positions.size))


def velocities_from_flux(flux, n: int) -> np.ndarray:
    """Initial velocities of section 1.1.3: n int_{(k-1)/n}^{k/n} lambda(w) dw, lambda = flux'.

    The integral of lambda = Lambda' is a difference of the flux itself, so the
    velocities are exact: n (Lambda(k/n) - Lambda((k-1)/n)). Initial data: moved by the active nudge of
    :mod:`particle_methods.perturbation`, if any.
    """
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    n = integer_at_least("n", n, 1, MAX_POSITIONS)
    values = finite_array("flux values", flux(np.arange(n + 1) / n))
    if values.size != n + 1:
        raise ValueError(f"flux must return one value per level k/n, k = 0..n ({n + 1}), got {values.size}")
    return nudged(finite_result("a velocity n (flux(k/n) - flux((k-1)/n))", n * np.diff(values),
                                "the flux values are too large: their differences overflow"))


def velocities_from_levels(flux, levels) -> np.ndarray:
    """Velocities of section 1.1.3 for masses m_k = c_k - c_{k-1}: the mean of lambda = flux' over (c_{k-1}, c_k].

    ``levels`` are the n + 1 cumulative masses 0 = c_0 < c_1 < ... < c_n, and the velocity of
    particle k is (Lambda(c_k) - Lambda(c_{k-1})) / (c_k - c_{k-1}), exact as in
    :func:`velocities_from_flux` (which it equals, up to rounding, for c_k = k/n). A cluster
    holding the levels (c_{a-1}, c_b] then moves at (Lambda(c_b) - Lambda(c_{a-1})) / (c_b - c_{a-1}),
    the Rankine-Hugoniot speed of the jump of u from c_{a-1} to c_b.
    """
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    levels = finite_array("levels", levels)
    integer_at_least("number of levels n + 1", levels.size, 2, MAX_POSITIONS + 1)
    if levels[0] != 0:
        raise ValueError(f"levels must start at c_0 = 0 (the n + 1 cumulative masses), got {levels[0]}")
    with np.errstate(over="ignore"):  # increasing levels from c_0 = 0 have widths c_k - c_{k-1} <= c_k
        widths = np.diff(levels)
    if not np.all(widths > 0):
        raise ValueError(f"levels must increase strictly (index {int(np.argmin(widths > 0)) + 1} does not)")
    try:
        values = finite_array("flux values", flux(levels))
    except ValueError as error:  # the flux's own refusal (an overflow) names its argument u: name the levels
        raise ValueError(f"flux(levels) failed at these levels: {error}") from None
    if values.size != levels.size:
        raise ValueError(f"flux must return one value per level ({levels.size}), got {values.size}")
    with np.errstate(over="ignore"):
        velocities = np.diff(values) / widths
    return finite_result("a velocity (flux(c_k) - flux(c_{k-1})) / (c_k - c_{k-1})", velocities,
                         "the flux values are too large, or differ too much across narrow levels")
