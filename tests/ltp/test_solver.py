"""LTP and SP runs: exact solution, conservation, the x^2 special case, bad input."""

import numpy as np
import pytest

from particle_methods.convergence import fit_order, order_table
from particle_methods.ltp import Particles, density_named, exact_density, potential, simulate
from particle_methods.norms import grid_errors

RHO1 = density_named("rho1")
GRID = np.linspace(-1, 1, 20001)


def l1_linf(sim, w, t):
    return grid_errors(sim.at(-1).density(GRID), exact_density(RHO1, w, t, GRID), GRID)


@pytest.fixture(scope="module")
def convergence():
    w = potential("quadratic")
    h = np.array([0.1, 0.05, 0.025])
    errors = np.array([l1_linf(simulate(RHO1, w, step, 1e-3, 0.25), w, 0.25) for step in h])
    return h, errors


def test_ltp_error_decreases_at_least_at_first_order(convergence):
    h, errors = convergence
    for column in (0, 1):
        order = fit_order(h, errors[:, column])
        assert order > 1.5, order_table(h, errors[:, column])
    assert errors[-1, 0] < 2e-2


def test_error_grid_is_fine_enough():
    w = potential("quadratic")
    sim = simulate(RHO1, w, 0.025, 1e-3, 0.25)
    coarse = l1_linf(sim, w, 0.25)
    fine_grid = np.linspace(-1, 1, 80001)
    fine = grid_errors(sim.at(-1).density(fine_grid), exact_density(RHO1, w, 0.25, fine_grid), fine_grid)
    assert fine[0] == pytest.approx(coarse[0], rel=1e-3)
    assert fine[1] == pytest.approx(coarse[1], rel=1e-2)


@pytest.mark.parametrize("kind, a, b", [("quadratic", None, None), ("power", 1.5, None),
                                        ("attractive_repulsive", 3.0, 2.5)])
def test_mass_and_centre_of_mass_are_conserved(kind, a, b):
    w = potential(kind, a=a, b=b)
    sim = simulate(RHO1, w, 0.05, 0.01, 0.3, record_every=10)
    wide = np.linspace(-1.5, 1.5, 30001)  # covers the support of every particle
    masses = [np.trapezoid(sim.at(i).density(wide), wide) for i in range(sim.steps.size)]
    np.testing.assert_allclose(masses, 1.0, atol=1e-9)
    if kind == "quadratic":  # x^2: the discrete centre of mass is exactly conserved
        centres = [sim.at(i).centre_of_mass for i in range(sim.steps.size)]
        np.testing.assert_allclose(centres, centres[0], rtol=0, atol=1e-14)
        assert centres[0] == pytest.approx(RHO1.mean, abs=1e-4)  # cell weights: O(h^2) off the exact mean


def test_sp_with_eps_h_is_ltp_up_to_the_common_width_for_x_squared():
    """For W = x^2 every LTP particle shrinks by the same factor exp(-2t); the centres follow the
    same moments, so SP with eps = h has the LTP centres and only the widths differ."""
    w = potential("quadratic")
    h, dt, t = 0.05, 0.01, 0.3
    ltp = simulate(RHO1, w, h, dt, t)
    sp = simulate(RHO1, w, h, dt, t, method="sp", eps=h)
    np.testing.assert_allclose(ltp.centres[-1], sp.centres[-1], rtol=0, atol=1e-14)
    np.testing.assert_allclose(ltp.widths[-1], h * np.exp(-2 * t), rtol=1e-12)
    np.testing.assert_allclose(sp.widths[-1], h)
    rescaled = Particles(sp.centres[-1], sp.weights, ltp.widths[-1], sp.shape)
    np.testing.assert_allclose(rescaled.density(GRID), ltp.at(-1).density(GRID), atol=1e-12)


@pytest.mark.parametrize("offset", [0.0, 0.5])
def test_symmetric_data_stay_symmetric(offset):
    """On the grid k h (a particle at 0) and on (k + 1/2) h (none at 0) alike."""
    sim = simulate("rho2", potential("attractive_repulsive", a=3, b=1.5), 0.05, 0.1, 2.0, offset=offset)
    centres = sim.centres[-1]
    assert (np.abs(sim.centres[0]).min() == 0.0) == (offset == 0.0)
    np.testing.assert_allclose(centres, -centres[::-1], atol=1e-12)
    np.testing.assert_allclose(sim.widths[-1], sim.widths[-1][::-1], rtol=1e-10)


def test_collapse_is_reported_with_its_step():
    with pytest.raises(ValueError, match=r"exceeds the stability bound .* at step \d+ .*: the particles collapse"):
        simulate("rho2", potential("power", a=1.5), 0.05, 0.05, 5.0)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"h": 0.0}, "h must be positive"),
        ({"dt": -0.1}, "dt must be positive"),
        ({"t_final": 0.55, "dt": 0.1}, "whole number of steps"),
        ({"method": "sp"}, "needs the particle width eps"),
        ({"method": "sp", "eps": 0.0}, "eps must be positive"),
        ({"eps": 0.1}, "eps is a parameter of the SP method only"),
        ({"method": "vortex"}, "unknown method"),
        ({"shape": "b5"}, "unknown shape"),
        ({"initial": "rho7"}, "unknown initial density"),
        ({"h": float("nan")}, "h must be finite"),
    ],
)
def test_bad_input(kwargs, message):
    arguments = {"initial": "rho1", "potential": potential("quadratic"), "h": 0.1, "dt": 0.1, "t_final": 0.2}
    arguments.update(kwargs)
    with pytest.raises(ValueError, match=message):
        simulate(**arguments)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: potential("morse"), "unknown kind of potential"),
        (lambda: potential("power"), "needs the exponent a"),
        (lambda: potential("power", a=0.5), "a must be at least 1"),
        (lambda: potential("attractive_repulsive", a=3.0), "needs the exponents a and b"),
        (lambda: exact_density(RHO1, potential("power", a=1.5), 0.1, GRID), "quadratic potential"),
    ],
)
def test_bad_potentials(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_simulation_and_simulate_refuse_census_values_by_name():
    """Census (issue 46): a ragged ``steps`` raised numpy's message, and record_every = 10**40 was taken."""
    from dataclasses import replace

    from particle_methods.ltp.solver import MAX_STEPS

    w = potential("power", a=1.5)
    sim = simulate("rho2", w, 0.5, 0.05, 0.1, record_every=1)
    with pytest.raises(TypeError, match="steps must be a rectangular array"):
        replace(sim, steps=[[1], [2, 3]])
    with pytest.raises(ValueError, match="record_every must be at most"):
        simulate("rho2", w, 0.5, 0.05, 0.1, record_every=MAX_STEPS + 1)
