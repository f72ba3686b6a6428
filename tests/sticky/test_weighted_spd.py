"""SPD with particle masses: the weighted hull against the weighted event-driven simulation and conservation laws."""

import numpy as np
import pytest
from scipy.optimize import isotonic_regression

from particle_methods.sticky import (
    burgers_flux,
    cluster_sizes,
    concave_flux,
    spd_positions,
    spd_trajectories,
    velocities_from_flux,
    velocities_from_levels,
)
from particle_methods.sticky.events import sticky_collisions
from particle_methods.validation import ParameterTypeError


def weighted_state(rng, n, rounded=False):
    """Sorted positions (coinciding ones if ``rounded``), velocities and masses spanning 1e-3..1."""
    x = np.sort(rng.normal(size=n))
    if rounded:
        x = np.round(x, 1)
    return x, rng.normal(size=n), 10.0 ** rng.uniform(-3, 0, size=n)


def first_collision(x, v):
    """Time of the first collision of the free motion (inf if none)."""
    approach = v[:-1] - v[1:]
    closing = approach > 0
    return float(np.min(np.diff(x)[closing] / approach[closing])) if np.any(closing) else np.inf


def cluster_masses(positions, masses):
    """Mass of each cluster (run of equal positions)."""
    ends = np.cumsum(cluster_sizes(positions))
    return np.add.reduceat(masses, ends - cluster_sizes(positions))


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("rounded", [False, True])
def test_weighted_hull_matches_weighted_event_driven_collisions(seed, rounded):
    rng = np.random.default_rng(seed)
    for n in (1, 2, 3, 10, 57, 200):
        x, v, masses = weighted_state(rng, n, rounded)
        first = first_collision(x, v)
        times = [0.0, float(rng.uniform(0, 3)), 10.0]
        if np.isfinite(first):
            times += [first / 2, first, first * (1 + 1e-9), 2 * first]  # before, at and after the first collision
        for t in times:
            scale = np.abs(x).max() + t * np.abs(v).max()
            expected = sticky_collisions(x, v, t, masses)
            np.testing.assert_allclose(spd_positions(x, v, t, masses), expected, rtol=0, atol=1e-10 * scale)
        np.testing.assert_allclose(spd_trajectories(x, v, times, masses)[-1], spd_positions(x, v, times[-1], masses),
                                   rtol=0, atol=0)


def test_weighted_hull_is_the_weighted_isotonic_regression(rng):
    """The positions are the mass-weighted L2 projection of the free positions onto D_n."""
    x, v, masses = weighted_state(rng, 20000)
    for t in (0.1, 1.5):
        expected = isotonic_regression(x + t * v, weights=masses).x
        np.testing.assert_allclose(spd_positions(x, v, t, masses), expected, rtol=0, atol=1e-11)


@pytest.mark.parametrize("c", [2.0**-10, 1.0, 2.0**700, 2.0**-1000])
def test_equal_power_of_two_masses_reproduce_the_equal_mass_kernel_exactly(rng, c):
    """Scaling masses by a power of two is exact, and unit masses are the counts of the equal-mass kernel."""
    x, v, _ = weighted_state(rng, 3000)
    masses = np.full(x.size, c)
    for t in (0.0, 0.7, 4.0):
        np.testing.assert_array_equal(spd_positions(x, v, t, masses), spd_positions(x, v, t))
    np.testing.assert_array_equal(sticky_collisions(x[:300], v[:300], 0.7, masses[:300]),
                                  sticky_collisions(x[:300], v[:300], 0.7))


