"""Numerical radial convolution of 2D kernels with the mollifier, tabulated for the pair sums.

For a radial kernel K in 2D, L = Delta K and the mollifier psi_delta = sum_i c_i G_{s_i}
(Gaussian mixture), the mollified Laplacian is a 1D integral per radius,

    L_delta(r) = sum_i c_i int_0^inf L(rho) rho (2/s_i^2) exp(-(r - rho)^2/s_i^2) i0e(2 r rho/s_i^2) d rho,

(the angular integral of a Gaussian is a modified Bessel function, i0e its scaled form),
and Gauss's theorem gives the gradient: grad K_delta(x) = x g(|x|) with
g(r) = r^{-2} int_0^r s L_delta(s) ds. Both are tabulated on a uniform radial grid of
[0, R] (one vector-valued adaptive quadrature for all nodes, cumulative Simpson for g) and interpolated
linearly in the pair sums. This is the paper's approach (it tabulated K * psi_delta by
an FFT in radial coordinates on 100 to 2e6 points); the tests check the tables against
the closed forms and their convergence in the grid.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import integrate, special

from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    instance,
    integer_at_least,
    positive,
    same_length,
)
from .checks import MAX_TABLE_WORK
from .mollifiers import Mollifier


@dataclass(frozen=True)
class RadialTable:
    """g and L_delta on r_j = j R / (M - 1)."""

    radius: float
    gradient: np.ndarray
    laplacian: np.ndarray

    def __post_init__(self):
        positive("radius", self.radius)
        for name in ("gradient", "laplacian"):
            object.__setattr__(self, name, finite_array(name, getattr(self, name)))
        integer_at_least("the number of table nodes", same_length(gradient=self.gradient, laplacian=self.laplacian), 2)

    @property
    def step(self) -> float:
        return self.radius / (self.gradient.size - 1)


def mollified_laplacian(laplacian, mollifier: Mollifier, delta: float, r) -> np.ndarray:
    """L_delta at the radii ``r`` (array), all at once: one adaptive quadrature of the vector-valued
    integrand per Gaussian (scipy's quad_vec, error in the max norm); ``laplacian`` is the radial
    Delta K, vectorised and integrable at 0 in 2D (it is never evaluated at rho = 0); a ValueError if the result
    is not finite."""
    laplacian, mollifier = _checked_laplacian(laplacian, mollifier)
    delta = positive("delta", delta)
    r = finite_array("r", r)
    if r.size == 0 or r.size > MAX_TABLE_WORK or np.any(r < 0):
        raise ValueError(f"r must hold 1 to MAX_TABLE_WORK = {MAX_TABLE_WORK:g} radii r >= 0 (a limit on the work of "
                         f"the quadrature), got {r.size} from {r.min(initial=0.0):.3g}")
    total = np.zeros_like(r)
    for weight, s in zip(mollifier.weights, mollifier.scaled_widths(delta)):
        def integrand(rho, s=s):
            return laplacian(rho) * rho * (2.0 / s**2) * np.exp(-((r - rho) / s) ** 2) * special.i0e(2 * r * rho / s**2)

        values, _ = integrate.quad_vec(integrand, 0.0, float(r.max()) + 9 * s, epsabs=1e-13, epsrel=1e-11,
                                       norm="max", limit=5000)
        total += weight * values
    return finite_result("L_delta", total, f"laplacian is not finite or overflows with delta = {delta} at r up to "
                         f"{r.max():.3g}")


def _checked_laplacian(laplacian, mollifier):
    """(laplacian, mollifier) if the first is a function and the second a 2D :class:`Mollifier`."""
    if not callable(laplacian):
        raise ParameterTypeError(f"laplacian must be a function of r, got {laplacian!r}")
    if instance("mollifier", mollifier, Mollifier).dimension != 2:
        raise ValueError("radial tables are built for 2D mollifiers")
    return laplacian, mollifier


def tabulate(laplacian, mollifier: Mollifier, delta: float, radius: float = 5.0, points: int = 2001) -> RadialTable:
    """Tables of g and L_delta for a radial 2D kernel given by its Laplacian (read-only arrays); a
    ValueError if they overflow (see :func:`~particle_methods.blob.kernels.kernel_2d` for the ranges
    of delta, radius and points that are accepted there)."""
    laplacian, mollifier = _checked_laplacian(laplacian, mollifier)
    positive("delta", delta)
    radius = positive("radius", radius)
    points = integer_at_least("points", points, 3, int(MAX_TABLE_WORK))
    r = np.linspace(0.0, radius, points)
    if not np.all(np.diff(r) > 0):
        raise ValueError(f"radius = {radius} is too small for {points} distinct nodes (points)")
    cause = f"the mollified kernel overflows for delta = {delta} on a table of radius {radius}"
    try:
        lap = mollified_laplacian(laplacian, mollifier, delta, r)
    except (OverflowError, ValueError):  # r is this function's own: only the result can be refused
        raise ValueError(f"the radial table is not finite: {cause} (laplacian too large)") from None
    flux = integrate.cumulative_simpson(r * lap, x=r, initial=0.0)
    gradient = np.empty_like(r)
    gradient[1:] = flux[1:] / r[1:] ** 2
    gradient[0] = lap[0] / 2.0
    finite_result("the radial table", [gradient, lap], cause)
    gradient.flags.writeable = False
    lap.flags.writeable = False
    return RadialTable(radius, gradient, lap)
