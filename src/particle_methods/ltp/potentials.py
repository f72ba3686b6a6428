"""Interaction potentials of section 6 as sums of power terms W(x) = sum_j c_j |x|^{a_j} / a_j.

x^2 is (c, a) = (2, 2); x^2/2 is (1, 2); |x|^a/a is (1, a); |x|^a/a - |x|^b/b is
(1, a), (-1, b); the attractive Newtonian potential of 1D, |x|/2, is (1/2, 1). With a_j > 1
every term has W' = c sign(x)|x|^{a-1} continuous and W'' = c (a - 1)|x|^{a-2} locally
integrable, singular at 0 when a < 2. A term with a = 1, c|x|, has W' = c sign(x) (0 at x = 0)
and W'' = 2c delta, a Dirac mass at 0, outside the paper's theory (Theorem 1 asks W' Lipschitz and
the singular potentials (5.1) stop short of the Newtonian singularity). :meth:`Potential.second_derivative`
returns its regular part, 0 away from 0; the kernels convolve the Dirac mass exactly, W'' * rho = 2c rho.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..validation import finite_number, finite_result, finite_values, instance, one_of
from .checks import power_arrays

#: The exponents each kind of potential takes.
KINDS = {"quadratic": (), "half_quadratic": (), "newtonian": (), "power": ("a",), "attractive_repulsive": ("a", "b")}
OVERFLOW = "overflow: |x| too large (or too close to 0 for W'') for double precision"


@dataclass(frozen=True)
class Potential:
    """W(x) = sum_j coefficients[j] |x|^exponents[j] / exponents[j]."""

    name: str
    coefficients: tuple[float, ...]
    exponents: tuple[float, ...]

    def __post_init__(self):
        instance("name", self.name, str)
        coefficients, exponents = power_arrays(self.coefficients, self.exponents)
        object.__setattr__(self, "coefficients", tuple(float(c) for c in coefficients))
        object.__setattr__(self, "exponents", tuple(float(a) for a in exponents))

    def __call__(self, x):
        """W(x), for finite x of any shape."""
        x = np.abs(finite_values("x", x))
        with np.errstate(over="ignore", invalid="ignore"):
            values = sum(c * x**a / a for c, a in zip(self.coefficients, self.exponents))
        return finite_result("W(x)", values, OVERFLOW)

    def derivative(self, x):
        """W'(x)."""
        x = finite_values("x", x)
        with np.errstate(over="ignore", invalid="ignore"):
            values = sum(c * np.sign(x) * np.abs(x) ** (a - 1) for c, a in zip(self.coefficients, self.exponents))
        return finite_result("W'(x)", values, OVERFLOW)

    def second_derivative(self, x):
        """W''(x) for x != 0: the regular part, to which a term with a = 1 (W'' = 2c delta) adds 0.
        ValueError at x = 0 for exponents below 2, where W'' is infinite (a Dirac mass for a = 1)."""
        x = np.abs(finite_values("x", x))
        if min(self.exponents) < 2.0 and np.any(x == 0.0):
            dirac = " (a Dirac mass for the terms with exponent 1)" if 1.0 in self.exponents else ""
            raise ValueError(f"x must not contain 0: W'' of {self.name} is infinite there{dirac}")
        with np.errstate(over="ignore", invalid="ignore"):
            values = sum((c * (a - 1) * x ** (a - 2) for c, a in zip(self.coefficients, self.exponents) if a != 1.0),
                         np.zeros_like(x))
        return finite_result("W''(x)", values, OVERFLOW)

    def as_arrays(self):
        """(coefficients, exponents) as float arrays for the compiled kernels."""
        return np.array(self.coefficients, dtype=np.float64), np.array(self.exponents, dtype=np.float64)


def potential(kind: str, a: float | None = None, b: float | None = None) -> Potential:
    """Potentials of section 6: 'quadratic' x^2, 'half_quadratic' x^2/2, 'power' |x|^a/a,
    'attractive_repulsive' |x|^a/a - |x|^b/b (a, b >= 1), and 'newtonian' |x|/2, the attractive Newtonian
    potential of 1D (W'' = delta); an exponent the kind does not take is refused."""
    needed = one_of("kind of potential", kind, KINDS)
    for name, value in (("a", a), ("b", b)):
        if name in needed and value is None:
            raise ValueError(f"the {kind} potential needs the exponent{'s' * (len(needed) - 1)} {' and '.join(needed)}")
        if name not in needed and value is not None:
            raise ValueError(f"the {kind} potential takes no exponent {name}, got {value!r}")
    if kind == "quadratic":
        return Potential("x^2", (2.0,), (2.0,))
    if kind == "half_quadratic":
        return Potential("x^2/2", (1.0,), (2.0,))
    if kind == "newtonian":
        return Potential("|x|/2", (0.5,), (1.0,))
    a = finite_number("a", a)
    if a < 1.0:
        raise ValueError(f"a must be at least 1 (a = 1 is the Newtonian |x|; below 1 W' is unbounded at 0), got {a}")
    if kind == "power":
        return Potential(f"|x|^{a:g}/{a:g}", (1.0,), (a,))
    b = finite_number("b", b)
    if b < 1.0:
        raise ValueError(f"b must be at least 1 (b = 1 is the Newtonian |x|; below 1 W' is unbounded at 0), got {b}")
    return Potential(f"|x|^{a:g}/{a:g} - |x|^{b:g}/{b:g}", (1.0, -1.0), (a, b))
