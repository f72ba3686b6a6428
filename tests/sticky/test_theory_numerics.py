"""The instruments of sections 3 and 4 (particle_methods.sticky.theory): the cubic flux's exact solution from
delta_0, the duplication x -> x^, the p-system's constants against their definitions, the collision
record of the iterated TSPD on cases whose collisions are known, and the input checks."""

import math

import numpy as np
import pytest

from particle_methods.finite_volume.fluxes import burgers_flux, concave_flux
from particle_methods.norms import w1_between_samples, w1_to_measure
from particle_methods.sticky.exact import BurgersSolution
from particle_methods.sticky.measures import Atoms, Laplace
from particle_methods.sticky.mspd import rank_velocities
from particle_methods.sticky.spd import spd_positions, velocities_from_flux
from particle_methods.sticky.theory import (
    CUBIC_TANGENT,
    CubicDiracSolution,
    collision_record,
    cubic_flux,
    cubic_speed,
    doubling_distance,
    duplicated,
    empirical_atoms,
    psystem_constants,
    sampled_configuration,
)
from particle_methods.systems import MINUS, PLUS, PSystem
from particle_methods.validation import ParameterTypeError

SYSTEM = PSystem(nu=0.5, kappa=5.0)


def test_cubic_dirac_solution_is_a_shock_then_a_fan():
    solution = CubicDiracSolution(0.5, 2.0)
    # The tangency: the chord of the flux from 0 to w* has the slope lambda(w*) (Rankine-Hugoniot = sonic).
    assert cubic_flux(CUBIC_TANGENT) / CUBIC_TANGENT == pytest.approx(cubic_speed(CUBIC_TANGENT), abs=1e-15)
    shock = 0.5 + 2.0 * cubic_speed(CUBIC_TANGENT)
    assert solution.cdf(shock - 1e-12) == 0.0 and solution.cdf(shock) == pytest.approx(CUBIC_TANGENT)
    assert solution.cdf(0.5) == 1.0  # lambda(1) = 0: the fan ends at the atom's place
    w = np.linspace(0.8, 0.99, 5)
    np.testing.assert_allclose(solution.cdf(solution.quantile(w)), w, rtol=1e-12)
    # G is the antiderivative of the quantile: its differences are the quantile's means.
    edges = np.linspace(0.0, 1.0, 2001)
    means = np.diff(solution.quantile_integral(edges)) / np.diff(edges)
    np.testing.assert_allclose(means, solution.quantile(0.5 * (edges[1:] + edges[:-1])), atol=1e-6)


def test_the_spd_from_delta_0_tends_to_the_cubic_solution_within_t_over_n():
    t = 3.0
    errors = [w1_to_measure(CubicDiracSolution(0.0, t),
                            spd_positions(np.zeros(n), velocities_from_flux(cubic_flux, n), t)) for n in (10, 1000)]
    assert errors[1] < errors[0] / 50 and errors[0] <= t / 10


def test_burgers_from_any_configuration_is_t_over_4n_from_its_fans():
    x = np.array([-1.0, -1.0, 0.3, 2.0, 2.0, 2.0, 5.0])
    n, t = x.size, 1.7
    solution = BurgersSolution(empirical_atoms(x), t)
    error = w1_to_measure(solution, spd_positions(x, velocities_from_flux(burgers_flux, n), t))
    assert error == pytest.approx(t / (4 * n), rel=1e-12)


def test_empirical_atoms_merge_equal_positions():
    atoms = empirical_atoms([0.0, 0.0, 1.0, 3.0])
    np.testing.assert_array_equal(atoms.positions, [0.0, 1.0, 3.0])
    np.testing.assert_allclose(atoms.weights, [0.5, 0.25, 0.25])


def test_duplication_keeps_the_empirical_measures_and_the_distances():
    x, y = np.array([[0.0, 1.0, 4.0], [-2.0, 0.5, 0.5]]), np.array([[0.5, 1.0, 2.0], [-1.0, 0.0, 3.0]])
    hat_x, hat_y = duplicated(x), duplicated(y)
    assert hat_x.shape == (2, 6) and np.array_equal(hat_x[1], [-2.0, -2.0, 0.5, 0.5, 0.5, 0.5])
    assert all(w1_between_samples(a, b) == 0.0 for a, b in zip(x, hat_x))
    # (4.9): the normalised L1 distance does not change.
    assert np.abs(hat_x - hat_y).sum() / 6 == pytest.approx(np.abs(x - y).sum() / 3)


def test_doubling_distance_on_the_two_fluxes_of_the_figures():
    x = np.sort(np.random.default_rng(0).normal(size=32))
    t = 2.5
    assert doubling_distance(burgers_flux, x, t) == pytest.approx(t / (4 * 32), rel=1e-12)
    assert doubling_distance(concave_flux, x, t) <= 1e-14
    assert 0 < doubling_distance(cubic_flux, x, t) <= t / (2 * 32)


