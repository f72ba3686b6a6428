"""Interaction kernels, their mollified versions in closed form, and the compiled pair sums.

A kernel is a sum of terms. Each term has a ``kind``, a coefficient and a parameter
and gives, at distance r, three radial values: the potential k(r), the factor
g(r) with grad K(x) = x g(|x|), and the Laplacian l(r). Mollification by a mixture
of Gaussians (:mod:`particle_methods.blob.mollifiers`) turns a term into one term
per Gaussian, each in closed form:

- GAUSS_ABS_1D, (|x|/2) * G_s:  k = (x erf(x/s) + s e^{-x^2/s^2}/sqrt(pi))/2,
  grad = erf(x/s)/2, Laplacian = G_s(x): the 1D Newtonian kernel (Delta K = delta_0).
- GAUSS_CUBIC_1D, (|x|^3/3) * G_s: with Z ~ N(x, s^2/2),
  k = E|Z|^3/3, grad = E[Z|Z|] = (x^2 + s^2/2) erf(x/s) + x s e^{-x^2/s^2}/sqrt(pi),
  Laplacian = 2 E|Z| = 2 (x erf(x/s) + s e^{-x^2/s^2}/sqrt(pi)).
- LOG, log|x|/(2 pi) in d dimensions: grad = x/(2 pi |x|^2), Laplacian (d - 2)/(2 pi |x|^2) away
  from the origin (in 2D, the Newtonian kernel, a Dirac mass), grad K(0) := 0.
- GAUSS_LOG_1D, (log|x|/(2 pi)) * G_s in 1D: with Dawson's integral F and z = |x|/s,
  grad = F(z)/(pi s) sign(x) (the principal value (1/x) * G_s = (2/s) F(x/s)),
  Laplacian = F'(z)/(pi s^2) = (1 - 2 z F(z))/(pi s^2); its potential is not needed here.
- GAUSS_LOG_2D, (log|x|/(2 pi)) * G_s in 2D: grad = x (1 - e^{-r^2/s^2})/(2 pi r^2),
  Laplacian = G_s = e^{-r^2/s^2}/(pi s^2), k = (log r + E1(r^2/s^2)/2)/(2 pi).
- TABLE, a mollified term tabulated on a radial grid (:mod:`particle_methods.blob.radial`),
  interpolated linearly; the parameter is the table's row in the ``tables`` array.
- EXP, e^{-|x|/lambda} unmollified in 2D (Morse terms, parameter lambda): grad = -x e^{-r/lambda}/(lambda r),
  Laplacian = e^{-r/lambda}/lambda^2 - e^{-r/lambda}/(lambda r); grad K(0) := 0.
- POWER, |x|^a/a unmollified in d dimensions: grad = x |x|^{a-2},
  Laplacian = (a + d - 2)|x|^{a-2}; grad K(0) := 0 as in the particle method, and a
  polynomial kernel of degree below m is left unchanged by mollification (Remark 3.4).

The pair sums v_i = -sum_j m_j grad K(X_i - X_j), div_i = -sum_j m_j Delta K(X_i - X_j)
are written once for any dimension.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numba import prange

from ..jit import njit, njit_threaded
from ..threads import threads_for
from ..validation import (
    finite_array,
    finite_result,
    in_interval,
    instance,
    integer_at_least,
    one_of,
    positive,
    real_array,
    same_length,
)
from . import newtonian_fmm, sums_1d
from .checks import MAX_FMM_PARTICLES, MAX_PARTICLES, MAX_TABLE_WORK
from .mollifiers import Mollifier
from .radial import RadialTable, tabulate
from .special import EULER_GAMMA, dawson_and_slope, exp1
from .tile_sums import row_share
from .vector_exp import Z_LIMIT, exp_minus_and_complement

GAUSS_ABS_1D, GAUSS_CUBIC_1D, POWER, LOG, GAUSS_LOG_2D, TABLE, EXP, GAUSS_LOG_1D = 0, 1, 2, 3, 4, 5, 6, 7
#: The dimensions each kind of term is written for (its Laplacian, or its Gaussian convolution, depends on d).
KIND_DIMENSIONS = {GAUSS_ABS_1D: (1,), GAUSS_CUBIC_1D: (1,), GAUSS_LOG_1D: (1,), POWER: (1, 2, 3), LOG: (1, 2, 3),
                   GAUSS_LOG_2D: (2,), TABLE: (2,), EXP: (2,)}
#: Distances beyond this many steps of a radial table would overflow its integer index.
_TABLE_REACH = 2.0**40
_SQRT_PI = math.sqrt(math.pi)
#: Beyond this many widths erfc and the Gaussian are below 1e-17 relative: erf = 1, e = 0 exactly
#: in double precision, and the mollified kernel equals the raw one.
_GAUSS_CUTOFF = 6.5


@njit
def _gauss_parts(r, s):
    """(erf(r/s), exp(-r^2/s^2)), skipping both special functions far from the origin."""
    if r > _GAUSS_CUTOFF * s:
        return 1.0, 0.0
    return math.erf(r / s), math.exp(-(r / s) ** 2)


@njit
def _forces(kind, coefficient, parameter, r, dimension):
    """(g(r), l(r)) of one term at distance r >= 0: grad K = x g(|x|), Delta K = l(|x|)."""
    if kind == GAUSS_ABS_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        g = erf / (2.0 * r) if r > 0 else 1.0 / (s * _SQRT_PI)
        return coefficient * g, coefficient * e / (s * _SQRT_PI)
    if kind == GAUSS_CUBIC_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        g = (r * r + 0.5 * s * s) * erf / r + s * e / _SQRT_PI if r > 0 else 2.0 * s / _SQRT_PI
        return coefficient * g, coefficient * 2.0 * (r * erf + s * e / _SQRT_PI)
    if kind == GAUSS_LOG_2D:
        s = parameter
        if r > _GAUSS_CUTOFF * s:  # e^{-r^2/s^2} < 1e-18: the raw kernel in double precision
            return coefficient / (2 * math.pi * r * r), 0.0
        if r == 0.0:
            return coefficient / (2 * math.pi * s * s), coefficient / (math.pi * s * s)
        z = (r / s) ** 2
        e = math.exp(-z)
        one_minus_e = 1.0 - e if z > 1e-3 else -math.expm1(-z)
        return coefficient * one_minus_e / (2 * math.pi * r * r), coefficient * e / (math.pi * s * s)
    if kind == LOG:
        if r == 0.0:
            return 0.0, 0.0
        g = coefficient / (2 * math.pi * r * r)
        return g, (dimension - 2.0) * g
    if kind == GAUSS_LOG_1D:
        s = parameter
        if r == 0.0:
            return coefficient / (math.pi * s * s), coefficient / (math.pi * s * s)
        f, slope = dawson_and_slope(r / s)
        return coefficient * f / (math.pi * s * r), coefficient * slope / (math.pi * s * s)
    if kind == EXP:
        if r == 0.0:
            return 0.0, 0.0
        lam = parameter
        e = math.exp(-r / lam)
        return -coefficient * e / (lam * r), coefficient * (e / (lam * lam) - e / (lam * r))
    # POWER: |x|^a / a
    a = parameter
    if r == 0.0:
        return (coefficient, coefficient * (a + dimension - 2.0)) if a == 2.0 else (0.0, 0.0)
    ra = _power(r, a - 2.0)
    return coefficient * ra, coefficient * (a + dimension - 2.0) * ra


@njit
def _power(r, b):
    """r^b, r > 0, by products and a square root for the exponents of section 4 (a call to pow costs
    several times more); pow for the others."""
    if b == 0.0:
        return 1.0
    if b == 1.0:
        return r
    if b == 2.0:
        return r * r
    if b == 5.0:
        r2 = r * r
        return r2 * r2 * r
    if b == -0.5:
        return 1.0 / math.sqrt(r)
    return r**b


@njit
def _potential(kind, coefficient, parameter, r):
    """k(r) of one (untabulated) term."""
    if kind == GAUSS_ABS_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        return coefficient * 0.5 * (r * erf + s * e / _SQRT_PI)
    if kind == GAUSS_CUBIC_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        # E|Z|^3 for Z ~ N(r, s^2/2): (r^3 + 3 r s^2/2) erf(r/s) + (r^2 + s^2) s e^{-r^2/s^2}/sqrt(pi)
        return coefficient * ((r**3 + 1.5 * r * s * s) * erf + (r * r + s * s) * s * e / _SQRT_PI) / 3.0
    if kind == GAUSS_LOG_2D:
        s = parameter
        if r == 0.0:
            return coefficient * (math.log(s) - 0.5 * EULER_GAMMA) / (2 * math.pi)
        z = (r / s) ** 2
        tail = 0.5 * exp1(z) if z < 745.0 else 0.0
        return coefficient * (math.log(r) + tail) / (2 * math.pi)
    if kind == GAUSS_LOG_1D:  # not tabulated: Kernel.has_potential is False
        return math.nan
    if kind == LOG:
        return coefficient * math.log(r) / (2 * math.pi) if r > 0 else 0.0
    if kind == EXP:
        return coefficient * math.exp(-r / parameter)
    return coefficient * r**parameter / parameter if r > 0 else 0.0


@njit
def _table_forces(coefficient, row, r, tables, steps):
    """(g, l) of a tabulated term by linear interpolation; the last node beyond the table."""
    table = tables[row]
    x = r / steps[row]
    j = min(int(x), table.shape[1] - 2)
    w = min(x - j, 1.0)
    g = table[0, j] * (1.0 - w) + table[0, j + 1] * w
    lap = table[1, j] * (1.0 - w) + table[1, j + 1] * w
    return coefficient * g, coefficient * lap


@njit
def profile_forces_kernel(kinds, coefficients, parameters, r, dimension, tables, steps):
    g = lap = 0.0
    for term in range(kinds.size):
        if kinds[term] == TABLE:
            tg, tl = _table_forces(coefficients[term], int(parameters[term]), r, tables, steps)
        else:
            tg, tl = _forces(kinds[term], coefficients[term], parameters[term], r, dimension)
        g += tg
        lap += tl
    return g, lap


@njit
def _profile_potential(kinds, coefficients, parameters, r):
    k = 0.0
    for term in range(kinds.size):
        k += _potential(kinds[term], coefficients[term], parameters[term], r)
    return k


#: Rows are dealt to this many accumulators, round robin, whatever the number of threads: each
#: pair is evaluated once, and the sums are added in the same order on any machine.
_ACCUMULATORS = 16
#: Below this many particles the direct sums run on one thread (:func:`particle_methods.threads.threads_for`,
#: measured by benchmarks/bench_threads.py). The sums are bit-identical on any number of threads.
PARALLEL_MIN_PARTICLES = 512
#: From this many particles on, the 2D Newtonian sums mollified by (4.2) go through the fast multipole
#: method (:mod:`.newtonian_fmm`): the crossover with the direct tiled sums measured by
#: benchmarks/bench_fmm.py (about 2,500 particles on one thread, 2,800 on two; delta = h^0.9).
FMM_MIN_PARTICLES = 2500
#: The same for the raw kernel (the particle method), whose direct sums need no exponential: the
#: crossover lies near 3,500 particles on one thread, 4,000 to 5,000 on two.
FMM_MIN_PARTICLES_RAW = 4000


def _threads_for(particles):
    """All of numba's threads for large systems, one below :data:`PARALLEL_MIN_PARTICLES`."""
    return threads_for(particles, PARALLEL_MIN_PARTICLES)


