"""e^{-z} and 1 - e^{-z} together, in plain arithmetic that LLVM vectorises.

numba's wheels have no vector math library, so ``math.exp`` inside a loop stays a scalar
call (about 13 clock cycles). Here z = k ln 2 - r with k = round(z / ln 2) and
|r| <= ln 2 / 2 (Cody and Waite: ln 2 split into a high part exact in k * LN2_HI and a low
part), q = e^r - 1 = r + r^2/2 + ... + r^14/14! by Horner's rule (truncation below
0.35^15/15! = 1.2e-19 relative), and 2^-k from a table, so that

    e^{-z} = 2^-k (1 + q),    1 - e^{-z} = (1 - 2^-k) - 2^-k q,

the second without cancellation for small z (k = 0 gives -q). k is clamped without a
branch at 1100, where 2^-k is already 0: then e^{-z} = 0 and 1 - e^{-z} = 1 exactly, as in
double precision. The clamp rounds z / ln 2 to within 1/4 as long as z <= 2^50 (:data:`Z_LIMIT`),
which keeps the table index in range: callers make sure of that bound before they enter compiled
code. Tested against ``numpy.exp`` and ``numpy.expm1`` on [0, 745] and beyond:
relative errors below 4e-16 for e^{-z} wherever it is a normal number, and for 1 - e^{-z}.
The table is a global constant (LLVM sees that it cannot alias the arrays being written).
"""

import numpy as np

from ..jit import njit
from ..validation import finite_array

_LN2_HI = 0.693147180369123816490    # ln 2 with its last 32 bits cleared: k * _LN2_HI is exact
_LN2_LO = 1.90821492927058770002e-10   # ln 2 - _LN2_HI
_INV_LN2 = 1.4426950408889634
#: 2^-k for k = 0, ..., 1100: 0 from k = 1075 on (below the smallest subnormal).
_TWO_POWERS = np.concatenate([2.0 ** -np.arange(0, 1075.0), np.zeros(26)])
_K_MAX = 1100.0
#: The largest z the function takes (see the module docstring).
Z_LIMIT = 2.0**50


@njit(inline="always")
def exp_minus_and_complement(z):
    """(e^{-z}, 1 - e^{-z}) for z >= 0, without branches (see the module docstring). Inlined in compiled loops:
    it trusts its caller's checks (:func:`exp_minus_and_complement_array` checks its z)."""
    kf = z * _INV_LN2 + 0.5
    k = int(0.5 * (kf + _K_MAX - abs(kf - _K_MAX)))  # min(kf, 1100) without a branch, then floor
    r = k * _LN2_HI - z + k * _LN2_LO
    q = 1.0 / 87178291200.0
    q = q * r + 1.0 / 6227020800.0
    q = q * r + 1.0 / 479001600.0
    q = q * r + 1.0 / 39916800.0
    q = q * r + 1.0 / 3628800.0
    q = q * r + 1.0 / 362880.0
    q = q * r + 1.0 / 40320.0
    q = q * r + 1.0 / 5040.0
    q = q * r + 1.0 / 720.0
    q = q * r + 1.0 / 120.0
    q = q * r + 1.0 / 24.0
    q = q * r + 1.0 / 6.0
    q = q * r + 0.5
    q = q * r + 1.0
    q = q * r
    t = _TWO_POWERS[k]
    return t + t * q, (1.0 - t) - t * q


def checked_argument(z, limit):
    """z as a finite float array within [0, limit], or a ValueError naming z (the array wrappers of the
    vectorised functions)."""
    z = finite_array("z", z)
    if np.any(z < 0) or np.any(z > limit):
        raise ValueError(f"z must lie in [0, {limit:g}]")
    return z


def exp_minus_and_complement_array(z):
    """The same, elementwise over a 1D array of z >= 0 (for tests and benchmarks)."""
    return _elementwise(checked_argument(z, Z_LIMIT))


@njit
def _elementwise(z):
    e = np.empty_like(z)
    complement = np.empty_like(z)
    for j in range(z.size):
        e[j], complement[j] = exp_minus_and_complement(z[j])
    return e, complement
