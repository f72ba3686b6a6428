"""Interaction potentials of section 6 as sums of power terms W(x) = sum_j c_j |x|^{a_j} / a_j.

x^2 is (c, a) = (2, 2); x^2/2 is (1, 2); |x|^a/a is (1, a); |x|^a/a - |x|^b/b is
(1, a), (-1, b). With a_j > 1 every term has W' = c sign(x)|x|^{a-1} continuous and
W'' = c (a - 1)|x|^{a-2} locally integrable, singular at 0 when a < 2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import finite_number


@dataclass(frozen=True)
class Potential:
    """W(x) = sum_j coefficients[j] |x|^exponents[j] / exponents[j]."""

    name: str
    coefficients: tuple[float, ...]
    exponents: tuple[float, ...]

    def __post_init__(self):
        if len(self.coefficients) != len(self.exponents) or not self.exponents:
            raise ValueError("a potential needs one coefficient per exponent")
        for a in self.exponents:
            if finite_number("exponent", a) <= 1.0:
                raise ValueError(f"exponent must exceed 1 (W' continuous, W'' integrable), got {a}")
        for c in self.coefficients:
            finite_number("coefficient", c)

    def __call__(self, x):
        x = np.abs(np.asarray(x, dtype=np.float64))
        return sum(c * x**a / a for c, a in zip(self.coefficients, self.exponents))

    def derivative(self, x):
        """W'(x)."""
        x = np.asarray(x, dtype=np.float64)
        return sum(c * np.sign(x) * np.abs(x) ** (a - 1) for c, a in zip(self.coefficients, self.exponents))

    def second_derivative(self, x):
        """W''(x) (infinite at 0 for exponents below 2)."""
        x = np.abs(np.asarray(x, dtype=np.float64))
        with np.errstate(divide="ignore"):
            return sum(c * (a - 1) * x ** (a - 2) for c, a in zip(self.coefficients, self.exponents))

    def as_arrays(self):
        """(coefficients, exponents) as float arrays for the compiled kernels."""
        return np.array(self.coefficients, dtype=np.float64), np.array(self.exponents, dtype=np.float64)


def potential(kind: str, a: float | None = None, b: float | None = None) -> Potential:
    """Potentials of section 6: 'quadratic' x^2, 'half_quadratic' x^2/2, 'power' |x|^a/a,
    'attractive_repulsive' |x|^a/a - |x|^b/b."""
    if kind == "quadratic":
        return Potential("x^2", (2.0,), (2.0,))
    if kind == "half_quadratic":
        return Potential("x^2/2", (1.0,), (2.0,))
    if kind == "power":
        if a is None:
            raise ValueError("the power potential needs the exponent a")
        return Potential(f"|x|^{a:g}/{a:g}", (1.0,), (float(a),))
    if kind == "attractive_repulsive":
        if a is None or b is None:
            raise ValueError("the attractive-repulsive potential needs the exponents a and b")
        return Potential(f"|x|^{a:g}/{a:g} - |x|^{b:g}/{b:g}", (1.0, -1.0), (float(a), float(b)))
    raise ValueError(f"unknown potential {kind!r}: expected quadratic, half_quadratic, power or "
                     "attractive_repulsive")