@pytest.mark.parametrize("c", [1e-3, 1 / 3000, 0.3, 7.5, 1e250, 1e-300])
def test_equal_masses_give_the_equal_mass_dynamics(rng, c):
    x, v, _ = weighted_state(rng, 3000, rounded=True)
    times = [0.0, 0.2, 1.0, 5.0]
    masses = np.full(x.size, c)
    np.testing.assert_allclose(spd_trajectories(x, v, times, masses), spd_trajectories(x, v, times),
                               rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(sticky_collisions(x[:200], v[:200], 1.0, masses[:200]),
                               sticky_collisions(x[:200], v[:200], 1.0), rtol=1e-13, atol=1e-13)


def test_any_positive_total_gives_the_same_positions(rng):
    x, v, masses = weighted_state(rng, 1000)
    reference = spd_positions(x, v, 1.0, masses)
    for factor in (1e-300, 1e-5, 3.0, 1e300):
        np.testing.assert_allclose(spd_positions(x, v, 1.0, masses * factor), reference, rtol=1e-14, atol=1e-14)


def test_two_particles_merge_with_conservation_of_momentum():
    x, v, masses = [0.0, 1.0], [1.0, -1.0], [3.0, 1.0]
    # They meet at t = 1/2 at 1/2, then move at (3 * 1 + 1 * (-1)) / 4 = 1/2.
    np.testing.assert_allclose(spd_positions(x, v, 0.25, masses), [0.25, 0.75])
    for t in (0.5, 1.0, 3.0):
        expected = 0.5 + (t - 0.5) * 0.5
        np.testing.assert_allclose(spd_positions(x, v, t, masses), [expected, expected])
        np.testing.assert_allclose(sticky_collisions(x, v, t, masses), [expected, expected])


@pytest.mark.parametrize("seed", range(4))
def test_cluster_mass_and_momentum_are_conserved(seed):
    rng = np.random.default_rng(seed)
    x, v, masses = weighted_state(rng, 500)
    total = masses.sum()
    earlier = None
    for t in (0.0, 0.05, 0.4, 2.0, 20.0):
        positions = spd_positions(x, v, t, masses)
        assert np.all(np.diff(positions) >= 0)
        sizes = cluster_sizes(positions)
        weights = cluster_masses(positions, masses)
        assert weights.sum() == pytest.approx(total, rel=1e-14)
        # Each cluster sits at the mass-weighted mean of its free positions (its momentum is conserved).
        starts = np.cumsum(sizes) - sizes
        free_momentum = np.add.reduceat(masses * (x + t * v), starts)
        np.testing.assert_allclose(positions[starts], free_momentum / weights, rtol=0, atol=1e-12 * (1 + t))
        # Clusters only merge: a cluster of an earlier time lies within one cluster now.
        if earlier is not None:
            assert np.all(np.diff(positions)[np.diff(earlier) == 0] == 0)
            assert sizes.size <= cluster_sizes(earlier).size
        earlier = positions
    # Flow property: restarting at time s with the same velocities and masses changes nothing.
    np.testing.assert_allclose(spd_positions(spd_positions(x, v, 0.4, masses), v, 1.6, masses),
                               spd_positions(x, v, 2.0, masses), rtol=0, atol=1e-11)


@pytest.mark.parametrize("flux", [burgers_flux, concave_flux])
def test_equal_levels_give_velocities_from_flux(flux):
    for n in (1, 8, 1000):
        np.testing.assert_allclose(velocities_from_levels(flux, np.arange(n + 1) / n), velocities_from_flux(flux, n),
                                   rtol=1e-12, atol=1e-14)


def test_levels_velocities_are_the_particle_method_with_kernel_abs_over_two(rng):
    """Lambda(F) = M F / 2 - F^2 / 2 gives v_k = (mass to the right - mass to the left) / 2 (K = |x| / 2)."""
    masses = 10.0 ** rng.uniform(-3, 0, size=300)
    total = masses.sum()
    levels = np.concatenate(([0.0], np.cumsum(masses)))
    velocities = velocities_from_levels(lambda c: total * c / 2 - c**2 / 2, levels)
    right = np.array([masses[k + 1:].sum() for k in range(masses.size)])
    left = np.array([masses[:k].sum() for k in range(masses.size)])
    np.testing.assert_allclose(velocities, (right - left) / 2, rtol=0, atol=1e-11 * total)


def test_clusters_move_at_the_rankine_hugoniot_speed_of_their_levels(rng):
    """With velocities_from_levels a cluster's momentum telescopes to a flux difference (Remark 3.3)."""
    x, _, masses = weighted_state(rng, 400)
    levels = np.concatenate(([0.0], np.cumsum(masses)))
    v = velocities_from_levels(concave_flux, levels / levels[-1])
    t0, t1 = 1.0, 1.5
    start, end = spd_positions(x, v, t0, masses), spd_positions(x, v, t1, masses)
    sizes = cluster_sizes(end)
    for first, size in zip(np.cumsum(sizes) - sizes, sizes):
        last = first + size
        if np.all(start[first:last] == start[first]):  # one cluster already at t0: it moved at its speed since
            low, high = levels[first] / levels[-1], levels[last] / levels[-1]
            speed = (concave_flux(high) - concave_flux(low)) / (high - low)
            assert end[first] - start[first] == pytest.approx((t1 - t0) * speed, abs=1e-11)


BAD_MASSES = [
    ([1.0, 1.0], "mismatched array lengths: x has 3, masses has 2"),
    ([1.0, 0.0, 1.0], "masses must be positive"),
    ([1.0, -1.0, 1.0], "masses must be positive"),
    ([1.0, np.nan, 1.0], "masses contains NaN"),
    ([1.0, np.inf, 1.0], "masses contains NaN"),
    ("abc", "masses must be an array"),
    (np.array(["a", "b", "c"]), "masses must hold real numbers"),
    ([1.0, 1j, 1.0], "masses must hold real numbers"),
    (np.ones((1, 3)), "masses must be a 1-dimensional array"),
    (2.0, "masses must be a 1-dimensional array"),
    ([1.0, 1e-200, 1e200], "MAX_MASS_RATIO"),
]


@pytest.mark.parametrize("masses, message", BAD_MASSES)
@pytest.mark.parametrize("call", [
    lambda masses: spd_positions([0.0, 1.0, 2.0], [1.0, 0.0, -1.0], 1.0, masses),
    lambda masses: spd_trajectories([0.0, 1.0, 2.0], [1.0, 0.0, -1.0], [0.0, 1.0], masses),
    lambda masses: spd_trajectories([0.0, 1.0, 2.0], [1.0, 0.0, -1.0], [], masses),
    lambda masses: sticky_collisions([0.0, 1.0, 2.0], [1.0, 0.0, -1.0], 1.0, masses),
])
def test_bad_masses_are_rejected_with_their_name(call, masses, message):
    with pytest.raises((ValueError, TypeError), match=message):
        call(masses)


def test_string_masses_raise_the_type_error():
    with pytest.raises(ParameterTypeError):
        spd_positions([0.0, 1.0], [0.0, 0.0], 1.0, "ab")


def test_heavy_masses_do_not_overflow_and_far_positions_are_refused():
    # Masses near the largest double are scaled: the sums of the hull stay finite.
    np.testing.assert_allclose(spd_positions([0.0, 1.0], [1.0, -1.0], 1.0, [1e308, 1e308]), [0.5, 0.5])
    with pytest.raises(ValueError, match="reduce t or v"):
        spd_positions([0.0, 1.0, 2.0], [1e308, 0.0, -1e308], 1.0, [1.0, 2.0, 3.0])


@pytest.mark.parametrize("flux, levels, message", [
    (burgers_flux, [0.0], "number of levels n \\+ 1 must be at least 2"),
    (burgers_flux, [0.1, 0.5, 1.0], "levels must start at c_0 = 0"),
    (burgers_flux, [0.0, 0.5, 0.5, 1.0], "levels must increase strictly \\(index 2"),
    (burgers_flux, [0.0, 1.7e308, -1.7e308], "levels must increase strictly"),
    (burgers_flux, [0.0, np.nan], "levels contains NaN"),
    (burgers_flux, "0 1", "levels must be an array"),
    (burgers_flux, [[0.0, 1.0]], "levels must be a 1-dimensional array"),
    (None, [0.0, 1.0], "flux must be callable"),
    (lambda c: c[:-1], [0.0, 0.5, 1.0], "flux must return one value per level"),
    (lambda c: 1e308 * (-1.0) ** np.arange(c.size), [0.0, 0.5, 1.0], "velocity .* is not finite"),
    (np.sign, [0.0, 5e-324, 1.0], "differ too much across narrow levels"),  # a jump of 1 over 5e-324
])
def test_bad_levels_and_fluxes(flux, levels, message):
    with pytest.raises((ValueError, TypeError), match=message):
        velocities_from_levels(flux, levels)
