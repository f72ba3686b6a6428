"""When a state counts as steady, or an end state as reached: criteria stated before measuring.

A claim about a steady state, a limit or an end state is measured only once a criterion written
in the config holds. Two kinds of criterion are used:

- :func:`first_steady_time`: the relative change of the state over a time window falls below a
  tolerance;
- :func:`holds_from`: a property of the state (an order recovered, no cluster left) holds from
  some recorded time on, up to the end of the run.

:func:`run_until` drives a simulation in chunks until the criterion holds or a stated maximum
time is reached; a state that never settles gives ``inf``, which fails any claim measured on it.
That ``inf`` is the only non-finite value these functions return, and it always means "never".
"""

from __future__ import annotations

import math

import numpy as np

from particle_methods.validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    in_interval,
    positive,
    sorted_array,
)

MAX_CHUNKS = 10**4
"""Most chunks :func:`run_until` runs (t_max / chunk): it keeps every state, and the figures need 10."""


def relative_change(times, states, window: float) -> tuple[np.ndarray, np.ndarray]:
    """Times t (those with a recorded time at or before t - window) and
    max|s(t) - s(t')| / max|s(t)| with t' the latest recorded time <= t - window
    (``inf`` where s(t) = 0 and s(t') is not: a change from nothing never counts as steady)."""
    times = finite_array("times", times)
    states = in_interval("states", states, -np.inf, np.inf)  # any finite real array
    window = positive("window", window)
    if states.ndim < 1 or states.shape[0] != times.size:
        raise ValueError("states must have one row per recorded time")
    if np.any(np.diff(times) <= 0):
        raise ValueError("times must be increasing")
    flat = states.reshape(times.size, -1)
    earlier = np.searchsorted(times, times - window, side="right") - 1
    usable = earlier >= 0
    scale = np.abs(flat[usable]).max(axis=1)
    change = finite_result("the change of the states", np.abs(flat[usable] - flat[earlier[usable]]).max(axis=1),
                           "states are too large: their differences overflow")
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
    times = sorted_array("times", times)
    try:
        condition = np.asarray(condition)
    except ValueError:  # ragged nested sequences
        raise ParameterTypeError("condition must be a rectangular array of booleans") from None
    if condition.size and condition.dtype != bool:
        raise ParameterTypeError(f"condition must be an array of booleans, got dtype {condition.dtype}")
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
    if not callable(advance) or not callable(done):
        raise ParameterTypeError("advance and done must be callable")
    state = in_interval("state", state, -np.inf, np.inf)
    chunk, t_max = positive("chunk", chunk), positive("t_max", t_max)
    t_min = finite_number("t_min", t_min)
    if not 0 <= t_min <= t_max:
        raise ValueError(f"t_min must lie in [0, t_max], got {t_min}")
    if t_max / chunk > MAX_CHUNKS:
        raise ValueError(f"t_max / chunk = {t_max / chunk:.3g} chunks, more than MAX_CHUNKS = {MAX_CHUNKS}: take "
                         "longer chunks")
    pieces, start = [state[None]], 0.0
    reached = math.inf
    while start < t_max - 1e-12 * t_max:
        step = min(chunk, t_max - start)
        record = in_interval("advance(state, chunk)", advance(pieces[-1][-1], step), -np.inf, np.inf)
        if record.shape[1:] != state.shape:
            raise ValueError(f"advance(state, chunk) must return records of shape {state.shape}, got {record.shape}")
        pieces.append(record[1:])
        start += step
        states = np.concatenate(pieces)
        times = np.linspace(0.0, start, states.shape[0])
        reached = _reached(done(times, states))
        if math.isfinite(reached) and start >= t_min - 1e-12 * t_max:
            return times, states, reached
    states = np.concatenate(pieces)
    return np.linspace(0.0, start, states.shape[0]), states, reached


def _reached(value) -> float:
    """The time ``done`` returned: a number, ``inf`` for "not yet"."""
    if isinstance(value, float) and value == math.inf:  # np.float64 is a float too
        return math.inf
    return finite_number("done(times, states)", value)