@njit
def _accumulate(c, positions, masses, kinds, coefficients, parameters, tables, steps, velocities, divergences):
    """Accumulator c: the rows i = c mod 16 and their partners j > i."""
    n, dimension = positions.shape
    diff = np.empty(dimension)
    _, self_lap = profile_forces_kernel(kinds, coefficients, parameters, 0.0, dimension, tables, steps)
    for i in range(c, n, _ACCUMULATORS):
        divergences[c, i] -= masses[i] * self_lap
        for j in range(i + 1, n):
            r2 = 0.0
            for axis in range(dimension):
                diff[axis] = positions[i, axis] - positions[j, axis]
                r2 += diff[axis] * diff[axis]
            g, lap = profile_forces_kernel(kinds, coefficients, parameters, math.sqrt(r2), dimension, tables, steps)
            for axis in range(dimension):
                velocities[c, i, axis] -= masses[j] * g * diff[axis]
                velocities[c, j, axis] += masses[i] * g * diff[axis]
            divergences[c, i] -= masses[j] * lap
            divergences[c, j] -= masses[i] * lap


@njit_threaded
def _accumulators_parallel(positions, masses, kinds, coefficients, parameters, tables, steps):
    n, dimension = positions.shape
    velocities = np.zeros((_ACCUMULATORS, n, dimension))
    divergences = np.zeros((_ACCUMULATORS, n))
    for c in prange(_ACCUMULATORS):
        _accumulate(c, positions, masses, kinds, coefficients, parameters, tables, steps, velocities, divergences)
    return velocities, divergences


