"""Compiled kernels of the LTP and SP methods: convolutions W'*rho_h, W''*rho_h, rho_h and its CDF.

rho_h = sum_k omega_k phi((x - x_k)/h_k)/h_k (2.27) with phi piecewise cubic, so

    (K * phi_k)(t) = int K(t - x_k - h_k s) phi(s) ds = sum over pieces j of int_j K(d - h_k s) P_j(s) ds

with d = t - x_k. Each term of W is a power, K = c sign(z)|z|^{a-1} for W' and
K = c (a-1)|z|^{a-2} for W'' (singular at 0 when a < 2). On a piece that contains
or lies near z = 0, the substitution z = d - h_k s turns P_j into a cubic in z and
z^m |z|^p has the exact antiderivative z^m |z|^{p+1}/(m+p+1) (times sign(z) for the
even kernel), so the singularity is integrated exactly. On a piece whose distance to
z = 0 exceeds NEAR times its length, K is analytic over the piece and a Gauss-Legendre
rule is used instead, where the monomial expansion would cancel badly. Its error decays
like rho^(-2n) with rho ~ 2 D / L the Bernstein-ellipse parameter (D the distance from
the piece's middle to the singularity, L its half-length): 6 nodes beyond 4 lengths,
4 beyond 12 and 3 beyond 40 keep every piece below about 1e-13 relative error. A particle whose
whole support lies beyond EXPANSION = 12 piece lengths from t takes one series instead of its pieces:
with u = |d|, sigma = sign(d) and mu_m = int s^m phi(s) ds the moments of the shape (support [-r, r]),

    int |d - h_k s|^q phi(s) ds = u^q sum_m binom(q, m) (-sigma h_k / u)^m mu_m,

a binomial series whose terms are at most |binom(q, m)| (r h_k / u)^m <= (r / (12 + r))^m (phi >= 0, so
|mu_m| <= r^m): the FAR_MOMENTS = 16 terms (m = 0..15) leave about 3e-14 relative for the cubic
B-spline (r = 2), with one power per pair instead of one per Gauss node (2 to 4 times faster).
Terms with a = 2 need no pair sums: (c z) * rho_h and c * rho_h are moments. Nor do the other integer
exponents 3 <= a <= POLYNOMIAL_MAX_EXPONENT: sign(z)|z|^{a-1} and |z|^{a-2} are the polynomials z^{a-1} and
z^{a-2} for z > 0 and (-1)^a times them for z < 0. Written around the centre of mass c0, with t' = t - c0
and E_k[y^l] = int phi(s) (x_k - c0 + h_k s)^l ds (binomial in the shape's moments mu_i), a particle
whose support lies left of t contributes sum_l binom(n, l) t'^{n-l} (-1)^l omega_k E_k[y^l] (n = a - 1,
a - 2), one right of t (-1)^a times that: for even a the sum over all particles (the moments of rho_h,
O(N) once, O(1) per target), for odd a twice the sum over the particles left of t (prefix sums over the
sorted right edges) minus the total, with the few particles whose support holds t integrated piece by
piece instead (as above).
Terms with a = 1, W = c|x| (the Newtonian potential in 1D), have W' = c sign(z) and the
distributional W'' = 2c delta, so both convolutions are exact without piece integrals:
(W' * rho_h)(t) = c (2 F_h(t) - M) with M = sum_k omega_k and F_h(t) = sum_k omega_k Phi((t - x_k)/h_k)
the cumulative mass (Phi the CDF of phi, exact on each cubic piece), and (W'' * rho_h)(t) = 2c rho_h(t).
F_h and rho_h take a prefix sum and the particles whose support holds the point, O(N log N) in all
rather than a sum over pairs.

The public :func:`convolutions`, :func:`density_at` and :func:`cumulative_mass_at` check every
array before the compiled loops read it (unchecked, they would read past mismatched arrays) and
check that the results are finite.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numba import prange

from ..jit import njit, njit_threaded
from ..threads import threads_for
from ..validation import finite_array, finite_result, integer_at_least
from .checks import exponent_array, particle_arrays, piece_arrays, power_arrays

NEAR = 4.0
#: (distance in piece lengths, number of Gauss-Legendre nodes), farthest first.
GAUSS_TIERS = ((40.0, 3), (12.0, 4), (NEAR, 6))
_RULES = [np.polynomial.legendre.leggauss(points) for _, points in GAUSS_TIERS]
_FAR, _MIDDLE = GAUSS_TIERS[0][0], GAUSS_TIERS[1][0]
#: A particle whose support lies beyond this many piece lengths from the target takes the binomial series.
EXPANSION = _MIDDLE
#: Integer exponents 3 <= a <= this take the moments of rho_h instead of pair sums (module docstring);
#: higher powers of t' would cancel more in the expansion.
POLYNOMIAL_MAX_EXPONENT = 6
#: Terms of the binomial series (moments m = 0 .. FAR_MOMENTS - 1 of the shape).
FAR_MOMENTS = 16
_NO_MOMENTS = np.zeros(FAR_MOMENTS)  # for sums without power terms, which never read them
_NODES_FAR, _WEIGHTS_FAR = _RULES[0]
_NODES_MIDDLE, _WEIGHTS_MIDDLE = _RULES[1]
_NODES_NEAR, _WEIGHTS_NEAR = _RULES[2]


@njit
def _power(magnitude, exponent):
    """magnitude ** exponent, with the exponents of section 6 that need no pow call."""
    if exponent == 1.0:
        return magnitude
    if exponent == 2.0:
        return magnitude * magnitude
    if exponent == 0.5:
        return np.sqrt(magnitude)
    if exponent == -0.5:
        return 1.0 / np.sqrt(magnitude)
    return magnitude**exponent


@njit
def _compose(coefficients, alpha, beta, out):
    """Coefficients of P(alpha + beta z) in powers of z, for P cubic (Horner on polynomials)."""
    out[:] = 0.0
    out[0] = coefficients[3]
    for m in range(2, -1, -1):
        # out <- out * (alpha + beta z) + coefficients[m]
        for j in range(3, 0, -1):
            out[j] = out[j] * alpha + out[j - 1] * beta
        out[0] = out[0] * alpha + coefficients[m]


@njit
def _piece_exact(d, width, lo, hi, coefficients, a, buffer):
    """Exact int_lo^hi of sign(z)|z|^{a-1} P(s) and |z|^{a-2} P(s) ds, z = d - width s."""
    _compose(coefficients, d / width, -1.0 / width, buffer)
    first = 0.0
    second = 0.0
    for end, sign_of_end in ((d - width * lo, 1.0), (d - width * hi, -1.0)):
        magnitude = abs(end)
        if magnitude == 0.0:
            continue
        power = _power(magnitude, a - 1.0)  # |z|^{a-1}
        zm = 1.0
        for m in range(4):
            first += sign_of_end * buffer[m] * zm * power * magnitude / (m + a)
            second += sign_of_end * buffer[m] * zm * np.sign(end) * power / (m + a - 1.0)
            zm *= end
    return first / width, second / width


@njit
def _piece_gauss(d, width, lo, hi, coefficients, a, nodes, weights):
    """Gauss-Legendre int_lo^hi of the same two integrands, for a piece far from z = 0."""
    half = 0.5 * (hi - lo)
    middle = 0.5 * (hi + lo)
    first = 0.0
    second = 0.0
    for g in range(nodes.size):
        s = middle + half * nodes[g]
        shape = coefficients[0] + s * (coefficients[1] + s * (coefficients[2] + s * coefficients[3]))
        z = d - width * s
        magnitude = abs(z)
        power = _power(magnitude, a - 2.0)
        first += weights[g] * shape * np.sign(z) * power * magnitude
        second += weights[g] * shape * power
    return first * half, second * half


@njit
def _particle_far(d, width, a, series, term):
    """int sign(z)|z|^{a-1} phi(s) ds and int |z|^{a-2} phi(s) ds, z = d - width s, for a particle whose
    support lies far from z = 0: the binomial series of the module docstring, its coefficients
    binom(q, m) mu_m precomputed for the term (:func:`far_series`), summed by Horner's rule in the
    ratio -sigma width / u: no division per pair and moment (the binomial coefficients' quotients,
    recomputed for every pair, took half of the time of the pair sums)."""
    u = abs(d)
    sigma = 1.0 if d > 0.0 else -1.0
    ratio = -sigma * width / u
    s1 = 0.0
    s2 = 0.0
    for m in range(series.shape[2] - 1, -1, -1):
        s1 = s1 * ratio + series[term, 0, m]
        s2 = s2 * ratio + series[term, 1, m]
    power = _power(u, a - 2.0)
    return sigma * power * u * s1, power * s2


def far_series(exponents, moments) -> np.ndarray:
    """Coefficients binom(a - 1, m) mu_m and binom(a - 2, m) mu_m of the binomial series of the module
    docstring for every power term (exponent a) and moment mu_m, shape (terms, 2, moments): those of
    int |z|^{a-1} sign(z) phi and int |z|^{a-2} phi, computed once per call instead of once per pair.
    Exponents of a potential (at least 1, :func:`.checks.power_arrays`), 1 to FAR_MOMENTS finite moments."""
    exponents = exponent_array(exponents)
    moments = finite_array("moments", moments)
    integer_at_least("the number of moments", moments.size, 1, FAR_MOMENTS)
    m = np.arange(moments.size)
    series = np.empty((exponents.size, 2, moments.size))
    for term, a in enumerate(exponents):
        for row, q in enumerate((a - 1.0, a - 2.0)):
            ratios = np.concatenate([[1.0], (q - m[:-1]) / (m[:-1] + 1.0)])
            with np.errstate(over="ignore", invalid="ignore"):  # huge exponents: refused just below
                series[term, row] = np.cumprod(ratios) * moments
    return finite_result("the far series", series, "the exponents or moments are too large for double precision")


def shape_moments(breaks, pieces, count: int = FAR_MOMENTS) -> np.ndarray:
    """mu_m = int s^m phi(s) ds for m < count, exact piece by piece (arrays already checked); computed once
    per shape (the time loops ask for them at every step). It trusts its caller's checks."""
    breaks, pieces = np.asarray(breaks, dtype=np.float64), np.asarray(pieces, dtype=np.float64)
    return _moments(breaks.tobytes(), pieces.tobytes(), pieces.shape, count).copy()


