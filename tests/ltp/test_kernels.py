"""Convolutions of singular and smooth kernels with the particle shapes, against quadrature."""

import numpy as np
import pytest
from scipy import integrate

from particle_methods.ltp import B3, HAT, potential
from particle_methods.ltp.kernels import convolutions, density_at, far_series, shape_moments, takes_pair_sums


def power_integral(phi, lo, hi, t, p):
    """int_lo^hi phi(y) |t - y|^p dy. Where the singular point t is an end of a piece,
    QUADPACK's algebraic weight (x - lo)^p or (hi - x)^p integrates it exactly."""
    if lo < t < hi:
        return power_integral(phi, lo, t, t, p) + power_integral(phi, t, hi, t, p)
    if hi == t:
        return integrate.quad(phi, lo, hi, weight="alg", wvar=(0.0, p), epsabs=1e-15)[0]
    if lo == t:
        return integrate.quad(phi, lo, hi, weight="alg", wvar=(p, 0.0), epsabs=1e-15)[0]
    return integrate.quad(lambda y: phi(y) * abs(t - y) ** p, lo, hi, epsabs=1e-15, epsrel=1e-13)[0]


def reference(potential_, shape, centres, weights, widths, t):
    """W'*rho_h and W''*rho_h at t by adaptive quadrature on each polynomial piece."""
    first = second = 0.0
    for xk, wk, hk in zip(centres, weights, widths):
        knots = xk + hk * shape.breaks

        def phi(y, xk=xk, hk=hk):
            return float(shape((y - xk) / hk)) / hk

        for lo, hi in zip(knots[:-1], knots[1:]):
            for c, a in zip(potential_.coefficients, potential_.exponents):
                # W' = c sign(z)|z|^(a-1): split where sign(t - y) changes.
                left = power_integral(phi, lo, min(hi, t), t, a - 1) if lo < t else 0.0
                right = power_integral(phi, max(lo, t), hi, t, a - 1) if hi > t else 0.0
                first += wk * c * (left - right)
                second += wk * c * (a - 1) * power_integral(phi, lo, hi, t, a - 2)
    return first, second


def assert_matches_quadrature(w, shape, centres, weights, widths, targets, rel, tolerance):
    """W' * rho_h and W'' * rho_h at every target within ``rel`` = (relative for W', for W'') and the absolute
    ``tolerance`` of :func:`reference`'s adaptive quadrature."""
    coefficients, exponents = w.as_arrays()
    first, second = convolutions(targets, centres, weights, widths, coefficients, exponents, shape.breaks,
                                 shape.coefficients)
    for i, t in enumerate(targets):
        expected_first, expected_second = reference(w, shape, centres, weights, widths, t)
        assert first[i] == pytest.approx(expected_first, rel=rel[0], abs=tolerance)
        assert second[i] == pytest.approx(expected_second, rel=rel[1], abs=tolerance)


CENTRES = np.array([-0.4, 0.0, 0.013, 0.5])
WEIGHTS = np.array([0.2, 0.3, 0.1, 0.4])
WIDTHS = np.array([0.05, 0.01, 0.004, 0.2])
TARGETS = np.array([-0.4, -0.37, 0.0, 0.006, 0.013, 0.05, 0.5, 0.93, 1.7])


@pytest.mark.parametrize("shape", [HAT, B3], ids=lambda s: s.name)
@pytest.mark.parametrize(
    "w",
    [potential("power", a=1.5), potential("attractive_repulsive", a=3, b=1.1), potential("attractive_repulsive",
                                                                                         a=4, b=2.5),
     potential("quadratic")],
    ids=lambda w: w.name,
)
def test_convolutions_match_independent_quadrature(shape, w):
    assert_matches_quadrature(w, shape, CENTRES, WEIGHTS, WIDTHS, TARGETS, rel=(1e-9, 1e-8), tolerance=1e-12)


def test_density_matches_the_sum_of_shapes():
    x = np.linspace(-1, 1, 301)
    expected = sum(w * B3((x - c) / h) / h for c, w, h in zip(CENTRES, WEIGHTS, WIDTHS))
    np.testing.assert_allclose(density_at(x, CENTRES, WEIGHTS, WIDTHS, B3.breaks, B3.coefficients), expected,
                               atol=1e-12)