@njit
def _reduce(velocities, divergences):
    """The accumulators summed in a fixed order."""
    velocity = np.zeros(velocities.shape[1:])
    divergence = np.zeros(divergences.shape[1])
    for c in range(_ACCUMULATORS):
        velocity += velocities[c]
        divergence += divergences[c]
    return velocity, divergence


#: Partners are taken in tiles of this many, so that the row's forces stay in the L1 cache between the
#: loop that computes them and the two that use them.
_TILE = 256


@njit
def _newtonian_2d_forces(xi, yi, x, y, start, stop, constants, wx, wy, lap):
    """Row i of the 2D Newtonian kernel: grad K(X_i - X_j) (as wx, wy) and Delta K(X_i - X_j) for
    start <= j < stop, into the tile buffers. Mollified (m = 4, two Gaussians (4.2)) when the first
    constant is 1, raw log|x|/(2 pi) (the particle method, Delta K = 0 away from 0) otherwise. No
    branch inside the loops, so LLVM vectorises them; at r = 0 (coincident particles) the gradient
    is finite and irrelevant (it multiplies X_i - X_j = 0), so grad K(0) := 0 holds."""
    mollified, c0, c1, a0, a1, l0, l1 = constants
    if mollified == 1.0:
        for j in range(start, stop):
            dx = xi - x[j]
            dy = yi - y[j]
            r2 = dx * dx + dy * dy
            e0, f0 = exp_minus_and_complement(r2 * a0)
            e1, f1 = exp_minus_and_complement(r2 * a1)
            g = (c0 * f0 + c1 * f1) / (r2 + 1e-300)
            wx[j - start] = g * dx
            wy[j - start] = g * dy
            lap[j - start] = l0 * e0 + l1 * e1
    else:
        for j in range(start, stop):
            dx = xi - x[j]
            dy = yi - y[j]
            g = c0 / (dx * dx + dy * dy + 1e-300)
            wx[j - start] = g * dx
            wy[j - start] = g * dy
            lap[j - start] = 0.0