@functools.lru_cache(maxsize=64)
def _moments(breaks, pieces, shape, count):
    breaks, pieces = np.frombuffer(breaks), np.frombuffer(pieces).reshape(shape)
    m = np.arange(count)[:, None] + np.arange(4)[None, :] + 1.0  # powers of s after integration
    lo, hi = breaks[:-1, None, None], breaks[1:, None, None]
    return np.sum(pieces[:, None, :] * (hi**m - lo**m) / m, axis=(0, 2))


@njit
def _shape_value(s, breaks, pieces):
    """phi(s) of the piecewise cubic shape, 0 outside the open support (-r, r)."""
    if s <= breaks[0] or s >= breaks[-1]:
        return 0.0
    j = 0
    while j < pieces.shape[0] - 1 and s >= breaks[j + 1]:
        j += 1
    c = pieces[j]
    return c[0] + s * (c[1] + s * (c[2] + s * c[3]))


@njit
def _shape_cdf(s, breaks, pieces):
    """Phi(s) = int_{-r}^s phi: 0 left of the support, 1 right of it, exact antiderivatives of the cubic
    pieces in between."""
    if s <= breaks[0]:
        return 0.0
    if s >= breaks[-1]:
        return 1.0
    total = 0.0
    for j in range(pieces.shape[0]):
        lo = breaks[j]
        if s <= lo:
            break
        hi = min(s, breaks[j + 1])
        c = pieces[j]
        total += (hi * (c[0] + hi * (c[1] / 2.0 + hi * (c[2] / 3.0 + hi * c[3] / 4.0)))
                  - lo * (c[0] + lo * (c[1] / 2.0 + lo * (c[2] / 3.0 + lo * c[3] / 4.0))))
    return total


