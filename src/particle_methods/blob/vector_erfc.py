"""erfc(z) and e^{-z^2} together, in plain arithmetic that LLVM vectorises (as :mod:`.vector_exp`).

erfc(z) = e^{-z^2} erfcx(z), where the scaled complementary error function erfcx is smooth and
slowly varying (erfcx(z) ~ 1/(z sqrt(pi)) for large z). On [0, 16), cut into 64 intervals of
width 1/4, erfcx is a polynomial of degree 13 in t = 8 (z - c) - 1 on each interval [c, c + 1/4],
its coefficients interpolated at Chebyshev points from ``scipy.special.erfcx`` when the module is
imported; the interval is found without a branch and its coefficients read from a global table
(gathered by vector instructions). e^{-z^2} comes from :func:`.vector_exp.exp_minus_and_complement`.
It takes 0 <= z <= 2^25 (:data:`Z_LIMIT`). Beyond z = 16, erfc(z) < 1e-112 and z is clamped
there: both values are then those at z = 16, negligible against anything they are added to,
never NaN. z^2 is carried to twice the working precision, so that the exponential does not
amplify its rounding (2 z^2 ulps otherwise).

Tested against mpmath at 40 digits on [0, 16]: relative error of erfc below 1.5e-15 (erfcx from
scipy is itself within 7e-16). The interpolation error of degree 13 is below 1e-17.
"""

import numpy as np
from numpy.polynomial import chebyshev
from scipy.special import erfcx

from ..jit import njit
from .vector_exp import Z_LIMIT as _EXP_LIMIT
from .vector_exp import checked_argument, exp_minus_and_complement

_WIDTH = 0.25
_INTERVALS = 64
_DEGREE = 13
_Z_MAX = _WIDTH * _INTERVALS
#: The largest z the function takes: z^2 within the exponential's range.
Z_LIMIT = _EXP_LIMIT**0.5


def _table():
    """Monomial coefficients in t in [-1, 1] of erfcx on each interval, constant term first (``cheb2poly`` drops
    trailing zero coefficients, which another BLAS's least squares can leave on an interval: they are put back)."""
    nodes = chebyshev.chebpts1(2 * (_DEGREE + 1))
    rows = np.zeros((_INTERVALS, _DEGREE + 1))
    for k in range(_INTERVALS):
        z = _WIDTH * (k + 0.5 * (nodes + 1.0))
        monomial = chebyshev.cheb2poly(chebyshev.chebfit(nodes, erfcx(z), _DEGREE))
        rows[k, : monomial.size] = monomial
    return rows


_COEFFICIENTS = _table()


@njit(inline="always")
def erfc_and_gauss(z):
    """(erfc(z), e^{-z^2}) for z >= 0, without branches (see the module docstring). Inlined in compiled loops: it
    trusts its caller's checks (:func:`erfc_and_gauss_array` checks its z)."""
    # min(z, 16) without a branch, and exactly z when z <= 16 (a + |a| = 0 exactly for a <= 0)
    zc = z - 0.5 * ((z - _Z_MAX) + abs(z - _Z_MAX))
    x = zc * (1.0 / _WIDTH)
    k = int(x - 0.5 * ((x - (_INTERVALS - 1)) + abs(x - (_INTERVALS - 1))))  # the interval, at most the last
    t = 2.0 * (x - k) - 1.0
    p = _COEFFICIENTS[k, 13]
    p = p * t + _COEFFICIENTS[k, 12]
    p = p * t + _COEFFICIENTS[k, 11]
    p = p * t + _COEFFICIENTS[k, 10]
    p = p * t + _COEFFICIENTS[k, 9]
    p = p * t + _COEFFICIENTS[k, 8]
    p = p * t + _COEFFICIENTS[k, 7]
    p = p * t + _COEFFICIENTS[k, 6]
    p = p * t + _COEFFICIENTS[k, 5]
    p = p * t + _COEFFICIENTS[k, 4]
    p = p * t + _COEFFICIENTS[k, 3]
    p = p * t + _COEFFICIENTS[k, 2]
    p = p * t + _COEFFICIENTS[k, 1]
    p = p * t + _COEFFICIENTS[k, 0]
    # z^2 = hi + lo exactly (Veltkamp's split, zh with 26 significant bits), e^{-z^2} = e^{-hi} (1 - lo):
    # without lo the rounding of z^2 alone would cost 2 z^2 ulps, 1e-14 at z = 11.
    c = 134217729.0 * zc
    zh = c - (c - zc)
    zl = zc - zh
    hi = zc * zc
    lo = ((zh * zh - hi) + 2.0 * zh * zl) + zl * zl
    e, _ = exp_minus_and_complement(hi)
    e = e - e * lo
    return e * p, e


def erfc_and_gauss_array(z):
    """The same, elementwise over a 1D array of z >= 0 (for tests and benchmarks)."""
    return _elementwise(checked_argument(z, Z_LIMIT))


@njit
def _elementwise(z):
    tail = np.empty_like(z)
    e = np.empty_like(z)
    for j in range(z.size):
        tail[j], e[j] = erfc_and_gauss(z[j])
    return tail, e