@njit
def _terms_2d_forces(xi, yi, x, y, start, stop, kinds, coefficients, parameters, tables, steps, wx, wy, lap, buffer):
    """Row i of a 2D kernel made of even powers below the mollifier's order (polynomials, Remark 3.4),
    Gaussian log terms and tabulated terms (:func:`tiled_2d_supported`): grad K and Delta K for
    start <= j < stop, term by term, each in a loop without branches (the table lookups, gathers
    from an argument array, stay scalar; the clamps of :func:`_table_forces` are written exactly:
    a - (a - b + |a - b|)/2 is a itself for a <= b)."""
    count = stop - start
    for j in range(start, stop):
        dx = xi - x[j]
        dy = yi - y[j]
        buffer[j - start] = dx * dx + dy * dy
    for j in range(count):
        wx[j] = 0.0   # g(r) until the end
        lap[j] = 0.0
    for t in range(kinds.size):
        c = coefficients[t]
        if kinds[t] == POWER:
            a = parameters[t]
            if a == 2.0:
                for j in range(count):
                    wx[j] += c
                    lap[j] += 2.0 * c
            else:  # a = 4: g = r^2, Delta = 4 r^2
                for j in range(count):
                    wx[j] += c * buffer[j]
                    lap[j] += 4.0 * c * buffer[j]
        elif kinds[t] == GAUSS_LOG_2D:
            s = parameters[t]
            inverse, g0, l0 = 1.0 / (s * s), c / (2 * math.pi), c / (math.pi * s * s)
            for j in range(count):
                e, f = exp_minus_and_complement(buffer[j] * inverse)
                wx[j] += g0 * f / (buffer[j] + 1e-300)
                lap[j] += l0 * e
        else:  # TABLE
            row = int(parameters[t])
            inverse, last = 1.0 / steps[row], tables.shape[2] - 2.0
            for j in range(count):
                u = math.sqrt(buffer[j]) * inverse
                wy[j] = u - 0.5 * ((u - last) + abs(u - last))   # min(u, last)
            for j in range(count):
                u = math.sqrt(buffer[j]) * inverse
                k = int(wy[j])
                w = u - k
                w = w - 0.5 * ((w - 1.0) + abs(w - 1.0))          # min(w, 1)
                wx[j] += c * (tables[row, 0, k] * (1.0 - w) + tables[row, 0, k + 1] * w)
                lap[j] += c * (tables[row, 1, k] * (1.0 - w) + tables[row, 1, k + 1] * w)
    for j in range(start, stop):
        g = wx[j - start]
        wx[j - start] = g * (xi - x[j])
        wy[j - start] = g * (yi - y[j])


@njit
def _partners_share(start, stop, mi, wx, wy, lap, vx, vy, divergence):
    """The partners' share of row i: for start <= j < stop, v_j += m_i grad K, div_j -= m_i Delta K."""
    for j in range(start, stop):
        vx[j] += mi * wx[j - start]
        vy[j] += mi * wy[j - start]
        divergence[j] -= mi * lap[j - start]


@njit
def _tiled_2d_accumulate(c, x, y, masses, constants, terms, self_lap, vx, vy, divergence):
    """Accumulator c of a tiled 2D path: rows i = c mod 16 and their partners j > i, tile by tile. The
    Newtonian kernel (:func:`_newtonian_2d_forces`, ``constants``) when ``terms`` has no kind, else the
    terms (kinds, coefficients, parameters, tables, steps) of :func:`_terms_2d_forces`."""
    n = x.size
    kinds, coefficients, parameters, tables, steps = terms
    wx = np.empty(_TILE)
    wy = np.empty(_TILE)
    lap = np.empty(_TILE)
    buffer = np.empty(_TILE)
    for i in range(c, n, _ACCUMULATORS):
        mi = masses[i]
        sx = sy = sd = 0.0
        for start in range(i + 1, n, _TILE):
            stop = min(start + _TILE, n)
            if kinds.size == 0:
                _newtonian_2d_forces(x[i], y[i], x, y, start, stop, constants, wx, wy, lap)
            else:
                _terms_2d_forces(x[i], y[i], x, y, start, stop, kinds, coefficients, parameters, tables, steps,
                                 wx, wy, lap, buffer)
            _partners_share(start, stop, mi, wx, wy, lap, vx[c], vy[c], divergence[c])
            tx, ty, td = row_share(start, stop, masses, wx, wy, lap)
            sx += tx
            sy += ty
            sd += td
        vx[c, i] -= sx
        vy[c, i] -= sy
        divergence[c, i] -= sd + mi * self_lap


@njit_threaded
def _tiled_2d_parallel(x, y, masses, constants, terms, self_lap):
    vx = np.zeros((_ACCUMULATORS, x.size))
    vy = np.zeros((_ACCUMULATORS, x.size))
    divergence = np.zeros((_ACCUMULATORS, x.size))
    for c in prange(_ACCUMULATORS):
        _tiled_2d_accumulate(c, x, y, masses, constants, terms, self_lap, vx, vy, divergence)
    return vx, vy, divergence


