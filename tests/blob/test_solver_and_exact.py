"""Blob and particle methods in 1D: exact solutions, convergence, invariants, bad input."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import data_1d, grid_1d
from particle_methods.blob.solver import run_1d
from particle_methods.convergence import fit_order, order_table
from particle_methods.norms import discrete_l1

SMOOTH = data_1d("smooth20")


def l1_errors(method, n, kernel="newtonian_attractive", order=4, t=0.5):
    run = run_1d("smooth20", kernel, 1.0 / n, [0.0, t], method=method, order=order)
    exact_x, exact_rho = newtonian_exact(SMOOTH, kernel, run.positions[0, :, 0], t)
    density = discrete_l1(run.densities[-1], exact_rho, 1.0 / n) if run.densities is not None else np.nan
    return discrete_l1(run.positions[-1, :, 0], exact_x, 1.0 / n), density


def test_exact_density_solves_its_ode():
    """Along a trajectory d rho/dt = s rho^2 (s = 1 attractive, -1 repulsive)."""
    alpha = np.array([0.1, 0.5])
    for kernel, sign in (("newtonian_attractive", 1.0), ("newtonian_repulsive", -1.0)):
        rho0 = SMOOTH(alpha)
        solution = solve_ivp(lambda t, r, sign=sign: sign * r**2, (0, 0.7), rho0, rtol=1e-12, atol=1e-14)
        np.testing.assert_allclose(newtonian_exact(SMOOTH, kernel, alpha, 0.7)[1], solution.y[:, -1], rtol=1e-9)


def test_exact_trajectories_against_a_direct_particle_solve():
    """The particle method is a direct ODE solve of the Lagrangian system: it converges at order 2."""
    n = np.array([50, 100, 200])
    errors = np.array([l1_errors("particle", k)[0] for k in n])
    assert fit_order(1.0 / n, errors) == pytest.approx(2.0, abs=0.1), order_table(1.0 / n, errors)
    assert errors[-1] < 1e-5


def test_blob_m4_order_on_a_few_h():
    n = np.array([40, 80, 160])
    errors = np.array([l1_errors("blob", k) for k in n])
    for column in (0, 1):
        order = fit_order(1.0 / n, errors[:, column])
        assert 2.8 < order < 4.0, order_table(1.0 / n, errors[:, column])


def test_energy_decreases_and_trajectories_never_cross():
    run = run_1d("indicator", "newtonian_attractive", 0.05, np.linspace(0, 1.2, 25))
    energies = run.energies()
    assert np.all(np.diff(energies) < 0)
    assert np.all(np.diff(run.positions[:, :, 0], axis=1) > 0)


def test_symmetric_data_give_symmetric_solutions():
    run = run_1d("smooth10", "cubic", 0.05, [0.0, 0.5], order=6)
    x = run.positions[-1, :, 0]
    np.testing.assert_allclose(x, -x[::-1], atol=1e-12)
    np.testing.assert_allclose(run.densities[-1], run.densities[-1][::-1], rtol=1e-10)


def test_particle_method_has_no_density_for_the_newtonian_kernel():
    assert run_1d("smooth20", "newtonian_attractive", 0.1, [0.0, 0.1], method="particle").densities is None
    assert run_1d("smooth20", "cubic", 0.1, [0.0, 0.1], method="particle").densities is not None


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: run_1d("smooth20", "cubic", -0.1, [0, 1]), "h must be positive"),
        (lambda: run_1d("smooth20", "cubic", 0.3, [0, 1]), "must divide 1"),
        (lambda: run_1d("smooth20", "cubic", 0.1, [0, 1], q=1.0), r"q must lie in \(1/2, 1\)"),
        (lambda: run_1d("smooth20", "cubic", 0.1, [0, 1], q=0.4), r"q must lie in \(1/2, 1\)"),
        (lambda: run_1d("smooth20", "cubic", 0.1, [0, 1], order=5), "no mollifier of order"),
        (lambda: run_1d("smooth20", "log", 0.1, [0, 1]), "unknown kernel"),
        (lambda: run_1d("gauss", "cubic", 0.1, [0, 1]), "unknown initial data"),
        (lambda: run_1d("smooth20", "cubic", 0.1, [0, 1], method="vortex"), "unknown method"),
        (lambda: run_1d("smooth20", "cubic", 0.1, [1, 0]), "times must be non-negative and strictly increasing"),
        (lambda: newtonian_exact(SMOOTH, "newtonian_attractive", [0.1], 1.0), "past the blow-up time"),
        (lambda: newtonian_exact(SMOOTH, "cubic", [0.1], 0.1), "unknown Newtonian kernel .cubic."),
        (lambda: grid_1d(0.0), "h must be positive"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()


@pytest.mark.parametrize("outward", [1e-17, 2.2e-16])
def test_a_label_on_a_jump_of_the_data_keeps_its_particles_density(outward):
    """The ends of the indicator (4.4) sit on grid points: a label rounded just outside reads the data as 0, its
    particle carries 1; given the run's own initial densities, the exact density along its trajectory is the
    particle's, however the label rounds (rounding decides nothing)."""
    from particle_methods.blob.initial import data_1d

    indicator = data_1d("indicator")
    labels = np.array([-1.0 - outward, 0.0, 1.0 + outward])
    carried = np.ones(3)
    _, density = newtonian_exact(indicator, "newtonian_attractive", labels, 0.2, rho0=carried)
    np.testing.assert_allclose(density, 1.0 / (1.0 - 0.2))
    with pytest.raises(ValueError, match="rho0"):
        newtonian_exact(indicator, "newtonian_attractive", labels, 0.2, rho0=np.ones(2))
