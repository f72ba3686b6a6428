"""Stationary uniform rings of power-law kernels K = |x|^a/a - |x|^b/b in 2D.

A particle on the uniform ring of radius R feels the radial force
int_0^{2 pi} grad K(R e_1 - R e(theta)) . e_1 dtheta / (2 pi). With |R e_1 - R e(theta)| =
2R sin(theta/2) and 1 - cos(theta) = 2 sin^2(theta/2), the term |x|^a/a contributes
(2R)^{a-1} B_a / pi with B_a = int_0^pi sin^a u du = sqrt(pi) Gamma((a+1)/2) / Gamma(a/2 + 1).
The ring is stationary when the attractive and repulsive parts balance:
(2R)^{a-b} = B_b / B_a, i.e. R = (B_b / B_a)^{1/(a-b)} / 2.
"""

from __future__ import annotations

import numpy as np
from scipy import special

from ..validation import finite_number, finite_result, positive


def sine_power_integral(a: float, name: str = "a") -> float:
    """B_a = int_0^pi sin^a(u) du for a > 0 (Gamma overflows beyond a of about 340: a ValueError)."""
    a = positive(name, a)
    value = np.sqrt(np.pi) * special.gamma((a + 1) / 2) / special.gamma(a / 2 + 1)
    return float(finite_result(f"B_{name} = int_0^pi sin^{name}", value, f"Gamma overflows for {name} = {a}"))


def uniform_ring_radius(a: float, b: float) -> float:
    """Radius of the stationary uniform ring of K = |x|^a/a - |x|^b/b, a > b > 0."""
    a, b = finite_number("a", a), finite_number("b", b)
    if not a > b:
        raise ValueError(f"a must exceed b, got a = {a}, b = {b}")
    radius = 0.5 * (sine_power_integral(b, "b") / sine_power_integral(a)) ** (1.0 / (a - b))
    return float(finite_result("the ring radius", radius, f"a - b = {a - b} is too small for the power 1/(a - b)"))
