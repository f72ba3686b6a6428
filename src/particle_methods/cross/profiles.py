"""Initial densities of the cross-method comparison: symmetric about 0 and non-increasing in |x|.

The data (4.3)-(4.5) of the blob paper (not normalised: (4.3) has mass M = 0.389, (4.4) mass 2)
and the Laplace law (5.4) of the sticky paper (mass 1). Every profile gives, in closed form or
by a safeguarded Newton iteration to rounding, what the exact solution of
:mod:`particle_methods.cross.exact` needs: the mass m(a) = int_0^a rho0 (odd), the moment
int_{-R}^a s rho0(s) ds from the left end -R of the support, and the position of a level,
the a <= 0 with F0(a) = M/2 + m(a) = w for 0 <= w <= M/2.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..blob.initial import DATA_1D, Data1D
from ..jit import njit
from ..validation import ParameterTypeError, finite_values, instance, one_of, positive

#: Newton steps (each safeguarded by bisection) allowed to reach rounding; bisection alone needs 64.
MAX_ITERATIONS = 200


#: Largest number of points or levels one call of an exact solution takes (each needs a root and a few arrays).
MAX_POINTS = 10**7


def limited(name: str, values: np.ndarray) -> np.ndarray:
    """The checked array ``values`` itself, refused beyond :data:`MAX_POINTS` values."""
    if values.size > MAX_POINTS:
        raise ValueError(f"{name} has {values.size} values, more than MAX_POINTS = {MAX_POINTS} in one call")
    return values


@njit
def rtsafe_start_kernel(low, high):
    """The start of :func:`monotone_root`'s iteration on the brackets [low, high]: (x, the size of the step before the
    last one, the last step's size), rtsafe's x, "dxold" and "dx". Halves are taken before the sum: the sum of two
    large brackets overflows. It trusts its caller's checks."""
    x, before_last, last = np.empty(low.size), np.empty(low.size), np.empty(low.size)
    for i in range(low.size):
        x[i] = 0.5 * low[i] + 0.5 * high[i]
        before_last[i] = 0.5 * high[i] - 0.5 * low[i]
        last[i] = high[i] - low[i]
    return x, before_last, last


@njit
def rtsafe_steps_kernel(x, low, high, before_last, last, active, value, slope):
    """One step of :func:`monotone_root`'s iteration at the points ``active``, given function(x) - target (``value``)
    and the derivative (``slope``) there, one entry per active point; x, low, high, before_last and last are updated
    in place. Returns the points still moving (a step of more than two ulps). The one home of the step, which the
    hull's compiled roots (:mod:`particle_methods.cross.hull`) take too; it trusts its caller's checks."""
    moving = np.empty(active.size, dtype=np.int64)
    kept = 0
    for k in range(active.size):
        i, xa = active[k], x[active[k]]
        lo = xa if value[k] < 0.0 else low[i]
        hi = xa if value[k] > 0.0 else high[i]
        newton = False
        if slope[k] > 0.0:  # else a Newton step leaves the bracket
            step = xa - value[k] / slope[k]
            newton = step >= lo and step <= hi and abs(step - xa) <= 0.5 * before_last[i]
        if not newton:
            step = 0.5 * lo + 0.5 * hi
        if value[k] == 0.0:
            step = xa
        before_last[i] = last[i]
        last[i] = abs(step - xa)
        x[i], low[i], high[i] = step, lo, hi
        if abs(step - xa) > 2.0 * np.spacing(max(abs(step), 1e-300)):
            moving[kept] = i
            kept += 1
    return moving[:kept]


def monotone_root(function: Callable, derivative: Callable, target, low, high):
    """The x in [low, high] with function(x) = target, for a non-decreasing ``function``, element-wise.

    Newton steps that leave the bracket, meet a zero derivative, or move by more than half the step
    before the last one are replaced by bisection (Numerical Recipes' rtsafe): the bracket shrinks at
    every step and at least halves every other step, so the iteration converges for any monotone
    function, and quadratically near a simple root; it stops when every step moves by less than two
    ulps. A Newton step may land on an end of the bracket: a root at 0 = high (the level of the Dirac
    mass) was otherwise approached by bisection, one halving per iteration towards the denormals, for
    all MAX_ITERATIONS (200) iterations of every call. ``low`` and ``high`` must bracket the root
    (function(low) <= target <= function(high)); the caller guarantees it. The functions, the targets and the
    bracket are checked (finite values, callables): a NaN from ``function`` or ``derivative`` is refused.
    """
    for name, value in (("function", function), ("derivative", derivative)):
        if not callable(value):
            raise ParameterTypeError(f"{name} must be callable, got {value!r}")
    target = limited("target", finite_values("target", target))
    shape = target.shape
    target = target.ravel()
    ends = []
    for name, end in (("low", low), ("high", high)):
        end = finite_values(name, end)
        try:
            ends.append(np.broadcast_to(end, shape).ravel().copy())
        except ValueError:
            raise ValueError(f"{name} must be a number or of the shape {shape} of target, got {end.shape}") from None
    low, high = ends
    x, before_last, last = rtsafe_start_kernel(low, high)
    active = np.arange(x.size)  # the points still moving: converged ones leave the iteration
    for _ in range(MAX_ITERATIONS):
        if active.size == 0:
            break
        xa = x[active]
        value = _real("function", function(xa), xa.shape) - target[active]
        slope = _real("derivative", derivative(xa), xa.shape)
        if not np.all(np.isfinite(value)):
            raise ValueError("function returned NaN or infinite values inside the bracket [low, high]")
        if np.any(np.isnan(slope)):
            raise ValueError("derivative returned NaN inside the bracket [low, high]")
        active = rtsafe_steps_kernel(x, low, high, before_last, last, active, value, slope)
    return x.reshape(shape)


