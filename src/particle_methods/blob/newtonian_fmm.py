"""The 2D Newtonian pair sums in O(N): far field by a fast multipole method, near field by a cell list.

For K = log|x|/(2 pi), raw (the particle method) or mollified by psi4 of (4.2), psi = sum_k w_k G_{s_k},

    grad K_delta(x) = x sum_k c_k (1 - e^{-|x|^2/s_k^2}) / (2 pi |x|^2),
    Delta K_delta(x) = sum_k c_k e^{-|x|^2/s_k^2} / (pi s_k^2),

(c_k the kernel's coefficient times w_k, sum_k c_k = C), so grad K_delta is the raw field
C x/(2 pi |x|^2) minus Gaussian terms. The raw part, -C/(2 pi) sum_{j != i} m_j (X_i - X_j)/|X_i - X_j|^2,
is the gradient of a 2D Laplace potential with charges m_j: FMMLIB2D's Cauchy FMM ``cfmm2dpartself``
(pyfmmlib's compiled library) computes it in O(N) at precision ``FMM_PRECISION`` (12 digits asked; the
sums agree with the direct ones to 2.8e-15 of their largest value on the Figure 5 grids,
``benchmarks/bench_fmm.py``).
The Gaussian terms are below 1e-18 of the raw term beyond ``GAUSS_CUTOFF`` widths s_max
(e^{-6.5^2} = 4.5e-19), so they are summed exactly over the pairs closer than that, found with a
cell list (cells a third of that wide); so is the whole divergence, since the Laplacian of the raw kernel is a
Dirac mass (its only share, the self term of i = j, is included). With delta = h^q the pairs within
6.5 sqrt(2) delta of a particle number about pi (9.2 h^{q-1})^2 ~ h^{-0.2} (about 730 at h = 1/160): the
near field grows like N^{1.1}.

The result equals the direct sums of :func:`particle_methods.blob.pair_sums.pair_sums` to rounding
(tested to 1e-13 relative to the largest value); each particle's near sum is taken in a fixed order,
so the near field is bit-identical on any number of threads. Coincident particles (which the FMM
cannot take) are left to the direct sums by the caller.
"""

from __future__ import annotations

import ctypes
import functools
import itertools
import math

import numba
import numpy as np

from ..jit import njit
from ..threads import pool
from ..validation import finite_array, finite_result, same_length
from .tile_sums import row_share
from .vector_exp import exp_minus_and_complement

#: FMMLIB2D's precision flag: 4 asks for 12 digits (1e-12 relative to the field's size).
FMM_PRECISION = 4
#: Beyond this many widths of the widest Gaussian, e^{-r^2/s^2} < 4.5e-19: the mollified kernel is the
#: raw one in double precision (the same cut-off as the direct sums').
GAUSS_CUTOFF = 6.5
#: Two particles closer than this fraction of the narrowest Gaussian's width send the sums to the direct
#: path: the raw field of the pair and its correction cancel, leaving about eps s / (N r) of the field
#: (3e-12 at r = 1e-8 for N = 1,246, delta = h^0.9, h = 1/20; below 1e-15 at r = 1e-3 s on the grids of Figure 5).
CLOSE_FRACTION = 1.0e-3
#: Below this many particles the near-field loop runs on one thread (measured, benchmarks/bench_threads.py).
PARALLEL_MIN_PARTICLES = 2000
#: Most candidate pairs the near field of one call examines (the pairs in each particle's cells of the cell list,
#: counted before the sums). Measured by benchmarks/bench_fmm.py on an AMD EPYC (AVX2, 2 cores): 9.4 to 10.8 ns of
#: CPU time per examined pair on one thread, from 4.8 * 10^7 pairs (Figure 5's grid at 1/h = 160) to
#: 7.9 * 10^8 (1/h = 560, 985,089 points, 8 s per call on 2 cores): a call at the limit takes about 10 s of one
#: core for its near field, and the FMM (6.5 s at 10^6 points) beside it. N points within one width examine N^2 / 2.
MAX_NEAR_PAIRS = 10**9


