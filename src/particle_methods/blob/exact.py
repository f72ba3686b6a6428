"""Exact solutions for the 1D Newtonian kernel and symmetric data, by mass coordinates (section 4.1).

With m(alpha) = int_0^alpha rho0, the trajectories are X(alpha, t) = alpha - s t m(alpha)
and the density along them rho = (1/rho0(alpha) - s t)^{-1}, with s = +1 for the
attractive kernel |x|/2 (blow-up at t = 1/max rho0) and s = -1 for the repulsive -|x|/2.
"""

from __future__ import annotations

import math

import numpy as np

from ..validation import finite_array, finite_result, nonnegative, one_of
from .initial import Data1D, as_data_1d, as_data_2d

SIGNS = {"newtonian_attractive": 1.0, "newtonian_repulsive": -1.0}


def blowup_time(data: Data1D, kernel: str) -> float:
    """First time at which the exact solution stops being classical, 1/max rho0; ``math.inf`` (never)
    for the repulsive kernel, the one non-finite value the package returns on purpose. ``data`` is a
    :class:`~particle_methods.blob.initial.Data1D` or its name."""
    data = as_data_1d(data)
    return 1.0 / data.maximum if one_of("Newtonian kernel", kernel, SIGNS) > 0 else math.inf


def _initial_density(data, labels, rho0):
    """The initial density at the labels: the data's, or ``rho0`` (one value per label, non-negative)."""
    if rho0 is None:
        return data(labels)
    rho0 = finite_array("rho0", rho0)
    if rho0.shape != labels.shape[:1] or np.any(rho0 < 0):
        raise ValueError(f"rho0 must hold one non-negative initial density per label of alpha or points "
                         f"({labels.shape[0]}), got shape {rho0.shape}")
    return rho0


def newtonian_exact(data: Data1D, kernel: str, alpha, t: float, rho0=None):
    """(X(alpha, t), rho(X(alpha, t), t)) for the Newtonian kernel ``kernel``, before the blow-up time.

    ``rho0``: the initial density carried by each label (default: the data at alpha). A run's own initial
    densities make the density along a trajectory that of its particle: a label on a jump of the data (the ends
    of the indicator (4.4)) then keeps the value its particle was given, however its position rounds."""
    data = as_data_1d(data)
    sign = one_of("Newtonian kernel", kernel, SIGNS)
    t = nonnegative("t", t)
    if t >= blowup_time(data, kernel):
        raise ValueError(f"t = {t} is past the blow-up time {blowup_time(data, kernel)} of the exact solution")
    alpha = finite_array("alpha", alpha)
    rho0 = _initial_density(data, alpha, rho0)
    positive = rho0 > 0
    density = np.zeros_like(alpha)
    density[positive] = 1.0 / (1.0 / rho0[positive] - sign * t)
    position = alpha - sign * t * data.mass_from_origin(alpha)
    cause = f"t = {t} is too large for these alpha"
    return finite_result("X(alpha, t)", position, cause), finite_result("rho(X(alpha, t), t)", density, cause)


def newtonian_exact_2d(data, points, t: float, rho0=None):
    """Attractive 2D Newtonian kernel log|x|/(2 pi), radial data ('regular' or 'disk', or their names):
    |X|^2 = r0^2 - 2 t m(r0) (mass coordinates, section 4.1) along rays, rho = (1/rho0 - t)^{-1};
    blow-up at t = 1/max rho0 over ``points`` (N, 2). ``rho0`` as in :func:`newtonian_exact`."""
    data = as_data_2d(data)
    t = nonnegative("t", t)
    points = finite_array("points", points, ndim=2)
    if points.shape[0] == 0 or points.shape[1] != 2:
        raise ValueError(f"points must have shape (N, 2) with N >= 1, got {points.shape}")
    rho0 = _initial_density(data, points, rho0)
    if t * rho0.max() >= 1.0:
        raise ValueError(f"t = {t} is past the blow-up time 1 / max rho0 = {1.0 / rho0.max()} of the exact solution")
    with np.errstate(over="ignore"):
        r0 = finite_result("|points|", np.hypot(points[:, 0], points[:, 1]), "points beyond the double range")
    r = np.sqrt(np.maximum(r0**2 - 2.0 * t * data.mass_from_origin(r0), 0.0))
    scale = np.divide(r, r0, out=np.zeros_like(r0), where=r0 > 0)
    density = np.zeros_like(r0)
    inside = rho0 > 0
    density[inside] = 1.0 / (1.0 / rho0[inside] - t)
    cause = f"t = {t} or the points are too large"
    return finite_result("X(r0, t)", points * scale[:, None], cause), finite_result("rho", density, cause)
