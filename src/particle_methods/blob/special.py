"""Special functions for the compiled kernels, to full double precision.

- :func:`exp1`, the exponential integral E1 (the potential of the mollified 2D log kernel);
- :func:`dawson`, Dawson's integral F(z) = exp(-z^2) int_0^z exp(t^2) dt (the mollified 1D log
  kernel: (1/x) * G_s = (2/s) F(x/s) as a principal value, for the Gaussian G_s of
  :mod:`particle_methods.blob.mollifiers`).

Neither is available inside numba (its wheels have no SVML or special-function library), so both
are written here and tested against scipy.special over the whole range the kernels use.
"""

import math

import numpy as np
from scipy import special

from ..jit import njit

EULER_GAMMA = 0.5772156649015329


@njit
def exp1(x):
    """Exponential integral E1(x), x > 0: power series below 1, continued fraction above. A compiled scalar
    function of the kernels: it trusts its caller's checks (x > 0 finite)."""
    if x < 1.0:
        total = 0.0
        term = 1.0
        for k in range(1, 40):
            term *= -x / k
            total -= term / k
        return -EULER_GAMMA - math.log(x) + total
    # Lentz's continued fraction for e^x E1(x) = 1/(x + 1/(1 + 1/(x + 2/(1 + 2/(x + ...))))).
    b = x + 1.0
    c = 1e300
    d = 1.0 / b
    result = d
    for i in range(1, 200):
        a = -float(i * i)
        b += 2.0
        d = 1.0 / (a * d + b)
        c = b + a / c
        delta = c * d
        result *= delta
        if abs(delta - 1.0) < 1e-16:
            break
    return result * math.exp(-x)


#: Dawson's integral at the nodes z_j = j / 32, 0 <= z_j <= 10, from scipy (computed once at import).
_DAWSON_STEP = 1.0 / 32.0
_DAWSON_NODES = special.dawsn(np.arange(321) * _DAWSON_STEP)
#: 1/(k + 1) for the Taylor recurrence: a multiplication per term instead of a division.
_RECIPROCALS = 1.0 / np.arange(1.0, 42.0)
#: From this z on, F is summed by its asymptotic series (also the far field of :mod:`.sums_1d`'s log path).
DAWSON_ASYMPTOTIC = 10.0


@njit
def dawson_and_slope(z):
    """(F(z), F'(z) = 1 - 2 z F(z)); F to a relative error below 1e-15, F' below 5e-13 (both tested
    against high-precision values).

    Below z = 10: the Taylor series about the nearest node z0 (|z - z0| <= 1/64), with the
    derivatives from F' = 1 - 2 z F, i.e. F^(k+1) = -2 z0 F^(k) - 2 k F^(k-1). Above: the
    asymptotic series F(z) ~ sum_n a_n / (2 z), a_n = (2n - 1)!! / (2 z^2)^n, whose terms fall
    below 1e-17 of the sum within 14 terms there, and F'(z) = -sum_{n >= 1} a_n without the
    cancellation of 1 - 2 z F. F is odd, F' even. A compiled scalar function of the kernels: it trusts its
    caller's checks (NaN in gives NaN out).
    """
    if z != z:  # NaN in, NaN out (and no table index from it)
        return z, z
    sign = 1.0 if z >= 0 else -1.0
    z = abs(z)
    if z >= DAWSON_ASYMPTOTIC:
        inverse = 1.0 / (2.0 * z * z)
        term = 1.0
        tail = 0.0
        for n in range(1, 40):
            term *= (2 * n - 1) * inverse
            tail += term
            if term < 1e-17 * tail:
                break
        return sign * (1.0 + tail) / (2.0 * z), -tail
    j = int(z / _DAWSON_STEP + 0.5)
    z0 = j * _DAWSON_STEP
    d = z - z0
    previous = _DAWSON_NODES[j]          # c_0 = F(z0)
    current = 1.0 - 2.0 * z0 * previous  # c_1 = F'(z0)
    total = previous + current * d
    slope = current
    power = 1.0                          # d^(k-1)
    last = abs(total)
    for k in range(1, 40):
        # c_{k+1} = F^(k+1)(z0) / (k+1)! = (-2 z0 c_k - 2 c_{k-1}) / (k + 1)
        previous, current = current, (-2.0 * z0 * current - 2.0 * previous) * _RECIPROCALS[k]
        power *= d
        slope += (k + 1) * current * power
        step = current * power * d
        total += step
        if abs(step) + last < 1e-17 * abs(total):  # two small terms: about z0 = 0 every other one is 0
            break
        last = abs(step)
    return sign * total, slope


@njit
def dawson(z):
    """Dawson's integral F(z) (see :func:`dawson_and_slope`); it trusts its caller's checks, as that does."""
    return dawson_and_slope(z)[0]
