"""1D pair sums in O(N log N + N w): a far field by sorted moments, a near field by windows.

In 1D the kernels of section 4 whose mollification is a Gaussian mixture, |x|/2 and |x|^3/3
(the terms GAUSS_ABS_1D and GAUSS_CUBIC_1D of :mod:`.kernels`), equal a polynomial in x and
sign(x) beyond a few widths: erf(r/s) = 1 and e^{-r^2/s^2} = 0 in double precision for
r > 6.5 s (the cutoff the generic loop uses too). Per Gaussian of width s and coefficient c,

- |x|/2:   grad = c sign(x)/2 - c sign(x) erfc(r/s)/2,  Delta = c e^{-r^2/s^2}/(s sqrt(pi)),
- |x|^3/3: grad = c (x|x| + sign(x) s^2/2) - c sign(x)(r^2 + s^2/2) erfc(r/s) + c x s e^{-r^2/s^2}/sqrt(pi),
           Delta = 2c|x| - 2c r erfc(r/s) + 2c s e^{-r^2/s^2}/sqrt(pi),

and the raw power terms of the particle method are the polynomials alone (|x|: grad c sign(x),
Delta 0 away from 0; |x|^3/3: grad c x|x|, Delta 2c|x|). The polynomial part summed over all
partners needs only the masses and first two moments of the particles left and right of X_i,
prefix sums over the sorted positions; the erfc part is summed over the partners within
6.5 s of X_i, a window of the sorted positions. The pair i = i belongs to the window, so the
self term of the Laplacian comes with it, and sign(0) = 0 gives grad K(0) = 0.

The log kernel c log|x|/(2 pi) (Figure 4's row label), raw (LOG) or mollified (GAUSS_LOG_1D), has no
such far field: its mollified gradient c F(r/s)/(pi s r) (F Dawson's integral) differs from the raw
c/(2 pi r^2) by a power of s/r. Beyond z = r/s = DAWSON_ASYMPTOTIC, F has the asymptotic series of
:func:`.special.dawson_and_slope`, so with u = 1/r^2, per term,

- grad = x g(r),  g = sum_{k>=0} G_k u^{k+1},        G_k = (c/2pi) (2k-1)!!/2^k s^{2k},
- Delta = sum_{k>=0} L_k u^{k+1},                     L_k = -(2k+1) G_k,

(the raw term is G_0 alone, s^0 = 1), and the coefficients summed over the terms once make the far
field of every pair two polynomials in u (:func:`log_series`): each pair costs a few multiplications
instead of a Dawson integral per Gaussian. The partners within DAWSON_ASYMPTOTIC widest widths take the
closed forms of :func:`.kernels.profile_forces_kernel`. It stays O(N^2), with a small constant.

Every row is computed on its own, in a fixed order, so the sums are identical on any number of threads.
"""

from __future__ import annotations

import math

import numpy as np
from numba import prange

from ..jit import njit, njit_threaded
from .kernels import GAUSS_ABS_1D, GAUSS_CUBIC_1D, GAUSS_LOG_1D, LOG, POWER, profile_forces_kernel
from .special import DAWSON_ASYMPTOTIC
from .vector_erfc import erfc_and_gauss

#: Beyond this many widths the Gaussian parts vanish in double precision (as in :mod:`.kernels`).
CUTOFF = 6.5
_SQRT_PI = math.sqrt(math.pi)


def supported(kinds, parameters) -> bool:
    """Whether a 1D kernel's terms are all Gaussian |x|/2, |x|^3/3 or raw powers 1 and 3 (a predicate on the
    arrays :func:`.pair_sums.pair_sums` has checked: it trusts its caller's checks)."""
    for kind, parameter in zip(kinds, parameters):
        if kind == POWER and parameter in (1.0, 3.0):
            continue
        if kind not in (GAUSS_ABS_1D, GAUSS_CUBIC_1D):
            return False
    return True


def far_coefficients(kinds, coefficients, parameters):
    """(a, b, c): far-field grad K = a sign(x) + b x|x| and Delta K = c |x|, summed over the terms (of the arrays
    :func:`.pair_sums.pair_sums` has checked: it trusts its caller's checks)."""
    a = b = c = 0.0
    for kind, coefficient, parameter in zip(kinds, coefficients, parameters):
        if kind == GAUSS_ABS_1D:
            a += 0.5 * coefficient
        elif kind == GAUSS_CUBIC_1D:
            a += 0.5 * coefficient * parameter**2
            b += coefficient
            c += 2.0 * coefficient
        elif parameter == 1.0:
            a += coefficient
        else:
            b += coefficient
            c += 2.0 * coefficient
    return a, b, c


