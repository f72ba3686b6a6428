"""Measures of the long-time behaviour (particle_methods.ltp.measures) on sizes, particles and densities
whose answer is known: finite-time collapse against exponential and algebraic shrinking, Dirac masses
against a spread of particles, one smooth bump against ripples."""

import math

import numpy as np
import pytest

from particle_methods.ltp.measures import (
    collapse_times,
    excess_variation,
    peak_count,
    shrink_rate_inverse,
    shrink_rate_ratios,
    side_concentration,
)

WINDOWS = [(0.25, 0.5), (0.5, 0.75), (0.75, 1.0)]


# collapse_times and shrink_rate_inverse


def test_shrink_rate_inverse_of_a_power_collapse_falls_linearly_to_zero():
    t = np.linspace(0.0, 1.9, 191)
    g = shrink_rate_inverse(t, (2.0 - t) ** 2)
    np.testing.assert_allclose(g[1:-1], (2.0 - t[1:-1]) / 2, rtol=5e-3)


def test_shrink_rate_inverse_is_constant_for_exponential_and_infinite_for_a_constant_size():
    t = 0.25 * np.arange(17)  # exactly spaced: the centred differences of a constant are exactly 0
    np.testing.assert_allclose(shrink_rate_inverse(t, 3.0 * np.exp(-0.5 * t)), 2.0, rtol=1e-10)
    assert np.all(np.isinf(shrink_rate_inverse(t, np.full(t.size, 0.3))))


def test_power_collapse_gives_negative_slopes_and_its_collapse_time_from_every_window():
    t = np.linspace(0.0, 1.9, 191)
    slopes, collapse = collapse_times(t, (2.0 - t) ** 2, WINDOWS)
    np.testing.assert_allclose(slopes, -0.5, rtol=1e-2)
    np.testing.assert_allclose(collapse, 2.0, rtol=1e-3)


@pytest.mark.parametrize("stop", [1.5, 1.8, 1.95])
def test_collapse_time_does_not_depend_on_where_the_run_stops(stop):
    t = np.linspace(0.0, stop, 301)
    _, collapse = collapse_times(t, (2.0 - t) ** 2, WINDOWS)
    np.testing.assert_allclose(collapse, 2.0, rtol=1e-3)


def test_collapse_time_of_another_power_is_found_too():
    t = np.linspace(0.0, 2.9, 291)
    slopes, collapse = collapse_times(t, 0.1 * (3.0 - t) ** 0.5, WINDOWS)
    np.testing.assert_allclose(slopes, -2.0, rtol=1e-2)
    np.testing.assert_allclose(collapse, 3.0, rtol=1e-3)


def test_exponential_shrinking_gives_zero_slopes_and_no_collapse():
    t = np.linspace(0.0, 4.0, 201)
    slopes, collapse = collapse_times(t, np.exp(-t), WINDOWS)
    assert np.all(np.abs(slopes) < 1e-12)
    # A slope of -1e-15 (rounding) extrapolates to a collapse at ~1e14: no finite-time collapse either.
    assert np.all(collapse > 1e10)


def test_algebraic_shrinking_gives_positive_slopes_and_no_collapse():
    t = np.linspace(0.0, 4.0, 201)
    slopes, collapse = collapse_times(t, (1.0 + t) ** -2.0, WINDOWS)
    np.testing.assert_allclose(slopes, 0.5, rtol=1e-2)
    assert np.all(np.isinf(collapse))


# shrink_rate_ratios

FLOOR = math.log1p(0.01) / 10.0  # the steady rate of a 1 % change per window of 10


def test_shrink_rate_ratios_of_exponential_sizes_are_one_and_start_two_windows_after_since():
    t = np.linspace(0.0, 60.0, 121)
    ends, ratios = shrink_rate_ratios(t, 0.5 * np.exp(-0.1 * t), 10.0, 10.0, FLOOR)
    assert ends[0] == pytest.approx(30.0) and ends[-1] == pytest.approx(60.0)
    np.testing.assert_allclose(ratios, 1.0, rtol=1e-9)


def test_shrink_rate_ratios_grow_when_the_shrinking_speeds_up():
    t = np.linspace(0.0, 60.0, 121)
    _, ratios = shrink_rate_ratios(t, np.exp(-0.002 * t**2), 10.0, 10.0, FLOOR)
    # rates 0.002 (2 t - 10): the ratio over t = 30 is 50/30
    assert ratios[0] == pytest.approx(5.0 / 3.0) and np.all(ratios > 1.0)