def _tiled_2d_sums(positions, masses, constants, terms, self_lap):
    x, y = np.ascontiguousarray(positions[:, 0]), np.ascontiguousarray(positions[:, 1])
    with _threads_for(x.size):
        vx, vy, divergence = _tiled_2d_parallel(x, y, masses, constants, terms, self_lap)
    return _reduce(np.stack([vx, vy], axis=-1), divergence)


def is_newtonian_2d(kinds) -> bool:
    """Whether 2D terms are the Newtonian kernel, raw (one LOG term) or mollified by (4.2) (two
    GAUSS_LOG_2D terms): its sums have a path of their own (:func:`_newtonian_2d_sums`)."""
    kinds = tuple(int(kind) for kind in kinds)
    return kinds in ((LOG,), (GAUSS_LOG_2D, GAUSS_LOG_2D))


def tiled_2d_supported(kinds, parameters) -> bool:
    """Whether a 2D kernel's terms are all even powers 2 and 4, Gaussian log terms or tables (the
    mollified kernels of section 4.4 other than the Newtonian one)."""
    return all(kind in (TABLE, GAUSS_LOG_2D) or (kind == POWER and parameter in (2.0, 4.0))
               for kind, parameter in zip(kinds, parameters))


def _check_span(positions, widths):
    """The vectorised exponential takes |X_i - X_j|^2 / s^2 up to :data:`Z_LIMIT`."""
    span2 = np.ptp(positions[:, 0]) ** 2 + np.ptp(positions[:, 1]) ** 2
    if widths.size and span2 / widths.min() ** 2 > Z_LIMIT:
        raise ValueError(f"positions spread over {np.sqrt(span2):.3g}, more than {np.sqrt(Z_LIMIT):.3g} "
                         f"widths {widths.min():.3g} of the mollifier: beyond the vectorised exponential's range")


_NO_TERMS = (np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0), np.zeros((1, 2, 2)), np.ones(1))


def _coincident(positions) -> bool:
    """Whether two of the points (N, 2) are equal."""
    order = np.lexsort((positions[:, 1], positions[:, 0]))
    ordered = positions[order]
    return bool(np.any(np.all(ordered[1:] == ordered[:-1], axis=1)))


def _newtonian_2d_sums(positions, masses, kinds, coefficients, widths, method):
    """Pair sums of the 2D Newtonian kernel, raw (one LOG term: the particle method) or mollified
    (two GAUSS_LOG_2D terms, (4.2)). From :data:`FMM_MIN_PARTICLES` (raw: :data:`FMM_MIN_PARTICLES_RAW`)
    distinct points on, by the fast multipole method and a near-field cell list (:mod:`.newtonian_fmm`,
    O(N)); below, or with coincident or nearly coincident points, directly, split into loops that
    vectorise: the forces of a row tile, then the partners' share and the row's share (summed in a
    fixed order)."""
    if kinds[0] != LOG:
        _check_span(positions, widths)
    threshold = FMM_MIN_PARTICLES_RAW if kinds[0] == LOG else FMM_MIN_PARTICLES
    fast = positions.shape[0] >= threshold if method == "auto" else method == "fmm"
    if fast and positions.shape[0] >= 2 and not _coincident(positions):
        sums = newtonian_fmm.newtonian_sums(positions, masses, coefficients, np.zeros(0) if kinds[0] == LOG else widths)
        if sums is not None:  # None: two particles far closer than the mollifier's width (see newtonian_sums)
            return sums
    if kinds[0] == LOG:
        constants = (0.0, coefficients[0] / (2 * math.pi), 0.0, 0.0, 0.0, 0.0, 0.0)
        self_lap = 0.0
    else:
        inverse = 1.0 / widths**2
        constants = (1.0, coefficients[0] / (2 * math.pi), coefficients[1] / (2 * math.pi), inverse[0],
                     inverse[1], coefficients[0] * inverse[0] / math.pi, coefficients[1] * inverse[1] / math.pi)
        self_lap = constants[5] + constants[6]
    return _tiled_2d_sums(positions, masses, constants, _NO_TERMS, self_lap)


#: How :func:`pair_sums` takes the 2D Newtonian kernel's sums.
NEWTONIAN_2D_METHODS = {"auto": "the fast multipole method from FMM_MIN_PARTICLES(_RAW) particles on, else direct",
                        "fmm": "the fast multipole method (direct below 2 particles and with coincident or nearly "
                               "coincident points)",
                        "direct": "the direct tiled sums"}


