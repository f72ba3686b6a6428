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
"""

from __future__ import annotations

import numpy as np

from ..jit import njit
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    integer_at_least,
    nonnegative,
    same_length,
    sorted_array,
)

#: Largest number of positions one call takes or returns: 0.8 GB of float64, and seconds for an
#: O(n) pass. The figures use at most 3 * 10**6 particles (config ``sticky.cost.hull_n``). It also
#: keeps the particle counts of the kernel within its int32 array.
MAX_POSITIONS = 10**8

_LARGEST = float(np.finfo(np.float64).max)


@njit
def _hull_positions(x, v, t, out):
    """Positions at time t of the SPD, written to ``out``; returns the number of clusters.

    The stack of hull segments lives in place: segment j keeps its sum of free
    positions in ``out[j]`` (there are never more segments than particles seen)
    and its particle count in ``counts[j]``; the segment being built stays in
    registers. The final pass runs backwards so that each segment's sum is read
    before its particles' slots are overwritten.
    """
    n = x.size
    counts = np.empty(n, dtype=np.int32)
    top = -1
    for k in range(n):
        total = x[k] + t * v[k]
        count = 1
        # Merge while the previous segment is steeper than the new one (a concave corner).
        while top >= 0 and out[top] * count > total * counts[top]:
            total += out[top]
            count += counts[top]
            top -= 1
        top += 1
        out[top] = total
        counts[top] = count
    end = n
    for segment in range(top, -1, -1):
        start = end - counts[segment]
        position = out[segment] / counts[segment]
        for k in range(start, end):
            out[k] = position
        end = start
    return top + 1


def _checked_state(x, v):
    x = sorted_array("x", x)
    v = finite_array("v", v)
    n = same_length(x=x, v=v)
    integer_at_least("number of particles n", n, 1, MAX_POSITIONS)
    return x, v


def _check_reach(x, speed: float, t: float, time_name: str = "t", velocity_name: str = "v") -> None:
    """Refuse free positions x + t v that could overflow the sums of the hull.

    The kernel adds up to n free positions and multiplies such sums by particle counts, so
    n^2 (|x| + t |v|) must stay below the largest double; then every sum, and every position
    (an average of free positions), is finite. ``x`` is sorted along its last axis (one row per
    type) and ``speed`` is max |v|.
    """
    n = x.shape[-1]
    with np.errstate(over="ignore"):
        reach = max(np.abs(x[..., 0]).max(), np.abs(x[..., -1]).max()) + t * speed
    limit = _LARGEST / n**2
    if not reach <= limit:
        raise ValueError(
            f"x + {time_name} {velocity_name} may overflow: |x| + {time_name} |{velocity_name}| reaches {reach:.3g}, "
            f"above {limit:.3g} (the largest double / n^2, n = {n}); reduce {time_name} or {velocity_name}"
        )


def spd_positions(x, v, t: float) -> np.ndarray:
    """Positions phi[v](x; t) of the SPD at time ``t`` (section 5.1.1), in O(n).

    Parameters
    ----------
    x : sorted initial positions (an element of D_n).
    v : initial velocities, one per particle.
    t : time, t >= 0.
    """
    x, v = _checked_state(x, v)
    t = nonnegative("t", t)
    _check_reach(x, np.abs(v).max(), t)
    out = np.empty_like(x)
    _hull_positions(x, v, t, out)
    return out


def spd_trajectories(x, v, times) -> np.ndarray:
    """SPD positions at each of ``times``: array of shape (len(times), n).

    The flow needs no time stepping: each row is an independent O(n) hull.
    """
    x, v = _checked_state(x, v)
    times = finite_array("times", times)
    if np.any(times < 0):
        raise ValueError("times must be non-negative")
    if times.size * x.size > MAX_POSITIONS:
        raise ValueError(f"{times.size} times of {x.size} particles give {times.size * x.size:.3g} positions, more "
                         f"than MAX_POSITIONS = {MAX_POSITIONS:.0e} in one call: split the times")
    if times.size:
        _check_reach(x, np.abs(v).max(), times.max(), "times")
    out = np.empty((times.size, x.size))
    for row, t in enumerate(times):
        _hull_positions(x, v, t, out[row])
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
    velocities are exact: n (Lambda(k/n) - Lambda((k-1)/n)).
    """
    if not callable(flux):
        raise ParameterTypeError(f"flux must be callable (the flux Lambda of (1.1)), got {flux!r}")
    n = integer_at_least("n", n, 1, MAX_POSITIONS)
    values = finite_array("flux values", flux(np.arange(n + 1) / n))
    if values.size != n + 1:
        raise ValueError(f"flux must return one value per level k/n, k = 0..n ({n + 1}), got {values.size}")
    return finite_result("a velocity n (flux(k/n) - flux((k-1)/n))", n * np.diff(values),
                         "the flux values are too large: their differences overflow")
