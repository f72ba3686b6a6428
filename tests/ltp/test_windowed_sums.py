"""rho_h and F_h by the windowed prefix sums of ltp/kernels.py against a brute-force sum over every particle."""

import numpy as np
import pytest
from numpy.polynomial import Polynomial

from particle_methods.ltp.kernels import PARALLEL_MIN_TARGETS, convolutions, cumulative_mass_at, density_at
from particle_methods.ltp.shapes import shape_named

#: Agreement asked of the windowed sums: 1e-13 times the total mass, absolute.
TOLERANCE = 1e-13
#: The widest particle: 50 times the widest of the others, whose widths vary by a factor 10.
WIDEST = 123


def shape_matrices(points, centres, widths, shape):
    """phi(s) and Phi(s) = int_{-r}^s phi at s = (t_i - x_k)/h_k, (points, particles), from the breaks and cubic
    pieces with numpy.polynomial: phi on the piece holding s (closed on the left, as the pieces meet continuously),
    0 outside (-r, r); Phi the sum over the pieces of the exact antiderivative from the piece's left end."""
    s = (points[:, None] - centres[None, :]) / widths[None, :]
    breaks, pieces = shape.breaks, shape.coefficients
    piece = np.clip(np.searchsorted(breaks, s, side="right") - 1, 0, len(pieces) - 1)
    phi = np.zeros_like(s)
    cdf = np.zeros_like(s)
    for j, coefficients in enumerate(pieces):
        polynomial = Polynomial(coefficients)
        on_piece = (piece == j) & (s > breaks[0]) & (s < breaks[-1])
        phi[on_piece] = polynomial(s[on_piece])
        cdf += polynomial.integ(lbnd=breaks[j])(np.clip(s, breaks[j], breaks[j + 1]))
    return phi, cdf


def brute_force(points, centres, weights, widths, shape):
    """(F_h, rho_h) at the points, summed over every particle."""
    phi, cdf = shape_matrices(points, centres, widths, shape)
    return cdf @ weights, (phi / widths) @ weights


def windowed(points, centres, weights, widths, shape, reach):
    """The windowed sums in NumPy, with a given window: F_h = the weights of the particles whose support ends at or
    left of t, plus omega_k Phi over the particles within ``reach`` of t whose support does not; rho_h over the
    particles within ``reach``. With reach = r max h_k this is the algorithm of ltp/kernels.py."""
    phi, cdf = shape_matrices(points, centres, widths, shape)
    done = centres[None, :] + shape.radius * widths[None, :] <= points[:, None]
    near = np.abs(points[:, None] - centres[None, :]) <= reach
    return (done + (near & ~done) * cdf) @ weights, (near * phi / widths) @ weights


def assert_close(got, expected, mass, what=""):
    gap = np.abs(got - expected).max()
    assert gap <= TOLERANCE * mass, f"{what}: max gap {gap:.3g} exceeds {TOLERANCE:g} x total mass {mass:.3g}"