@functools.cache
def _cfmm2dpartself():
    """FMMLIB2D's Cauchy FMM ``cfmm2dpartself`` from pyfmmlib's compiled library, called through ctypes:
    unlike pyfmmlib's f2py wrappers, a ctypes call releases the interpreter's lock, so the FMM runs beside
    the compiled near field. (The Laplace routine ``lfmm2dpartself`` takes complex charges and runs this
    one twice, once for their imaginary part; with real masses once is enough.) Fortran arguments: every
    one by reference, integers of 4 bytes."""
    import pyfmmlib._internal  # here: the package loads without it until a large 2D Newtonian sum is asked for

    function = ctypes.CDLL(pyfmmlib._internal.__file__).cfmm2dpartself_
    integer = ctypes.POINTER(ctypes.c_int)
    real = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
    complex_ = np.ctypeslib.ndpointer(dtype=np.complex128, flags="C_CONTIGUOUS")
    # ier, iprec, nsource, source, ifcharge, charge, ifdipole, dipstr, ifpot, pot, ifgrad, grad, ifhess, hess
    function.argtypes = [integer, integer, integer, real, integer, complex_, integer, complex_, integer, complex_,
                         integer, complex_, integer, complex_]
    function.restype = None
    return function


def _points_and_masses(positions, masses):
    """``positions`` as finite float64 (N, 2) with N >= 2 and ``masses`` as finite float64 (N,), or a ValueError
    (ParameterTypeError) naming the parameter."""
    positions = np.ascontiguousarray(finite_array("positions", positions, ndim=2))
    masses = np.ascontiguousarray(finite_array("masses", masses))
    if positions.shape[1:] != (2,) or positions.shape[0] < 2:
        raise ValueError(f"positions must have shape (N, 2) with N >= 2, got {positions.shape}")
    same_length(positions=positions[:, 0], masses=masses)
    return positions, masses


def far_field(positions, masses) -> np.ndarray:
    """sum_{j != i} m_j (X_i - X_j) / |X_i - X_j|^2, shape (N, 2), by FMMLIB2D's FMM: with z = x + iy, the
    Cauchy sum g_i = sum_{j != i} m_j / (z_i - z_j) = sum_{j != i} m_j ((x_i - x_j) - i (y_i - y_j)) / r^2,
    so the field is (Re g, -Im g). ``positions`` (N >= 2, 2) and ``masses`` (N,) are finite; coincident
    points make the field infinite, which raises a ValueError."""
    positions, masses = _points_and_masses(positions, masses)
    n = masses.size
    ier, iprec, count, yes, no = (ctypes.c_int(value) for value in (0, FMM_PRECISION, n, 1, 0))
    gradient = np.zeros(n, dtype=np.complex128)
    unused = np.zeros(max(2 * n, 1), dtype=np.complex128)
    _cfmm2dpartself()(ctypes.byref(ier), ctypes.byref(iprec), ctypes.byref(count),
                      np.ascontiguousarray(positions, dtype=np.float64), ctypes.byref(yes),
                      masses.astype(np.complex128), ctypes.byref(no), unused, ctypes.byref(no), unused,
                      ctypes.byref(yes), gradient, ctypes.byref(no), unused)
    if ier.value != 0:
        raise RuntimeError(f"FMMLIB2D's cfmm2dpartself failed with error code {ier.value} (out of memory)")
    return finite_result("the far field", np.stack([gradient.real, -gradient.imag], axis=1),
                         "two positions coincide or the masses overflow")


@njit
def _cell_keys(x, y, side):
    """(key, column count) of each point's cell of the given side: key = row * columns + column (the
    caller bounds the span of the points to 2^25 widths of the mollifier, :func:`pair_sums._check_span`, so
    keys stay below 2^52)."""
    x0, y0 = x.min(), y.min()
    columns = int((x.max() - x0) / side) + 1
    keys = np.empty(x.size, dtype=np.int64)
    for i in range(x.size):
        keys[i] = int((y[i] - y0) / side) * columns + int((x[i] - x0) / side)
    return keys, columns


#: Cells of the near-field list are 1/CELL_SPLIT of the cut-off wide: a particle's partners j > i lie in its own
#: row of cells and the next CELL_SPLIT rows, within _REACH cells to either side (about 2.8 cut-off^2 of area
#: for 3, against pi cut-off^2 / 2 needed; 2 to 5 measured within 10 % of each other at 80,000 particles).
CELL_SPLIT = 3
#: Cells a partner can lie in, to either side, in the row d rows away: a cell d >= 2 rows away is at least
#: (d - 1) sides away, so columns beyond sqrt(CELL_SPLIT^2 - (d - 1)^2) sides hold no pair within the cut-off.
_REACH = np.array([CELL_SPLIT, CELL_SPLIT] + [int(np.ceil(np.sqrt(CELL_SPLIT**2 - (d - 1) ** 2)))
                                              for d in range(2, CELL_SPLIT + 1)], dtype=np.int64)