def pair_sums(positions, masses, kinds, coefficients, parameters, tables, steps, newtonian_2d="auto"):
    """Velocities -sum_j m_j grad K(X_i - X_j) (shape (N, d)) and divergences -sum_j m_j Delta K(X_i - X_j).

    grad K is odd and Delta K even, so each pair i < j is evaluated once and added to both rows,
    half the kernel evaluations of the plain double loop. Accumulator c takes the rows i = c mod 16
    and their partners; the accumulators are then summed in a fixed order, on one thread below
    :data:`PARALLEL_MIN_PARTICLES` particles and on all of them above (the same sums either way).
    The 2D Newtonian kernel, raw or mollified by (4.2), takes a vectorised path with the same
    accumulators (:func:`_newtonian_2d_sums`, exponentials from :mod:`.vector_exp`), or the fast multipole
    method (:mod:`.newtonian_fmm`), as ``newtonian_2d`` says (:data:`NEWTONIAN_2D_METHODS`).
    The arrays are those of :meth:`Kernel.arrays`; ``positions`` (N, d) and ``masses`` (N,) are checked here.
    """
    one_of("newtonian_2d", newtonian_2d, NEWTONIAN_2D_METHODS)
    positions = np.ascontiguousarray(positions, dtype=np.float64)
    masses = np.ascontiguousarray(masses, dtype=np.float64)
    if positions.ndim != 2 or masses.shape != positions.shape[:1]:
        raise ValueError(f"positions must have shape (N, d) and masses (N,), got {positions.shape} and {masses.shape}")
    if not (np.isfinite(positions).all() and np.isfinite(masses).all()):
        raise ValueError("positions and masses must be finite")
    if positions.shape[1] == 2 and is_newtonian_2d(kinds):
        return _newtonian_2d_sums(positions, masses, kinds, coefficients, parameters, newtonian_2d)
    if np.any(kinds == TABLE) and np.ptp(positions, axis=0).max() > _TABLE_REACH * steps.min():
        raise ValueError("positions spread over more than 2^40 steps of the kernel's radial table")
    if positions.shape[1] == 2 and tiled_2d_supported(kinds, parameters):
        _check_span(positions, parameters[kinds == GAUSS_LOG_2D])
        _, self_lap = profile_forces_kernel(kinds, coefficients, parameters, 0.0, 2, tables, steps)
        return _tiled_2d_sums(positions, masses, (0.0,) * 7, (kinds, coefficients, parameters, tables, steps),
                              self_lap)
    if positions.shape[1] == 1 and sums_1d.supported(kinds, parameters):
        with _threads_for(positions.shape[0]):
            return sums_1d.pair_sums_1d(positions, masses, kinds, coefficients, parameters)
    with _threads_for(positions.shape[0]):
        return _reduce(*_accumulators_parallel(positions, masses, kinds, coefficients, parameters, tables, steps))


@njit_threaded
def pair_energy(positions, masses, kinds, coefficients, parameters, tables, steps):
    """E_delta = 1/2 sum_{i,j} K(X_i - X_j) m_i m_j, (2.4) on the particle system (2.3)."""
    n, dimension = positions.shape
    partial = np.zeros(n)
    for i in prange(n):
        total = 0.0
        for j in range(n):
            r2 = 0.0
            for axis in range(dimension):
                d = positions[i, axis] - positions[j, axis]
                r2 += d * d
            k = _profile_potential(kinds, coefficients, parameters, math.sqrt(r2))
            total += masses[j] * k
        partial[i] = masses[i] * total
    return 0.5 * partial.sum()


