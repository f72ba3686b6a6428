"""Input checks shared by every solver: each raises ``ValueError`` naming the parameter."""

from __future__ import annotations

import math
from numbers import Integral, Real

import numpy as np

from .jit import njit


def finite_array(name: str, values, ndim: int = 1) -> np.ndarray:
    """Return ``values`` as a float64 array after checking its rank and finiteness."""
    array = np.asarray(values, dtype=np.float64)
    if array.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-dimensional array, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} contains NaN or infinite values")
    return array


@njit
def _first_defect(values):
    """(kind, index) of the first non-finite (kind 1) or out-of-order (kind 2) entry."""
    previous = -np.inf
    for k in range(values.size):
        value = values[k]
        if not np.isfinite(value):
            return 1, k
        if value < previous:
            return 2, k
        previous = value
    return 0, -1


def sorted_array(name: str, values, ndim: int = 1) -> np.ndarray:
    """Finite array whose last axis is non-decreasing (positions in D_n).

    One-dimensional inputs are scanned once by a compiled loop, so the check stays
    cheap next to the O(n) solvers it guards.
    """
    array = np.asarray(values, dtype=np.float64)
    if array.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-dimensional array, got shape {array.shape}")
    rows = array.reshape(-1, array.shape[-1]) if array.size else array.reshape(0, 0)
    for row in rows:
        kind, index = _first_defect(np.ascontiguousarray(row))
        if kind == 1:
            raise ValueError(f"{name} contains NaN or infinite values (first at index {index})")
        if kind == 2:
            raise ValueError(f"{name} must be sorted in non-decreasing order (index {index} decreases)")
    return array


def same_length(**arrays: np.ndarray) -> int:
    """Common length of the last axis of ``arrays``; raise if they differ."""
    lengths = {name: np.shape(a)[-1] for name, a in arrays.items()}
    if len(set(lengths.values())) != 1:
        detail = ", ".join(f"{name} has {n}" for name, n in lengths.items())
        raise ValueError(f"mismatched array lengths: {detail}")
    return next(iter(lengths.values()))


def finite_number(name: str, value) -> float:
    """Return ``value`` as a float after checking that it is a finite real number."""
    if isinstance(value, bool) or not isinstance(value, (Real, np.floating, np.integer)):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value}")
    return value


def positive(name: str, value) -> float:
    """Finite number > 0."""
    value = finite_number(name, value)
    if value <= 0:
        raise ValueError(f"{name} must be positive, got {value}")
    return value


def nonnegative(name: str, value) -> float:
    """Finite number >= 0."""
    value = finite_number(name, value)
    if value < 0:
        raise ValueError(f"{name} must be non-negative, got {value}")
    return value


def integer_at_least(name: str, value, minimum: int) -> int:
    """Integer >= ``minimum``."""
    if isinstance(value, bool) or not isinstance(value, (Integral, np.integer)):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return int(value)


def in_interval(name: str, values, low: float, high: float) -> np.ndarray:
    """Finite array with every entry in the closed interval [low, high]."""
    array = np.asarray(values, dtype=np.float64)
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} contains NaN or infinite values")
    if np.any(array < low) or np.any(array > high):
        raise ValueError(f"{name} must lie in [{low}, {high}]")
    return array


def one_of(what: str, name, table: dict):
    """``table[name]``, or a ValueError "unknown <what> <name>: expected one of ..."."""
    try:
        return table[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown {what} {name!r}: expected one of {sorted(table)}") from None