#: Particles are dealt to this many accumulators, round robin, whatever the number of threads.
ACCUMULATORS = 16
#: Partners are taken in chunks of this many (the buffers of a row's terms; longer rows take several).
_ROW_BUFFER = 4096


#: Most squarings of the widest Gaussian's exponential that stand for a narrower one (:func:`squarings`).
MAX_SQUARINGS = 4


def squarings(inverse) -> np.ndarray:
    """For the Gaussians' a_k = 1/s_k^2: s_k squarings when a_k = 2^{s_k} min(a) to rounding (s_k <= MAX_SQUARINGS),
    -1 when a_k is no such multiple. e^{-a_k r^2} is then (e^{-min(a) r^2})^(2^{s_k}): one exponential per pair for
    the widths (1, sqrt(2)) of (4.2), whose squares are 1 and 2 up to the rounding of sqrt(2)^2 (2 + 4.4e-16): the
    narrower Gaussian, taken as the wider's square, is exp(-r^2/s^2) for an s^2 within 2.2e-16 relative of the
    rounded width's: a relative error of r^2/s^2 x 2.2e-16, at most 1.9e-14 at the cut-off (r^2/s^2 = 84.5, where
    the term is e^{-84.5}), beside the 8e-16 of squaring an exponential correct to 4e-16. Also used by the direct
    sums (:func:`.pair_sums.newtonian_2d_forces`). It trusts its caller's checks (positive finite a_k)."""
    inverse = np.asarray(inverse, dtype=np.float64)
    ratios = inverse / inverse.min()
    powers = np.round(np.log2(ratios))
    exact = (powers <= MAX_SQUARINGS) & (np.abs(ratios - 2.0**powers) <= 8 * np.finfo(float).eps * ratios)
    return np.where(exact, powers, -1).astype(np.int64)


@njit
def _row_terms(xi, yi, x, y, masses, lo, hi, g_weights, l_weights, inverse, powers, cutoff2, partners, mj, wx, wy, wd,
               r2, base, e):
    """Partners lo <= j < hi of a particle at (xi, yi): those closer than the cut-off go, in order, to the first
    m places of the buffers (their indices to ``partners``, masses to ``mj``, r^2 to ``r2``), then
    sum_k g_k e^{-a_k r^2}/r^2 (X_i - X_j) into (wx, wy) and sum_k l_k e^{-a_k r^2} into wd; returns m. Only the
    partners within the cut-off (about 56 % of the examined ones) take exponentials; the loops after the first
    have no branches, so that LLVM vectorises them (base and e are buffers). A Gaussian with powers[k] = s >= 0
    (:func:`squarings`) takes the widest's exponential squared s times, one with -1 its own exponential."""
    m = 0
    for j in range(lo, hi):
        dx = xi - x[j]
        dy = yi - y[j]
        distance2 = dx * dx + dy * dy
        partners[m] = j
        r2[m] = distance2
        m += 1 if distance2 < cutoff2 else 0
    for j in range(m):
        mj[j] = masses[partners[j]]
        wx[j] = 0.0
        wd[j] = 0.0
    widest = inverse.min()
    if powers.max() >= 0:
        for j in range(m):
            base[j], _ = exp_minus_and_complement(r2[j] * widest)
    for k in range(inverse.size):
        a, g, lap = inverse[k], g_weights[k], l_weights[k]
        if powers[k] < 0:
            for j in range(m):
                e[j], _ = exp_minus_and_complement(r2[j] * a)
        else:
            for j in range(m):
                e[j] = base[j]
            for _ in range(powers[k]):
                for j in range(m):
                    e[j] *= e[j]
        for j in range(m):
            wx[j] += g * e[j]
            wd[j] += lap * e[j]
    for j in range(m):
        g = wx[j] / (r2[j] + 1e-300)  # finite for coincident points (which send the sums to the direct path)
        wx[j] = g * (xi - x[partners[j]])
        wy[j] = g * (yi - y[partners[j]])
    return m


