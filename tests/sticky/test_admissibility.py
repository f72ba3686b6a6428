"""The exact test of Remark 3.3 (particle_methods.sticky.admissibility): it passes on the SPD of a concave
flux at every n and t, and fails where the remark does not apply (a convex flux: upward jumps are
rarefactions) and on plausible wrong dynamics (free flight with crossing, clusters that merge late)."""

import numpy as np
import pytest
from fuzzing import FUZZ, bad_array, bad_scalar, extreme, naming, safe_call
from hypothesis import given
from hypothesis import strategies as st

from particle_methods.sticky import admissibility_violation, spd_state
from particle_methods.sticky.admissibility import MAX_POINTS, Admissibility
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.spd import MAX_POSITIONS, spd_positions, velocities_from_flux, velocities_from_levels
from particle_methods.validation import ParameterTypeError

CONCAVE = SCALAR_CASES["concave_laplace"]
TWO_ATOMS = SCALAR_CASES["burgers_two_atoms"]
#: Rounding of the relative violations (speeds of order 1, jumps of at least 1/1000 here).
ROUNDING = 1e-12


def burgers(u):
    return 0.5 * np.asarray(u) ** 2


def initial(n, data="laplace"):
    """The concave flux's particles: the Laplace data (2.1) of Figure 3, symmetric (its clusters merge in
    pairs into a stationary shock at 0), or sorted normal samples (any x in D_n, Remark 3.3), not symmetric."""
    if data == "laplace":
        return CONCAVE.initial_state(n)
    return np.sort(np.random.default_rng(n).normal(size=n)), velocities_from_flux(CONCAVE.flux, n)


def concave_state(n, t, data="laplace"):
    return spd_state(*initial(n, data), t)


def free_flight(n, t):
    """No sticking: every particle keeps its initial velocity, and particles cross."""
    x, v = initial(n, "random")
    return x + t * v, v


def late_merge(n, t, lag=0.5):
    """The SPD's positions, but each particle still moves with its cluster of time t - lag: the clusters
    formed since then have not yet merged their momenta."""
    x, v = initial(n, "random")
    return spd_state(x, v, t)[0], spd_state(x, v, t - lag)[1]


def unweighted_merge(n, t, lag=0.5):
    """The SPD's positions; a cluster formed since t - lag moves at the plain mean of the velocities of the
    clusters it merged (momentum not conserved: a speed other than the Rankine-Hugoniot speed)."""
    x, v = initial(n, "random")
    positions, velocities = spd_state(x, v, t)
    before, speeds = spd_state(x, v, t - lag)
    for y in np.unique(positions):
        members = positions == y
        _, first = np.unique(before[members], return_index=True)
        velocities[members] = speeds[members][first].mean()
    return positions, velocities


@pytest.mark.parametrize("data", ["laplace", "random"])
@pytest.mark.parametrize("n", [1, 2, 3, 4, 7, 32, 100, 1000])
@pytest.mark.parametrize("t", [0.0, 1.0, 2.5, 5.0, 17.0, 100.0])
def test_the_spd_of_a_concave_flux_is_admissible_at_every_n_and_t(data, n, t):
    result = admissibility_violation(*concave_state(n, t, data), CONCAVE.flux)
    assert result.rankine_hugoniot <= ROUNDING and result.entropy == 0.0, result
    assert result.largest == max(result.rankine_hugoniot, result.entropy)
    assert 0.4 < result.speed_scale <= 0.5


def test_clusters_are_counted():
    assert admissibility_violation(*concave_state(32, 100.0), CONCAVE.flux).clusters == 1  # one shock at 0
    assert admissibility_violation(*concave_state(32, 0.0), CONCAVE.flux).clusters == 32


@pytest.mark.parametrize("n", [2, 8, 64])
@pytest.mark.parametrize("points", [1, 4, 9])
def test_burgers_from_two_atoms_violates_oleinik_by_the_predicted_amount(n, points):
    """Figure 2: every particle is its own cluster, a jump of h = 1/n at its Rankine-Hugoniot speed, but the
    chord of u^2/2 lies above the flux: (E) fails by h q/(2(q + 1)) at the state h/(q + 1) past u_-."""
    x, v = TWO_ATOMS.initial_state(n)
    result = admissibility_violation(*spd_state(x, v, 1.0), TWO_ATOMS.flux, points=points)
    assert result.rankine_hugoniot <= ROUNDING
    assert result.entropy * result.speed_scale == pytest.approx(points / (2 * (points + 1) * n), rel=1e-12)


def test_the_dirac_example_of_remark_33_is_not_admissible():
    n = 10
    positions, velocities = spd_state(np.zeros(n), velocities_from_flux(burgers, n), 2.0)
    assert admissibility_violation(positions, velocities, burgers).entropy > 0.01


