"""SPD by the hull algorithm against independent references and conservation laws."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import isotonic_regression

from particle_methods.finite_volume import burgers_flux, concave_flux
from particle_methods.sticky.events import sticky_collisions
from particle_methods.sticky.hull_reference import hull_vertices, spd_positions_python
from particle_methods.sticky.spd import cluster_sizes, spd_positions, spd_trajectories, velocities_from_flux


def random_state(rng, n, rounded=False):
    x = np.sort(rng.normal(size=n))
    if rounded:  # coinciding initial positions, as for atoms
        x = np.round(x, 1)
    return x, rng.normal(size=n)


@pytest.mark.parametrize("rounded", [False, True])
def test_hull_matches_event_driven_collisions(rng, rounded):
    for _ in range(150):
        n = int(rng.integers(1, 25))
        x, v = random_state(rng, n, rounded)
        t = float(rng.uniform(0, 4))
        np.testing.assert_allclose(spd_positions(x, v, t), sticky_collisions(x, v, t), atol=1e-10)


def test_hull_matches_paper_pseudocode_and_isotonic_regression(rng):
    x, v = random_state(rng, 2000)
    positions = spd_positions(x, v, 1.5)
    np.testing.assert_allclose(positions, spd_positions_python(x, v, 1.5), atol=1e-9)
    np.testing.assert_allclose(positions, isotonic_regression(x + 1.5 * v).x, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    n=st.integers(1, 40),
    seed=st.integers(0, 2**32 - 1),
    s=st.floats(0, 5),
    t=st.floats(0, 5),
)
def test_conservation_order_and_flow_property(n, seed, s, t):
    x, v = random_state(np.random.default_rng(seed), n)
    later = spd_positions(x, v, s + t)
    # Mass and momentum: the centre of mass moves at the mean velocity.
    assert later.mean() == pytest.approx(x.mean() + (s + t) * v.mean(), abs=1e-10)
    # Order preservation: positions stay in D_n.
    assert np.all(np.diff(later) >= -1e-12)
    # Flow property: restarting at time s with the same velocities changes nothing.
    np.testing.assert_allclose(spd_positions(spd_positions(x, v, s), v, t), later, atol=1e-9)


def test_positions_never_move_faster_than_fastest_particle(rng):
    x, v = random_state(rng, 500)
    t = 2.0
    displacement = spd_positions(x, v, t) - x
    assert np.all(displacement <= t * v.max() + 1e-12)
    assert np.all(displacement >= t * v.min() - 1e-12)


def test_trajectories_stack_positions(rng):
    x, v = random_state(rng, 50)
    times = [0.0, 0.3, 2.0]
    path = spd_trajectories(x, v, times)
    assert path.shape == (3, 50)
    for row, t in zip(path, times):
        np.testing.assert_array_equal(row, spd_positions(x, v, t))
    np.testing.assert_array_equal(path[0], x)


def test_velocities_from_flux_are_cell_averages_of_lambda():
    n = 8
    k = np.arange(1, n + 1)
    np.testing.assert_allclose(velocities_from_flux(burgers_flux, n), (2 * k - 1) / (2 * n))
    np.testing.assert_allclose(velocities_from_flux(concave_flux, n), 0.5 - (2 * k - 1) / (2 * n))


def test_cluster_sizes():
    np.testing.assert_array_equal(cluster_sizes([0.0, 0.0, 1.0, 2.0, 2.0, 2.0]), [2, 1, 3])
    x = np.zeros(6)
    v = velocities_from_flux(concave_flux, 6)  # decreasing speeds: everything sticks at once
    assert cluster_sizes(spd_positions(x, v, 1.0)).tolist() == [6]


def test_hull_pass_is_linear(rng):
    x, v = random_state(rng, 5000)
    q = np.concatenate(([0.0], np.cumsum(x + v)))
    history = []
    hull_vertices(q, trace=history)
    assert sum(len(step.removed) for step in history) <= len(q)


@pytest.mark.parametrize(
    "x, v, t, message",
    [
        ([1.0, 0.0], [0.0, 0.0], 1.0, "sorted"),
        ([0.0, np.nan], [0.0, 0.0], 1.0, "NaN"),
        ([0.0, 1.0], [0.0, np.inf], 1.0, "NaN or infinite"),
        ([0.0, 1.0], [0.0], 1.0, "mismatched"),
        ([], [], 1.0, "at least 1"),
        ([0.0, 1.0], [0.0, 0.0], -1.0, "t must be non-negative"),
        ([0.0, 1.0], [0.0, 0.0], np.nan, "t must be finite"),
        ([[0.0, 1.0]], [[0.0, 0.0]], 1.0, "1-dimensional"),
    ],
)
def test_bad_input_raises_clear_errors(x, v, t, message):
    with pytest.raises(ValueError, match=message):
        spd_positions(x, v, t)


def test_bad_flux_and_n():
    with pytest.raises(ValueError, match="n must be at least 1"):
        velocities_from_flux(burgers_flux, 0)
    with pytest.raises(ValueError, match="NaN"):
        velocities_from_flux(lambda u: np.where(u > 0.5, np.nan, u), 4)


def test_the_hull_counts_its_pushes_writes_tests_and_pops():
    """n pushes and n writes, a pop per merge (n - clusters of them), and a test before every merge and one that
    stops merging unless the stack emptied (at least once: the first particle): 3n + 2m - e, 1 <= e <= n - m."""
    rng = np.random.default_rng(3)
    n = 500
    x, v = np.sort(rng.uniform(size=n)), rng.normal(size=n)
    positions, operations = spd_positions(x, v, 0.7, return_operations=True)
    merges = n - cluster_sizes(positions).size
    assert merges > 0 and 3 * n + 2 * merges - (n - merges) <= operations <= 3 * n + 2 * merges - 1
    assert np.array_equal(positions, spd_positions(x, v, 0.7))
    _, free = spd_positions(x, np.sort(v), 0.7, return_operations=True)  # increasing velocities: no collision
    assert free == 3 * n - 1
    _, one = spd_positions(x, -np.sort(v) * 1e3, 0.7, return_operations=True)  # every particle merges at once
    assert one == 3 * n + 2 * (n - 1) - n
    with pytest.raises(TypeError, match="return_operations"):
        spd_positions(x, v, 0.7, return_operations=1)


def test_check_reach_checked_masses_and_hull_iterations_check_their_arguments():
    """Issue 46 (census): AttributeError, IndexError, NaN and any field accepted before."""
    from particle_methods.sticky.hull_reference import HullIteration
    from particle_methods.sticky.spd import check_reach, checked_masses
    from particle_methods.validation import ParameterTypeError

    with pytest.raises(ParameterTypeError, match="x must be an array"):
        check_reach(None, 1.0, 0.5)
    with pytest.raises(ValueError, match="x contains NaN"):
        check_reach(np.array([1.0, np.nan]), 1.0, 0.5)
    with pytest.raises(ValueError, match=r"speed \(max \|v\|\) must be finite"):
        check_reach(np.array([0.0, 1.0]), np.inf, 0.5)
    with pytest.raises(ValueError, match="t must be non-negative"):
        check_reach(np.array([0.0, 1.0]), 1.0, -1.0)
    with pytest.raises(ValueError, match=r"the speed max \|v\| is 1.7e\+308"):
        check_reach(np.array([0.0, 1.0]), 1.7e308, 0.5)
    with pytest.raises(ValueError, match="x must be an array of positions"):
        checked_masses([1.0], 3.0)
    with pytest.raises(ParameterTypeError, match="k must be an integer"):
        HullIteration(np.nan, (0,), (), (0, 1))
    with pytest.raises(ParameterTypeError, match="after must be a tuple of vertex indices"):
        HullIteration(1, (0,), (), None)