@njit(inline="always")
def _particle_pieces(d, width, a, breaks, pieces, buffer):
    """int sign(z)|z|^{a-1} phi(s) ds and int |z|^{a-2} phi(s) ds, z = d - width s, piece by piece: the
    exact antiderivatives on pieces near z = 0, Gauss-Legendre rules (GAUSS_TIERS) on the others."""
    pair_first = 0.0
    pair_second = 0.0
    for j in range(pieces.shape[0]):
        lo = breaks[j]
        hi = breaks[j + 1]
        z_far = d - width * lo
        z_near = d - width * hi
        length = width * (hi - lo)
        distance = max(z_near, -z_far)
        if distance > _FAR * length:
            p1, p2 = _piece_gauss(d, width, lo, hi, pieces[j], a, _NODES_FAR, _WEIGHTS_FAR)
        elif distance > _MIDDLE * length:
            p1, p2 = _piece_gauss(d, width, lo, hi, pieces[j], a, _NODES_MIDDLE, _WEIGHTS_MIDDLE)
        elif distance > NEAR * length:
            p1, p2 = _piece_gauss(d, width, lo, hi, pieces[j], a, _NODES_NEAR, _WEIGHTS_NEAR)
        else:
            p1, p2 = _piece_exact(d, width, lo, hi, pieces[j], a, buffer)
        pair_first += p1
        pair_second += p2
    return pair_first, pair_second


