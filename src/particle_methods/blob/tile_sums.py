"""The share of one row in a tile of pair sums, summed in a fixed order (the direct 2D sums of
:mod:`.kernels` and the near field of :mod:`.newtonian_fmm`)."""

from ..jit import njit


@njit
def row_share(start, stop, masses, wx, wy, lap):
    """The row's own share over a tile, sum_j m_j (grad K, Delta K), in a fixed order: two interleaved
    partial sums per quantity (even and odd j), added at the end. Compiled, inside the pair sums' loops: it
    trusts its caller's checks."""
    sx0 = sx1 = sy0 = sy1 = sd0 = sd1 = 0.0
    count = stop - start
    k = 0
    while k + 1 < count:
        m0, m1 = masses[start + k], masses[start + k + 1]
        sx0 += m0 * wx[k]
        sy0 += m0 * wy[k]
        sd0 += m0 * lap[k]
        sx1 += m1 * wx[k + 1]
        sy1 += m1 * wy[k + 1]
        sd1 += m1 * lap[k + 1]
        k += 2
    if k < count:
        sx0 += masses[start + k] * wx[k]
        sy0 += masses[start + k] * wy[k]
        sd0 += masses[start + k] * lap[k]
    return sx0 + sx1, sy0 + sy1, sd0 + sd1
