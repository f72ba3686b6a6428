"""The scalar fluxes of the sticky paper and the exact Godunov flux.

The Burgers flux (5.1), f(u) = u^2/2, and the concave flux (5.3), f(u) = u(1 - u)/2, each with a
single extremum u*. The Godunov flux at a face is the flux of the entropy solution of the Riemann
problem there (Godunov 1959; LeVeque, Finite Volume Methods, eq. (12.4)):

    F(a, b) = min_{a <= u <= b} f(u)  if a <= b,    F(a, b) = max_{b <= u <= a} f(u)  if a > b.

For a flux with one extremum both optimisations have a closed form: the minimum of a convex f over
[a, b] is f(clip(u*, a, b)) and its maximum is max(f(a), f(b)); a concave f swaps the two.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..jit import njit
from ..validation import ParameterTypeError, finite_number, finite_result, in_interval, real_array

_SHAPES = ("convex", "concave")


def burgers_formula(u):
    """u^2/2 without checks, for finite float states or arrays of them (compiled kernels call it on
    scalars: no array is made). It trusts its caller's checks."""
    return 0.5 * u ** 2


def concave_formula(u):
    """u(1 - u)/2 without checks, for finite float states or arrays of them (compiled kernels call it
    on scalars: no array is made). It trusts its caller's checks."""
    return 0.5 * u * (1.0 - u)


def burgers_flux(u):
    """Flux of the Burgers equation (5.1), Lambda(u) = u^2/2."""
    u = in_interval("u", u, -np.inf, np.inf)  # any finite real array
    return finite_result("the Burgers flux u^2/2", burgers_formula(u), "u is too large")


def concave_flux(u):
    """Concave flux of (5.3), Lambda(u) = u(1 - u)/2."""
    u = in_interval("u", u, -np.inf, np.inf)
    return finite_result("the concave flux u(1 - u)/2", concave_formula(u), "u is too large")


@dataclass(frozen=True)
class ScalarFlux:
    """A flux f with a single extremum u*, where f' vanishes and changes sign.

    ``f`` and ``derivative`` act element-wise on arrays. Because f' is monotone,
    the largest |f'| over an interval is reached at one of its ends.
    """

    f: Callable
    derivative: Callable
    extremum: float
    shape: str

    def __post_init__(self):
        if not callable(self.f):
            raise ParameterTypeError(f"f must be callable, got {self.f!r}")
        if not callable(self.derivative):
            raise ParameterTypeError(f"derivative must be callable, got {self.derivative!r}")
        object.__setattr__(self, "extremum", finite_number("extremum", self.extremum))
        if not isinstance(self.shape, str):
            raise ParameterTypeError(f"shape must be one of {_SHAPES} (a string), got {self.shape!r}")
        if self.shape not in _SHAPES:
            raise ValueError(f"shape must be one of {_SHAPES}, got {self.shape!r}")
        # One evaluation of each function at u*: a function that answers NaN, inf or no number is refused here,
        # by its name, rather than met later inside a scheme.
        for name, function in (("f", self.f), ("derivative", self.derivative)):
            try:
                value = real_array(f"{name}(extremum)", function(np.array([self.extremum])))
            except (ValueError, TypeError) as error:  # a TypeError of numpy's may take no message: ours does
                kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
                raise kind(f"{name}(extremum) failed at extremum = {self.extremum}: {error}") from None
            finite_result(f"{name}(extremum)", value, f"{name} returned NaN or inf at extremum = {self.extremum}")

    def max_speed(self, lo, hi) -> float:
        """max |f'(u)| over lo <= u <= hi."""
        lo = finite_number("lo", lo)
        hi = finite_number("hi", hi)
        if lo > hi:
            raise ValueError(f"lo must not exceed hi, got lo={lo} > hi={hi}")
        speeds = real_array("derivative(u)", self.derivative(np.array([lo, hi])))
        return float(finite_result("max |f'|", np.max(np.abs(speeds)), "derivative returned non-finite values"))


def _burgers_speed(u):
    """f'(u) = u for the Burgers flux."""
    return np.asarray(u, dtype=np.float64)


def _concave_speed(u):
    """f'(u) = 1/2 - u for the concave flux (5.3)."""
    return 0.5 - np.asarray(u, dtype=np.float64)


#: Burgers flux (5.1), f(u) = u^2/2: convex, minimum at u* = 0.
BURGERS = ScalarFlux(f=burgers_flux, derivative=_burgers_speed, extremum=0.0, shape="convex")

#: Concave flux (5.3), f(u) = u(1 - u)/2: maximum at u* = 1/2.
CONCAVE = ScalarFlux(f=concave_flux, derivative=_concave_speed, extremum=0.5, shape="concave")

#: The fluxes the compiled scheme knows, by their position in this tuple.
COMPILED_FLUXES = (BURGERS, CONCAVE)
_burgers_kernel = njit(burgers_formula)
_concave_kernel = njit(concave_formula)


def checked_flux(flux) -> ScalarFlux:
    if not isinstance(flux, ScalarFlux):
        raise ParameterTypeError(f"flux must be a ScalarFlux, got {type(flux).__name__}")
    return flux


def _flux_at(flux: ScalarFlux, states: np.ndarray, name: str) -> np.ndarray:
    """flux.f(states), its refusal (an overflow: u^2/2 of u = 1e300) re-raised naming the parameter ``name``."""
    try:
        return real_array("f(u)", flux.f(states))
    except (ValueError, TypeError) as error:
        kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
        raise kind(f"{name}: {error}") from None


def godunov_flux(flux: ScalarFlux, left, right):
    """Exact Godunov flux F(left, right), element-wise over broadcast arrays.

    Returns a float for scalar inputs and an array otherwise.
    """
    flux = checked_flux(flux)
    a = in_interval("left", left, -np.inf, np.inf)  # any finite real array
    b = in_interval("right", right, -np.inf, np.inf)
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError(f"left and right must broadcast together, got shapes {a.shape} and {b.shape}") from None
    low, high = np.minimum(a, b), np.maximum(a, b)
    at_extremum = _flux_at(flux, np.clip(flux.extremum, low, high), "left and right")
    f_a, f_b = _flux_at(flux, a, "left"), _flux_at(flux, b, "right")
    if flux.shape == "convex":
        value = np.where(a <= b, at_extremum, np.maximum(f_a, f_b))
    else:
        value = np.where(a <= b, np.minimum(f_a, f_b), at_extremum)
    value = finite_result("the Godunov flux", real_array("f(u)", value), "f overflowed at these left and right states")
    return float(value) if value.ndim == 0 else value


@njit
def flux_value_kernel(flux_id, u):
    if flux_id == 0:
        return _burgers_kernel(u)
    return _concave_kernel(u)


@njit
def face_flux_kernel(flux_id, convex, extremum, a, b):
    """Godunov flux F(a, b) of the flux number ``flux_id`` in ``COMPILED_FLUXES``."""
    low, high = min(a, b), max(a, b)
    if convex == (a <= b):
        return flux_value_kernel(flux_id, min(max(extremum, low), high))
    if convex:
        return max(flux_value_kernel(flux_id, a), flux_value_kernel(flux_id, b))
    return min(flux_value_kernel(flux_id, a), flux_value_kernel(flux_id, b))