@pytest.mark.parametrize("sizes", [lambda t: 0.3 + 0.2 * np.exp(-0.5 * t), lambda t: np.full(t.size, 0.2),
                                   lambda t: 0.2 / (1.0 + t)], ids=["settling", "settled", "algebraic"])
def test_shrink_rate_ratios_fall_below_one_for_a_width_that_settles_or_slows(sizes):
    t = np.linspace(0.0, 60.0, 121)
    _, ratios = shrink_rate_ratios(t, sizes(t), 10.0, 10.0, FLOOR)
    assert ratios.min() < 0.7


def test_shrink_rate_ratios_of_a_settled_size_with_rounding_noise_are_near_zero():
    t = np.linspace(0.0, 60.0, 121)
    noisy = 0.2 * (1.0 + 1e-15 * np.random.default_rng(0).standard_normal(t.size))
    _, ratios = shrink_rate_ratios(t, noisy, 10.0, 10.0, FLOOR)  # tiny rates of either sign: not shrinking
    assert np.abs(ratios).max() < 1e-9


def test_shrink_rate_ratios_take_whole_windows_with_coarse_records_and_refuse_short_runs():
    ends, ratios = shrink_rate_ratios([0.0, 1.0, 2.0, 3.0], [8.0, 4.0, 1.0, 0.25], 1.0, 0.0, FLOOR)
    np.testing.assert_allclose(ends, [2.0, 3.0])
    np.testing.assert_allclose(ratios, [2.0, 1.0])
    with pytest.raises(ValueError, match="two windows"):
        shrink_rate_ratios(np.linspace(0.0, 60.0, 121), np.ones(121), 10.0, 41.0, FLOOR)
    with pytest.raises(ValueError, match="floor"):
        shrink_rate_ratios(np.linspace(0.0, 60.0, 121), np.ones(121), 10.0, 10.0, 0.0)
    with pytest.raises(ValueError, match="increasing"):
        shrink_rate_ratios([0.0, 2.0, 1.0], np.ones(3), 0.5, 0.0, FLOOR)


# side_concentration


def test_two_tight_clusters_have_widths_of_their_spread_and_all_the_mass_near_their_peaks():
    spread = 1e-3
    offsets = np.linspace(-spread / 2, spread / 2, 101)
    centres = np.concatenate([-0.5 + offsets, 0.5 + offsets])
    weights = np.full(centres.size, 1.0 / centres.size)
    peak_values = np.exp(-(((np.abs(centres) - 0.5) / spread) ** 2))
    widths, masses = side_concentration(centres, weights, peak_values, 0.9, 0.01)
    np.testing.assert_allclose(widths, 0.9 * spread, rtol=0.02)
    np.testing.assert_allclose(masses, 0.5)
    assert masses.sum() == pytest.approx(1.0)


def test_uniform_particles_have_wide_widths_and_a_radius_share_of_mass():
    half = 1.0
    centres = np.linspace(-half, half, 2001)
    centres = centres[centres != 0.0]
    weights = np.full(centres.size, 1.0 / centres.size)
    peak_values = 1.0 - np.abs(np.abs(centres) - 0.5)  # densest at +-0.5, inside each side
    radius = 0.01
    widths, masses = side_concentration(centres, weights, peak_values, 0.9, radius)
    np.testing.assert_allclose(widths, 0.9 * half, rtol=0.01)
    np.testing.assert_allclose(masses, radius / half, rtol=0.1)  # 2 radius of the total length 2 half


def test_a_particle_at_zero_is_on_neither_side():
    centres = np.array([-0.5, 0.0, 0.5])
    weights = np.array([0.25, 0.5, 0.25])
    widths, masses = side_concentration(centres, weights, np.ones(3), 0.9, 0.1)
    np.testing.assert_allclose(widths, 0.0)
    np.testing.assert_allclose(masses, [0.25, 0.25])  # the middle half of the mass is counted on neither side


@pytest.mark.parametrize("middle", [0.0, 1e-17, -1e-17, 7e-16, -7e-16])
def test_a_particle_within_rounding_of_zero_is_on_neither_side(middle):
    """The particle at 0 of a symmetric run drifts by rounding to either side: the sides' widths must not
    depend on where (with it on a side, the width holding 0.9 of that side's mass would change)."""
    centres = np.array([-0.6, -0.5, -0.4, middle, 0.4, 0.5, 0.6])
    weights = np.array([0.1, 0.2, 0.1, 0.2, 0.1, 0.2, 0.1])
    widths, masses = side_concentration(centres, weights, np.ones(7), 0.9, 0.05)
    reference = side_concentration(np.delete(centres, 3), np.delete(weights, 3), np.ones(6), 0.9, 0.05)
    np.testing.assert_array_equal(widths, reference[0])
    np.testing.assert_allclose(masses, reference[1] * 0.8)  # the same side masses, of a total that includes it