@pytest.mark.parametrize("shape", [HAT, B3], ids=lambda s: s.name)
@pytest.mark.parametrize("a", [1.2, 1.5, 2.5, 3.5])
def test_far_particles_by_the_binomial_series_match_a_fine_gauss_rule(shape, a):
    """Particles 12 piece lengths or more from every target take the binomial series of the module
    docstring; against 30 Gauss nodes per piece (exact to rounding so far from z = 0) the sums agree to
    1e-12 relative (the 3- and 4-node rules it replaced were off by up to 1.5e-11 here)."""
    rng = np.random.default_rng(2)
    h, n = 0.01, 200
    centres = np.sort(rng.uniform(-1, 1, n))
    weights = rng.uniform(0.5, 1.5, n) * h
    widths = h * rng.uniform(0.5, 3, n)
    targets = np.concatenate([np.linspace(-2.1, -1.2, 50), np.linspace(1.2, 2.1, 50)])
    first, second = convolutions(targets, centres, weights, widths, np.array([1.0]), np.array([a]), shape.breaks,
                                 shape.coefficients)
    nodes, gauss_weights = np.polynomial.legendre.leggauss(30)
    expected_first, expected_second = np.zeros(targets.size), np.zeros(targets.size)
    for lo, hi, c in zip(shape.breaks[:-1], shape.breaks[1:], shape.coefficients):
        s = 0.5 * (hi + lo) + 0.5 * (hi - lo) * nodes
        phi = 0.5 * (hi - lo) * gauss_weights * (c[0] + s * (c[1] + s * (c[2] + s * c[3])))
        z = targets[:, None, None] - centres[None, :, None] - widths[None, :, None] * s
        expected_first += np.sum(weights[:, None] * phi * np.sign(z) * np.abs(z) ** (a - 1), axis=(1, 2))
        expected_second += (a - 1) * np.sum(weights[:, None] * phi * np.abs(z) ** (a - 2), axis=(1, 2))
    assert np.max(np.abs(first - expected_first)) <= 1e-12 * np.max(np.abs(expected_first))
    assert np.max(np.abs(second - expected_second)) <= 1e-12 * np.max(np.abs(expected_second))


def test_far_series_holds_the_binomial_coefficients_times_the_moments():
    """far_series(a, mu)[term, row, m] = binom(q, m) mu_m with q = a - 1 (row 0) and a - 2 (row 1): the
    coefficients the pair sums evaluate by Horner's rule, against scipy's binomial coefficients."""
    from scipy.special import binom

    moments = shape_moments(B3.breaks, B3.coefficients)
    exponents = np.array([1.5, 2.5, 4.0])
    series = far_series(exponents, moments)
    m = np.arange(moments.size)
    for term, a in enumerate(exponents):
        np.testing.assert_allclose(series[term, 0], binom(a - 1.0, m) * moments, rtol=1e-13, atol=0)
        np.testing.assert_allclose(series[term, 1], binom(a - 2.0, m) * moments, rtol=1e-13, atol=0)


@pytest.mark.parametrize("shape, a", [(B3, 3.0), (B3, 4.0), (B3, 5.0), (HAT, 3.0), (HAT, 6.0)],
                         ids=lambda v: getattr(v, "name", v))
def test_integer_exponents_by_moments_match_quadrature_among_overlapping_particles(shape, a):
    """Integer 3 <= a <= POLYNOMIAL_MAX_EXPONENT take the moments of rho_h (odd a: prefix sums, the particles
    holding the target piece by piece): on 30 particles of widths 0.02 to 0.3 (many supports overlap) both
    convolutions agree with adaptive quadrature at targets inside supports, at their edges and at centres."""
    rng = np.random.default_rng(5)
    centres = np.sort(rng.uniform(-1.0, 1.0, 30))
    weights = rng.uniform(0.5, 1.5, 30) / 30
    widths = rng.uniform(0.02, 0.3, 30)
    edges = np.concatenate([centres[[5, 20]] + shape.radius * widths[[5, 20]],
                            centres[[9]] - shape.radius * widths[[9]]])
    targets = np.concatenate([rng.uniform(-1.5, 1.5, 6), centres[[3, 17]], edges])
    assert_matches_quadrature(potential("power", a=a), shape, centres, weights, widths, targets, rel=(1e-10, 1e-10),
                              tolerance=1e-13)


