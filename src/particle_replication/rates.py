"""Fitted rates shown in full: pairwise slopes and the fit over every window of resolutions.

A claimed rate is decided on one window of consecutive resolutions, chosen by a rule written in
the config before measuring (``window`` = the number of finest resolutions). The claims scripts
record every fit with a :class:`Recorder`, which logs the table and writes
``results/<paper>/rates.json``; the report prints the same tables, so a reader sees how the
slope moves with the window and which window decided the verdict.

The fitted quantity is a least-squares slope of y against x. For an order of convergence
x = log(resolution) and y = log(error); where the paper's rate carries a log factor the
measure must separate it from the rate without it, for example y = n * error against
x = log n, whose slope tends to a positive constant for log(n)/n and to 0 for 1/n.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from particle_methods.validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    instance,
    integer_at_least,
)

MAX_POINTS = 100
"""Most resolutions one fit accepts: :func:`window_slopes` fits all n^2/2 windows, a second for 100."""


def _text(name: str, value) -> str:
    if not isinstance(value, str):
        raise ParameterTypeError(f"{name} must be a string, got {value!r}")
    return value


def _path(name: str, value) -> Path:
    if not isinstance(value, (str, os.PathLike)):
        raise ParameterTypeError(f"{name} must be a path, got {value!r}")
    return Path(value)


def _listed(name: str, values, kind, what: str) -> list:
    """``values`` as a list whose items are all of type ``kind`` (``what`` in messages)."""
    if isinstance(values, (str, bytes, os.PathLike)) or not hasattr(values, "__iter__"):
        raise ParameterTypeError(f"{name} must be a list of {what}, got {values!r}")
    values = list(values)
    if not all(isinstance(value, kind) for value in values):
        raise ParameterTypeError(f"{name} must hold {what} only")
    return values


@dataclass(frozen=True)
class RateFit:
    """Slopes of y against x over every window of consecutive points, and the deciding one."""

    claim: str
    quantity: str
    resolution: str
    values: tuple[float, ...]
    slopes: tuple[tuple[float | None, ...], ...]
    window: int
    label: str = ""
    """What distinguishes fits recorded for the same claim (a time, a case)."""

    def __post_init__(self):
        for name in ("claim", "quantity", "resolution", "label"):
            _text(name, getattr(self, name))
        instance("values", self.values, tuple)
        if not 2 <= len(self.values) <= MAX_POINTS:
            raise ValueError(f"values must be a tuple of 2 to {MAX_POINTS} resolutions, got {self.values!r}")
        for value in self.values:
            finite_number("values", value)
        count = len(self.values)
        instance("window", self.window, int)
        if isinstance(self.window, bool) or not 2 <= self.window <= count:
            raise ValueError(f"window must be an integer from 2 to {count} (the number of values), got "
                             f"{self.window!r}")
        instance("slopes", self.slopes, tuple)
        if not (len(self.slopes) == count
                and all(isinstance(row, tuple) and len(row) == count for row in self.slopes)):
            raise ValueError(f"slopes must be a {count} x {count} tuple of tuples (one row per first point)")
        for i, row in enumerate(self.slopes):
            for j, value in enumerate(row):
                if j <= i and value is not None:
                    raise ValueError(f"slopes[{i}][{j}] must be None (no window ends before it starts)")
                if j > i:
                    finite_number(f"slopes[{i}][{j}]", value)

    @property
    def slope(self) -> float:
        """The slope over the deciding window: the ``window`` finest points."""
        last = len(self.values) - 1
        return float(self.slopes[last - self.window + 1][last])

    def window_values(self) -> tuple[float, ...]:
        """The slope over every window of ``window`` consecutive points, coarse to fine: K = (points -
        window + 1) values, the last one the deciding :attr:`slope`."""
        count = len(self.values)
        return tuple(float(self.slopes[i][i + self.window - 1]) for i in range(count - self.window + 1))

    @property
    def pairwise(self) -> list[float]:
        return [float(self.slopes[i][i + 1]) for i in range(len(self.values) - 1)]

    def table(self) -> str:
        """Plain text: one row per first point, one column per last point; * marks the deciding fit."""
        count = len(self.values)
        head = (f"{self.claim}{f' ({self.label})' if self.label else ''}: slope of {self.quantity}; rows: first "
                f"{self.resolution}, columns: last")
        lines = [head, " " * 12 + "".join(f"{value:>12.5g}" for value in self.values[1:])]
        first = count - self.window
        for i in range(count - 1):
            cells = []
            for j in range(1, count):
                value = self.slopes[i][j]
                mark = "*" if (i, j) == (first, count - 1) else " "
                cells.append(" " * 12 if value is None else f"{value:11.4f}{mark}")
            lines.append(f"{self.values[i]:>12.5g}" + "".join(cells))
        return "\n".join(lines)


def window_slopes(x, y) -> list[list[float | None]]:
    """slopes[i][j]: least-squares slope of y against x over points i..j (None unless j > i)."""
    x = finite_array("x", x)
    y = finite_array("y", y)
    if x.shape != y.shape or x.size < 2:
        raise ValueError("x and y must be 1D arrays of the same length, at least 2")
    if x.size > MAX_POINTS:
        raise ValueError(f"x and y must have at most MAX_POINTS = {MAX_POINTS} points (every window is fitted), "
                         f"got {x.size}")
    count = x.size
    slopes: list[list[float | None]] = [[None] * count for _ in range(count)]
    for i in range(count):
        for j in range(i + 1, count):
            xs, ys = x[i:j + 1], y[i:j + 1]
            if np.ptp(xs) == 0:
                raise ValueError("x must not repeat inside a window")
            slopes[i][j] = finite_result(f"the slope over points {i}..{j}", float(np.polyfit(xs, ys, 1)[0]),
                                         "x or y too large")
    return slopes


def fit(claim: str, quantity: str, resolution: str, values, x, y, window: int, label: str = "") -> RateFit:
    """Slopes of y against x (arrays over the resolutions ``values``, coarse to fine); the
    verdict uses the ``window`` finest points."""
    values = finite_array(_text("resolution", resolution), values)
    window = integer_at_least("window", window, 2)
    if window > values.size:
        raise ValueError(f"window must not exceed the number of resolutions ({values.size}), got {window}")
    slopes = window_slopes(x, y)
    if values.shape != np.shape(x):
        raise ValueError(f"{resolution} must have one value per point")
    return RateFit(claim, quantity, resolution, tuple(float(v) for v in values),
                   tuple(tuple(row) for row in slopes), window, label)


def order(claim: str, resolution: str, values, errors, window: int, label: str = "") -> RateFit:
    """Order of convergence: slope of log(error) against log(resolution)."""
    values = finite_array(_text("resolution", resolution), values)
    errors = finite_array("errors", errors)
    if np.any(values <= 0) or np.any(errors <= 0):
        raise ValueError("resolutions and errors must be positive to take logarithms")
    return fit(claim, f"log error against log {resolution}", resolution, values, np.log(values), np.log(errors),
               window, label)


class Slope(float):
    """A fitted slope that remembers its value on every window of the same length (:meth:`RateFit.window_values`)
    and the resolutions it was fitted on, so that a claim decided on it also states on how many windows its
    verdict holds (:func:`particle_replication.claims.claim`). Negation, scaling by a plain number and the
    difference of two slopes fitted on the same resolutions keep the windows (window by window); any other
    arithmetic gives a plain float."""

    windows: tuple[float, ...]
    resolutions: tuple[float, ...]

    def __new__(cls, rate: RateFit):
        if not isinstance(rate, RateFit):
            raise ParameterTypeError(f"rate must be a RateFit, got {type(rate).__name__}")
        return cls._made(rate.slope, rate.window_values(), rate.values)

    @classmethod
    def _made(cls, value: float, windows, resolutions) -> Slope:
        slope = float.__new__(cls, value)
        slope.windows, slope.resolutions = tuple(windows), tuple(resolutions)
        return slope

    def __neg__(self) -> Slope:
        return Slope._made(-float(self), (-value for value in self.windows), self.resolutions)

    def __sub__(self, other):
        difference = float(self) - other
        if isinstance(other, Slope) and other.resolutions == self.resolutions and len(other.windows) == len(
                self.windows):
            return Slope._made(difference, (a - b for a, b in zip(self.windows, other.windows)), self.resolutions)
        return difference

    def __rsub__(self, other):
        return other - float(self)

    def __mul__(self, other):
        """A slope scaled by a plain number (a change of units) keeps its windows."""
        if isinstance(other, (int, float)) and not isinstance(other, Slope):
            return Slope._made(float(self) * other, (value * other for value in self.windows), self.resolutions)
        return float(self) * other

    __rmul__ = __mul__


def chosen(slopes, pick):
    """``pick(values)`` (min, max, or a rule returning one of the values) applied to the deciding slopes and, when
    every one is a :class:`Slope` fitted on the same resolutions, window by window: the claim on the chosen
    value then states on how many windows its verdict holds (:func:`particle_replication.claims.claim`).
    A plain float otherwise (NaN among the slopes is passed to ``pick`` as it is)."""
    if not callable(pick):
        raise ParameterTypeError(f"pick must be callable, got {pick!r}")
    slopes = list(slopes)
    value = float(pick([float(slope) for slope in slopes]))
    if not slopes or not all(isinstance(slope, Slope) and slope.resolutions == slopes[0].resolutions
                             for slope in slopes):
        return value
    windows = [float(pick([slope.windows[i] for slope in slopes])) for i in range(len(slopes[0].windows))]
    return Slope._made(value, windows, slopes[0].resolutions)


class Recorder:
    """Collects the fits of one claims script, logs each table, writes them as JSON."""

    def __init__(self, log=print):
        if not callable(log):
            raise ParameterTypeError(f"log must be callable, got {log!r}")
        self.fits: list[RateFit] = []
        self._log = log

    def add(self, rate: RateFit) -> Slope:
        """Keep and log ``rate``; return its deciding slope, with its value on every window (:class:`Slope`)."""
        if not isinstance(rate, RateFit):
            raise ParameterTypeError(f"rate must be a RateFit, got {type(rate).__name__}")
        self.fits.append(rate)
        self._log(rate.table())
        return Slope(rate)

    def write(self, path) -> None:
        write_rates(path, self.fits)


def write_rates(path, fits) -> None:
    path = _path("path", path)
    fits = _listed("fits", fits, RateFit, "RateFit objects")
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_suffix(path.suffix + ".tmp")
    temporary.write_text(json.dumps([asdict(rate) for rate in fits], indent=1))
    temporary.replace(path)


def read_rates(path) -> list[RateFit]:
    path = _path("path", path)
    try:
        rows = json.loads(path.read_text())
    except json.JSONDecodeError as error:
        raise ValueError(f"{path} is not JSON: {error}") from None
    if not isinstance(rows, list):
        raise ValueError(f"{path} must hold a JSON list of rate fits")
    fits = []
    for index, row in enumerate(rows):
        try:
            fits.append(RateFit(**{**row, "values": tuple(row["values"]),
                                   "slopes": tuple(tuple(r) for r in row["slopes"])}))
        except (KeyError, TypeError) as error:
            raise ValueError(f"{path}: entry {index} is not a rate fit ({error})") from None
    return fits


def merge_rates(sources, path) -> list[RateFit]:
    fits = [rate for source in _listed("sources", sources, str | os.PathLike, "paths") for rate in read_rates(source)]
    write_rates(path, fits)
    return fits


def value_at_error(errors, values, eps: float) -> float:
    """``values`` interpolated log-log at the error ``eps`` between the two runs whose errors bracket
    it; NaN if ``eps`` lies outside the measured errors (no extrapolation)."""
    errors, values = np.asarray(errors, dtype=float), np.asarray(values, dtype=float)
    order_ = np.argsort(errors)
    errors, values = errors[order_], values[order_]
    if not errors[0] <= eps <= errors[-1]:
        return math.nan
    return float(np.exp(np.interp(np.log(eps), np.log(errors), np.log(values))))
