"""Initial data of section 4.2-4.3 on [-1, 1] and the particles of Definition 2.2.

(4.3) (1 - x^2)^20, (4.4) the indicator of [-1, 1], (4.5) (1 - x^2)^10, none normalised,
as in the paper. Particles sit at the grid points jh of [-1, 1] with masses rho0(jh) h^d.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import polynomial as P

from ..validation import positive


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
    try:
        return DATA_1D[name]
    except KeyError:
        raise ValueError(f"unknown initial data {name!r}: expected one of {sorted(DATA_1D)}") from None


def grid_1d(h: float) -> np.ndarray:
    """Grid points jh of [-1, 1], as a column (N, 1); h must divide 1 for the ends to be nodes."""
    h = positive("h", h)
    half = int(round(1.0 / h))
    if abs(half * h - 1.0) > 1e-9:
        raise ValueError(f"h = {h} must divide 1 so that the grid hZ contains the ends of [-1, 1]")
    return (h * np.arange(-half, half + 1))[:, None]