@njit
def _near_accumulate(c, x, y, masses, keys, columns, g_weights, l_weights, inverse, powers, cutoff2, sums, closest):
    """Accumulator c: the particles i = c mod ACCUMULATORS (sorted by cell key) and their partners j > i in
    the cells of their own and the next CELL_SPLIT rows; each pair within the cut-off is evaluated once and
    added to both, into sums[c, :, :] (v_x, v_y, div of a particle side by side: one cache line a partner).
    closest[c] gets the smallest squared distance of these pairs."""
    n = x.size
    partners = np.empty(_ROW_BUFFER, dtype=np.int64)
    mj = np.empty(_ROW_BUFFER)
    wx = np.empty(_ROW_BUFFER)
    wy = np.empty(_ROW_BUFFER)
    wd = np.empty(_ROW_BUFFER)
    r2 = np.empty(_ROW_BUFFER)
    base = np.empty(_ROW_BUFFER)
    e = np.empty(_ROW_BUFFER)
    self_term = 0.0
    for k in range(l_weights.size):
        self_term += l_weights[k]
    for i in range(c, n, ACCUMULATORS):
        row, column = keys[i] // columns, keys[i] % columns
        mi = masses[i]
        sx = sy = sd = 0.0
        for r in range(row, row + CELL_SPLIT + 1):
            reach = _REACH[r - row]
            stop = np.searchsorted(keys, r * columns + min(column + reach, columns - 1), side="right")
            lo = i + 1 if r == row else np.searchsorted(keys, r * columns + max(column - reach, 0))
            for start in range(lo, stop, _ROW_BUFFER):
                m = _row_terms(x[i], y[i], x, y, masses, start, min(start + _ROW_BUFFER, stop), g_weights, l_weights,
                               inverse, powers, cutoff2, partners, mj, wx, wy, wd, r2, base, e)
                tx, ty, td = row_share(0, m, mj, wx, wy, wd)
                for j in range(m):
                    closest[c] = min(closest[c], r2[j])
                sx += tx
                sy += ty
                sd += td
                for j in range(m):
                    partner = partners[j]
                    sums[c, partner, 0] -= mi * wx[j]
                    sums[c, partner, 1] -= mi * wy[j]
                    sums[c, partner, 2] -= mi * wd[j]
        sums[c, i, 0] += sx
        sums[c, i, 1] += sy
        sums[c, i, 2] -= sd + mi * self_term


def near_sums(arguments, threads, beside=lambda: None):
    """Gaussian share of grad K_delta and the divergence, for the points sorted by cell key of ``arguments``
    (:func:`near_field`): v_i = sum_j m_j sum_k g_k e^{-a_k r^2}/r^2 (X_i - X_j),
    div_i = -sum_j m_j sum_k l_k e^{-a_k r^2} over the pairs with r^2 < cutoff2 (i = j included in div), each
    pair evaluated once, in ACCUMULATORS accumulators summed in a fixed order; also the smallest squared
    distance between two particles closer than the cut-off (inf when there is none). ``threads`` threads (this
    one and threads - 1 of a pool) take the accumulators one at a time as they come free; the first thread of
    the pool runs ``beside`` (the FMM) first, so that no core waits for the other half of the work. Each
    accumulator is summed by one thread in a fixed order: the same sums on any number of threads.
    Returns ((v_x, v_y, div, closest), beside's result). It trusts its caller's checks."""
    sums = np.zeros((ACCUMULATORS, arguments[0].size, 3))
    closest = np.full(ACCUMULATORS, np.inf)
    claimed = itertools.count()  # next() on it is atomic: each accumulator goes to one thread

    def work(task):
        result = task()
        c = next(claimed)
        while c < ACCUMULATORS:
            _near_accumulate(c, *arguments, sums, closest)  # compiled: releases the interpreter's lock
            c = next(claimed)
        return result

    if threads == 1:
        result = work(beside)
    else:
        helpers = [pool(threads - 1).submit(work, beside if k == 0 else (lambda: None)) for k in range(threads - 1)]
        work(lambda: None)
        result = [helper.result() for helper in helpers][0]
    total = sums[0].copy()
    for c in range(1, ACCUMULATORS):
        total += sums[c]
    return (total[:, 0], total[:, 1], total[:, 2], closest.min()), result


def _near_pair_count(keys, columns) -> int:
    """Pairs (i, j > i) :func:`_near_accumulate` examines, from the sorted cell keys: in each row of cells the
    partners of a particle are a range of keys, counted by two binary searches per particle and row."""
    rows, column = np.divmod(keys, columns)
    total = np.int64(0)
    for d, reach in enumerate(_REACH):
        row = (rows + d) * columns
        stop = np.searchsorted(keys, row + np.minimum(column + reach, columns - 1), side="right")
        start = np.arange(1, keys.size + 1) if d == 0 else np.searchsorted(keys, row + np.maximum(column - reach, 0))
        total += np.sum(stop - start)
    return int(total)