def test_a_particle_beyond_rounding_of_zero_is_on_its_side():
    centres = np.array([-0.6, -0.5, -0.4, 1e-6, 0.4, 0.5, 0.6])
    weights = np.array([0.1, 0.2, 0.1, 0.2, 0.1, 0.2, 0.1])
    widths, _ = side_concentration(centres, weights, np.ones(7), 0.9, 0.05)
    assert widths[0] == pytest.approx(0.2) and widths[1] > 0.3


def test_side_concentration_picks_the_densest_particle_of_each_side():
    centres = np.array([-0.9, -0.2, 0.3, 0.8])
    weights = np.full(4, 0.25)
    widths, masses = side_concentration(centres, weights, np.array([1.0, 2.0, 1.0, 3.0]), 1.0, 0.05)
    np.testing.assert_allclose(widths, [0.7, 0.5])
    np.testing.assert_allclose(masses, [0.25, 0.25])


# peak_count


X = np.linspace(-1.1, 1.1, 2201)


def bump(centre, width=0.1, height=1.0):
    return height * np.exp(-(((X - centre) / width) ** 2))


def test_one_smooth_bump_counts_one():
    assert peak_count(bump(0.0), 0.05) == 1


def test_two_bumps_count_two():
    assert peak_count(bump(-0.5) + bump(0.5), 0.05) == 2


def test_a_one_percent_bump_on_a_big_one_is_not_counted():
    density = bump(0.0, 0.5) + bump(0.1, 0.005, 0.01)  # on the big one's shoulder
    assert peak_count(density, 1e-9) == 2  # it is a local maximum ...
    assert peak_count(density, 0.05) == 1  # ... but not a peak at prominence 0.05


def test_an_isolated_small_bump_counts_since_prominence_is_relative_to_its_own_height():
    assert peak_count(bump(-0.5) + bump(0.6, 0.02, 0.01), 0.05) == 2


def test_a_rippled_density_counts_its_ripples():
    envelope = np.clip(1.0 - X**2, 0.0, None)
    ripples = envelope * (1.0 + 0.3 * np.cos(2 * np.pi * X / 0.1))
    assert peak_count(ripples, 0.05) == 19  # one ripple every 0.1 on (-1, 1), the end ones washed out
    assert peak_count(envelope, 0.05) == 1


# excess_variation


def test_excess_variation_of_one_bump_per_side_is_at_most_zero():
    assert excess_variation(X, bump(-0.5) + bump(0.5)) == pytest.approx(0.0, abs=1e-6)
    assert excess_variation(X, bump(-0.5, 0.4) + bump(0.5, 0.4)) < 0  # a valley between them


def test_excess_variation_grows_with_ripples_and_a_lone_small_bump_adds_its_height():
    rippled = (bump(-0.5, 0.2) + bump(0.5, 0.2)) * (1.0 + 0.3 * np.cos(2 * np.pi * X / 0.05))
    assert excess_variation(X, rippled) > 1.0
    lone = bump(-0.5) + bump(0.5) + bump(0.0, 0.005, 0.02)
    assert excess_variation(X, lone) == pytest.approx(2 * 0.02 / (2 * (1.0 + 1.0)), rel=0.05)  # up and down


# bad inputs


@pytest.mark.parametrize("call", [
    lambda: shrink_rate_inverse([0.0, 1.0, 2.0], [1.0, 0.5]),
    lambda: shrink_rate_ratios([0.0, 1.0, 2.0], [1.0, 0.5], 1.0, 0.0, 0.1),
    lambda: side_concentration([-1.0, 1.0], [0.5, 0.5], [1.0], 0.9, 0.1),
    lambda: excess_variation([0.0, 1.0], [1.0]),
], ids=["shrink_rate_inverse", "shrink_rate_ratios", "side_concentration", "excess_variation"])
def test_mismatched_lengths_raise(call):
    with pytest.raises(ValueError, match="mismatched"):
        call()