def test_a_cluster_of_a_convex_flux_fails_between_its_levels_even_at_its_rankine_hugoniot_speed():
    """Two particles stuck together under Burgers' flux: the momentum is right, the shock is not."""
    velocities = velocities_from_flux(burgers, 2)
    result = admissibility_violation([0.0, 0.0], np.full(2, velocities.mean()), burgers, points=1)
    assert result.rankine_hugoniot <= ROUNDING and result.clusters == 1
    # sigma = 1/2; at u = 1/4, sigma - (Lambda(1/4) - Lambda(0)) / (1/4) = 3/8 (and as much at u = 3/4, from the
    # right), over the largest quotient (Lambda(1) - Lambda(3/4)) / (1/4) = 7/8
    assert result.entropy == pytest.approx(3 / 7, rel=1e-12)
    assert result.speed_scale == pytest.approx(7 / 8, rel=1e-12)


@pytest.mark.parametrize("dynamics", [free_flight, late_merge, unweighted_merge])
@pytest.mark.parametrize("t", [2.0, 3.0, 3.5])  # clusters of several particles merge in (t - 0.5, t]
def test_wrong_dynamics_move_clusters_at_other_speeds(dynamics, t):
    result = admissibility_violation(*dynamics(32, t), CONCAVE.flux)
    assert result.rankine_hugoniot > 1e-3, result


def test_free_flight_is_the_spd_until_the_first_collision():
    """Before any two particles meet (t < 2 for the Laplace data) free flight is the SPD: nothing to see."""
    x, v = initial(32)
    assert admissibility_violation(x + v, v, CONCAVE.flux).largest <= ROUNDING


def test_unequal_masses_use_the_levels_of_their_cumulative_masses():
    rng = np.random.default_rng(3)
    masses = rng.uniform(0.2, 1.0, 40)
    masses /= masses.sum()
    levels = np.concatenate(([0.0], np.cumsum(masses)))
    x = np.sort(rng.normal(size=40))
    v = velocities_from_levels(CONCAVE.flux, levels)
    for t in (0.0, 1.0, 4.0, 30.0):
        result = admissibility_violation(*spd_state(x, v, t, masses), CONCAVE.flux, masses=masses)
        assert result.largest <= ROUNDING, (t, result)
    # the same state read as equal masses puts the jumps at other levels: the speeds no longer match
    assert admissibility_violation(*spd_state(x, v, 4.0, masses), CONCAVE.flux).rankine_hugoniot > 1e-3


def test_the_order_of_the_particles_does_not_matter():
    rng = np.random.default_rng(4)
    positions, velocities = free_flight(32, 2.0)
    masses = rng.uniform(0.5, 1.5, 32)
    order = rng.permutation(32)
    assert (admissibility_violation(positions, velocities, CONCAVE.flux, masses)
            == admissibility_violation(positions[order], velocities[order], CONCAVE.flux, masses[order]))


def test_a_constant_flux_has_no_speed_and_no_violation():
    result = admissibility_violation([0.0, 0.0, 1.0], [0.0, 0.0, 0.0], lambda u: np.zeros_like(u))
    assert result == Admissibility(0.0, 0.0, 0.0, 2)


def test_spd_state_moves_each_cluster_at_its_mean_velocity():
    positions, velocities = spd_state([0.0, 1.0, 3.0], [2.0, 0.0, -1.0], 1.0)  # the first two meet at t = 1/2
    np.testing.assert_array_equal(positions, spd_positions([0.0, 1.0, 3.0], [2.0, 0.0, -1.0], 1.0))
    np.testing.assert_allclose(velocities, [1.0, 1.0, -1.0])
    _, weighted = spd_state([0.0, 1.0, 3.0], [2.0, 0.0, -1.0], 1.0, masses=[1.0, 3.0, 1.0])
    np.testing.assert_allclose(weighted, [0.5, 0.5, -1.0])
    _, huge = spd_state([0.0, 0.0], [1.7e308, 1.7e308], 0.0)  # a mean that a plain sum would overflow
    np.testing.assert_array_equal(huge, [1.7e308, 1.7e308])


@pytest.mark.parametrize("arguments, error, name", [
    ((None, [0.0], burgers), ParameterTypeError, "positions"),
    (("ab", [0.0], burgers), ParameterTypeError, "positions"),
    (([[0.0]], [0.0], burgers), ValueError, "positions"),
    (([np.nan], [0.0], burgers), ValueError, "positions"),
    (([], [], burgers), ValueError, "particles"),
    (([0.0], [1j], burgers), ParameterTypeError, "velocities"),
    (([0.0, 1.0], [0.0], burgers), ValueError, "velocities"),
    (([0.0], [np.inf], burgers), ValueError, "velocities"),
    (([0.0], [0.0], "u^2/2"), ParameterTypeError, "flux"),
    (([0.0], [0.0], lambda u: 1.0), ValueError, "flux"),
    (([0.0], [0.0], lambda u: np.nan * u), ValueError, "flux"),
    (([0.0], [0.0], lambda u: u + 1j), ParameterTypeError, "flux"),
    (([0.0, 1.0], [0.0, 0.0], lambda u: 1e308 * (-1.0) ** np.arange(np.size(u))), ValueError, "flux"),
    (([0.0], [0.0], lambda u: u[:-1]), ValueError, "flux"),
])
def test_bad_input_is_refused_naming_the_parameter(arguments, error, name):
    with pytest.raises(error, match=name):
        admissibility_violation(*arguments)