@dataclass(frozen=True)
class Kernel:
    """K as a sum of terms (kind, coefficient, parameter), with its name, dimension and any radial
    tables its TABLE terms point to (rows of ``tables``, each (g, Laplacian) on a grid of ``steps``)."""

    name: str
    dimension: int
    kinds: tuple[int, ...]
    coefficients: tuple[float, ...]
    parameters: tuple[float, ...]
    tables: tuple = ()

    def __post_init__(self):
        """Check the terms before any compiled sum reads them; store them as tuples of Python numbers."""
        instance("name", self.name, str)
        dimension = integer_at_least("dimension", self.dimension, 1, 3)
        kinds = real_array("kinds", self.kinds)
        coefficients = finite_array("coefficients", self.coefficients)
        parameters = finite_array("parameters", self.parameters)
        tables = tuple(instance("tables", self.tables, (tuple, list)))
        for table in tables:
            instance("tables", table, RadialTable)
        if kinds.ndim != 1 or not np.all(np.isin(kinds, list(KIND_DIMENSIONS))):
            raise ValueError(f"kinds must be a sequence of term kinds {sorted(KIND_DIMENSIONS)}, got {self.kinds!r}")
        if same_length(kinds=kinds, coefficients=coefficients, parameters=parameters) == 0:
            raise ValueError("a kernel needs at least one term")
        for kind, parameter in zip(kinds.astype(int), parameters):
            if dimension not in KIND_DIMENSIONS[kind]:
                raise ValueError(f"terms of kind {kind} are written for dimension {KIND_DIMENSIONS[kind]}, "
                                 f"not {dimension}")
            if kind == TABLE and parameter not in range(len(tables)):
                raise ValueError(f"the parameter of a TABLE term must index one of the {len(tables)} tables, "
                                 f"got {parameter}")
            if kind not in (LOG, TABLE) and parameter <= 0:
                raise ValueError(f"the parameter of a term of kind {kind} (width, power or length) must be positive, "
                                 f"got {parameter}")
        if len({table.gradient.size for table in tables}) > 1:
            raise ValueError("the radial tables of one kernel must have the same number of nodes")
        object.__setattr__(self, "kinds", tuple(int(kind) for kind in kinds))
        object.__setattr__(self, "coefficients", tuple(float(c) for c in coefficients))
        object.__setattr__(self, "parameters", tuple(float(p) for p in parameters))
        object.__setattr__(self, "tables", tables)

    @property
    def jumps_at_origin(self) -> bool:
        """Whether grad K jumps or blows up at 0 (a raw |x|^a/a with a <= 1, log|x| or e^{-|x|/lambda}
        term): the particle method's ODE then stops being defined where two particles meet."""
        return any(kind in (LOG, EXP) or (kind == POWER and a <= 1.0) for kind, a in zip(self.kinds, self.parameters))

    @property
    def max_particles(self) -> int:
        """The most particles of one ODE solve with this kernel: :data:`~.checks.MAX_FMM_PARTICLES` for the 2D
        Newtonian kernel (O(N) sums by the fast multipole method), :data:`~.checks.MAX_PARTICLES` otherwise."""
        return MAX_FMM_PARTICLES if self.dimension == 2 and is_newtonian_2d(self.kinds) else MAX_PARTICLES

    @property
    def has_potential(self) -> bool:
        """Whether K itself is known (tabulated terms and the mollified 1D log kernel carry only grad
        and Laplacian)."""
        return TABLE not in self.kinds and GAUSS_LOG_1D not in self.kinds

    def arrays(self):
        if self.tables:
            size = max(t.gradient.size for t in self.tables)
            tables = np.zeros((len(self.tables), 2, size))
            for row, t in enumerate(self.tables):
                tables[row, 0, : t.gradient.size] = t.gradient
                tables[row, 1, : t.laplacian.size] = t.laplacian
            steps = np.array([t.step for t in self.tables])
        else:
            tables, steps = np.zeros((1, 2, 2)), np.ones(1)
        return (np.array(self.kinds, dtype=np.int64), np.array(self.coefficients, dtype=np.float64),
                np.array(self.parameters, dtype=np.float64), tables, steps)

    def profile(self, r):
        """(k, g, l) at the distances r >= 0 (any shape), vectorised (for plots and tests): K = k(|x|),
        grad K = x g(|x|), Delta K = l(|x|); k is None when K itself is not known (:attr:`has_potential`)."""
        r = in_interval("r", r, 0.0, np.inf)
        kinds, coefficients, parameters, tables, steps = self.arrays()
        if self.tables and r.size and r.max() > _TABLE_REACH * steps.min():
            raise ValueError(f"r must stay within 2^40 steps of the kernel's radial table, got {r.max()}")
        cause = "the kernel overflows at these distances"
        forces = [profile_forces_kernel(kinds, coefficients, parameters, float(x), self.dimension, tables, steps)
                  for x in r.ravel()]
        g, lap = np.moveaxis(finite_result("grad K and Delta K", np.reshape(forces, r.shape + (2,)), cause), -1, 0)
        if not self.has_potential:
            return None, g, lap
        k = np.reshape([_profile_potential(kinds, coefficients, parameters, float(x)) for x in r.ravel()], r.shape)
        return finite_result("K", k, cause), g, lap


#: 1D kernels of section 4: name -> (sign, kind of its Gaussian convolution, power a).
KERNELS_1D = {
    "newtonian_attractive": (1.0, GAUSS_ABS_1D, 1.0),   # K = (Delta)^{-1} = |x|/2
    "newtonian_repulsive": (-1.0, GAUSS_ABS_1D, 1.0),   # K = (-Delta)^{-1} = -|x|/2
    "cubic": (1.0, GAUSS_CUBIC_1D, 3.0),                # K = |x|^3/3
    "log_repulsive": (-1.0, GAUSS_LOG_1D, 0.0),         # K = -log|x|/(2 pi), Figure 4's row label
}


def kernel_1d(name: str, mollifier: Mollifier | None = None, delta: float | None = None) -> Kernel:
    """A 1D kernel of section 4, mollified by psi_delta, or raw (particle method) without mollifier."""
    sign, gaussian_kind, a = one_of("kernel", name, KERNELS_1D)
    if mollifier is None:
        if delta is not None:
            raise ValueError("delta needs a mollifier")
        if gaussian_kind == GAUSS_LOG_1D:
            return Kernel(name, 1, (LOG,), (sign,), (0.0,))
        # |x|/2 for the Newtonian kernels, |x|^3/3 for the cubic one.
        return Kernel(name, 1, (POWER,), (sign * (0.5 if a == 1.0 else 1.0),), (a,))
    if instance("mollifier", mollifier, Mollifier).dimension != 1:
        raise ValueError("a 1D kernel needs a 1D mollifier")
    delta = positive("delta", delta)
    widths = mollifier.scaled_widths(delta)
    # The Gaussian terms carry the kernel's own factor (1/2, 1/3 or 1/(2 pi)): only sign and weights remain.
    return Kernel(f"{name} (m = {mollifier.order}, delta = {delta:.4g})", 1,
                  tuple(gaussian_kind for _ in widths), tuple(sign * w for w in mollifier.weights),
                  tuple(float(s) for s in widths))