def near_field(positions, masses, coefficients, widths):
    """(order, pairs, arguments) of the near field of checked inputs: the points' order by cell key, the pairs
    :func:`_near_accumulate` examines (:func:`_near_pair_count`) and the arguments of :func:`near_sums`. It trusts
    its caller's checks (:func:`newtonian_sums` makes them)."""
    inverse = 1.0 / np.asarray(widths, dtype=np.float64) ** 2
    g_weights = np.asarray(coefficients, dtype=np.float64) / (2 * math.pi)
    l_weights = np.asarray(coefficients, dtype=np.float64) * inverse / math.pi
    cutoff = GAUSS_CUTOFF * float(np.max(widths))
    x, y = np.ascontiguousarray(positions[:, 0]), np.ascontiguousarray(positions[:, 1])
    keys, columns = _cell_keys(x, y, cutoff / CELL_SPLIT)
    order = np.argsort(keys, kind="stable")
    arguments = (x[order], y[order], masses[order], keys[order], columns, g_weights, l_weights, inverse,
                 squarings(inverse), cutoff * cutoff)
    return order, _near_pair_count(keys[order], columns), arguments


def newtonian_sums(positions, masses, coefficients, widths):
    """Velocities -sum_j m_j grad K(X_i - X_j) (N, 2) and divergences -sum_j m_j Delta K(X_i - X_j) of the
    2D Newtonian kernel: raw C log|x|/(2 pi) when ``widths`` is empty (``coefficients`` = (C,)), else the
    Gaussian terms (c_k, s_k) of its mollification (4.2). Inputs are checked by the caller
    (:func:`particle_methods.blob.pair_sums.pair_sums`) and again here: finite (N >= 2, 2) positions, finite
    masses, positive widths, a spread of at most 2^25 widths.

    With two threads or more (and :data:`PARALLEL_MIN_PARTICLES` particles), the FMM runs on one thread
    while the near field's accumulators go to the others, and to the FMM's thread once it is done (the near
    field took 0.9 to 1.2 times the FMM's CPU time from 2 * 10^4 to 10^6 points on Figure 5's grids).

    Returns None when two particles are closer than :data:`CLOSE_FRACTION` times the narrowest width: the
    raw field of the pair, m/(2 pi r), and its Gaussian correction then cancel to a few digits, and the
    caller takes the direct sums, which compute 1 - e^{-r^2/s^2} without cancellation."""
    positions, masses = _points_and_masses(positions, masses)
    coefficients, widths = finite_array("coefficients", coefficients), finite_array("widths", widths)
    if widths.size and (coefficients.size != widths.size or np.any(widths <= 0)):
        raise ValueError("widths must be positive, one for each of the coefficients")
    if widths.size and np.ptp(positions, axis=0).max() > 2.0**25 * widths.min():
        raise ValueError("positions spread over more than 2^25 widths of the mollifier (the cell list's keys)")
    total = float(np.sum(coefficients))
    if widths.size == 0:
        velocity = finite_result("the velocities", (-total / (2 * math.pi)) * far_field(positions, masses),
                                 "the masses or coefficients are too large")
        return velocity, np.zeros(masses.size)
    order, pairs, arguments = near_field(positions, masses, coefficients, widths)
    if pairs > MAX_NEAR_PAIRS:
        raise ValueError(f"positions put {pairs:.3g} pairs in the near field of widths up to {np.max(widths):.3g} "
                         f"(about N^2 / 2 when the N points lie within a few widths), more than MAX_NEAR_PAIRS = "
                         f"{MAX_NEAR_PAIRS:.0e}: the Gaussian terms would be summed over every one")
    threads = numba.get_num_threads() if masses.size >= PARALLEL_MIN_PARTICLES else 1
    (vx, vy, div, closest), field = near_sums(arguments, threads, lambda: far_field(positions, masses))
    if math.sqrt(closest) < CLOSE_FRACTION * float(np.min(widths)):
        return None
    velocity = (-total / (2 * math.pi)) * field
    velocity[order, 0] += vx
    velocity[order, 1] += vy
    divergence = np.empty(masses.size)
    divergence[order] = div
    cause = "the masses or coefficients are too large, or the widths too small"
    return finite_result("the velocities", velocity, cause), finite_result("the divergences", divergence, cause)
