"""When a state counts as steady, or an end state as reached: criteria stated before measuring.

A claim about a steady state, a limit or an end state is measured only once a criterion written
in the config holds. Two kinds of criterion are used:

- :func:`first_steady_time`: the relative change of the state over a time window falls below a
  tolerance;
- :func:`holds_from`: a property of the state (an order recovered, no cluster left) holds from
  some recorded time on, up to the end of the run.

:func:`run_until` drives a simulation in chunks until the criterion holds or a stated maximum
time is reached; a state that never settles gives ``inf``, which fails any claim measured on it.
"""

from __future__ import annotations

import math

import numpy as np

from .validation import finite_array, positive


def relative_change(times, states, window: float) -> tuple[np.ndarray, np.ndarray]:
    """Times t (those with a recorded time at or before t - window) and
    max|s(t) - s(t')| / max|s(t)| with t' the latest recorded time <= t - window."""
    times = finite_array("times", times)
    states = np.asarray(states, dtype=np.float64)
    window = positive("window", window)
    if states.ndim < 1 or states.shape[0] != times.size:
        raise ValueError("states must have one row per recorded time")
    if not np.all(np.isfinite(states)):
        raise ValueError("states contains NaN or infinite values")
    if np.any(np.diff(times) <= 0):
        raise ValueError("times must be increasing")
    flat = states.reshape(times.size, -1)
    earlier = np.searchsorted(times, times - window, side="right") - 1
    usable = earlier >= 0
    scale = np.abs(flat[usable]).max(axis=1)
    change = np.abs(flat[usable] - flat[earlier[usable]]).max(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        relative = np.where(scale > 0, change / np.where(scale > 0, scale, 1.0), np.where(change > 0, np.inf, 0.0))
    return times[usable], relative


def first_steady_time(times, states, window: float, tolerance: float) -> float:
    """First recorded time from which the relative change over ``window`` stays <= ``tolerance``
    until the end of the record; ``inf`` when it does not hold at the last recorded time."""
    tolerance = positive("tolerance", tolerance)
    checked, relative = relative_change(times, states, window)
    return holds_from(checked, relative <= tolerance)


def holds_from(times, condition) -> float:
    """First recorded time from which ``condition`` holds at every later recorded time; ``inf``
    when it fails at the last one (or there is no record)."""
    times = finite_array("times", times)
    condition = np.asarray(condition, dtype=bool)
    if condition.shape != times.shape:
        raise ValueError("condition must have one value per recorded time")
    if condition.size == 0 or not condition[-1]:
        return math.inf
    failing = np.flatnonzero(~condition)
    return float(times[failing[-1] + 1] if failing.size else times[0])


def run_until(advance, state, chunk: float, t_min: float, t_max: float, done):
    """Advance ``state`` by chunks of ``chunk`` until ``done(times, states)`` returns a finite time
    and at least ``t_min`` is covered, or until ``t_max``.

    ``advance(state, chunk)`` returns the states recorded over one chunk at a uniform spacing
    (the same for every chunk), the first being ``state`` itself; ``done`` receives every recorded
    time and state so far. Returns (times, states, time at which the criterion holds or ``inf``).
    """
    chunk, t_max = positive("chunk", chunk), positive("t_max", t_max)
    if not 0 <= t_min <= t_max:
        raise ValueError(f"t_min must lie in [0, t_max], got {t_min}")
    pieces, start = [np.asarray(state)[None]], 0.0
    reached = math.inf
    while start < t_max - 1e-12 * t_max:
        step = min(chunk, t_max - start)
        record = np.asarray(advance(pieces[-1][-1], step))
        pieces.append(record[1:])
        start += step
        states = np.concatenate(pieces)
        times = np.linspace(0.0, start, states.shape[0])
        reached = done(times, states)
        if math.isfinite(reached) and start >= t_min - 1e-12 * t_max:
            return times, states, reached
    states = np.concatenate(pieces)
    return np.linspace(0.0, start, states.shape[0]), states, reached
