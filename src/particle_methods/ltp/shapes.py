"""Reference particle shapes (2.12), (2.13) and the bi-orthogonal kernel of the hat (after (2.18)).

A shape is a piecewise cubic polynomial on unit pieces: ``breaks`` holds the piece
boundaries in the reference variable s and ``coefficients[j]`` the coefficients of
s^0..s^3 on piece j. The convolution kernels integrate potentials against these
pieces exactly (:mod:`particle_methods.ltp.kernels`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import one_of


@dataclass(frozen=True)
class Shape:
    """Piecewise cubic reference shape with unit mass and the partition of unity."""

    name: str
    breaks: np.ndarray
    coefficients: np.ndarray

    @property
    def radius(self) -> float:
        """Half-width of the support: phi vanishes outside [-radius, radius]."""
        return float(self.breaks[-1])

    @property
    def second_moment(self) -> float:
        """int s^2 phi(s) ds."""
        total = 0.0
        for (lo, hi), c in zip(zip(self.breaks[:-1], self.breaks[1:]), self.coefficients):
            total += sum(c[m] * (hi ** (m + 3) - lo ** (m + 3)) / (m + 3) for m in range(4))
        return float(total)

    def __call__(self, s):
        """phi(s), vectorised."""
        s = np.asarray(s, dtype=np.float64)
        piece = np.clip(np.searchsorted(self.breaks, s, side="right") - 1, 0, len(self.coefficients) - 1)
        c = self.coefficients[piece]
        value = c[..., 0] + s * (c[..., 1] + s * (c[..., 2] + s * c[..., 3]))
        return np.where((s >= self.breaks[0]) & (s <= self.breaks[-1]), value, 0.0)


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
    s = np.abs(np.asarray(s, dtype=np.float64))
    return np.where(s <= 0.5, 1.5, np.where(s <= 1.0, -0.5, 0.0))
