"""Literal transcription of the pseudo-code of section 5.1.1, in plain Python.

It works on the cumulative sums Q(k) = Q_t(k/n) as the paper writes it, keeps
the list L of hull vertices (most recent first) and records each iteration, which
Figure 1 draws. It is the baseline a user would write without a compiler; the
compiled solver is :func:`particle_methods.sticky.spd.spd_positions`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import ParameterTypeError, finite_array, integer_at_least, nonnegative
from .spd import MAX_POSITIONS, check_reach, checked_state


@dataclass(frozen=True)
class HullIteration:
    """One pass of the for loop: the list before, the vertices removed, the list after."""

    k: int
    before: tuple[int, ...]
    removed: tuple[int, ...]
    after: tuple[int, ...]

    def __post_init__(self):
        integer_at_least("k", self.k, 0, MAX_POSITIONS)
        for name in ("before", "removed", "after"):
            vertices = getattr(self, name)
            if not isinstance(vertices, tuple) or not all(
                    isinstance(v, (int, np.integer)) and not isinstance(v, bool) and v >= 0 for v in vertices):
                raise ParameterTypeError(f"{name} must be a tuple of vertex indices (integers >= 0), got {vertices!r}")


def cumulative_free_positions(x, v, t: float) -> np.ndarray:
    """Q(k) = sum_{k' <= k} (x_{k'} + t v_{k'}), k = 0..n, with Q(0) = 0."""
    x, v = checked_state(x, v)
    t = nonnegative("t", t)
    check_reach(x, np.abs(v).max(), t)  # then the n partial sums are finite too
    return np.concatenate(([0.0], np.cumsum(x + t * v)))


def hull_vertices(q, trace: list | None = None) -> list[int]:
    """Run the pseudo-code on Q(0..n) and return the final list L of hull vertices.

    L is written most recent first, as in the paper; it is stored reversed (a
    Python list whose end is the paper's "first element") so that removing and
    inserting at the front cost O(1), as the paper's complexity count assumes.
    When ``trace`` is a list, one :class:`HullIteration` per pass is appended to it.
    """
    q = finite_array("q", q).tolist()
    if len(q) < 2:
        raise ValueError(f"q must hold Q(0..n) for n >= 1, at least 2 values, got {len(q)}")
    if trace is not None and not isinstance(trace, list):
        raise ParameterTypeError(f"trace must be a list or None, got {type(trace).__name__}")
    stack = [0, 1]
    for k in range(2, len(q)):
        before = tuple(reversed(stack)) if trace is not None else ()
        removed = []
        while len(stack) > 1 and (q[k] - q[stack[-1]]) / (k - stack[-1]) < (
            q[stack[-1]] - q[stack[-2]]
        ) / (stack[-1] - stack[-2]):
            removed.append(stack.pop())
        stack.append(k)
        if trace is not None:
            trace.append(HullIteration(k, before, tuple(removed), tuple(reversed(stack))))
    return list(reversed(stack))


def spd_positions_python(x, v, t: float) -> np.ndarray:
    """SPD positions from the hull vertices: slopes of the piecewise-linear hull."""
    q = cumulative_free_positions(x, v, t)
    vertices = hull_vertices(q)[::-1]
    positions = np.empty(len(q) - 1)
    for left, right in zip(vertices[:-1], vertices[1:]):
        positions[left:right] = (q[right] - q[left]) / (right - left)
    return positions
