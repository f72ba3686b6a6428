"""The compiled pair sums of the blob and particle methods over the kernels of :mod:`.kernels`.

v_i = -sum_j m_j grad K(X_i - X_j) and div_i = -sum_j m_j Delta K(X_i - X_j), written once for any
dimension (each pair evaluated once, dealt to 16 fixed accumulators, so the sums are bit-identical on
any number of threads); in 1D through :mod:`.sums_1d` where its windowed sums apply; in 2D through
vectorised row tiles for the mollified kernels of section 4.4, and through the fast multipole method
(:mod:`.newtonian_fmm`) for the Newtonian kernel from a measured number of particles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import prange

from ..jit import njit, njit_threaded
from ..threads import threads_for
from ..validation import finite_array, finite_result, finite_values, integer_at_least, one_of, same_length
from . import newtonian_fmm, sums_1d
from .kernels import (
    EXP,
    GAUSS_LOG_2D,
    KIND_DIMENSIONS,
    LOG,
    POWER,
    TABLE,
    TABLE_REACH,
    is_newtonian_2d,
    profile_forces_kernel,
    profile_potential_kernel,
    radial_power,
)
from .tile_sums import row_share
from .vector_exp import Z_LIMIT, exp_minus_and_complement

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
def newtonian_2d_forces(xi, yi, x, y, start, stop, constants, wx, wy, lap):
    """Row i of the 2D Newtonian kernel: grad K(X_i - X_j) (as wx, wy) and Delta K(X_i - X_j) for
    start <= j < stop, into the tile buffers. Mollified (m = 4, two Gaussians (4.2)) when the first
    constant is 1 or 2, raw log|x|/(2 pi) (the particle method, Delta K = 0 away from 0) when it is 0. With 2,
    a0 = 2 a1 to rounding (:func:`.newtonian_fmm.squarings`; (4.2)'s widths 1 and sqrt(2)): the narrower
    Gaussian's e^{-a0 r^2} is the square e^2 of the wider's, and its complement 1 - e^2 = (1 - e)(1 + e), one
    exponential per pair and no cancellation (the absolute error of either, r^2 a0 x 2.2e-16 x e^{-a0 r^2}, stays
    below 1e-16). No branch inside the loops, so LLVM vectorises them; at r = 0 (coincident particles) the
    gradient is finite and irrelevant (it multiplies X_i - X_j = 0), so grad K(0) := 0 holds. It trusts its
    caller's checks."""
    mollified, c0, c1, a0, a1, l0, l1 = constants
    # One loop per case: a test inside the loop, even of this invariant flag, kept LLVM from vectorising it (the
    # loop took twice as long, measured).
    if mollified == 2.0:
        for j in range(start, stop):
            dx = xi - x[j]
            dy = yi - y[j]
            r2 = dx * dx + dy * dy
            e1, f1 = exp_minus_and_complement(r2 * a1)
            e0 = e1 * e1
            f0 = f1 * (1.0 + e1)
            g = (c0 * f0 + c1 * f1) / (r2 + 1e-300)
            wx[j - start] = g * dx
            wy[j - start] = g * dy
            lap[j - start] = l0 * e0 + l1 * e1
    elif mollified == 1.0:
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


def newtonian_2d_constants(coefficients, widths) -> tuple:
    """The constants (flag, c0, c1, a0, a1, l0, l1) of :func:`newtonian_2d_forces` for the mollified Newtonian
    kernel's two Gaussian terms (coefficients C_k, widths s_k, (4.2)): c_k = C_k/(2 pi), a_k = 1/s_k^2,
    l_k = C_k a_k/pi, the narrower Gaussian first (each sum of the two terms is the same either way round), the
    flag 2 when a0 = 2 a1 to rounding (one exponential a pair), else 1. It trusts its caller's checks."""
    inverse = 1.0 / widths**2
    order = [0, 1] if inverse[0] >= inverse[1] else [1, 0]
    c, a = coefficients[order], inverse[order]
    flag = 2.0 if list(newtonian_fmm.squarings(a)) == [1, 0] else 1.0
    return (flag, *(c / (2 * math.pi)), *a, *(c * a / math.pi))


@njit
def _terms_2d_forces(xi, yi, x, y, start, stop, kinds, coefficients, parameters, tables, steps, wx, wy, lap, buffer):
    """Row i of a 2D kernel made of even powers below the mollifier's order (polynomials, Remark 3.4),
    Gaussian log terms and tabulated terms, or of the raw powers, log and exponential terms of the
    particle method (:func:`tiled_2d_supported`): grad K and Delta K for start <= j < stop, term by
    term, each in a loop without branches but selects (the table lookups, gathers from an argument
    array, stay scalar; the clamps of :func:`_table_forces` are written exactly: a - (a - b + |a - b|)/2
    is a itself for a <= b). Raw terms give (0, 0) at r = 0, as :func:`.kernels.profile_forces_kernel`."""
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
            elif a == 4.0:  # g = r^2, Delta = 4 r^2
                for j in range(count):
                    wx[j] += c * buffer[j]
                    lap[j] += 4.0 * c * buffer[j]
            else:  # raw |x|^a/a (particle method): g = r^(a-2), Delta = a r^(a-2); (0, 0) at r = 0
                b = a - 2.0
                for j in range(count):
                    r2 = buffer[j]
                    power = radial_power(math.sqrt(r2), b) if r2 > 0.0 else 0.0
                    wx[j] += c * power
                    lap[j] += c * a * power
        elif kinds[t] == LOG:  # raw log|x|/(2 pi): g = 1/(2 pi r^2), Delta = 0 away from 0; (0, 0) at r = 0
            g0 = c / (2 * math.pi)
            for j in range(count):
                r2 = buffer[j]
                wx[j] += g0 / r2 if r2 > 0.0 else 0.0
        elif kinds[t] == EXP:  # raw e^{-r/lambda}: g = -e/(lambda r), Delta = e/lambda^2 - e/(lambda r); (0, 0) at 0
            lam = parameters[t]
            inverse = 1.0 / lam
            for j in range(count):
                r2 = buffer[j]
                r = math.sqrt(r2)
                e, _ = exp_minus_and_complement(r * inverse)
                over_r = c * e * inverse / r if r2 > 0.0 else 0.0
                wx[j] -= over_r
                lap[j] += c * e * inverse * inverse - over_r if r2 > 0.0 else 0.0
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
    Newtonian kernel (:func:`newtonian_2d_forces`, ``constants``) when ``terms`` has no kind, else the
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
                newtonian_2d_forces(x[i], y[i], x, y, start, stop, constants, wx, wy, lap)
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




def tiled_2d_supported(kinds) -> bool:
    """Whether a 2D kernel's terms are all of the kinds the tiled path takes: powers, Gaussian log terms
    and tables (the mollified kernels of section 4.4 other than the Newtonian one), raw log and
    exponential terms (the particle method on them). A predicate on the kinds :func:`pair_sums` has checked:
    it trusts its caller's checks."""
    return all(kind in (TABLE, GAUSS_LOG_2D, POWER, LOG, EXP) for kind in kinds)


def _check_span(positions, widths, lengths=()):
    """The vectorised exponential takes |X_i - X_j|^2 / s^2 (``widths`` s of Gaussian terms) and
    |X_i - X_j| / lambda (``lengths`` lambda of exponential terms) up to :data:`Z_LIMIT`."""
    span2 = np.ptp(positions[:, 0]) ** 2 + np.ptp(positions[:, 1]) ** 2
    if len(widths) and span2 / np.min(widths) ** 2 > Z_LIMIT:
        raise ValueError(f"positions spread over {np.sqrt(span2):.3g}, more than {np.sqrt(Z_LIMIT):.3g} "
                         f"widths {np.min(widths):.3g} of the mollifier: beyond the vectorised exponential's range")
    if len(lengths) and np.sqrt(span2) / np.min(lengths) > Z_LIMIT:
        raise ValueError(f"positions spread over {np.sqrt(span2):.3g}, more than {Z_LIMIT:.3g} decay lengths "
                         f"{np.min(lengths):.3g} of the kernel: beyond the vectorised exponential's range")


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
        constants = newtonian_2d_constants(coefficients, widths)
        self_lap = constants[5] + constants[6]
    return _tiled_2d_sums(positions, masses, constants, _NO_TERMS, self_lap)


#: How :func:`pair_sums` takes the 2D Newtonian kernel's sums.
NEWTONIAN_2D_METHODS = {"auto": "the fast multipole method from FMM_MIN_PARTICLES(_RAW) particles on, else direct",
                        "fmm": "the fast multipole method (direct below 2 particles and with coincident or nearly "
                               "coincident points)",
                        "direct": "the direct tiled sums"}


def checked_terms(dimension, kinds, coefficients, parameters, tables, steps):
    """The arrays of :meth:`.kernels.Kernel.arrays` as the compiled sums take them (int64 kinds, float64 the
    others), after the checks of :class:`.kernels.Kernel` (known kinds of this dimension, positive widths, powers
    and lengths, TABLE parameters indexing a row of ``tables``) and of the tables (rows (2, M >= 2) of finite
    values, one positive step each): a ValueError (ParameterTypeError) naming the array otherwise. A run checks its
    kernel's terms once (:func:`.solver.integrate_particles`) and sums them at every right-hand side with
    :func:`checked_pair_sums`."""
    dimension = integer_at_least("dimension", dimension, 1, 3)
    kind_values = finite_array("kinds", kinds)
    coefficients, parameters = finite_array("coefficients", coefficients), finite_array("parameters", parameters)
    if same_length(kinds=kind_values, coefficients=coefficients, parameters=parameters) == 0:
        raise ValueError("kinds: a kernel needs at least one term")
    kind_list = kind_values.tolist()  # a few terms: Python's loop is faster than numpy's calls here
    if not all(kind in KIND_DIMENSIONS and dimension in KIND_DIMENSIONS[kind] for kind in kind_list):
        raise ValueError(f"kinds must be term kinds written for dimension {dimension}, got {kind_values}")
    tables, steps = finite_values("tables", tables), finite_array("steps", steps)
    if tables.ndim != 3 or tables.shape[1:2] != (2,) or tables.shape[2] < 2 or steps.shape != tables.shape[:1]:
        raise ValueError(f"tables must have shape (rows, 2, M >= 2) and steps (rows,), got {tables.shape} and "
                         f"{steps.shape}")
    if steps.min() <= 0:
        raise ValueError("steps must be positive")
    for kind, parameter in zip(kind_list, parameters.tolist()):
        if kind == TABLE and parameter not in range(tables.shape[0]):
            raise ValueError(f"parameters: a TABLE term's parameter must index one of the {tables.shape[0]} tables")
        if kind not in (TABLE, LOG) and parameter <= 0:
            raise ValueError("parameters: the widths, powers and lengths of the terms must be positive")
    return kind_values.astype(np.int64), coefficients, parameters, np.ascontiguousarray(tables), steps


def pair_sums(positions, masses, kinds, coefficients, parameters, tables, steps, newtonian_2d="auto"):
    """Velocities -sum_j m_j grad K(X_i - X_j) (shape (N, d)) and divergences -sum_j m_j Delta K(X_i - X_j).

    grad K is odd and Delta K even, so each pair i < j is evaluated once and added to both rows,
    half the kernel evaluations of the plain double loop. Accumulator c takes the rows i = c mod 16
    and their partners; the accumulators are then summed in a fixed order, on one thread below
    :data:`PARALLEL_MIN_PARTICLES` particles and on all of them above (the same sums either way).
    The 2D Newtonian kernel, raw or mollified by (4.2), takes a vectorised path with the same
    accumulators (:func:`_newtonian_2d_sums`, exponentials from :mod:`.vector_exp`), or the fast multipole
    method (:mod:`.newtonian_fmm`), as ``newtonian_2d`` says (:data:`NEWTONIAN_2D_METHODS`).
    The arrays are those of :meth:`Kernel.arrays`; they, ``positions`` (N, d) and ``masses`` (N,) are checked
    here, and so are the sums (a ValueError if they overflow).
    """
    one_of("newtonian_2d", newtonian_2d, NEWTONIAN_2D_METHODS)
    positions = np.ascontiguousarray(finite_array("positions", positions, ndim=2))
    masses = np.ascontiguousarray(finite_array("masses", masses))
    if masses.shape != positions.shape[:1] or not 1 <= positions.shape[1] <= 3:
        raise ValueError(f"positions must have shape (N, d), d <= 3, and masses (N,), got {positions.shape} and "
                         f"{masses.shape}")
    terms = checked_terms(positions.shape[1], kinds, coefficients, parameters, tables, steps)
    velocity, divergence = checked_pair_sums(positions, masses, *terms, newtonian_2d)
    cause = "the positions, masses, coefficients or parameters are too large (or the widths too small)"
    return finite_result("the velocities", velocity, cause), finite_result("the divergences", divergence, cause)


def checked_pair_sums(positions, masses, kinds, coefficients, parameters, tables, steps, newtonian_2d):
    """The sums of :func:`pair_sums` for contiguous float64 ``positions`` (N, d) and ``masses`` (N,) and the terms
    of :func:`checked_terms`: it trusts its caller's checks (and leaves the sums' finiteness to its caller)."""
    if positions.shape[1] == 2 and is_newtonian_2d(kinds):
        return _newtonian_2d_sums(positions, masses, kinds, coefficients, parameters, newtonian_2d)
    if np.any(kinds == TABLE) and np.ptp(positions, axis=0).max() > TABLE_REACH * steps.min():
        raise ValueError("positions spread over more than 2^40 steps of the kernel's radial table")
    if positions.shape[1] == 2 and tiled_2d_supported(kinds):
        _check_span(positions, parameters[kinds == GAUSS_LOG_2D], parameters[kinds == EXP])
        _, self_lap = profile_forces_kernel(kinds, coefficients, parameters, 0.0, 2, tables, steps)
        return _tiled_2d_sums(positions, masses, (0.0,) * 7, (kinds, coefficients, parameters, tables, steps),
                              self_lap)
    if positions.shape[1] == 1 and sums_1d.supported(kinds, parameters):
        with _threads_for(positions.shape[0]):
            return sums_1d.pair_sums_1d(positions, masses, kinds, coefficients, parameters)
    if positions.shape[1] == 1 and sums_1d.log_supported(kinds):
        with _threads_for(positions.shape[0]):
            return sums_1d.log_pair_sums_1d(positions, masses, kinds, coefficients, parameters, tables, steps)
    with _threads_for(positions.shape[0]):
        return generic_sums_kernel(positions, masses, kinds, coefficients, parameters, tables, steps)


def generic_sums_kernel(positions, masses, kinds, coefficients, parameters, tables, steps):
    """The generic loop of every kernel, for arrays checked by the caller (:func:`pair_sums`): each pair
    i < j once through :func:`~.kernels.profile_forces_kernel` (a branch per term kind, scalar
    special functions), dealt to the 16 accumulators and summed in a fixed order. The path of the
    build before issue 14 for every kernel: the reference the vectorised paths are tested and
    benchmarked against."""
    return _reduce(*_accumulators_parallel(positions, masses, kinds, coefficients, parameters, tables, steps))


@njit_threaded
def pair_energy(positions, masses, kinds, coefficients, parameters, tables, steps):
    """E_delta = 1/2 sum_{i,j} K(X_i - X_j) m_i m_j, (2.4) on the particle system (2.3). Compiled, for the arrays
    of a checked run and kernel (:meth:`.solver.BlobRun.energies` checks the result): it trusts its caller's checks."""
    n, dimension = positions.shape
    partial = np.zeros(n)
    for i in prange(n):
        total = 0.0
        for j in range(n):
            r2 = 0.0
            for axis in range(dimension):
                d = positions[i, axis] - positions[j, axis]
                r2 += d * d
            k = profile_potential_kernel(kinds, coefficients, parameters, math.sqrt(r2))
            total += masses[j] * k
        partial[i] = masses[i] * total
    return 0.5 * partial.sum()