@njit
def _expanded_power(t, moments, n):
    """sum_l binom(n, l) t^{n-l} (-1)^l moments[l]: the sum of E[(t - y)^n] over the particles whose
    moments moments[l] = sum omega_k E_k[y^l] are given."""
    total = 0.0
    binomial = 1.0
    for power in range(n + 1):
        term = binomial * moments[power] * t ** (n - power)
        total += -term if power % 2 else term
        binomial = binomial * (n - power) / (power + 1.0)
    return total


@njit
def _is_polynomial(a):
    """Whether the term with exponent a takes the moments of rho_h (an integer 3 <= a <= POLYNOMIAL_MAX_EXPONENT)."""
    return 3.0 <= a <= POLYNOMIAL_MAX_EXPONENT and a == np.floor(a)


@njit_threaded
def _convolutions(targets, centres, weights, widths, coefficients, exponents, breaks, pieces, series, cumulative,
                  density, polynomial):
    """(W' * rho_h)(t_i) and (W'' * rho_h)(t_i) at every target t_i; the terms with a = 1 from F_h and rho_h
    at the targets (``cumulative``, ``density``, computed once by :func:`_cumulative_and_density`), those
    with integer 3 <= a <= POLYNOMIAL_MAX_EXPONENT from the moments of :func:`_polynomial_moments`
    (``polynomial``)."""
    origin, rows, totals, prefix, right_edges, left_counts, window_starts, window_stops, order = polynomial
    first = np.zeros(targets.size)
    second = np.zeros(targets.size)
    total_mass = 0.0
    first_moment = 0.0
    for k in range(centres.size):
        total_mass += weights[k]
        first_moment += weights[k] * centres[k]
    longest = 0.0
    for j in range(pieces.shape[0]):
        longest = max(longest, breaks[j + 1] - breaks[j])
    for i in prange(targets.size):
        buffer = np.empty(4)
        f = 0.0
        s2 = 0.0
        for term in range(exponents.size):
            c = coefficients[term]
            a = exponents[term]
            if a == 2.0:
                # W' = c z and W'' = c: moments of rho_h (each phi_k has unit mass and mean x_k).
                f += c * (targets[i] * total_mass - first_moment)
                s2 += c * total_mass
                continue
            if a == 1.0:
                # W' = c sign(z) and W'' = 2c delta: the cumulative mass F_h and rho_h itself, no piece integrals.
                f += c * (2.0 * cumulative[i] - total_mass)
                s2 += 2.0 * c * density[i]
                continue
            term_first = 0.0
            term_second = 0.0
            if _is_polynomial(a):
                n = int(a) - 1
                shifted = targets[i] - origin
                term_first = _expanded_power(shifted, totals, n)
                term_second = _expanded_power(shifted, totals, n - 1)
                if n % 2 == 0:  # odd a: the particles right of t enter with the sign flipped
                    left = prefix[left_counts[i]]
                    term_first = 2.0 * _expanded_power(shifted, left, n) - term_first
                    term_second = 2.0 * _expanded_power(shifted, left, n - 1) - term_second
                    for m in range(window_starts[i], window_stops[i]):
                        k = order[m]
                        d = targets[i] - centres[k]
                        if right_edges[k] > targets[i] and d > widths[k] * breaks[0]:
                            # t inside the support (the test of the prefix sums: counted right of t): exact instead
                            p1, p2 = _particle_pieces(d, widths[k], a, breaks, pieces, buffer)
                            term_first += weights[k] * p1 + _expanded_power(shifted, rows[k], n)
                            term_second += weights[k] * p2 + _expanded_power(shifted, rows[k], n - 1)
                f += c * term_first
                s2 += c * (a - 1.0) * term_second
                continue
            for k in range(centres.size):
                d = targets[i] - centres[k]
                width = widths[k]
                if max(d - width * breaks[-1], width * breaks[0] - d) > EXPANSION * width * longest:
                    p1, p2 = _particle_far(d, width, a, series, term)
                    term_first += weights[k] * p1
                    term_second += weights[k] * p2
                    continue
                p1, p2 = _particle_pieces(d, width, a, breaks, pieces, buffer)
                term_first += weights[k] * p1
                term_second += weights[k] * p2
            f += c * term_first
            s2 += c * (a - 1.0) * term_second
        first[i] = f
        second[i] = s2
    return first, second


