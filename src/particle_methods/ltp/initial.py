"""Initial densities (6.1)-(6.3), normalised to unit mass, and the particle weights (2.14), (2.16).

Each density gives its CDF in closed form (or by converged adaptive quadrature
for (6.3)), so that cell integrals of rho^0 are exact differences of the CDF.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import integrate, special

from ..validation import one_of, positive
from .shapes import Shape


@dataclass(frozen=True)
class InitialDensity:
    """A probability density on [lower, upper] with its CDF."""

    name: str
    pdf: Callable
    cdf: Callable
    lower: float
    upper: float

    @property
    def mean(self) -> float:
        """Centre of mass lambda = int x rho^0(x) dx."""
        return float(integrate.quad(lambda x: x * float(self.pdf(x)), self.lower, self.upper,
                                    epsabs=1e-14, limit=200)[0])


def _gaussian_bumps():
    """(6.1): exp(-30 (x - 0.5)^2) + 2 exp(-50 (x + 0.3)^2) on [-1, 1]."""
    bumps = ((1.0, 30.0, 0.5), (2.0, 50.0, -0.3))

    def primitive(x):
        x = np.clip(np.asarray(x, dtype=np.float64), -1.0, 1.0)
        return sum(amp * 0.5 * np.sqrt(np.pi / a) * special.erf(np.sqrt(a) * (x - c)) for amp, a, c in bumps)

    total = primitive(1.0) - primitive(-1.0)

    def pdf(x):
        x = np.asarray(x, dtype=np.float64)
        inside = (x >= -1.0) & (x <= 1.0)
        return np.where(inside, sum(amp * np.exp(-a * (x - c) ** 2) for amp, a, c in bumps), 0.0) / total

    return InitialDensity("rho1", pdf, lambda x: (primitive(x) - primitive(-1.0)) / total, -1.0, 1.0)


def _indicator():
    """(6.2): the indicator of [-1, 1], normalised."""
    return InitialDensity(
        "rho2",
        lambda x: np.where(np.abs(np.asarray(x, dtype=np.float64)) <= 1.0, 0.5, 0.0),
        lambda x: np.clip((np.asarray(x, dtype=np.float64) + 1.0) / 2.0, 0.0, 1.0),
        -1.0,
        1.0,
    )


def _bump():
    """(6.3): exp(1/(x^2 - 1)) on (-1, 1), normalised; CDF by adaptive quadrature (C-infinity data)."""

    def raw(x):
        x = np.asarray(x, dtype=np.float64)
        inside = np.abs(x) < 1.0
        return np.where(inside, np.exp(1.0 / np.where(inside, x**2 - 1.0, -1.0)), 0.0)

    total = integrate.quad(lambda x: float(raw(x)), -1.0, 1.0, epsabs=1e-15, epsrel=1e-13)[0]

    def cdf(x):
        x = np.clip(np.asarray(x, dtype=np.float64), -1.0, 1.0)
        flat = [integrate.quad(lambda y: float(raw(y)), -1.0, float(v), epsabs=1e-15, epsrel=1e-13)[0]
                for v in np.ravel(x)]
        return np.reshape(flat, np.shape(x)) / total

    return InitialDensity("rho3", lambda x: raw(x) / total, cdf, -1.0, 1.0)


DENSITIES = {"rho1": _gaussian_bumps(), "rho2": _indicator(), "rho3": _bump()}


def density_named(name: str) -> InitialDensity:
    """Initial density (6.1) 'rho1', (6.2) 'rho2' or (6.3) 'rho3'."""
    return one_of("initial density", name, DENSITIES)


def grid_particles(density: InitialDensity, h: float, shape: Shape, weights: str = "cell"):
    """Centres x_k = k h and weights of the particles that carry mass.

    ``weights='cell'``: omega_k = int over [x_k - h/2, x_k + h/2] of rho^0 (2.14).
    ``weights='biorthogonal'``: omega_k = int phi~((x - x_k)/h) rho^0(x) dx (2.16) with
    the kernel bi-orthogonal to the hat; only valid for the hat shape.
    Both are differences of the CDF, hence exact.
    """
    h = positive("h", h)
    first = int(np.floor(density.lower / h)) - 1
    last = int(np.ceil(density.upper / h)) + 1
    centres = h * np.arange(first, last + 1)
    cdf = density.cdf
    if weights == "cell":
        values = cdf(centres + 0.5 * h) - cdf(centres - 0.5 * h)
    elif weights == "biorthogonal":
        if shape.name != "hat":
            raise ValueError("biorthogonal weights (2.16) are defined here for the hat shape only")
        middle = cdf(centres + 0.5 * h) - cdf(centres - 0.5 * h)
        sides = (cdf(centres + h) - cdf(centres + 0.5 * h)) + (cdf(centres - 0.5 * h) - cdf(centres - h))
        values = 1.5 * middle - 0.5 * sides
    else:
        raise ValueError(f"unknown weights {weights!r}: expected 'cell' or 'biorthogonal'")
    keep = values != 0.0
    return centres[keep], values[keep]
