"""Initial densities (6.1)-(6.3), normalised to unit mass, and the particle weights (2.14), (2.16).

Each density gives its CDF in closed form (or by converged adaptive quadrature
for (6.3)), so that cell integrals of rho^0 are exact differences of the CDF.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..perturbation import nudged
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    finite_values,
    instance,
    integer_at_least,
    one_of,
    positive,
    real_array,
    same_length,
)
from .checks import MAX_PARTICLES
from .shapes import Shape

#: Grid indices k = x / h stay below this bound, where the centres x_k = k h are exact integers times h.
MAX_INDEX = 2.0**53


@dataclass(frozen=True)
class InitialDensity:
    """A density of finite mass on [lower, upper] (finite, lower < upper) with its CDF int_lower^x rho^0.

    The particle methods need no unit mass: the weights (2.14), (2.16) are differences of the CDF and
    sum to the mass; (6.1)-(6.3) are normalised to unit mass. The construction tries both functions: the cdf at
    [lower, upper] must give finite non-decreasing values, the pdf a finite value at the middle, unless it refuses
    every point with a ValueError (a measure with no density: :func:`atomic`).
    """

    name: str
    pdf: Callable
    cdf: Callable
    lower: float
    upper: float

    def __post_init__(self):
        instance("name", self.name, str)
        for name in ("pdf", "cdf"):
            if not callable(getattr(self, name)):
                raise ParameterTypeError(f"{name} must be callable, got {getattr(self, name)!r}")
        lower, upper = finite_number("lower", self.lower), finite_number("upper", self.upper)
        if not lower < upper:
            raise ValueError(f"lower must be below upper, got [{lower}, {upper}]")
        object.__setattr__(self, "lower", lower)
        object.__setattr__(self, "upper", upper)
        ends = real_array("the values of cdf", self.cdf(np.array([lower, upper])))
        if ends.shape != (2,) or not np.all(np.isfinite(ends)) or ends[1] < ends[0]:
            raise ValueError(f"cdf must give finite non-decreasing values, one per point: at [lower, upper] = "
                             f"[{lower:g}, {upper:g}] it gives {ends}")
        try:  # an atomic measure has no density: its pdf refuses every point
            middle = self.pdf(np.array([0.5 * lower + 0.5 * upper]))
        except ValueError:
            return
        middle = real_array("the values of pdf", middle)
        if not np.all(np.isfinite(middle)):
            raise ValueError(f"pdf must give finite values, got {middle} at the middle of [lower, upper]")

    @property
    def mean(self) -> float:
        """Centre of mass lambda of (6.4): int x rho^0(x) dx divided by the mass cdf(upper) - cdf(lower)."""
        from scipy import integrate

        moment = float(integrate.quad(lambda x: x * float(self.pdf(x)), self.lower, self.upper,
                                      epsabs=1e-14, limit=200)[0])
        mass = float(self.cdf(self.upper) - self.cdf(self.lower))
        if not mass > 0:
            raise ValueError(f"the density {self.name} must have positive mass, its cdf gives {mass}")
        return finite_result("the centre of mass", moment / mass, f"the pdf of {self.name} is not integrable")


def _gaussian_bumps():
    """(6.1): exp(-30 (x - 0.5)^2) + 2 exp(-50 (x + 0.3)^2) on [-1, 1]."""
    bumps = ((1.0, 30.0, 0.5), (2.0, 50.0, -0.3))

    def primitive(x):
        from scipy import special

        x = np.clip(finite_values("x", x), -1.0, 1.0)
        return sum(amp * 0.5 * np.sqrt(np.pi / a) * special.erf(np.sqrt(a) * (x - c)) for amp, a, c in bumps)

    total = primitive(1.0) - primitive(-1.0)

    def pdf(x):
        x = finite_values("x", x)
        inside = (x >= -1.0) & (x <= 1.0)
        return np.where(inside, sum(amp * np.exp(-a * (x - c) ** 2) for amp, a, c in bumps), 0.0) / total

    return InitialDensity("rho1", pdf, lambda x: (primitive(x) - primitive(-1.0)) / total, -1.0, 1.0)


def _indicator():
    """(6.2): the indicator of [-1, 1], normalised."""
    return InitialDensity(
        "rho2",
        lambda x: np.where(np.abs(finite_values("x", x)) <= 1.0, 0.5, 0.0),
        lambda x: np.clip((finite_values("x", x) + 1.0) / 2.0, 0.0, 1.0),
        -1.0,
        1.0,
    )


def _bump():
    """(6.3): exp(1/(x^2 - 1)) on (-1, 1), normalised; CDF by adaptive quadrature (C-infinity data)."""

    def raw(x):
        x = np.asarray(x, dtype=np.float64)
        inside = np.abs(x) < 1.0
        return np.where(inside, np.exp(1.0 / np.where(inside, x**2 - 1.0, -1.0)), 0.0)

    from scipy import integrate

    total = integrate.quad(lambda x: float(raw(x)), -1.0, 1.0, epsabs=1e-15, epsrel=1e-13)[0]

    def cdf(x):
        x = np.clip(finite_values("x", x), -1.0, 1.0)
        flat = [integrate.quad(lambda y: float(raw(y)), -1.0, float(v), epsabs=1e-15, epsrel=1e-13)[0]
                for v in np.ravel(x)]
        return np.reshape(flat, np.shape(x)) / total

    return InitialDensity("rho3", lambda x: raw(finite_values("x", x)) / total, cdf, -1.0, 1.0)


#: The makers of the initial densities (6.1) to (6.3) by name. Each is made when first asked for
#: (:func:`density_named`): (6.1)'s and (6.3)'s normalisations need scipy, whose import (0.3 to 0.7 s) most of
#: the jobs that import this package never need.
DENSITIES = {"rho1": _gaussian_bumps, "rho2": _indicator, "rho3": _bump}


def golden_atoms(count: int, lower: float, upper: float):
    """``count`` atoms of equal mass 1/count at lower + (upper - lower) frac(i g), i = 1..count, g the golden
    ratio (sorted): a measure with no density, spread over [lower, upper] with no regular spacing, so that no grid
    step h puts them all at cell centres or all at cell edges."""
    count = integer_at_least("count", count, 1, MAX_PARTICLES)
    lower, upper = finite_number("lower", lower), finite_number("upper", upper)
    if not lower < upper:
        raise ValueError(f"lower must be below upper, got [{lower}, {upper}]")
    fractions = np.remainder(np.arange(1, count + 1) * (0.5 * (1.0 + math.sqrt(5.0))), 1.0)
    return np.sort(lower + (upper - lower) * fractions), np.full(count, 1.0 / count)


def atomic(positions, masses) -> InitialDensity:
    """The measure sum_i masses[i] delta_{positions[i]} (Theorem 3's initial probability measure, Remark 4): its
    CDF is the right-continuous step function, so the cell weights (2.14) are the masses of the atoms in each
    cell; it has no density (``pdf`` raises ValueError). Positions finite, masses positive."""
    positions = finite_array("positions", positions)
    masses = finite_array("masses", masses)
    same_length(positions=positions, masses=masses)
    if positions.size == 0 or np.any(masses <= 0):
        raise ValueError("an atomic measure needs at least one atom and positive masses")
    order = np.argsort(positions, kind="stable")
    x, levels = positions[order], np.concatenate([[0.0], np.cumsum(masses[order])])

    def cdf(y):
        return levels[np.searchsorted(x, finite_values("x", y), side="right")]

    def pdf(y):
        raise ValueError("an atomic measure has no density")

    with np.errstate(over="ignore"):
        span = max(x[-1] - x[0], 1.0)
        lower, upper = x[0] - 1e-3 * span, x[-1] + 1e-3 * span
    if not (np.isfinite(span) and lower < x[0] and x[-1] < upper):
        raise ValueError(f"positions must leave room for a margin around the atoms in double precision, got "
                         f"[{x[0]:g}, {x[-1]:g}]")
    return InitialDensity(f"{x.size} atoms", pdf, cdf, float(lower), float(upper))


def density_named(name: str) -> InitialDensity:
    """Initial density (6.1) 'rho1', (6.2) 'rho2' or (6.3) 'rho3' (made once, then the same object)."""
    return _made(one_of("initial density", name, DENSITIES))


@functools.cache
def _made(maker: Callable[[], InitialDensity]) -> InitialDensity:
    return maker()


def grid_particles(density: InitialDensity, h: float, shape: Shape, weights: str = "cell", offset: float = 0.0):
    """Centres x_k = (k + offset) h and weights of the particles that carry mass.

    ``offset`` in [0, 1) shifts the grid by that fraction of h (0: the grid of (2.14) with a particle
    at x = 0; 0.5: the cell edges of that grid, no particle at 0); the weights are the same
    integrals of rho^0 over the shifted cells.

    ``weights='cell'``: omega_k = int over [x_k - h/2, x_k + h/2] of rho^0 (2.14).
    ``weights='biorthogonal'``: omega_k = int phi~((x - x_k)/h) rho^0(x) dx (2.16) with
    the kernel bi-orthogonal to the hat; only valid for the hat shape.
    Both are differences of the CDF, hence exact. At most MAX_PARTICLES particles.
    """
    instance("density", density, InitialDensity)
    h = positive("h", h)
    instance("shape", shape, Shape)
    rule = one_of("weights", weights, WEIGHTS)
    offset = finite_number("offset", offset)
    if not 0.0 <= offset < 1.0:
        raise ValueError(f"offset must lie in [0, 1) (a fraction of h), got {offset}")
    with np.errstate(over="ignore", invalid="ignore"):  # tiny h: infinite indices, refused just below
        low = np.floor(density.lower / h - offset) - 1  # first and last k
        high = np.ceil(density.upper / h - offset) + 1
        if not high - low + 1 <= MAX_PARTICLES:
            raise ValueError(f"h = {h:g} gives about {(density.upper - density.lower) / h:.3g} particles on "
                             f"[{density.lower:g}, {density.upper:g}], beyond the limit MAX_PARTICLES = "
                             f"{MAX_PARTICLES} of one call")
    if max(abs(low), abs(high)) >= MAX_INDEX:
        raise ValueError(f"h = {h:g} puts [{density.lower:g}, {density.upper:g}] at grid indices beyond 2^53")
    if not math.isfinite(h * (float(max(abs(low), abs(high))) + 1.0)):  # Python floats: inf, no warning
        raise ValueError(f"h = {h:g} is too large: the cells around [{density.lower:g}, {density.upper:g}] overflow")
    centres = h * (np.arange(int(low), int(high) + 1) + offset)
    values = real_array("the weights", rule(density.cdf, centres, h, shape))
    if values.shape != centres.shape:
        raise ValueError(f"the CDF of {density.name} must return one value per point, got shape {values.shape}")
    finite_result("the weights", values, f"the CDF of {density.name} is not finite")
    if weights == "cell" and values.size and values.min() < -WEIGHT_ROUNDING * np.abs(values).max():
        raise ValueError(f"the CDF of {density.name} decreases: the cell weights (2.14) are its increments, "
                         f"and one is {values.min():.3g}")
    keep = values != 0.0
    return nudged(centres[keep]), nudged(values[keep])


#: Cell weights (2.14) below -WEIGHT_ROUNDING times the largest one are refused: the CDF decreases. (Rounding in the
#: flat tails of a CDF leaves increments of a few ulps of either sign.)
WEIGHT_ROUNDING = 1e-12


def _cell_weights(cdf, centres, h, shape):
    """(2.14): omega_k = int over [x_k - h/2, x_k + h/2] of rho^0."""
    return cdf(centres + 0.5 * h) - cdf(centres - 0.5 * h)


def _biorthogonal_weights(cdf, centres, h, shape):
    """(2.16) with the kernel (2.17) bi-orthogonal to the hat."""
    if shape.name != "hat":
        raise ValueError("biorthogonal weights (2.16) are defined here for the hat shape only")
    middle = cdf(centres + 0.5 * h) - cdf(centres - 0.5 * h)
    sides = (cdf(centres + h) - cdf(centres + 0.5 * h)) + (cdf(centres - 0.5 * h) - cdf(centres - h))
    return 1.5 * middle - 0.5 * sides


WEIGHTS = {"cell": _cell_weights, "biorthogonal": _biorthogonal_weights}