def _polynomial_moments(targets, centres, weights, widths, breaks, moments, count, odd):
    """What :func:`_convolutions` needs for its terms with integer 3 <= a <= POLYNOMIAL_MAX_EXPONENT (module
    docstring), ``count`` the largest such a: the centre of mass c0; every particle's omega_k E_k[y^l], (N, L),
    and their sums over all particles, (L,), for l < L = count. If a term has an ``odd`` exponent, also their
    prefix sums over the particles sorted by right edge x_k + h_k r, (N + 1, L); the right edges (the kernel
    tests a particle against t with the very numbers the prefix sums were sorted by: a support ending at t
    counts left of t in both); for every target the number of right edges at or left of it and the window
    [start, stop) of the centres sorted by ``order`` within r max h_k of it, where every support holding the
    target lies (else empty arrays). NumPy sorts and searches here: compiled, they would cost every cold
    process their compilation."""
    origin = float(np.dot(weights, centres) / weights.sum())
    shifted = centres - origin
    rows = np.zeros((centres.size, count))
    for power in range(count):
        for i in range(power + 1):
            rows[:, power] += math.comb(power, i) * moments[i] * shifted ** (power - i) * widths**i
    rows *= weights[:, None]
    totals = rows.sum(axis=0)
    if not odd:
        none = np.zeros(0, dtype=np.int64)
        return origin, rows, totals, np.zeros((0, count)), np.zeros(0), none, none, none, none
    right = centres + breaks[-1] * widths
    by_right = np.argsort(right, kind="stable")
    prefix = np.concatenate([np.zeros((1, count)), np.cumsum(rows[by_right], axis=0)])
    order = np.argsort(centres, kind="stable")
    reach = max(breaks[-1], -breaks[0]) * widths.max()
    sorted_centres = centres[order]
    return (origin, rows, totals, prefix, right, np.searchsorted(right[by_right], targets, side="right"),
            np.searchsorted(sorted_centres, targets - reach), np.searchsorted(sorted_centres, targets + reach,
                                                                             side="right"), order)


@njit
def _prefix_by_right_edge(weights, by_right):
    """Prefix sums of the weights in the order ``by_right`` of the particles' right edges,
    Neumaier-compensated."""
    prefix = np.zeros(weights.size + 1)
    total = 0.0
    compensation = 0.0
    for m in range(weights.size):
        w = weights[by_right[m]]
        t = total + w
        compensation += (total - t) + w if abs(total) >= abs(w) else (w - t) + total
        total = t
        prefix[m + 1] = total + compensation
    return prefix


