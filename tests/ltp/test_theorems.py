"""The pieces of the theorem studies (particle_methods.ltp.theorems) and the new measures: atomic data, the exact
flow of atoms, W1 to atoms, the L1 distance of two reconstructions, the algebraic reading of shrink rates."""

import math

import numpy as np
import pytest
from scipy import integrate

from particle_methods.ltp import B3, Particles, grid_particles, potential
from particle_methods.ltp.initial import atomic, golden_atoms
from particle_methods.ltp.measures import l1_distance, shrink_rate_ratios
from particle_methods.ltp.theorems import atom_flow, w1_to_atoms

B3_MEAN_ABS = integrate.quad(lambda s: abs(s) * float(B3(s)), -2, 2, points=[-1, 0, 1])[0]


def test_cell_weights_of_atoms_are_the_masses_in_each_cell():
    measure = atomic([0.013, -0.31, 0.02], [0.2, 0.5, 0.3])
    centres, omega = grid_particles(measure, 0.05, B3)
    np.testing.assert_allclose(centres, [-0.3, 0.0])
    np.testing.assert_allclose(omega, [0.5, 0.5])
    with pytest.raises(ValueError, match="no density"):
        measure.pdf(0.0)


@pytest.mark.parametrize("positions, masses", [([], []), ([0.0, 1.0], [0.5]), ([0.0], [-1.0]), ([np.nan], [1.0])])
def test_atomic_refuses_bad_atoms(positions, masses):
    with pytest.raises(ValueError):
        atomic(positions, masses)


@pytest.mark.parametrize("h", [0.01, 0.005, 0.0025, 0.00125])
def test_golden_atoms_have_unit_mass_and_sit_at_several_phases_of_the_grid(h):
    x, m = golden_atoms(40, -0.9, 0.9)
    assert m.sum() == pytest.approx(1.0) and np.all(np.diff(x) > 0) and x.min() > -0.9 and x.max() < 0.9
    phases = np.remainder(x / h + 0.5, 1.0)  # 0.5: at a cell centre
    assert np.count_nonzero(np.histogram(phases, bins=4, range=(0, 1))[0]) >= 3


def test_atom_flow_is_the_exact_flow_of_two_atoms_for_x_squared():
    # W = x^2: x_1 - x_2 shrinks like exp(-2 t) (each atom of mass 1/2 pulls with 2 (x_i - x_j) / 2)
    x = atom_flow([-0.5, 0.5], [0.5, 0.5], potential("quadratic"), [0.25, 0.5])
    np.testing.assert_allclose(x[:, 1] - x[:, 0], np.exp(-2 * np.array([0.25, 0.5])), rtol=1e-10)


@pytest.mark.parametrize("shift", [0.0, 0.003, 0.02, 0.5])
def test_w1_of_a_particle_to_an_atom_matches_quadrature(shift):
    width = 0.01
    particle = Particles(np.array([shift]), np.array([1.0]), np.array([width]), B3)
    expected = width * integrate.quad(lambda s: abs(s - (-shift / width)) * float(B3(s)), -2, 2,
                                      points=[-1, 0, 1, -shift / width])[0]
    assert w1_to_atoms(particle, [0.0], [1.0]) == pytest.approx(expected, rel=1e-12)
    if shift == 0.0:
        assert expected == pytest.approx(width * B3_MEAN_ABS)


def test_w1_to_atoms_refuses_unequal_masses():
    particle = Particles(np.array([0.0]), np.array([1.0]), np.array([0.01]), B3)
    with pytest.raises(ValueError, match="mass"):
        w1_to_atoms(particle, [0.0], [0.5])


def test_l1_distance_of_shifted_particles_matches_quadrature():
    first = Particles(np.array([0.0, 0.3]), np.array([0.5, 0.5]), np.array([0.1, 0.05]), B3)
    second = Particles(np.array([0.02, 0.3]), np.array([0.5, 0.5]), np.array([0.1, 0.06]), B3)
    expected = integrate.quad(lambda x: abs(float(first.density(x)[0] - second.density(x)[0])), -0.3, 0.5,
                              points=[0.0, 0.02, 0.3], limit=400, epsabs=1e-13)[0]
    assert l1_distance(first, second) == pytest.approx(expected, rel=1e-3)
    assert l1_distance(first, first) == 0.0


