"""Hopf's formula as the exact test of Remark 3.3 (particle_methods.sticky.hopf): the SPD of a concave flux
passes at every n and t, from any atoms and masses; states that keep the particles' order but sit at the
wrong time, move with wrong velocities or ignore the collisions fail, and so does a convex flux."""

import numpy as np
import pytest

from particle_methods.finite_volume.fluxes import burgers_flux, concave_flux
from particle_methods.sticky.admissibility import MAX_POINTS
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.hopf import hopf_gap
from particle_methods.sticky.spd import spd_positions, velocities_from_flux, velocities_from_levels
from particle_methods.validation import ParameterTypeError

CONCAVE = SCALAR_CASES["concave_laplace"]
#: Rounding of the relative gaps: partial sums of up to 1000 terms of relative size 1.
ROUNDING = 1e-12
#: The smallest gap of a wrong state below (their relative displacements are about 1e-3 and more).
WRONG = 1e-5


def random_atoms(n):
    return np.sort(np.random.default_rng(n).normal(size=n))


@pytest.mark.parametrize("n", [1, 2, 3, 7, 32, 1000])
@pytest.mark.parametrize("t", [0.0, 0.5, 2.5, 17.0, 100.0])
@pytest.mark.parametrize("data", ["laplace", "random"])
def test_the_spd_of_a_concave_flux_satisfies_hopfs_formula(n, t, data):
    x = CONCAVE.initial_state(n)[0] if data == "laplace" else random_atoms(n)
    assert hopf_gap(x, spd_positions(x, velocities_from_flux(concave_flux, n), t), t, concave_flux) <= ROUNDING


def test_unequal_masses_use_their_own_levels():
    x = random_atoms(50)
    masses = np.random.default_rng(1).uniform(0.5, 2.0, 50)
    masses /= masses.sum()
    levels = np.concatenate(([0.0], np.cumsum(masses)))
    positions = spd_positions(x, velocities_from_levels(concave_flux, levels), 3.0, masses)
    assert hopf_gap(x, positions, 3.0, concave_flux, masses=masses) <= ROUNDING
    assert hopf_gap(x, positions, 3.0, concave_flux) > WRONG  # the same positions read with equal masses


@pytest.mark.parametrize("time_factor, velocity_factor", [(2.0, 1.0), (1.0, 2.0), (1.0, 0.5), (1.5, 1.0)])
def test_a_wrong_clock_or_wrong_velocities_fail(time_factor, velocity_factor):
    x = random_atoms(200)
    v = velocities_from_flux(concave_flux, 200)
    assert hopf_gap(x, spd_positions(x, velocity_factor * v, time_factor * 2.0), 2.0, concave_flux) > WRONG


def test_free_flight_is_the_spd_until_the_first_collision_only():
    x, v = CONCAVE.initial_state(64)
    assert hopf_gap(x, np.sort(x + 0.5 * v), 0.5, concave_flux) <= ROUNDING  # no collision yet at t = 0.5
    assert hopf_gap(x, np.sort(x + 5.0 * v), 5.0, concave_flux) > WRONG


def test_a_convex_flux_is_not_the_entropy_solution():
    """Burgers from two atoms: the SPD's clusters are rarefactions; G lies above f between levels."""
    x, v = SCALAR_CASES["burgers_two_atoms"].initial_state(4)
    assert hopf_gap(x, spd_positions(x, v, 1.0), 1.0, burgers_flux) > WRONG
    assert hopf_gap(x, spd_positions(x, v, 1.0), 1.0, burgers_flux, points=0) <= ROUNDING  # only between levels


def test_a_shift_of_every_position_changes_nothing():
    x, v = CONCAVE.initial_state(100)
    positions = spd_positions(x, v, 4.0)
    assert hopf_gap(x + 1e3, positions + 1e3, 4.0, concave_flux) <= 1e3 * ROUNDING


@pytest.mark.parametrize("nudge", [1e-17, -1e-17])
def test_a_cluster_split_by_rounding_changes_nothing(nudge):
    """A member of a cluster moved by 1e-17 makes a new corner of G: the gap there is rounding, not a verdict."""
    x, v = CONCAVE.initial_state(16)
    positions = spd_positions(x, v, 5.0)
    member = int(np.flatnonzero(positions[1:] == positions[:-1])[0])
    positions[member] += nudge
    assert hopf_gap(x, positions, 5.0, concave_flux) <= ROUNDING


def test_nothing_moves_nothing_to_compare():
    assert hopf_gap(np.zeros(3), np.zeros(3), 0.0, lambda u: np.zeros_like(u)) == 0.0


@pytest.mark.parametrize("kwargs, error, name", [
    ({"t": -1.0}, ValueError, "t"),
    ({"t": float("nan")}, ValueError, "t"),
    ({"positions": np.zeros(3)}, ValueError, "positions"),
    ({"positions": [0.0, float("inf"), 1.0, 2.0]}, ValueError, "positions"),
    ({"flux": "u(1-u)/2"}, ParameterTypeError, "flux"),
    ({"flux": lambda u: np.zeros(2)}, ValueError, "flux"),
    ({"flux": lambda u: u / 0.0}, ValueError, "flux"),
    ({"masses": [1.0, -1.0, 1.0, 1.0]}, ValueError, "masses"),
    ({"masses": [1.0, 1.0]}, ValueError, "masses"),
    ({"points": -1}, ValueError, "points"),
    ({"points": 1.5}, ParameterTypeError, "points"),
    ({"points": MAX_POINTS + 1}, ValueError, "points"),
])
def test_bad_inputs_are_refused_by_name(kwargs, error, name):
    args = {"initial": np.arange(4.0), "positions": np.arange(4.0), "t": 1.0, "flux": concave_flux, **kwargs}
    with np.errstate(divide="ignore", invalid="ignore"), pytest.raises(error, match=name):
        hopf_gap(**args)
