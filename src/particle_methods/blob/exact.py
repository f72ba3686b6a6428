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