def test_the_algebraic_reading_gives_one_for_powers_and_more_for_exponentials():
    t = np.linspace(0.0, 60.0, 121)
    _, power = shrink_rate_ratios(t, 0.2 / (1.0 + t) ** 2, 10.0, 10.0, 1e-3, algebraic=True)
    _, exponential = shrink_rate_ratios(t, np.exp(-0.1 * t), 10.0, 10.0, 1e-3, algebraic=True)
    _, settling = shrink_rate_ratios(t, 0.3 + 0.2 * np.exp(-0.5 * t), 10.0, 10.0, 1e-3, algebraic=True)
    assert np.all(np.abs(power - 1.0) < 0.05) and exponential.min() > 1.1 and settling.max() < 0.1
    with pytest.raises(ValueError, match="after t = 0"):
        shrink_rate_ratios(t, np.exp(-0.1 * t), 10.0, 0.0, 1e-3, algebraic=True)
    assert not math.isnan(power.sum())


def test_the_studies_check_their_section_grid_and_solver():
    """Census (issue 46): the studies indexed ``q``, passed ``grid_points`` to linspace and called ``run`` with no
    check (AttributeError, IndexError, MemoryError for 10**18 points, minutes for 2**31)."""
    from particle_methods.ltp import simulate
    from particle_methods.ltp.theorems import MAX_GRID_POINTS, theorem1_time_error, theorem3_atomic

    q = {"initial": "rho2", "a": 3.0, "t": 0.1, "h_values": [0.5], "dt_values": [0.1, 0.05], "fit_points": 2}
    assert theorem1_time_error(q, 11)["theorem1_gaps"].shape == (1, 1, 2)
    with pytest.raises(TypeError, match="q must be of type dict"):
        theorem1_time_error(None, 11)
    with pytest.raises(ValueError, match="q .* lacks fit_points"):
        theorem1_time_error({key: q[key] for key in q if key != "fit_points"}, 11)
    with pytest.raises(ValueError, match="grid_points must be at most"):
        theorem1_time_error(q, MAX_GRID_POINTS + 1)
    with pytest.raises(TypeError, match="grid_points must be an integer"):
        theorem1_time_error(q, True)
    with pytest.raises(TypeError, match="run must take the arguments of simulate"):
        theorem1_time_error(q, 11, run=lambda x: x)
    with pytest.raises(TypeError, match="the result of run must be of type Simulation"):
        theorem1_time_error(q, 11, run=lambda *args, **kwargs: np.zeros(3))
    with pytest.raises(TypeError, match="run must be a function"):
        theorem3_atomic({"atoms": 3, "a": 3.0, "dt": 0.05, "dt_factor": 2, "h_values": [0.5], "times": [0.1]},
                        run=None)
    assert simulate  # the default solver


def test_records_atom_flow_and_w1_check_their_arguments():
    """Census (issue 46): records took any sim and times (AttributeError; minutes for 10**8 times), atom_flow
    any times and rtol (IndexError, AttributeError, a hang over t = 1e299) and named no masses on overflow."""
    from particle_methods.ltp import simulate
    from particle_methods.ltp.theorems import MAX_FLOW_TIME, records

    w = potential("power", a=3.0)
    sim = simulate("rho2", w, 0.5, 0.05, 0.1, record_every=1)
    assert records(sim, [0.05, 0.1]) == [1, 2]
    with pytest.raises(TypeError, match="sim must be of type Simulation"):
        records(None, [0.1])
    with pytest.raises(ValueError, match="the number of times must be at most 3"):
        records(sim, np.full(4, 0.1))
    with pytest.raises(ValueError, match="times must be record times of sim"):
        records(sim, [0.07])
    positions, masses = golden_atoms(3, -0.9, 0.9)
    for times in ([], [0.0, 0.0], [0.0, 2 * MAX_FLOW_TIME], [-1.0, 0.1]):
        with pytest.raises(ValueError, match="times must increase strictly"):
            atom_flow(positions, masses, w, times)
    for rtol, error in ((None, TypeError), (1j, TypeError), (-1.0, ValueError), (1.0, ValueError)):
        with pytest.raises(error, match="rtol"):
            atom_flow(positions, masses, w, [0.0, 0.1], rtol=rtol)
    with pytest.raises(ValueError, match="masses must be non-negative"):
        atom_flow(positions, -masses, w, [0.0, 0.1])
    with pytest.raises(ValueError, match="masses or positions"):
        atom_flow(positions, np.full(3, 1e300), w, [0.0, 0.1])
    particles = sim.at(0)
    with pytest.raises(ValueError, match="masses must sum to the particles' mass"):
        w1_to_atoms(particles, positions, 2 * masses)
