"""Measures with exact quantiles, discretisations (2.1) and (1.9), exact W1 distances."""

import numpy as np
import pytest
from scipy import integrate, stats

from particle_methods.norms import w1_between_samples, w1_to_measure
from particle_methods.sticky.cases import cells_distance, cells_quantile
from particle_methods.sticky.measures import (
    Atoms,
    Laplace,
    Pareto,
    TruncatedExponential,
    Uniform,
    Weibull,
    averaged_quantiles,
    median_quantiles,
)

MEASURES = [Uniform(-1, 2), TruncatedExponential(1.0), Laplace(0.3), Pareto(3.0), Weibull(0.5), Weibull(2.0),
            Atoms([-1.0, 1.0])]


@pytest.mark.parametrize("measure", MEASURES, ids=lambda m: type(m).__name__)
def test_quantile_integral_is_antiderivative_of_quantile(measure):
    for w in (0.1, 0.5, 0.77, 0.999):
        expected = integrate.quad(lambda s: float(measure.quantile(s)), 0, w, limit=200, points=[0.5])[0]
        assert float(measure.quantile_integral(w)) == pytest.approx(expected, abs=1e-8)


@pytest.mark.parametrize("measure", MEASURES[:-1], ids=lambda m: type(m).__name__)
def test_cdf_inverts_quantile(measure):
    w = np.linspace(0.01, 0.99, 50)
    np.testing.assert_allclose(measure.cdf(measure.quantile(w)), w, atol=1e-12)