@pytest.mark.parametrize("masses, points, error, name", [
    ([1.0, -1.0], 4, ValueError, "masses"),
    ([1.0, 0.0], 4, ValueError, "masses"),
    ([1.0], 4, ValueError, "masses"),
    ([1.0, np.nan], 4, ValueError, "masses"),
    ("ab", 4, ParameterTypeError, "masses"),
    ([1.7e308, 1.7e308], 4, ValueError, "masses"),
    (None, 0, ValueError, "points"),
    (None, 1.5, ParameterTypeError, "points"),
    (None, True, ParameterTypeError, "points"),
    (None, MAX_POINTS + 1, ValueError, "points"),
])
def test_bad_masses_and_points_are_refused_naming_them(masses, points, error, name):
    with pytest.raises(error, match=name):
        admissibility_violation([0.0, 1.0], [0.0, 0.0], burgers, masses, points)


def test_the_sampled_states_are_bounded():
    n = MAX_POSITIONS // (MAX_POINTS + 1) + 1
    with pytest.raises(ValueError, match="points"):
        admissibility_violation(np.zeros(n), np.zeros(n), burgers, points=MAX_POINTS)


def rows(n):
    row = st.lists(st.one_of(extreme, st.floats(-10, 10)), min_size=n, max_size=n).map(np.array)
    masses = st.lists(st.one_of(st.sampled_from([5e-324, 1e-300, 1e300, 1.7e308]), st.floats(1e-3, 1e3)),
                      min_size=n, max_size=n).map(np.array)
    return st.tuples(row, row, st.one_of(st.none(), masses))


@FUZZ
@given(state=st.one_of(st.integers(1, 5).flatmap(rows), st.tuples(bad_array, bad_array, bad_array)),
       flux=st.sampled_from([burgers, CONCAVE.flux, None, lambda u: np.nan * u, lambda u: 1e300 * np.asarray(u),
                             lambda u: 1e308 * (-1.0) ** np.arange(np.size(u))]),
       points=st.one_of(st.integers(-1, 5), bad_scalar), t=st.one_of(st.floats(0, 10), bad_scalar))
def test_entry_points_return_finite_values_or_refuse(state, flux, points, t):
    positions, velocities, masses = state
    names = ("positions", "velocities", "flux", "masses", "points", "particles")
    result = safe_call(naming(admissibility_violation, *names), positions, velocities, flux, masses, points)
    if result is not None:
        assert np.isfinite([result.rankine_hugoniot, result.entropy, result.speed_scale]).all()
        assert result.rankine_hugoniot >= 0 and result.entropy >= 0
    safe_call(naming(spd_state, "x", "v", "t", "particles", "masses"), np.sort(positions) if
              isinstance(positions, np.ndarray) and positions.dtype.kind == "f" else positions, velocities, t, masses)


def test_the_helpers_check_their_arguments_by_name():
    """Issue 46 (census): flux_values took any callable and states, mass_levels indexed with any order."""
    from particle_methods.finite_volume import burgers_flux
    from particle_methods.sticky.admissibility import checked_sampling, flux_values, mass_levels

    with pytest.raises(ParameterTypeError, match="flux must be callable"):
        flux_values(None, np.array([0.0, 1.0]))
    with pytest.raises(ValueError, match="flux refused states: the Burgers flux"):
        flux_values(burgers_flux, np.array([0.0, 1e300]))
    with pytest.raises(ValueError, match="states contains NaN"):
        flux_values(burgers_flux, np.array([0.0, np.nan]))
    with pytest.raises(ParameterTypeError, match="fewest_points must be an integer"):
        checked_sampling(4, burgers_flux, 4, None)
    with pytest.raises(ValueError, match="points must be at least fewest_points = 255"):
        checked_sampling(4, burgers_flux, 4, 255)
    with pytest.raises(ValueError, match="particles contains NaN"):
        mass_levels([0.5, 0.5], [0.0, np.nan], np.array([0, 1]))
    with pytest.raises(ParameterTypeError, match="order must hold one integer index per particle"):
        mass_levels([0.5, 0.5], [0.0, 1.0], np.array([0.0, 1.0]))
    with pytest.raises(ValueError, match="order must be a permutation"):
        mass_levels([0.5, 0.5], [0.0, 1.0], np.array([0, 0]))
    with pytest.raises(ValueError, match="flux refused the levels of the masses"):
        admissibility_violation([0.0, 0.0, 1.0], [0.5, 0.5, -1.0], burgers_flux, [1e300, 1e300, 1e300], points=4)