@pytest.mark.parametrize("sizes", [[1.0, 0.0, 0.5], [1.0, -0.1, 0.5]])
def test_non_positive_sizes_raise(sizes):
    with pytest.raises(ValueError, match="positive"):
        shrink_rate_inverse([0.0, 1.0, 2.0], sizes)
    with pytest.raises(ValueError, match="positive"):
        collapse_times([0.0, 1.0, 2.0], sizes, [(0.0, 1.0)])
    with pytest.raises(ValueError, match="positive"):
        shrink_rate_ratios([0.0, 1.0, 2.0], sizes, 1.0, 0.0, 0.1)


def test_too_few_records_raise():
    with pytest.raises(ValueError, match="three records"):
        shrink_rate_inverse([0.0, 1.0], [1.0, 0.5])
    with pytest.raises(ValueError, match="increasing"):
        shrink_rate_inverse([0.0, 2.0, 1.0], [1.0, 0.5, 0.2])
    t = np.linspace(0.0, 1.0, 11)
    with pytest.raises(ValueError, match="windows: the window .* holds fewer than 3 records"):
        collapse_times(t, np.exp(-t), [(0.0, 0.1)])  # two records in the window


def test_a_window_of_constant_size_raises():
    t = 0.125 * np.arange(9)  # exactly spaced, so that g is exactly infinite
    with pytest.raises(ValueError, match="where g is finite"):
        collapse_times(t, np.ones(t.size), [(0.0, 1.0)])


@pytest.mark.parametrize("call", [
    lambda: shrink_rate_inverse([0.0, 1.0, math.nan], [1.0, 0.5, 0.2]),
    lambda: collapse_times([0.0, 1.0, 2.0], [1.0, math.nan, 0.2], [(0.0, 1.0)]),
    lambda: shrink_rate_ratios([0.0, 1.0, 2.0], [1.0, math.nan, 0.2], 1.0, 0.0, 0.1),
    lambda: side_concentration([-1.0, math.nan], [0.5, 0.5], [1.0, 1.0], 0.9, 0.1),
    lambda: peak_count([0.0, math.nan, 0.0]),
    lambda: excess_variation([-1.0, 0.0, 1.0], [0.0, math.inf, 0.0]),
], ids=["shrink_rate_inverse", "collapse_times", "shrink_rate_ratios", "side_concentration", "peak_count",
        "excess_variation"])
def test_nan_raises(call):
    with pytest.raises(ValueError, match="NaN"):
        call()


def test_side_concentration_rejects_bad_parameters():
    centres, weights = np.array([-0.5, 0.5]), np.array([0.5, 0.5])
    with pytest.raises(ValueError, match="both sides"):
        side_concentration(np.array([0.2, 0.5]), weights, np.ones(2), 0.9, 0.1)
    with pytest.raises(ValueError, match="fraction"):
        side_concentration(centres, weights, np.ones(2), 1.5, 0.1)
    with pytest.raises(ValueError, match="radius"):
        side_concentration(centres, weights, np.ones(2), 0.9, 0.0)
    with pytest.raises(ValueError, match="positive sum"):
        side_concentration(centres, np.zeros(2), np.ones(2), 0.9, 0.1)


def test_peak_count_and_excess_variation_reject_bad_parameters():
    with pytest.raises(ValueError, match="prominence"):
        peak_count(bump(0.0), 0.0)
    with pytest.raises(ValueError, match="both sides"):
        excess_variation(X, bump(0.5) * (X > 0))
    with pytest.raises(ValueError, match="increasing"):
        excess_variation(X[::-1], bump(0.5))


def test_profile_changes_bounds_every_and_side_concentration_names_the_centres():
    """Census (issue 46): ``every`` = 10**40 overflowed numpy's integers (OverflowError), and 'both sides of
    x = 0 need particles' named no parameter."""
    from particle_methods.ltp import potential, simulate
    from particle_methods.ltp.measures import profile_changes
    from particle_methods.ltp.solver import MAX_STEPS

    sim = simulate("rho2", potential("power", a=1.5), 0.5, 0.05, 0.1, record_every=1)
    assert profile_changes(sim, 0.05, every=2)[0].tolist() == [0.1]
    assert profile_changes(sim, 0.05, every=MAX_STEPS + 1)[0].size == 0  # record 0 only, with none before it
    with pytest.raises(ValueError, match="every must be at most"):
        profile_changes(sim, 0.05, every=10**40)
    with pytest.raises(ValueError, match="centres must hold particles on both sides"):
        side_concentration(np.array([0.2, 0.5]), np.array([0.5, 0.5]), np.ones(2), 0.9, 0.1)
