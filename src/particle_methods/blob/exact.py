"""Exact solutions for the 1D Newtonian kernel and symmetric data, by mass coordinates (section 4.1).

With m(alpha) = int_0^alpha rho0, the trajectories are X(alpha, t) = alpha - s t m(alpha)
and the density along them rho = (1/rho0(alpha) - s t)^{-1}, with s = +1 for the
attractive kernel |x|/2 (blow-up at t = 1/max rho0) and s = -1 for the repulsive -|x|/2.
"""

from __future__ import annotations

import numpy as np

from ..validation import finite_array, nonnegative
from .initial import Data1D

SIGNS = {"newtonian_attractive": 1.0, "newtonian_repulsive": -1.0}


def blowup_time(data: Data1D, kernel: str) -> float:
    """First time at which the exact solution stops being classical (inf when repulsive)."""
    return 1.0 / data.maximum if SIGNS[kernel] > 0 else np.inf


def newtonian_exact(data: Data1D, kernel: str, alpha, t: float):
    """(X(alpha, t), rho(X(alpha, t), t)) for the Newtonian kernel ``kernel``."""
    if kernel not in SIGNS:
        raise ValueError(f"exact solutions exist for {sorted(SIGNS)}, not {kernel!r}")
    t = nonnegative("t", t)
    if t >= blowup_time(data, kernel):
        raise ValueError(f"t = {t} is past the blow-up time {blowup_time(data, kernel)} of the exact solution")
    alpha = finite_array("alpha", alpha)
    sign = SIGNS[kernel]
    rho0 = data(alpha)
    positive = rho0 > 0
    density = np.zeros_like(alpha)
    density[positive] = 1.0 / (1.0 / rho0[positive] - sign * t)
    return alpha - sign * t * data.mass_from_origin(alpha), density


def newtonian_exact_2d(data, points, t: float):
    """Attractive 2D Newtonian kernel log|x|/(2 pi), radial data: |X|^2 = r0^2 - 2 t m(r0) (mass
    coordinates, section 4.1) along rays, rho = (1/rho0 - t)^{-1}; blow-up at t = 1/max rho0."""
    t = nonnegative("t", t)
    points = finite_array("points", points, ndim=2)
    rho0 = data(points)
    if t >= 1.0 / rho0.max():
        raise ValueError(f"t = {t} is past the blow-up time {1.0 / rho0.max()} of the exact solution")
    r0 = np.linalg.norm(points, axis=1)
    r = np.sqrt(np.maximum(r0**2 - 2.0 * t * data.mass_from_origin(r0), 0.0))
    scale = np.divide(r, r0, out=np.zeros_like(r0), where=r0 > 0)
    density = np.zeros_like(r0)
    inside = rho0 > 0
    density[inside] = 1.0 / (1.0 / rho0[inside] - t)
    return points * scale[:, None], density
