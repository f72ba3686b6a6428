"""Exact entropy solutions and the convergence of the SPD towards them."""

import numpy as np
import pytest

from particle_methods.convergence import fit_order, order_table
from particle_methods.finite_volume import burgers_flux
from particle_methods.norms import w1_to_measure
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.exact import BurgersSolution, ConcaveLaplaceSolution
from particle_methods.sticky.measures import Atoms, Laplace
from particle_methods.sticky.spd import cluster_sizes, spd_positions, velocities_from_flux


@pytest.mark.parametrize("n", [1, 3, 64, 1000])
@pytest.mark.parametrize("t", [0.5, 7.0])
def test_burgers_from_one_dirac_has_error_t_over_4n(n, t):
    """Remark 3.3: particles at t(k - 1/2)/n against the uniform law on [0, t]."""
    positions = spd_positions(np.zeros(n), velocities_from_flux(burgers_flux, n), t)
    np.testing.assert_allclose(positions, t * (np.arange(1, n + 1) - 0.5) / n, rtol=1e-11)
    assert w1_to_measure(BurgersSolution(Atoms([0.0]), t), positions) == pytest.approx(t / (4 * n), rel=1e-9)


def test_burgers_two_atoms_is_two_rarefaction_fans():
    t = 6.0
    solution = BurgersSolution(Atoms([-1.0, 1.0]), t)
    x = np.array([-1.5, -1.0, -1.0 + t / 4, -1.0 + t / 2 + 0.5, 1 + t / 2, 1 + 3 * t / 4, 1 + t, 9.0])
    np.testing.assert_allclose(solution.cdf(x), [0, 0, 0.25, 0.5, 0.5, 0.75, 1.0, 1.0], atol=1e-15)


@pytest.mark.parametrize("weights", [None, [0.3, 0.2, 0.5]])
@pytest.mark.parametrize("t", [0.5, 3.0, 10.0])
def test_burgers_cdf_from_atoms_in_closed_form_matches_the_bisection(weights, t):
    solution = BurgersSolution(Atoms([-1.0, 0.5, 1.0], weights), t)
    x = np.concatenate([np.linspace(-3.0, 13.0, 2001), solution.quantile(np.linspace(0.0, 1.0, 101))])
    bisection = super(BurgersSolution, solution)._cdf(x)
    assert np.abs(solution.cdf(x) - bisection).max() <= 1e-15


def test_burgers_two_atoms_error_is_first_order():
    case = SCALAR_CASES["burgers_two_atoms"]
    n = np.array([4, 8, 16, 32])
    errors = np.array([case.error(int(k), 20.0) for k in n])
    order = fit_order(n, errors)
    assert order == pytest.approx(-1.0, abs=1e-6), order_table(n, errors, "n")
    np.testing.assert_allclose(errors, 20.0 / (4 * n), rtol=1e-9)


def test_concave_solution_shock_level_and_characteristics():
    for t in (0.0, 1.0, 2.0):
        assert ConcaveLaplaceSolution(t).shock_level == 0.5
    for t in (3.0, 10.0):
        solution = ConcaveLaplaceSolution(t)
        w0 = solution.shock_level
        # The characteristic of level w0 has just reached the shock at x = 0.
        assert np.log(2 * w0) + t * (0.5 - w0) == pytest.approx(0.0, abs=1e-12)
        assert 0 < w0 < 1 / t
        # The shock at 0 carries the mass 1 - 2 w0; the law stays symmetric.
        assert float(solution.cdf(0.0) - solution.cdf(-1e-12)) == pytest.approx(1 - 2 * w0, abs=1e-9)
        assert float(solution.quantile_integral(1.0)) == pytest.approx(0.0, abs=1e-15)


def test_concave_solution_at_time_zero_is_the_initial_law():
    x = np.linspace(-5, 5, 101)
    np.testing.assert_allclose(ConcaveLaplaceSolution(0.0).cdf(x), Laplace(0.0).cdf(x), atol=1e-15)


def test_concave_solution_is_the_limit_of_the_spd():
    """The SPD error, exact for the discretised data (Remark 3.3), tends to 0 like log(n)/n."""
    case = SCALAR_CASES["concave_laplace"]
    n = np.array([2**10, 2**12, 2**14])
    errors = np.array([case.error(int(k), 1.0) for k in n])
    assert fit_order(n, errors / np.log(n)) == pytest.approx(-1.0, abs=0.05), order_table(n, errors, "n")


def test_particles_reach_the_shock_when_characteristics_do():
    """For large t and few particles every particle sits in the shock: the plateau of Fig 3 (d)."""
    case = SCALAR_CASES["concave_laplace"]
    positions = case.positions(8, 12.0)
    assert cluster_sizes(positions).tolist() == [8]
    np.testing.assert_allclose(positions, 0.0, atol=1e-12)
    assert case.error(8, 12.0) == pytest.approx(w1_to_measure(ConcaveLaplaceSolution(12.0), np.zeros(1)))


def test_negative_time_is_rejected():
    with pytest.raises(ValueError, match="t must be non-negative"):
        ConcaveLaplaceSolution(-1.0)
    with pytest.raises(ValueError, match="t must be non-negative"):
        BurgersSolution(Atoms([0.0]), -0.1)


def test_lambert_w0_matches_scipy_and_solves_its_equation():
    """The compiled principal branch against scipy's on [-1/e, 0] (1e-14 relative away from the branch
    point, whose conditioning costs both digits there), and w e^w = z to rounding everywhere."""
    from scipy import special

    from particle_methods.sticky.exact import lambert_w0

    z = np.concatenate([-np.logspace(-300, 0, 2001) / np.e, np.linspace(-1 / np.e, 0.0, 2001)])
    w = lambert_w0(z)
    away = z > -1 / np.e + 1e-4
    reference = special.lambertw(z[away], 0).real
    assert np.all(np.abs(w[away] - reference) <= 1e-14 * np.abs(reference))
    assert np.all(np.abs(w * np.exp(w) - z) <= 4e-16 * np.maximum(np.abs(z), 1e-300))
    assert np.all(w >= -1.0) and lambert_w0(0.0) == 0.0 and lambert_w0(-1 / np.e) == -1.0


def test_lambert_w0_refuses_arguments_outside_its_real_domain():
    from particle_methods.sticky.exact import lambert_w0

    for z in (0.1, -0.5, np.nan):
        with pytest.raises(ValueError, match="z"):
            lambert_w0(np.array([-0.1, z]))