def particles(seed, n=400):
    """Unsorted centres in [-1, 1], widths from 0.005 to 0.05 and one particle (WIDEST) 50 times the widest of
    them, unequal weights."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-1.0, 1.0, n)
    widths = 0.005 * 10 ** rng.uniform(0.0, 1.0, n)
    widths[WIDEST] = 50 * widths.max()
    weights = rng.uniform(0.5, 2.0, n) / n
    return centres, weights, widths


def points_for(seed, centres, widths, shape):
    """Random points among the particles and far outside every support (both sides), the centres and the
    right and left ends of every support."""
    rng = np.random.default_rng(seed + 1)
    outer = shape.radius * widths.max() + 1.0
    return np.concatenate([rng.uniform(-1.2, 1.2, 1500), rng.uniform(-outer - 1.0, outer + 1.0, 300), centres,
                           centres + shape.radius * widths, centres - shape.radius * widths, [-outer, outer]])


@pytest.fixture(params=["hat", "b3"])
def case(request):
    shape = shape_named(request.param)
    seed = {"hat": 1, "b3": 2}[request.param]
    centres, weights, widths = particles(seed)
    points = points_for(seed, centres, widths, shape)
    return shape, points, centres, weights, widths


def test_density_and_cumulative_mass_match_the_brute_force(case):
    shape, points, centres, weights, widths = case
    assert np.any(np.diff(centres) < 0)  # unsorted
    mass = weights.sum()
    cumulative, density = brute_force(points, centres, weights, widths, shape)
    arrays = (centres, weights, widths, shape.breaks, shape.coefficients)
    got_density, got_cumulative = density_at(points, *arrays), cumulative_mass_at(points, *arrays)
    assert_close(got_density, density, mass, "rho_h")
    assert_close(got_cumulative, cumulative, mass, "F_h")
    # outside every support: rho_h = 0, F_h = 0 on the left and the total mass on the right
    left = points < np.min(centres - shape.radius * widths)
    right = points > np.max(centres + shape.radius * widths)
    assert left.sum() > 10 and right.sum() > 10
    assert not got_density[left | right].any() and not got_cumulative[left].any()
    np.testing.assert_allclose(got_cumulative[right], mass, rtol=0, atol=TOLERANCE * mass)
    order = np.argsort(points)
    assert np.all(np.diff(got_cumulative[order]) >= -TOLERANCE * mass)  # non-decreasing (positive weights)


def test_every_point_alone_gets_the_same_bits(case):
    """Few points (one thread) and many (all threads) give each point the same value."""
    shape, points, centres, weights, widths = case
    arrays = (centres, weights, widths, shape.breaks, shape.coefficients)
    assert points.size >= PARALLEL_MIN_TARGETS > 50
    np.testing.assert_array_equal(density_at(points[::40], *arrays), density_at(points, *arrays)[::40])
    np.testing.assert_array_equal(cumulative_mass_at(points[::40], *arrays), cumulative_mass_at(points, *arrays)[::40])


@pytest.mark.parametrize("c", [0.5, -1.25])
def test_newtonian_term_of_convolutions_is_the_cumulative_mass_and_the_density(case, c):
    """W = c|x|: W' * rho_h = c (2 F_h - M) and W'' * rho_h = 2 c rho_h."""
    shape, points, centres, weights, widths = case
    mass = weights.sum()
    cumulative, density = brute_force(points, centres, weights, widths, shape)
    first, second = convolutions(points, centres, weights, widths, [c], [1.0], shape.breaks, shape.coefficients)
    assert_close(first, c * (2 * cumulative - mass), abs(c) * mass, "W' * rho_h")
    assert_close(second, 2 * c * density, abs(c) * mass, "W'' * rho_h")


def test_newtonian_term_adds_to_the_other_terms(case):
    """A potential with a = 1, 2 and 3 terms: the sum of its terms taken one by one (the a = 1 term's F_h and
    rho_h are not mixed with the pair sums of the others)."""
    shape, points, centres, weights, widths = case
    points = points[::20]
    arrays = (centres, weights, widths)
    pieces = (shape.breaks, shape.coefficients)
    coefficients, exponents = [0.5, -0.3, 0.2], [1.0, 2.0, 3.0]
    first, second = convolutions(points, *arrays, coefficients, exponents, *pieces)
    terms = [convolutions(points, *arrays, [c], [a], *pieces) for c, a in zip(coefficients, exponents)]
    np.testing.assert_allclose(first, sum(t[0] for t in terms), rtol=0, atol=1e-14 * np.abs(first).max())
    np.testing.assert_allclose(second, sum(t[1] for t in terms), rtol=0, atol=1e-14 * np.abs(second).max())


def test_a_window_that_ignores_the_widest_particle_is_rejected(case):
    """The check above would catch a window as wide as the ordinary particles only: the widest particle's share
    would be lost wherever its centre lies outside that window (most of its support). The NumPy model of the
    windowed sums passes with the full window r max h_k and fails with the narrow one; so does the brute force
    with the widest particle removed."""
    shape, points, centres, weights, widths = case
    mass = weights.sum()
    cumulative, density = brute_force(points, centres, weights, widths, shape)
    full = shape.radius * widths.max()
    narrow = shape.radius * np.delete(widths, WIDEST).max()
    assert full == 50 * narrow
    model_cumulative, model_density = windowed(points, centres, weights, widths, shape, full)
    assert_close(model_cumulative, cumulative, mass, "F_h")
    assert_close(model_density, density, mass, "rho_h")
    narrow_cumulative, narrow_density = windowed(points, centres, weights, widths, shape, narrow)
    with pytest.raises(AssertionError, match="exceeds"):
        assert_close(narrow_cumulative, cumulative, mass, "F_h")
    with pytest.raises(AssertionError, match="exceeds"):
        assert_close(narrow_density, density, mass, "rho_h")
    removed = [np.delete(a, WIDEST) for a in (centres, weights, widths)]
    without_cumulative, without_density = brute_force(points, *removed, shape)
    with pytest.raises(AssertionError, match="exceeds"):
        assert_close(without_cumulative, cumulative, mass, "F_h")
    with pytest.raises(AssertionError, match="exceeds"):
        assert_close(without_density, density, mass, "rho_h")
    # the widest particle's share is large, far beyond rounding
    assert np.abs(narrow_density - density).max() > 1e-3 * weights[WIDEST] / widths[WIDEST]
