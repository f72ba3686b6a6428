"""2D blob machinery: kernels, radial tables, exact radial solution, symmetry, the ring radius."""

import numpy as np
import pytest

from particle_methods.blob.exact import newtonian_exact_2d
from particle_methods.blob.initial import data_2d
from particle_methods.blob.kernels import kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.rings import uniform_ring_radius
from particle_methods.blob.solver import mass_defect, run_2d, setup_2d
from particle_methods.convergence import fit_order, order_table
from particle_methods.norms import discrete_l1

PSI = mollifier(4, 2)


def direct_gradient(raw, r, delta, points=200):
    """Radial component of (grad K * psi_delta)(r e_1), the mollifier cut at |y| = 6 delta, by 2D quadrature in
    polar coordinates (s, phi) centred at r e_1, where grad K is singular or has a kink: with grad K(z) = g(|z|) z,
    the integrand g(s) s^2 cos(phi) psi_delta(|r e_1 - z|) is smooth there (g(s) s^2 is 1/(2 pi), s^3, s^4 or
    K'(s) s for the kernels below), so Gauss-Legendre rules in phi over [0, pi] (the integrand is even in phi) and
    in s up to the disc's edge converge spectrally; the test checks the rule against itself at half the points."""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    phi, phi_weights = (nodes + 1) * np.pi / 2, weights * np.pi / 2
    reach = r * np.cos(phi) + np.sqrt((6 * delta) ** 2 - (r * np.sin(phi)) ** 2)  # the disc's edge, r < 6 delta
    s, s_weights = (nodes[None, :] + 1) / 2 * reach[:, None], weights[None, :] / 2 * reach[:, None]
    rho = np.sqrt(r * r - 2 * r * s * np.cos(phi)[:, None] + s * s)
    values = raw.profile(s)[1] * s * s * np.cos(phi)[:, None] * PSI(rho, delta)
    return 2 * float(np.sum(phi_weights[:, None] * s_weights * values))


@pytest.mark.parametrize("name", ["newtonian", "cubic", "quartic_power", "morse_2"])
def test_mollified_gradients_match_direct_convolution(name):
    delta = 0.3
    smooth, raw = kernel_2d(name, PSI, delta, table_points=4001), kernel_2d(name)
    for r in (0.07, 0.5, 1.3):
        direct = direct_gradient(raw, r, delta)
        assert direct == pytest.approx(direct_gradient(raw, r, delta, points=100), abs=1e-10)  # the rule converged
        assert float(smooth.profile(np.array(r))[1]) * r == pytest.approx(direct, abs=2e-6)


def test_tables_reproduce_the_closed_forms_and_converge():
    """|x|^4/4 is unchanged by psi4 (grad and Laplacian are polynomials of degree < 4)."""
    r = np.linspace(0.05, 2.0, 37)
    coarse = kernel_2d("quartic_power", PSI, 0.3, table_points=2001)
    fine = kernel_2d("quartic_power", PSI, 0.3, table_points=8001)
    g_coarse, g_fine = coarse.profile(r)[1], fine.profile(r)[1]
    assert np.abs(g_fine - g_coarse).max() < 2e-5
    from particle_methods.blob.radial import tabulate

    table = tabulate(lambda s: 4 * s * s, PSI, 0.3, 5.0, 2001)
    grid = np.linspace(0, 5, 2001)
    np.testing.assert_allclose(table.laplacian, 4 * grid**2, atol=1e-10)
    np.testing.assert_allclose(table.gradient[2:], grid[2:] ** 2, atol=1e-5)


def test_radial_exact_solution_against_a_direct_solve():
    """Particle method (direct ODE solve) converges to the mass-coordinate solution at order 2."""
    data = data_2d("regular")
    n = np.array([5, 10, 20])
    errors = []
    for k in n:
        sim = run_2d(data, "newtonian", 1.0 / k, [0.0, 0.4], method="particle", rtol=1e-10, atol=1e-12)
        exact, _ = newtonian_exact_2d(data, sim.positions[0], 0.4)
        errors.append(discrete_l1(sim.positions[-1], exact, 1.0 / k, 2))
    assert fit_order(1.0 / n, errors) == pytest.approx(2.0, abs=0.15), order_table(1.0 / n, np.array(errors))


def test_m4_order_on_coarse_grids():
    data = data_2d("regular")
    n = np.array([5, 10, 20])
    errors = []
    for k in n:
        sim = run_2d(data, "newtonian", 1.0 / k, [0.0, 0.5], rtol=1e-10, atol=1e-12)
        exact, _ = newtonian_exact_2d(data, sim.positions[0], 0.5)
        errors.append(discrete_l1(sim.positions[-1], exact, 1.0 / k, 2))
    assert 2.8 < fit_order(1.0 / n, errors) < 4.0, order_table(1.0 / n, np.array(errors))


def test_rotation_and_reflection_symmetry():
    sim = run_2d("bump", "cubic", 0.2, [0.0, 1.0], rtol=1e-10, atol=1e-12)
    start, end = sim.positions[0], sim.positions[-1]
    for transform in (lambda p: p[:, ::-1], lambda p: p * [1, -1], lambda p: np.stack([-p[:, 1], p[:, 0]], 1)):
        images = transform(start)
        order = [int(np.argmin(np.linalg.norm(start - q, axis=1))) for q in images]
        np.testing.assert_allclose(end[order], transform(end), atol=1e-9)


def test_energy_decreases_and_mass_is_conserved_in_2d():
    sim = run_2d("quartic", "quadratic", 0.25, np.linspace(0, 2, 9), rtol=1e-10, atol=1e-12)
    assert np.all(np.diff(sim.energies()) < 0)
    points, rho0, masses, kernel, _ = setup_2d("bump", "newtonian", 0.25)
    assert mass_defect(points, rho0, masses, kernel, 0.8, rtol=1e-10, atol=1e-12) < 1e-7


def test_uniform_ring_is_stationary():
    a, b = 4.0, 1.5
    radius = uniform_ring_radius(a, b)
    theta = np.linspace(0, 2 * np.pi, 20001)[1:-1]
    ring = radius * np.stack([np.cos(theta), np.sin(theta)], 1)
    z = np.array([radius, 0.0]) - ring
    d = np.linalg.norm(z, axis=1)
    radial = ((d ** (a - 2) - d ** (b - 2)) * z[:, 0]).mean()
    assert abs(radial) < 1e-3
    assert radius == pytest.approx(0.5 * (1.7485 / (3 * np.pi / 8)) ** 0.4, rel=1e-3)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: kernel_2d("yukawa"), "unknown 2D kernel"),
        (lambda: kernel_2d("cubic", mollifier(4, 1), 0.1), "2D mollifier"),
        (lambda: data_2d("square"), "unknown 2D data"),
        (lambda: run_2d("regular", "newtonian", 0.2, [0, 1], method="vortex"), "unknown method"),
        (lambda: newtonian_exact_2d(data_2d("regular"), np.zeros((1, 2)), 1.0), "past the blow-up time"),
        (lambda: uniform_ring_radius(1.5, 4.0), "a must exceed b"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()
