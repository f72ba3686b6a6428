"""Reference particle shapes (2.12), (2.13) and the bi-orthogonal kernel of the hat (after (2.18)).

A shape is a piecewise cubic polynomial on unit pieces: ``breaks`` holds the piece
boundaries in the reference variable s and ``coefficients[j]`` the coefficients of
s^0..s^3 on piece j. The convolution kernels integrate potentials against these
pieces exactly (:mod:`particle_methods.ltp.kernels`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import finite_values, instance, one_of
from .checks import piece_arrays

#: Largest rounding error accepted on the unit mass and zero mean of a shape.
MOMENT_TOLERANCE = 1e-12


@dataclass(frozen=True)
class Shape:
    """Piecewise cubic reference shape with unit mass and the partition of unity.

    The breaks must increase from -r to r and the coefficients hold one cubic per piece; the
    shape must have unit mass and mean 0, as the kernels assume for quadratic terms.
    """

    name: str
    breaks: np.ndarray
    coefficients: np.ndarray

    def __post_init__(self):
        instance("name", self.name, str)
        breaks, coefficients = piece_arrays(self.breaks, self.coefficients)
        object.__setattr__(self, "breaks", breaks)
        object.__setattr__(self, "coefficients", coefficients)
        mass, mean = self._moment(0), self._moment(1)
        if not (abs(mass - 1.0) <= MOMENT_TOLERANCE and abs(mean) <= MOMENT_TOLERANCE):
            raise ValueError(f"the coefficients of shape {self.name!r} on its breaks must give unit mass and mean 0, "
                             f"got mass {mass} and mean {mean}")

    @property
    def radius(self) -> float:
        """Half-width of the support: phi vanishes outside [-radius, radius]."""
        return float(self.breaks[-1])

    @property
    def second_moment(self) -> float:
        """int s^2 phi(s) ds."""
        return self._moment(2)

    @property
    def absolute_moment(self) -> float:
        """int |s| phi(s) ds: the W1 distance from a unit point mass at 0 to phi, exact piece by piece (B3: 7/15)."""
        return self._moment(1, absolute=True)

    def _moment(self, order: int, absolute: bool = False) -> float:
        """int s^order phi(s) ds (int |s|^order phi(s) ds when ``absolute``), piece by piece; a piece across 0
        is split there."""
        power = order + 1
        total = 0.0
        with np.errstate(over="ignore", invalid="ignore"):  # huge breaks: a non-finite moment, refused
            for (lo, hi), c in zip(zip(self.breaks[:-1], self.breaks[1:]), self.coefficients):
                parts = [(lo, hi, 1.0)]
                if absolute:
                    parts = [(a, b, sign) for a, b, sign in ((lo, min(hi, 0.0), -1.0), (max(lo, 0.0), hi, 1.0))
                             if a < b]
                for a, b, sign in parts:
                    total += sign * sum(c[m] * (b ** (m + power) - a ** (m + power)) / (m + power)
                                        for m in range(4))
        return float(total)

    def __call__(self, s):
        """phi(s), vectorised, for finite s of any shape."""
        s = finite_values("s", s)
        inside = (s >= self.breaks[0]) & (s <= self.breaks[-1])
        s = np.clip(s, self.breaks[0], self.breaks[-1])  # outside the support phi = 0: no overflow
        piece = np.clip(np.searchsorted(self.breaks, s, side="right") - 1, 0, len(self.coefficients) - 1)
        c = self.coefficients[piece]
        value = c[..., 0] + s * (c[..., 1] + s * (c[..., 2] + s * c[..., 3]))
        return np.where(inside, value, 0.0)


#: Hat function (2.12) in 1D: max(1 - |s|, 0).
HAT = Shape("hat", np.array([-1.0, 0.0, 1.0]), np.array([[1.0, 1.0, 0.0, 0.0], [1.0, -1.0, 0.0, 0.0]]))

#: Cubic B-spline (2.13).
B3 = Shape(
    "b3",
    np.array([-2.0, -1.0, 0.0, 1.0, 2.0]),
    np.array([[8.0, 12.0, 6.0, 1.0], [4.0, 0.0, -6.0, -3.0], [4.0, 0.0, -6.0, 3.0], [8.0, -12.0, 6.0, -1.0]]) / 6.0,
)

SHAPES = {"hat": HAT, "b3": B3}


def shape_named(name: str) -> Shape:
    """The shape called ``name`` ('hat' or 'b3'); ValueError otherwise."""
    return one_of("shape", name, SHAPES)


def hat_biorthogonal_kernel(s):
    """Kernel bi-orthogonal to the hat (2.17): 3/2 on [-1/2, 1/2], -1/2 on the rest of [-1, 1]."""
    s = np.abs(finite_values("s", s))
    return np.where(s <= 0.5, 1.5, np.where(s <= 1.0, -0.5, 0.0))
