"""Exact solution (6.4) for quadratic potentials, by the method of characteristics.

For W = c x^2/2 the velocity is -(W' * rho)(x) = -c (x - lambda) with lambda the
(conserved) centre of mass, so characteristics contract towards lambda like e^{-c t}
and rho(t, x) = rho^0((x - lambda) e^{c t} + lambda) e^{c t}: c = 2 for W = x^2 (6.4),
c = 1 for W = x^2/2.
"""

from __future__ import annotations

import numpy as np

from ..validation import nonnegative
from .initial import InitialDensity
from .potentials import Potential


def quadratic_rate(potential: Potential) -> float:
    """c such that W = c x^2/2; ValueError for any other potential."""
    if potential.exponents != (2.0,):
        raise ValueError(f"the exact solution (6.4) needs a quadratic potential, got {potential.name}")
    return potential.coefficients[0]


def exact_density(initial: InitialDensity, potential: Potential, t: float, x) -> np.ndarray:
    """rho(t, x) of (6.4) for W = c x^2 / 2."""
    rate = quadratic_rate(potential)
    t = nonnegative("t", t)
    centre = initial.mean
    factor = np.exp(rate * t)
    return initial.pdf((np.asarray(x, dtype=np.float64) - centre) * factor + centre) * factor


def exact_support(initial: InitialDensity, potential: Potential, t: float) -> tuple[float, float]:
    """Image of [lower, upper] by the flow at time t."""
    rate = quadratic_rate(potential)
    centre = initial.mean
    shrink = np.exp(-rate * nonnegative("t", t))
    return centre + (initial.lower - centre) * shrink, centre + (initial.upper - centre) * shrink