def _real(name: str, values, shape) -> np.ndarray:
    """What ``name`` returned at the points of ``shape``, as contiguous float64; refused unless real numbers."""
    values = np.asarray(values)
    if values.dtype.kind not in "biuf":
        raise ParameterTypeError(f"{name} must return real numbers, got {values.dtype} values")
    try:
        return np.ascontiguousarray(np.broadcast_to(values, shape), dtype=float)
    except ValueError:
        raise ValueError(f"{name} returned values of shape {values.shape} at {shape} points") from None


@dataclass(frozen=True)
class Profile:
    """A symmetric, non-increasing-in-|x| initial density rho0 on (-radius, radius).

    ``mass_from_origin`` is m(a) = int_0^a rho0 (odd in a), ``moment_from_left`` is
    int_{-radius}^a s rho0(s) ds, ``level_position`` the inverse of F0 = M/2 + m on levels
    0 <= w <= M/2 (non-positive positions).
    """

    name: str
    mass: float
    peak: float
    radius: float
    density: Callable
    mass_from_origin: Callable
    moment_from_left: Callable
    level_position: Callable

    def __post_init__(self):
        # Checked at construction: a zero or negative peak or mass would give a CDF outside [0, M] or divide by 0
        # in the blow-up time 1/peak.
        instance("name", self.name, str)
        for key in ("mass", "peak"):
            value = positive(key, getattr(self, key))
            if not math.isfinite(value):
                raise ValueError(f"{key} must be finite, got {value}")
        if not (isinstance(self.radius, (int, float)) and not isinstance(self.radius, bool) and self.radius > 0):
            raise ParameterTypeError(f"radius must be a positive number (inf for an unbounded support), got "
                                     f"{self.radius!r}")
        try:
            float(self.radius)
        except OverflowError:
            raise ValueError(f"radius is beyond the double-precision range, got {self.radius!r}") from None
        for key in ("density", "mass_from_origin", "moment_from_left", "level_position"):
            if not callable(getattr(self, key)):
                raise ParameterTypeError(f"{key} must be callable, got {getattr(self, key)!r}")
        # One probe of each function where every profile is defined (the centre, the level M/4): a function that
        # returns NaN or inf there is refused at once, not found in an exact solution's results.
        for key, at in (("density", 0.0), ("mass_from_origin", 0.0), ("moment_from_left", 0.0),
                        ("level_position", 0.25 * self.mass)):
            value = np.asarray(getattr(self, key)(np.array([at])))
            if value.dtype.kind not in "biuf" or not np.all(np.isfinite(value)):
                raise ValueError(f"{key} must return finite real values, got {value!r} at {at}")


def _polynomial_profile(data: Data1D) -> Profile:
    """(4.3)-(4.5): (1 - x^2)^p on [-1, 1], or the indicator (p = 0)."""
    mass = data.mass

    def level_position(w):
        w = np.asarray(w, dtype=np.float64)
        return monotone_root(data.mass_from_origin, data, w - 0.5 * mass, -np.ones_like(w), np.zeros_like(w))

    return Profile(data.name, mass, data.maximum, 1.0, data, data.mass_from_origin, data.moment_from_left,
                   level_position)


def _laplace_mass(a):
    a = np.asarray(a, dtype=np.float64)
    return np.sign(a) * 0.5 * -np.expm1(-np.abs(a))


def _laplace_moment(a):
    """int_{-inf}^a s e^{-|s|}/2 ds: (a - 1) e^a / 2 for a <= 0, -(a + 1) e^{-a} / 2 above."""
    a = np.asarray(a, dtype=np.float64)
    return np.where(a <= 0.0, 0.5 * (a - 1.0) * np.exp(np.minimum(a, 0.0)),
                    -0.5 * (a + 1.0) * np.exp(-np.maximum(a, 0.0)))


def _laplace_level(w):
    with np.errstate(divide="ignore"):
        return np.log(2.0 * np.asarray(w, dtype=np.float64))


LAPLACE = Profile("Laplace law e^{-|x|}/2 (5.4)", 1.0, 0.5, math.inf, lambda x: 0.5 * np.exp(-np.abs(x)),
                  _laplace_mass, _laplace_moment, _laplace_level)

PROFILES = {**{name: _polynomial_profile(data) for name, data in DATA_1D.items()}, "laplace": LAPLACE}


def profile(data) -> Profile:
    """The profile of ``data``: a name ('smooth20' (4.3), 'indicator' (4.4), 'smooth10' (4.5), 'laplace'),
    a :class:`~particle_methods.blob.initial.Data1D`, or a :class:`Profile`."""
    if isinstance(data, Profile):
        return data
    if isinstance(data, Data1D):
        return _polynomial_profile(data)
    if isinstance(data, str):
        return one_of("initial data", data, PROFILES)
    raise ParameterTypeError(f"data must be a data name, a Data1D or a Profile, got {data!r}")

