"""Multitype sticky particles by the iterated typewise SPD (sections 1.2.2, 4.1, 5.2.1).

A configuration is an array x of shape (d, n): row gamma holds the sorted
positions of the n particles of type gamma (mass 1/n each). On each time step
Delta every type moves by the SPD of its own particles (the TSPD), with
velocities (1.8) frozen at the start of the step and computed from the ranks of
each particle among the other types.

A diagonal system is any object with an integer attribute ``d`` and a method
``speed_primitive(gamma, levels)`` returning an antiderivative, in its own
variable levels[..., gamma], of the characteristic speed lambda^gamma evaluated
at ``levels`` (an array whose last axis has length d). With it the integral in
(1.8) is exact: n (P(k/n) - P((k-1)/n)).
"""

from __future__ import annotations

import numpy as np

from ..jit import njit
from ..validation import integer_at_least, positive, sorted_array
from .spd import _hull_positions


@njit
def _ranks(x):
    """Merge of the d sorted rows, pseudo-code of section 5.2.1, in O(n d^2).

    Returns counts[gamma, k, g]: the number of particles of type g placed before
    particle gamma:k (own type included, so counts[gamma, k, gamma] = k + 1).
    Among particles at the same place the highest type is taken first, the
    post-collisional order imposed by (USH): strict inequality towards lower
    types, non-strict towards higher ones, as in (1.8).
    """
    d, n = x.shape
    counts = np.empty((d, n, d), dtype=np.int64)
    current = np.zeros(d, dtype=np.int64)
    for _ in range(d * n):
        chosen = -1
        for g in range(d):
            if current[g] < n and (chosen < 0 or x[g, current[g]] <= x[chosen, current[chosen]]):
                chosen = g
        k = current[chosen]
        current[chosen] = k + 1
        for g in range(d):
            counts[chosen, k, g] = current[g]
    return counts


def _checked_configuration(x, system) -> np.ndarray:
    x = sorted_array("x", x, ndim=2)
    if x.shape[0] != system.d:
        raise ValueError(f"x must have one row per type: expected {system.d} rows, got {x.shape[0]}")
    integer_at_least("number of particles per type n", x.shape[1], 1)
    return x


def rank_velocities(x, system) -> np.ndarray:
    """Velocities (1.8) of every particle of the configuration ``x`` (shape (d, n))."""
    x = _checked_configuration(x, system)
    return _rank_velocities(x, system)


def _rank_velocities(x, system) -> np.ndarray:
    d, n = x.shape
    levels = _ranks(x) / n
    velocities = np.empty((d, n))
    for gamma in range(d):
        upper = levels[gamma]
        lower = upper.copy()
        lower[:, gamma] -= 1.0 / n
        velocities[gamma] = n * (system.speed_primitive(gamma, upper) - system.speed_primitive(gamma, lower))
    return velocities


def _tspd_step(x, system, delta, out):
    velocities = _rank_velocities(x, system)
    for gamma in range(x.shape[0]):
        _hull_positions(x[gamma], velocities[gamma], delta, out[gamma])


def mspd_trajectory(x0, system, delta: float, steps: int) -> np.ndarray:
    """Iterated TSPD: configurations at times 0, Delta, ..., steps*Delta, shape (steps+1, d, n)."""
    x0 = _checked_configuration(x0, system)
    delta = positive("Delta", delta)
    steps = integer_at_least("steps", steps, 0)
    path = np.empty((steps + 1, *x0.shape))
    path[0] = x0
    for step in range(steps):
        _tspd_step(path[step], system, delta, path[step + 1])
    return path


def mspd_positions(x0, system, delta: float, steps: int) -> np.ndarray:
    """Iterated TSPD after ``steps`` steps of length Delta, keeping only the current state."""
    x0 = _checked_configuration(x0, system)
    delta = positive("Delta", delta)
    steps = integer_at_least("steps", steps, 0)
    current, following = x0.copy(), np.empty_like(x0)
    for _ in range(steps):
        _tspd_step(current, system, delta, following)
        current, following = following, current
    return current