@njit
def _compensated_prefix(values):
    """Exclusive prefix sums, each with Neumaier's compensation: out[k] = sum_{j<k} values[j]."""
    out = np.empty(values.size + 1)
    total = compensation = 0.0
    out[0] = 0.0
    for k in range(values.size):
        t = total + values[k]
        if abs(total) >= abs(values[k]):
            compensation += (total - t) + values[k]
        else:
            compensation += (values[k] - t) + total
        total = t
        out[k + 1] = total + compensation
    return out


#: Partners are taken in tiles of this many (their per-pair values stay in the L1 cache), rows in
#: blocks of this many per task of the parallel loop.
_TILE = 256
_ROWS = 64


@njit
def _gaussian_tile(xk, x, start, stop, kinds, coefficients, widths, g, lap_tile):
    """The Gaussian parts of grad K(x_k - x_j) and Delta K(x_k - x_j) for start <= j < stop, summed over
    the terms, into g and l. No branch in the loops over j, so LLVM vectorises them; sign(d) is
    d / (|d| + 1e-300), exactly +-1 or 0 for |d| > 1e-280."""
    for j in range(stop - start):
        g[j] = 0.0
        lap_tile[j] = 0.0
    for t in range(kinds.size):
        if kinds[t] == POWER:
            continue
        c, s = coefficients[t], widths[t]
        inverse = 1.0 / s
        if kinds[t] == GAUSS_ABS_1D:
            half, gauss = 0.5 * c, c / (s * _SQRT_PI)
            for j in range(start, stop):
                d = xk - x[j]
                r = abs(d)
                tail, e = erfc_and_gauss(r * inverse)
                g[j - start] -= half * d / (r + 1e-300) * tail
                lap_tile[j - start] += gauss * e
        else:
            scale, half_s2 = s / _SQRT_PI, 0.5 * s * s
            for j in range(start, stop):
                d = xk - x[j]
                r = abs(d)
                tail, e = erfc_and_gauss(r * inverse)
                g[j - start] += c * (d * scale * e - d / (r + 1e-300) * (r * r + half_s2) * tail)
                lap_tile[j - start] += 2.0 * c * (scale * e - r * tail)


@njit
def _weighted(start, stop, masses, g, lap_tile):
    """(sum_j m_j g_j, sum_j m_j l_j) over a tile, in a fixed order (even and odd j apart, then added)."""
    g0 = g1 = l0 = l1 = 0.0
    count = stop - start
    k = 0
    while k + 1 < count:
        m0, m1 = masses[start + k], masses[start + k + 1]
        g0 += m0 * g[k]
        l0 += m0 * lap_tile[k]
        g1 += m1 * g[k + 1]
        l1 += m1 * lap_tile[k + 1]
        k += 2
    if k < count:
        g0 += masses[start + k] * g[k]
        l0 += masses[start + k] * lap_tile[k]
    return g0 + g1, l0 + l1


@njit
def _windows(x, radius):
    """(lower, upper): the partners j of row k with |x_j - x_k| <= radius are lower[k] <= j < upper[k]."""
    n = x.size
    lower = np.empty(n, dtype=np.int64)
    upper = np.empty(n, dtype=np.int64)
    j = 0
    for k in range(n):
        while x[k] - x[j] > radius:
            j += 1
        lower[k] = j
    j = n
    for k in range(n - 1, -1, -1):
        while x[j - 1] - x[k] > radius:
            j -= 1
        upper[k] = j
    return lower, upper


