"""Input checks shared by every public function.

Each check names the parameter it rejects. A value of the wrong kind (None, a string, a complex
number, an object array) raises :class:`ParameterTypeError`, a ``TypeError`` that is also a
``ValueError`` so that callers catching either see it; a value of the right kind out of range
raises ``ValueError``. :func:`finite_result` turns a non-finite result of valid inputs (an
overflow) into a ``ValueError`` naming its cause instead of returning NaN or inf.
"""

from __future__ import annotations

import math
from numbers import Integral, Real

import numpy as np

from .jit import njit

#: Most entries of one array argument: beyond every work limit of the package (the largest, the SPD's 10**8
#: positions, included), so that an array far too large (a zero-stride view of 10**9 entries costs no memory) is
#: refused before any copy or pass over it.
MAX_ENTRIES = 2 * 10**8


class ParameterTypeError(TypeError, ValueError):
    """A parameter of the wrong type: a TypeError, and a ValueError for callers catching that."""


def real_array(name: str, values) -> np.ndarray:
    """``values`` as a float64 array; ParameterTypeError for None, strings, complex or objects."""
    if values is None or isinstance(values, (str, bytes)):
        raise ParameterTypeError(f"{name} must be an array of real numbers, got {values!r}")
    try:
        array = np.asarray(values)
    except ValueError as error:  # ragged nested sequences
        raise ParameterTypeError(f"{name} must be a rectangular array of real numbers ({error})") from None
    if array.dtype.kind not in "biuf":
        raise ParameterTypeError(f"{name} must hold real numbers, got dtype {array.dtype}")
    if array.size > MAX_ENTRIES:
        raise ValueError(f"{name} has {array.size} entries, more than {MAX_ENTRIES} (a limit on the work of one call)")
    return array.astype(np.float64, copy=False)


def instance(name: str, value, kind):
    """``value`` if it is an instance of ``kind`` (a type or a tuple of types), else a ParameterTypeError."""
    if not isinstance(value, kind):
        expected = kind.__name__ if isinstance(kind, type) else " or ".join(k.__name__ for k in kind)
        raise ParameterTypeError(f"{name} must be of type {expected}, got {value!r}")
    return value


def finite_values(name: str, values) -> np.ndarray:
    """``values`` of any shape (a number too) as float64, after checking type and finiteness."""
    array = real_array(name, values)
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} contains NaN or infinite values")
    return array


def finite_array(name: str, values, ndim: int = 1) -> np.ndarray:
    """Return ``values`` as a float64 array after checking its type, rank and finiteness."""
    array = real_array(name, values)
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
    array = real_array(name, values)
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
        raise ParameterTypeError(f"{name} must be a real number, got {value!r}")
    try:
        value = float(value)
    except OverflowError:
        raise ValueError(f"{name} is beyond the double-precision range, got {value!r}") from None
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


def time_within(name: str, value, limit: float, limit_name: str, why: str) -> float:
    """Finite time in [0, ``limit``]; ``limit_name`` names the module constant that sets the limit, ``why`` its
    reason."""
    value = nonnegative(name, value)
    if value > limit:
        raise ValueError(f"{name} = {value:g} is beyond {limit_name} = {limit:g}: {why}")
    return value


def integer_at_least(name: str, value, minimum: int, maximum: int | None = None) -> int:
    """Integer >= ``minimum`` (and <= ``maximum``, a limit on the work a call may ask for)."""
    if isinstance(value, bool) or not isinstance(value, (Integral, np.integer)):
        raise ParameterTypeError(f"{name} must be an integer, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    if maximum is not None and value > maximum:
        raise ValueError(f"{name} must be at most {maximum} (a limit on the work of one call), got {value}")
    return int(value)


def in_interval(name: str, values, low: float, high: float) -> np.ndarray:
    """Finite array with every entry in the closed interval [low, high]."""
    array = real_array(name, values)
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} contains NaN or infinite values")
    if np.any(array < low) or np.any(array > high):
        raise ValueError(f"{name} must lie in [{low}, {high}]")
    return array


def one_of(what: str, name, table: dict):
    """``table[name]``; a ParameterTypeError when ``name`` is not of the keys' type (None or bytes for a
    string key), else a ValueError "unknown <what> <name>: expected one of ..."."""
    key_types = {type(key) for key in table}
    if key_types and not isinstance(name, tuple(key_types)):
        raise ParameterTypeError(f"{what} must be one of {sorted(table)}, got {name!r} of type {type(name).__name__}")
    try:
        return table[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown {what} {name!r}: expected one of {sorted(table)}") from None


def finite_result(what: str, values, cause: str):
    """``values`` unchanged if every entry is finite; else a ValueError saying what overflowed and why."""
    if not np.all(np.isfinite(values)):
        raise ValueError(f"{what} is not finite: {cause}")
    return values