@njit_threaded
def _cumulative_and_density(points, centres, weights, widths, breaks, pieces, order, by_right):
    """(F_h, rho_h) at every point, (2.27) and its integral, in O((N + P) log N + P w) for w particles
    within the widest support of a point. F_h(t) = sum over particles whose support ends left of t (a
    prefix sum over the sorted right edges) + sum_k omega_k Phi((t - x_k)/h_k) over the particles whose
    support contains t, all of them among the centres within r max h_k of t. ``order`` sorts the centres,
    ``by_right`` the right edges x_k + r h_k (:func:`_cumulative_and_density_of`)."""
    right = centres + breaks[-1] * widths
    right_sorted = right[by_right]
    prefix = _prefix_by_right_edge(weights, by_right)
    reach = breaks[-1] * widths.max()
    sorted_centres = centres[order]
    cumulative = np.zeros(points.size)
    density = np.zeros(points.size)
    for i in prange(points.size):
        t = points[i]
        total = prefix[np.searchsorted(right_sorted, t, side="right")]
        value = 0.0
        for m in range(np.searchsorted(sorted_centres, t - reach), np.searchsorted(sorted_centres, t + reach,
                                                                                    side="right")):
            k = order[m]
            if right[k] > t:  # the others are in the prefix sum
                s = (t - centres[k]) / widths[k]
                total += weights[k] * _shape_cdf(s, breaks, pieces)
                shape = _shape_value(s, breaks, pieces)
                if shape != 0.0:
                    value += weights[k] * shape / widths[k]
        cumulative[i] = total
        density[i] = value
    return cumulative, density


#: Below this many targets the compiled loops run on one thread (:func:`particle_methods.threads.threads_for`;
#: measured by benchmarks/bench_threads.py: alone, two threads pay from about 200 targets; with a second
#: process on the other core they lose up to 800 (1.4x slower at 400) and break even near 1600).
PARALLEL_MIN_TARGETS = 1000


def _cumulative_and_density_of(points, centres, weights, widths, breaks, pieces):
    """:func:`_cumulative_and_density`, the particles sorted by NumPy (a sort compiled by numba costs
    about 3 s of compilation in every cold process)."""
    order = np.argsort(centres, kind="stable")
    by_right = np.argsort(centres + breaks[-1] * widths, kind="stable")
    return _cumulative_and_density(points, centres, weights, widths, breaks, pieces, order, by_right)


@functools.lru_cache(maxsize=64)
def _term_needs(exponents: bytes) -> tuple[bool, int, bool]:
    """For the exponents of a potential's terms: whether a term takes pair sums, the largest exponent that
    takes the moments of rho_h (0 if none; :func:`_is_polynomial`) and whether one of those is odd."""
    exponents = np.frombuffer(exponents)
    polynomial = [a for a in exponents if 3.0 <= a <= POLYNOMIAL_MAX_EXPONENT and a == math.floor(a)]
    pairs = any(a not in (1.0, 2.0) and a not in polynomial for a in exponents)
    return pairs, int(max(polynomial, default=0)), any(a % 2 == 1 for a in polynomial)


def takes_pair_sums(exponents) -> bool:
    """Whether a potential with these exponents needs the O(N^2) pair sums (an exponent other than 1, 2 and
    the integers 3 <= a <= POLYNOMIAL_MAX_EXPONENT, which :func:`convolution_sums` takes in O(N log N))."""
    return _term_needs(exponent_array(exponents).tobytes())[0]


@functools.lru_cache(maxsize=64)
def _cached_far_series(exponents: bytes, moments: bytes) -> np.ndarray:
    """:func:`far_series`, computed once per potential and shape (the time loops ask at every step)."""
    return far_series(np.frombuffer(exponents), np.frombuffer(moments))


_NO_SERIES = np.zeros((0, 2, FAR_MOMENTS))  # for potentials without pair sums, which never read it
_NO_POLYNOMIAL = (0.0, np.zeros((0, 1)), np.zeros(1), np.zeros((0, 1)), np.zeros(0),
                  *(np.zeros(0, dtype=np.int64),) * 4)