@njit_threaded
def sorted_sums(x, masses, kinds, coefficients, widths, far, radius):
    """Velocities and divergences (-sum_j m_j grad K, -sum_j m_j Delta K) of positions ``x`` sorted
    increasingly; ``far`` = (a, b, c) of :func:`far_coefficients`, ``radius`` the window half-width. Compiled, for
    the arrays :func:`.pair_sums.pair_sums` has checked: it trusts its caller's checks."""
    n = x.size
    a, b, c = far
    m0 = _compensated_prefix(masses)
    m1 = _compensated_prefix(masses * x)
    m2 = _compensated_prefix(masses * x * x)
    # first[k], last[k]: the run of positions equal to x[k] (ties have sign 0).
    first = np.empty(n, dtype=np.int64)
    last = np.empty(n, dtype=np.int64)
    for k in range(n):
        first[k] = first[k - 1] if k > 0 and x[k] == x[k - 1] else k
    for k in range(n - 1, -1, -1):
        last[k] = last[k + 1] if k < n - 1 and x[k] == x[k + 1] else k
    lower, upper = _windows(x, radius)
    velocity = np.empty(n)
    divergence = np.empty(n)
    for block in prange((n + _ROWS - 1) // _ROWS):
        g = np.empty(_TILE)
        lap_tile = np.empty(_TILE)
        for k in range(block * _ROWS, min(block * _ROWS + _ROWS, n)):
            _row(k, x, masses, kinds, coefficients, widths, far, m0, m1, m2, first[k], last[k], lower[k], upper[k],
                 g, lap_tile, velocity, divergence)
    return velocity, divergence


@njit
def _row(k, x, masses, kinds, coefficients, widths, far, m0, m1, m2, first, last, lower, upper, g, lap_tile, velocity,
         divergence):
    """Row k: the polynomial part from the moments left and right of x_k, the Gaussian parts over the window."""
    n = x.size
    a, b, c = far
    xk = x[k]
    left0, left1, left2 = m0[first], m1[first], m2[first]
    right0, right1, right2 = m0[n] - m0[last + 1], m1[n] - m1[last + 1], m2[n] - m2[last + 1]
    # sum_j m_j sign(x_k - x_j), m_j (x_k - x_j)|x_k - x_j| and m_j |x_k - x_j|
    signs = left0 - right0
    squares = (xk * xk * left0 - 2.0 * xk * left1 + left2) - (xk * xk * right0 - 2.0 * xk * right1 + right2)
    distances = (xk * left0 - left1) - (xk * right0 - right1)
    grad = lap = 0.0
    for start in range(lower, upper, _TILE):
        stop = min(start + _TILE, upper)
        _gaussian_tile(xk, x, start, stop, kinds, coefficients, widths, g, lap_tile)
        tile_grad, tile_lap = _weighted(start, stop, masses, g, lap_tile)
        grad += tile_grad
        lap += tile_lap
    velocity[k] = -(a * signs + b * squares + grad)
    divergence[k] = -(c * distances + lap)


def pair_sums_1d(positions, masses, kinds, coefficients, parameters):
    """The 1D pair sums of :func:`.pair_sums.pair_sums` for the kernels :func:`supported` takes:
    positions (N, 1) and masses (N,) already checked; returns velocities (N, 1) and divergences (N,).
    It trusts its caller's checks."""
    x = positions[:, 0]
    order = np.argsort(x, kind="stable")
    far = far_coefficients(kinds, coefficients, parameters)
    widths = np.where(kinds == POWER, 0.0, parameters)
    radius = CUTOFF * float(widths.max(initial=0.0))
    v, d = sorted_sums(np.ascontiguousarray(x[order]), np.ascontiguousarray(masses[order]), kinds,
                       coefficients, widths, far, radius)
    velocity = np.empty_like(positions)
    divergence = np.empty_like(masses)
    velocity[order, 0] = v
    divergence[order] = d
    return velocity, divergence


def log_supported(kinds) -> bool:
    """Whether a 1D kernel's terms are all log terms, raw (LOG) or mollified (GAUSS_LOG_1D) (a predicate on the
    arrays :func:`.pair_sums.pair_sums` has checked: it trusts its caller's checks)."""
    return len(kinds) > 0 and all(kind in (LOG, GAUSS_LOG_1D) for kind in kinds)


def _series_length(cutoff):
    """Terms kept: the first omitted one, (2K+1)!!/(2 cutoff^2)^K relative to the first (the larger of
    the two series' K-th terms at z = cutoff), is below 1e-17."""
    count, term = 0, 1.0
    while term >= 1e-17:
        count += 1
        term *= (2 * count + 1) / (2.0 * cutoff * cutoff)
    return count


#: Terms of the far-field series (15 at DAWSON_ASYMPTOTIC = 10).
SERIES_TERMS = _series_length(DAWSON_ASYMPTOTIC)


def log_series(kinds, coefficients, parameters):
    """(G, L), the far-field coefficients of the log kernel's terms (module docstring), SERIES_TERMS each (of the
    arrays :func:`.pair_sums.pair_sums` has checked: it trusts its caller's checks)."""
    k = np.arange(SERIES_TERMS)
    double_factorial = np.concatenate(([1.0], np.cumprod(2.0 * k[1:] - 1.0)))   # (2k-1)!!, (-1)!! = 1
    growth = double_factorial / 2.0**k
    g = np.zeros(SERIES_TERMS)
    for kind, coefficient, width in zip(kinds, coefficients, parameters):
        if kind == LOG:
            g[0] += coefficient / (2.0 * math.pi)
        else:
            g += coefficient / (2.0 * math.pi) * growth * width ** (2.0 * k)
    return g, -(2.0 * k + 1.0) * g


@njit
def _log_far_tile(xk, x, start, stop, series_g, series_l, g, lap_tile):
    """grad K(x_k - x_j) and Delta K(x_k - x_j) by the far-field series for start <= j < stop, into g and
    lap_tile: Horner's rule, one coefficient per pass over the tile, so LLVM vectorises each pass."""
    count = stop - start
    u = np.empty(count)
    for j in range(count):
        d = xk - x[start + j]
        u[j] = 1.0 / (d * d)
        g[j] = series_g[-1]
        lap_tile[j] = series_l[-1]
    for k in range(series_g.size - 2, -1, -1):
        cg, cl = series_g[k], series_l[k]
        for j in range(count):
            g[j] = g[j] * u[j] + cg
            lap_tile[j] = lap_tile[j] * u[j] + cl
    for j in range(count):
        g[j] *= u[j] * (xk - x[start + j])
        lap_tile[j] *= u[j]


@njit
def _log_row(k, x, masses, terms, series_g, series_l, lower, upper, g, lap_tile):
    """Row k of the log kernel: (sum_j m_j grad K(x_k - x_j), sum_j m_j Delta K(x_k - x_j)), the far
    partners (j < lower, j >= upper) by the series in tiles, the near ones by the closed forms."""
    kinds, coefficients, parameters, tables, steps = terms
    grad = lap = 0.0
    for first, last in ((0, lower), (upper, x.size)):
        for start in range(first, last, _TILE):
            stop = min(start + _TILE, last)
            _log_far_tile(x[k], x, start, stop, series_g, series_l, g, lap_tile)
            tile_grad, tile_lap = _weighted(start, stop, masses, g, lap_tile)
            grad += tile_grad
            lap += tile_lap
    for j in range(lower, upper):
        d = x[k] - x[j]
        pair_g, pair_lap = profile_forces_kernel(kinds, coefficients, parameters, abs(d), 1, tables, steps)
        grad += masses[j] * pair_g * d
        lap += masses[j] * pair_lap
    return grad, lap


@njit_threaded
def sorted_log_sums(x, masses, terms, series_g, series_l, radius):
    """Velocities and divergences of the log kernel for positions ``x`` sorted increasingly; ``terms`` the
    arrays of :meth:`.kernels.Kernel.arrays`, (series_g, series_l) of :func:`log_series`, ``radius`` the
    near window's half-width. Compiled, for the arrays :func:`.pair_sums.pair_sums` has checked: it trusts its
    caller's checks."""
    n = x.size
    lower, upper = _windows(x, radius)
    velocity = np.empty(n)
    divergence = np.empty(n)
    for block in prange((n + _ROWS - 1) // _ROWS):
        g = np.empty(_TILE)
        lap_tile = np.empty(_TILE)
        for k in range(block * _ROWS, min(block * _ROWS + _ROWS, n)):
            grad, lap = _log_row(k, x, masses, terms, series_g, series_l, lower[k], upper[k], g, lap_tile)
            velocity[k] = -grad
            divergence[k] = -lap
    return velocity, divergence


def log_pair_sums_1d(positions, masses, kinds, coefficients, parameters, tables, steps):
    """The 1D pair sums of :func:`.pair_sums.pair_sums` for the kernels :func:`log_supported` takes:
    positions (N, 1) and masses (N,) already checked; returns velocities (N, 1) and divergences (N,).
    It trusts its caller's checks."""
    x = positions[:, 0]
    order = np.argsort(x, kind="stable")
    series_g, series_l = log_series(kinds, coefficients, parameters)
    widths = np.where(kinds == LOG, 0.0, parameters)
    radius = DAWSON_ASYMPTOTIC * float(widths.max(initial=0.0))
    v, d = sorted_log_sums(np.ascontiguousarray(x[order]), np.ascontiguousarray(masses[order]),
                           (kinds, coefficients, parameters, tables, steps), series_g, series_l, radius)
    velocity = np.empty_like(positions)
    divergence = np.empty_like(masses)
    velocity[order, 0] = v
    divergence[order] = d
    return velocity, divergence