@pytest.mark.parametrize("a", [3.0, 4.0, 5.0])
def test_integer_exponents_on_a_grid_where_supports_end_at_the_targets(a):
    """On the grid x_k = k h with widths h, every support of B3 ends at a target (x_k +- 2h): the moments path
    (prefix sums for odd a) classifies those particles as the prefix sums were sorted and agrees with the pair
    sums of a = a + 1e-12 (which differ from it by about 1e-12 relative) at every centre."""
    h = 0.05
    centres = h * np.arange(-20, 21)
    weights = np.exp(-(centres**2)) * h
    widths = np.full(centres.size, h)
    exact = convolutions(centres, centres, weights, widths, np.array([1.0]), np.array([a]), B3.breaks,
                         B3.coefficients)
    nearby = convolutions(centres, centres, weights, widths, np.array([1.0]), np.array([a + 1e-12]), B3.breaks,
                          B3.coefficients)
    for value, pairs in zip(exact, nearby):
        np.testing.assert_allclose(value, pairs, rtol=0, atol=1e-10 * np.abs(pairs).max())


def test_which_potentials_take_pair_sums():
    """The work limit of simulate counts N^2 pairs per step only for these (tests/ltp/test_ltp_safety.py)."""
    assert not takes_pair_sums([1.0]) and not takes_pair_sums([2.0]) and not takes_pair_sums([3.0, 4.0, 6.0])
    assert takes_pair_sums([3.0, 2.5]) and takes_pair_sums([1.5]) and takes_pair_sums([7.0])


def test_far_series_and_takes_pair_sums_check_their_arrays():
    """Census (issue 46): far_series allocated (terms, 2, moments) for any input (a zero-stride array of 10**9
    moments asked for 16 GB) and returned inf for huge exponents; both functions now refuse by name."""
    from particle_methods.ltp.checks import MAX_TERMS
    from particle_methods.ltp.kernels import FAR_MOMENTS

    moments = np.array([1.0, 0.0, 1 / 3])
    with pytest.raises(ValueError, match="moments has 1000000000 entries"):
        far_series([1.5], np.broadcast_to(1.0, (10**9,)))
    with pytest.raises(ValueError, match="the number of moments must be at most"):
        far_series([1.5], np.ones(FAR_MOMENTS + 1))
    with pytest.raises(ValueError, match="exponents or moments are too large"):
        far_series([1e300], moments)
    with pytest.raises(ValueError, match="exponents contains NaN"):
        far_series([np.nan], moments)
    with pytest.raises(TypeError, match="exponents must be an array"):
        takes_pair_sums(None)
    with pytest.raises(ValueError, match="the number of exponents .* must be at most"):
        takes_pair_sums(np.full(MAX_TERMS + 1, 1.5))


def test_the_kernels_name_the_pieces_and_the_arguments_that_overflow():
    """Census (issue 46): the kernels called their ``pieces`` 'coefficients' in their messages, and an overflow
    named no argument; now the message names the pieces, and the overflowing arguments among its candidates."""
    x, weights, widths = np.array([-1.0, 0.0, 1.0]), np.array([0.2, 0.3, 0.5]), np.full(3, 0.5)
    with pytest.raises(TypeError, match="pieces must be an array"):
        density_at(x, x, weights, widths, B3.breaks, None)
    with pytest.raises(ValueError, match="rho_h is not finite: .*the widths"):
        density_at(x, x, weights, np.full(3, 5e-324), B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="the moments of the shape is not finite: breaks or pieces too large"):
        convolutions(x, x, weights, widths, [1.0], [1.5], B3.breaks * 1e300, B3.coefficients)
