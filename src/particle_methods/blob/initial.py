"""Initial data of section 4.2-4.3 on [-1, 1] and the particles of Definition 2.2.

(4.3) (1 - x^2)^20, (4.4) the indicator of [-1, 1], (4.5) (1 - x^2)^10, none normalised,
as in the paper. Particles sit at the grid points jh of [-1, 1] with masses rho0(jh) h^d.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import polynomial as P

from ..validation import one_of, positive


@dataclass(frozen=True)
class Data1D:
    """A symmetric density on [-1, 1]: polynomial (1 - x^2)^power, or the indicator (power 0)."""

    name: str
    power: int

    def __call__(self, x):
        x = np.asarray(x, dtype=np.float64)
        return np.where(np.abs(x) <= 1.0, np.clip(1.0 - x * x, 0.0, None) ** self.power, 0.0)

    @property
    def maximum(self) -> float:
        return 1.0

    def mass_from_origin(self, x):
        """m(x) = int_0^x rho0 (odd in x), exactly: the antiderivative of the polynomial."""
        x = np.clip(np.asarray(x, dtype=np.float64), -1.0, 1.0)
        coefficients = P.polypow([1.0, 0.0, -1.0], self.power)
        return P.polyval(x, P.polyint(coefficients))


DATA_1D = {"smooth20": Data1D("(1 - x^2)^20 (4.3)", 20), "indicator": Data1D("indicator of [-1, 1] (4.4)", 0),
           "smooth10": Data1D("(1 - x^2)^10 (4.5)", 10)}


def data_1d(name: str) -> Data1D:
    """Initial data 'smooth20' (4.3), 'indicator' (4.4) or 'smooth10' (4.5)."""
    return one_of("initial data", name, DATA_1D)


def grid_1d(h: float) -> np.ndarray:
    """Grid points jh of [-1, 1], as a column (N, 1); h must divide 1 for the ends to be nodes."""
    h = positive("h", h)
    half = int(round(1.0 / h))
    if abs(half * h - 1.0) > 1e-9:
        raise ValueError(f"h = {h} must divide 1 so that the grid hZ contains the ends of [-1, 1]")
    return (h * np.arange(-half, half + 1))[:, None]


@dataclass(frozen=True)
class Data2D:
    """2D initial data of section 4.4, with its radial mass function m(r) = int_0^r s rho0(s) ds."""

    name: str
    radius: float

    def __call__(self, points):
        points = np.asarray(points, dtype=np.float64)
        r2 = (points**2).sum(axis=-1)
        if self.name == "regular":          # (1 - |x|^2)_+^2
            return np.clip(1.0 - r2, 0.0, None) ** 2
        if self.name == "disk":             # indicator of the closed unit disk
            return np.where(r2 <= 1.0, 1.0, 0.0)
        if self.name == "quartic":          # (4.7): C (1 - |x|^2)^2 with unit mass, C = 3/pi
            return 3.0 / np.pi * np.clip(1.0 - r2, 0.0, None) ** 2
        if self.name == "bump":             # exp(1/(|x|^2 - 1)) with unit mass
            inside = r2 < 1.0
            return np.where(inside, np.exp(1.0 / np.where(inside, r2 - 1.0, -1.0)), 0.0) / _BUMP_MASS
        if self.name == "star":             # (4.6): 1 for r < (sin^2(5 theta/2) + 1/2)/4
            theta = np.arctan2(points[..., 1], points[..., 0])
            return np.where(np.sqrt(r2) < (np.sin(2.5 * theta) ** 2 + 0.5) / 4.0, 1.0, 0.0)
        raise ValueError(f"unknown 2D data {self.name!r}")

    def mass_from_origin(self, r):
        """m(r) = int_0^r s rho0(s) ds for the radial data with exact solutions (regular, disk)."""
        r = np.clip(np.asarray(r, dtype=np.float64), 0.0, 1.0)
        if self.name == "regular":
            return (1.0 - (1.0 - r**2) ** 3) / 6.0
        if self.name == "disk":
            return r**2 / 2.0
        raise ValueError(f"no radial mass function for {self.name!r}")


def _bump_mass() -> float:
    from scipy import integrate

    return integrate.quad(lambda r: 2 * np.pi * r * np.exp(1.0 / (r * r - 1.0)), 0.0, 1.0, epsabs=1e-15)[0]


_BUMP_MASS = _bump_mass()
DATA_2D = {name: Data2D(name, 0.375 if name == "star" else 1.0) for name in ("regular", "disk", "quartic", "bump",
                                                                             "star")}


def data_2d(name: str) -> Data2D:
    """2D data: 'regular' (1 - |x|^2)_+^2, 'disk' (indicator), 'bump' exp(1/(|x|^2 - 1)) with unit mass,
    'quartic' (4.7) and 'star' (4.6)."""
    return one_of("2D data", name, DATA_2D)


def grid_2d(h: float, data: Data2D) -> np.ndarray:
    """Points of hZ^2 where rho0 > 0, shape (N, 2)."""
    h = positive("h", h)
    half = int(np.ceil(data.radius / h)) + 1
    axis = h * np.arange(-half, half + 1)
    points = np.stack(np.meshgrid(axis, axis, indexing="ij"), axis=-1).reshape(-1, 2)
    return points[data(points) > 0]