def test_atoms_cdf_and_pseudo_inverse():
    m = Atoms([-1.0, 1.0])
    np.testing.assert_array_equal(m.cdf([-2.0, -1.0, 0.0, 1.0]), [0.0, 0.5, 0.5, 1.0])
    # (1.5): F^{-1}(v) = inf{x : F(x) >= v}, so F^{-1}(1/2) = -1.
    np.testing.assert_array_equal(m.quantile([0.25, 0.5, 0.5 + 1e-12, 1.0]), [-1.0, -1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="sum to 1"):
        Atoms([0.0, 1.0], [0.5, 0.6])
    with pytest.raises(ValueError, match="sorted"):
        Atoms([1.0, 0.0])


def test_discretisations_of_uniform_law():
    n = 5
    k = np.arange(1, n + 1)
    np.testing.assert_allclose(median_quantiles(Uniform(0, 1), n), (2 * k - 1) / (2 * n))
    # (1.9) averages F^{-1} over [(2k-1)/(2(n+1)), (2k+1)/(2(n+1))]: midpoint k/(n+1) for a linear quantile.
    np.testing.assert_allclose(averaged_quantiles(Uniform(0, 1), n), k / (n + 1))
    assert np.all(averaged_quantiles(Atoms([0.0]), 7) == 0.0)


def test_w1_to_measure_matches_brute_force_integration(rng):
    measure = Laplace(0.0)
    points = np.sort(rng.normal(size=40))
    grid = np.linspace(-40, 40, 2_000_001)
    empirical = np.searchsorted(points, grid, side="right") / points.size
    brute = np.trapezoid(np.abs(measure.cdf(grid) - empirical), grid)
    assert w1_to_measure(measure, points) == pytest.approx(brute, abs=1e-6)


def test_w1_between_samples_matches_scipy(rng):
    x = np.sort(rng.normal(size=37))
    y = np.sort(rng.normal(0.5, 2.0, size=64))
    assert w1_between_samples(x, y) == pytest.approx(stats.wasserstein_distance(x, y), rel=1e-12)
    assert w1_between_samples(x, x) == 0.0


def test_lemma_21_uniform_and_two_atoms_are_exact():
    for n in (1, 2, 7, 100):
        # Uniform on [a, b]: every cell contributes (b - a)/(4 n^2), so n W1 = (b - a)/4 exactly.
        assert n * w1_to_measure(Uniform(0, 3), median_quantiles(Uniform(0, 3), n)) == pytest.approx(0.75)
    two_atoms = Atoms([-1.0, 1.0])
    for n in (2, 10):
        assert w1_to_measure(two_atoms, median_quantiles(two_atoms, n)) == pytest.approx(0.0, abs=1e-15)
    for n in (1, 3, 11):  # odd n attains the bound (b - a)/(2n) of Lemma 2.1 (iii)
        assert w1_to_measure(two_atoms, median_quantiles(two_atoms, n)) == pytest.approx(1.0 / n)


def test_median_quantiles_minimise_w1(rng):
    measure = Weibull(1.0)
    best = w1_to_measure(measure, median_quantiles(measure, 20))
    for _ in range(20):
        shifted = np.sort(median_quantiles(measure, 20) + rng.normal(scale=0.01, size=20))
        assert w1_to_measure(measure, shifted) >= best - 1e-15


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: Uniform(1.0, 1.0), "b must exceed a"),
        (lambda: Pareto(1.0), "alpha must exceed 1"),
        (lambda: Weibull(-1.0), "alpha must be positive"),
        (lambda: Laplace(np.nan), "loc must be finite"),
        (lambda: median_quantiles(Uniform(), 0), "n must be at least 1"),
        (lambda: w1_to_measure(Uniform(), [0.5, 0.1]), "sorted"),
        (lambda: w1_between_samples([], [0.0]), "at least one"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_cells_quantile_is_the_left_edge_of_the_first_cell_reaching_the_level():
    edges = np.linspace(0.0, 4.0, 5)
    w = np.array([0.0, 0.25, 0.5, 1.0])
    assert cells_quantile(w, edges, 0.5) == 2.0
    assert cells_quantile(w, edges, 0.3) == 2.0
    assert cells_quantile(w, edges, 1.0) == 3.0
    assert cells_quantile(np.zeros(4), edges, 0.5) == 4.0
    with pytest.raises(ValueError, match="level"):
        cells_quantile(w, edges, 0.0)
    with pytest.raises(ValueError, match="x_edges"):
        cells_quantile(w, edges[:-1], 0.5)


def test_cells_distance_is_the_sum_over_types_of_the_l1_distances():
    fine, coarse = np.linspace(0.0, 1.0, 5), np.linspace(0.0, 1.0, 3)
    a = np.array([[0.0, 0.5, 0.5, 1.0], [0.0, 0.0, 1.0, 1.0]])
    b = np.array([[0.25, 0.75], [0.0, 1.0]])
    assert cells_distance(a, fine, b, coarse) == pytest.approx(0.25 * (0.25 + 0.25 + 0.25 + 0.25) + 0.0)
    assert cells_distance(a, fine, a, fine) == 0.0
    with pytest.raises(ValueError, match="types"):
        cells_distance(a, fine, b[:1], coarse)


def test_cases_and_cell_distances_name_what_they_refuse():
    """Issue 46 (census): ScalarCase took any field; the distances named values_a and no configuration."""
    from particle_methods.finite_volume import burgers_flux
    from particle_methods.sticky.cases import SCALAR_CASES, ScalarCase, distance_to_cells

    case = SCALAR_CASES["burgers_two_atoms"]
    with pytest.raises(ValueError, match="flux_lipschitz must be finite"):
        ScalarCase(case.initial, burgers_flux, case.solution, np.nan)
    with pytest.raises(TypeError, match="solution must be callable"):
        ScalarCase(case.initial, burgers_flux, None, 1.0)
    with pytest.raises(ValueError, match="flux values contains NaN"):
        ScalarCase(case.initial, lambda u: np.full(np.shape(u), np.nan), case.solution, 1.0)
    edges = np.linspace(-1.0, 1.0, 5)
    with pytest.raises(ValueError, match=r"w_a\[0\] and w_b\[0\]: the L1 distance is not finite"):
        cells_distance(np.full((1, 4), -1.7e308), edges, np.full((1, 4), 1.7e308), edges)
    with pytest.raises(ValueError, match="the particles of configuration span"):
        distance_to_cells(np.array([[0.0, 2.0]]), np.zeros((1, 4)), edges)
    with pytest.raises(ValueError, match="configuration must be sorted"):
        distance_to_cells(np.array([[0.5, 0.0]]), np.zeros((1, 4)), edges)
    with pytest.raises(ValueError, match="x_edges must contain at least 2 edges"):
        distance_to_cells(np.array([[0.0]]), np.zeros((1, 4)), [])
    # the census's whole-word naming: the row of w that overflows, and the unsorted configuration, by name
    with pytest.raises(ValueError, match=r"^w\[0\] against configuration\[0\]: "):
        distance_to_cells(np.array([[-0.5, 0.5]]), np.full((1, 4), -1.7e308), edges)
    from particle_methods.sticky.cases import configuration_distance

    with pytest.raises(ValueError, match="^b must hold each type's positions sorted"):
        configuration_distance(np.array([[0.0, 1.0]]), np.array([[1.0, 0.0]]))
