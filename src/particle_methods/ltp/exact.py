"""Exact solution (6.4) for quadratic potentials, by the method of characteristics.

For W = c x^2/2 the velocity is -(W' * rho)(x) = -c (x - lambda) with lambda the
(conserved) centre of mass, so characteristics contract towards lambda like e^{-c t}
and rho(t, x) = rho^0((x - lambda) e^{c t} + lambda) e^{c t}: c = 2 for W = x^2 (6.4),
c = 1 for W = x^2/2. For c t beyond log(max double) ~ 709.8 the density exceeds the double
range and t is refused.
"""

from __future__ import annotations

import numpy as np

from ..validation import finite_result, finite_values, instance, nonnegative
from .initial import InitialDensity
from .potentials import Potential


def quadratic_rate(potential: Potential) -> float:
    """c such that W = c x^2/2; ValueError for any other potential."""
    instance("potential", potential, Potential)
    if potential.exponents != (2.0,):
        raise ValueError(f"the exact solution (6.4) needs a quadratic potential, got {potential.name}")
    return potential.coefficients[0]


def _arguments(initial: InitialDensity, potential: Potential, t: float) -> tuple[float, float]:
    """(c, t) after checking the three arguments of (6.4)."""
    instance("initial", initial, InitialDensity)
    return quadratic_rate(potential), nonnegative("t", t)


def exact_density(initial: InitialDensity, potential: Potential, t: float, x) -> np.ndarray:
    """rho(t, x) of (6.4) for W = c x^2 / 2, at finite x of any shape."""
    rate, t = _arguments(initial, potential, t)
    x = finite_values("x", x)
    centre = initial.mean
    with np.errstate(over="ignore"):
        factor = finite_result("e^(c t) in (6.4)", np.exp(rate * t), f"t = {t:g} is too large (c t > 709)")
        origin = (x - centre) * factor + centre
    inside = (origin >= initial.lower) & (origin <= initial.upper)  # rho^0 = 0 outside; origin may overflow
    density = np.where(inside, initial.pdf(np.where(inside, origin, initial.lower)) * factor, 0.0)
    return finite_result("the exact density (6.4)", density, f"t = {t:g} is too large: rho^0 e^(c t) overflows")


def exact_support(initial: InitialDensity, potential: Potential, t: float) -> tuple[float, float]:
    """Image of [lower, upper] by the flow at time t."""
    rate, t = _arguments(initial, potential, t)
    centre = initial.mean
    with np.errstate(over="ignore"):
        shrink = np.exp(-rate * t)
    support = centre + (initial.lower - centre) * shrink, centre + (initial.upper - centre) * shrink
    return finite_result("the exact support", support, f"t = {t:g} is too large: the support overflows")