def convolution_sums(targets, centres, weights, widths, coefficients, exponents, breaks, pieces):
    """(W' * rho_h)(t_i) and (W'' * rho_h)(t_i) for arrays already checked (by :func:`convolutions`, or
    once before the time loop of :func:`particle_methods.ltp.solver.simulate`, which checks every step's
    results): the terms with a = 1 from F_h and rho_h (:func:`_cumulative_and_density`), those with an
    integer 3 <= a <= POLYNOMIAL_MAX_EXPONENT from the moments of rho_h (:func:`_polynomial_moments`), the
    others by the pair sums of :func:`_convolutions`. It trusts its caller's checks."""
    pairs, largest, odd = _term_needs(exponents.tobytes())
    with threads_for(targets.size, PARALLEL_MIN_TARGETS):
        if np.any(exponents == 1.0):
            cumulative, density = _cumulative_and_density_of(targets, centres, weights, widths, breaks, pieces)
        else:
            cumulative = density = targets
        moments = shape_moments(breaks, pieces) if pairs or largest else _NO_MOMENTS
        series = _cached_far_series(exponents.tobytes(), moments.tobytes()) if pairs else _NO_SERIES
        polynomial = (_polynomial_moments(targets, centres, weights, widths, breaks, moments, largest, odd)
                      if largest else _NO_POLYNOMIAL)
        return _convolutions(targets, centres, weights, widths, coefficients, exponents, breaks, pieces, series,
                             cumulative, density, polynomial)


OVERFLOW = "overflow: the particles are too narrow or too far from the points for double precision"
#: The same, naming the arguments of the public kernels below that enter the sums.
ARGUMENTS_OVERFLOW = ("overflow beyond double precision: the weights, the centres, the widths (too narrow or too "
                      "wide), the shape's breaks and pieces{}")


def convolutions(targets, centres, weights, widths, coefficients, exponents, breaks, pieces):
    """(W' * rho_h)(t_i) and (W'' * rho_h)(t_i) at every target t_i, the velocity and Jacobian of (2.31)
    (for a term c|x|, a = 1, W'' * rho_h is the convolution with the Dirac mass 2c delta)."""
    targets = np.ascontiguousarray(finite_array("targets", targets))
    centres, weights, widths = particle_arrays(centres, weights, widths)
    coefficients, exponents = power_arrays(coefficients, exponents)
    breaks, pieces = piece_arrays(breaks, pieces, name="pieces")
    with np.errstate(over="ignore", invalid="ignore"):
        finite_result("the moments of the shape", shape_moments(breaks, pieces), "breaks or pieces too large")
    cause = ARGUMENTS_OVERFLOW.format(" or the potential's coefficients and exponents are too large")
    with np.errstate(over="ignore", invalid="ignore"):
        first, second = convolution_sums(targets, centres, weights, widths, coefficients, exponents, breaks, pieces)
    return finite_result("W' * rho_h", first, cause), finite_result("W'' * rho_h", second, cause)


def density_at(points, centres, weights, widths, breaks, pieces):
    """rho_h(points) of (2.27) = sum_k omega_k phi((x - x_k)/h_k)/h_k."""
    points = np.ascontiguousarray(finite_array("points", points))
    centres, weights, widths = particle_arrays(centres, weights, widths)
    breaks, pieces = piece_arrays(breaks, pieces, name="pieces")
    with threads_for(points.size, PARALLEL_MIN_TARGETS):
        _, density = _cumulative_and_density_of(points, centres, weights, widths, breaks, pieces)
    return finite_result("rho_h", density, ARGUMENTS_OVERFLOW.format(" are too large"))


def cumulative_mass_at(points, centres, weights, widths, breaks, pieces):
    """F_h(points) = int_{-inf}^x rho_h = sum_k omega_k Phi((x - x_k)/h_k), the cumulative mass of (2.27)
    (Phi the CDF of the shape): 0 left of every particle, the total mass sum_k omega_k right of them."""
    points = np.ascontiguousarray(finite_array("points", points))
    centres, weights, widths = particle_arrays(centres, weights, widths)
    breaks, pieces = piece_arrays(breaks, pieces, name="pieces")
    with threads_for(points.size, PARALLEL_MIN_TARGETS):
        cumulative, _ = _cumulative_and_density_of(points, centres, weights, widths, breaks, pieces)
    return finite_result("F_h", cumulative, ARGUMENTS_OVERFLOW.format(" are too large"))