@pytest.mark.parametrize("kappa", [5.0, 1.0])
def test_psystem_constants_match_the_definitions(kappa):
    system = PSystem(nu=0.5, kappa=kappa)
    constants = psystem_constants(system)
    w = np.linspace(0.0, 1.0, 401)
    w_minus, w_plus = (grid.ravel() for grid in np.meshgrid(w, w))
    minus, plus = system.speeds(w_minus, w_plus)
    assert constants.speed_bound == pytest.approx(max(np.abs(minus).max(), np.abs(plus).max()), rel=1e-12)
    assert constants.hyperbolicity == pytest.approx(minus.min() - plus.max(), rel=1e-12)
    # (LC) with the l1 distance: the largest partial derivative, by differences on a fine grid of the spread.
    spread = np.linspace(-1.0, 1.0, 200001)
    speed = system.speed_scale / np.cosh(system.a * spread)
    assert constants.lipschitz == pytest.approx(np.abs(np.diff(speed) / np.diff(spread)).max(), rel=1e-5)
    assert constants.crossings_bound == math.ceil(2 * constants.speed_bound / constants.hyperbolicity)
    if kappa == 5.0:
        assert (constants.lipschitz, constants.crossings_bound) == (pytest.approx(2.5), 3)
        assert constants.constant_over_stability == pytest.approx(15.0)
    else:  # below kappa = 2 the derivative peaks at |s| = 1, under kappa / (4 nu)
        assert constants.lipschitz < kappa / (4 * 0.5)


def test_collision_record_sees_one_crossing_once():
    # One particle per type: the - particle (faster, to the right) starts 0.3 behind the + particle.
    x = np.array([[0.0], [0.3]])
    velocities = rank_velocities(x, SYSTEM)[:, 0]  # (1.8), constant until they meet
    meeting = 0.3 / (velocities[MINUS] - velocities[PLUS])
    delta = 0.05
    record = collision_record(x, SYSTEM, delta, 20)
    assert record.collisions.sum() == 1 and record.pair_counts.sum() == 1 and record.pair_counts.max() == 1
    # The iterate y_l still has the pair in R(y_l) and meets within Delta: l Delta < meeting <= (l + 1) Delta.
    assert np.flatnonzero(record.collisions)[0] == math.ceil(meeting / delta) - 1
    assert 0 < record.largest_collision_gap <= 2 * psystem_constants(SYSTEM).speed_bound * delta
    assert record.mspd_distances[0] == 0.0
    assert np.all(record.step_distances[record.collisions == 0] <= 1e-15)
    bound = 2 * delta * psystem_constants(SYSTEM).lipschitz * record.collisions / 1**2
    assert np.all(record.step_distances <= bound + 1e-15)
    assert record.smallest_shrink >= psystem_constants(SYSTEM).hyperbolicity * delta * (1 - 1e-12)


def test_collision_record_without_crossings_matches_the_mspd():
    # w0+ >= w0- with every + particle left of every - particle: no pair is in R(x).
    x = np.array([[1.0, 2.0, 3.0], [-3.0, -2.0, -1.0]])
    record = collision_record(x, SYSTEM, 0.1, 10)
    assert record.collisions.sum() == 0 and math.isinf(record.largest_collision_gap)
    assert record.mspd_distances.max() <= 1e-14


def test_sampled_configurations_are_sorted_draws():
    rng = np.random.default_rng(3)
    x = sampled_configuration([Laplace(1.0), Atoms([0.0])], 500, rng)
    assert x.shape == (2, 500) and np.all(np.diff(x, axis=-1) >= 0) and np.all(x[1] == 0.0)
    again = sampled_configuration([Laplace(1.0), Atoms([0.0])], 500, np.random.default_rng(3))
    assert np.array_equal(x, again)
    assert w1_to_measure(Laplace(1.0), x[0]) < 0.2


def test_inputs_are_checked():
    with pytest.raises(ValueError, match="sorted"):
        duplicated([1.0, 0.0])
    with pytest.raises(ParameterTypeError):
        doubling_distance("u^2/2", [0.0, 1.0], 1.0)
    with pytest.raises(ValueError, match="non-negative"):
        CubicDiracSolution(0.0, -1.0)
    with pytest.raises(ValueError, match="positive"):
        collision_record(np.zeros((2, 3)), SYSTEM, 0.0, 3)
    with pytest.raises(ParameterTypeError):
        sampled_configuration([Laplace(0.0)], 10, 42)
    with pytest.raises(ParameterTypeError):
        psystem_constants("p-system")
    with pytest.raises(ValueError, match="rows"):
        collision_record(np.zeros((3, 2)), SYSTEM, 0.1, 3)


def test_records_and_constants_check_their_fields():
    """Issue 46 (census): CollisionRecord and SystemConstants took None, strings and NaN; their documented
    sentinels (-inf gap with no collision, +inf shrink with no type pair) stay allowed."""
    from particle_methods.sticky.theory import CollisionRecord, SystemConstants

    good = dict(collisions=np.array([1]), step_distances=np.array([0.1]), pair_counts=np.ones((1, 2, 2)),
                smallest_shrink=0.5, largest_collision_gap=0.1, mspd_distances=np.array([0.1, 0.2]), extent=1.0)
    assert CollisionRecord(**good).collisions.dtype.kind == "i"  # counts stay integers
    with pytest.raises(ValueError, match="step_distances contains NaN"):
        CollisionRecord(**good | {"step_distances": np.array([np.nan])})
    with pytest.raises(ValueError, match="largest_collision_gap must be finite"):
        CollisionRecord(**good | {"largest_collision_gap": -np.inf})
    assert CollisionRecord(**good | {"collisions": np.array([0]), "largest_collision_gap": -np.inf})
    assert CollisionRecord(**good | {"pair_counts": np.zeros((0, 2, 2)), "smallest_shrink": np.inf})
    with pytest.raises(ParameterTypeError, match="extent must be a real number"):
        CollisionRecord(**good | {"extent": None})
    with pytest.raises(ParameterTypeError, match="d must be an integer"):
        SystemConstants("2", 1.0, 0.5, 1.0, 1)
    with pytest.raises(ValueError, match="hyperbolicity must be finite"):
        SystemConstants(2, 1.0, np.nan, 1.0, 1)
    assert SystemConstants(2, 1.0, 0.5, 1.0, 1).constant_over_stability == 2.0