#: 2D kernels of section 4.4: name -> unmollified terms (kind, coefficient, parameter).
KERNELS_2D = {
    "newtonian": ((LOG, 1.0, 0.0),),                           # log|x|/(2 pi) = (Delta)^{-1}
    "quadratic": ((POWER, 1.0, 2.0),),                            # |x|^2/2
    "cubic": ((POWER, 1.0, 3.0),),                                # |x|^3/3
    "quartic_log": ((POWER, 1.0, 4.0), (LOG, -1.0, 0.0)),      # |x|^4/4 - log|x|/(2 pi)
    "quartic_power": ((POWER, 1.0, 4.0), (POWER, -1.0, 1.5)),     # |x|^4/4 - |x|^1.5/1.5
    "septic_power": ((POWER, 1.0, 7.0), (POWER, -1.0, 1.5)),      # |x|^7/7 - |x|^1.5/1.5
    "morse_1": ((EXP, 1.0, 1.0), (EXP, -2.0, 2.0)),               # e^{-|x|} - 2 e^{-|x|/2}
    "morse_2": ((EXP, 2.0, 1.0), (EXP, -2.0, 2.0)),               # 2 e^{-|x|} - 2 e^{-|x|/2}
}


def _radial_laplacian(kind, parameter):
    """Delta of one unmollified 2D term (without its coefficient), as a function of r > 0."""
    if kind == POWER:
        return lambda r: parameter * r ** (parameter - 2.0)  # (a + d - 2) r^{a-2} with d = 2
    if kind == EXP:
        return lambda r: np.exp(-r / parameter) * (1.0 / parameter**2 - 1.0 / (parameter * r))
    raise ValueError(f"no radial Laplacian for term kind {kind}")


def _check_table(delta, radius, points):
    """A radial table on [0, radius] with ``points`` nodes must resolve and cover psi_delta (step <= delta <=
    radius), within :data:`~particle_methods.blob.checks.MAX_TABLE_WORK`."""
    step = radius / (points - 1)
    if not step <= delta <= radius:
        raise ValueError(f"delta = {delta} must lie between the radial table's step {step:.4g} and its radius {radius} "
                         "(table_radius, table_points)")
    if points * radius / delta > MAX_TABLE_WORK:
        raise ValueError(f"table_points x table_radius / delta = {points * radius / delta:.4g} exceeds MAX_TABLE_WORK "
                         f"= {MAX_TABLE_WORK:g} (a limit on the work of the radial quadrature)")


@functools.lru_cache(maxsize=32)
def _mollified_table(kind, parameter, mollifier, delta, radius, points):
    """The radial table of one unmollified term (without its coefficient), built once per process:
    the two Morse kernels share theirs, and the runs of a figure rebuild the same kernel."""
    return tabulate(_radial_laplacian(kind, parameter), mollifier, delta, radius, points)


def kernel_2d(name: str, mollifier: Mollifier | None = None, delta: float | None = None, *,
              table_radius: float = 5.0, table_points: int = 8001) -> Kernel:
    """A 2D kernel of section 4.4, raw (particle method) or mollified by psi_delta.

    Mollification: the log term becomes Gaussian terms in closed form; a power |x|^a/a with
    a even and a - 1 < m is unchanged (its gradient and Laplacian are polynomials of degree
    below m, Remark 3.4); every other term is tabulated by numerical radial convolution
    (:func:`particle_methods.blob.radial.tabulate`) on [0, table_radius] with table_points nodes, which
    must resolve and cover psi_delta (step <= delta <= table_radius).
    """
    terms = one_of("2D kernel", name, KERNELS_2D)
    table_radius = positive("table_radius", table_radius)
    table_points = integer_at_least("table_points", table_points, 3, int(MAX_TABLE_WORK))
    if mollifier is None:
        if delta is not None:
            raise ValueError("delta needs a mollifier")
        kinds, coefficients, parameters = zip(*terms)
        return Kernel(name, 2, kinds, coefficients, parameters)
    if instance("mollifier", mollifier, Mollifier).dimension != 2:
        raise ValueError("a 2D kernel needs a 2D mollifier")
    delta = positive("delta", delta)
    kinds, coefficients, parameters, tables = [], [], [], []
    for kind, coefficient, parameter in terms:
        if kind == LOG:
            for weight, width in zip(mollifier.weights, mollifier.scaled_widths(delta)):
                kinds.append(GAUSS_LOG_2D)
                coefficients.append(coefficient * weight)
                parameters.append(float(width))
        elif kind == POWER and parameter % 2 == 0 and parameter - 1 < mollifier.order:
            kinds.append(kind)
            coefficients.append(coefficient)
            parameters.append(parameter)
        else:
            _check_table(delta, table_radius, table_points)
            tables.append(_mollified_table(kind, float(parameter), mollifier, delta, table_radius, table_points))
            kinds.append(TABLE)
            coefficients.append(coefficient)
            parameters.append(float(len(tables) - 1))
    return Kernel(f"{name} (m = {mollifier.order}, delta = {delta:.4g})", 2, tuple(kinds), tuple(coefficients),
                  tuple(parameters), tuple(tables))
