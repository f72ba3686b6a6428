"""Exact MSPD (event-driven): the scalar SPD, the iterated TSPD's limit, invariants, event counts,
the compiled p-system primitive against the Python one, and n = 20,000 per type in O(n d) memory."""

import math
import tracemalloc

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from particle_methods.finite_volume import burgers_flux, concave_flux
from particle_methods.norms import w1_between_samples
from particle_methods.sticky import mspd_exact
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import ScalarLaw, mspd_positions, rank_velocities
from particle_methods.sticky.multitype_events import (
    MAX_EVENTS,
    MAX_PYTHON_EVENTS,
    PRIMITIVE_WAYS,
    _primitive_formula,
    _primitive_of_spread,
    _primitive_table,
    _Run,
)
from particle_methods.sticky.spd import cluster_sizes, spd_positions, velocities_from_flux
from particle_methods.systems import MINUS, PLUS, PSystem

SYSTEM = PSystem()
CASES = {"rarefaction": 0.1, "shocks": -4.0}


class ThreeFields:
    """d = 3, lambda^g = s_g + eps (w_1 + w_2 + w_3) with s = (2, 0, -2): (USH) holds for eps < 2/3."""

    d = 3

    def __init__(self, eps=0.3):
        self.eps = eps

    def speed_primitive(self, gamma, levels):
        own = levels[..., gamma]
        others = levels.sum(axis=-1) - own
        return (2.0 - 2.0 * gamma) * own + self.eps * (0.5 * own**2 + own * others)


class PythonPSystem(PSystem):
    """The p-system with its primitive called from Python: mspd_exact takes the path of any user system."""

    def speed_primitive(self, gamma, levels):
        return super().speed_primitive(gamma, levels)


class SlowsDown:
    """d = 2, lambda^0 = 1 - 3 w^1 and lambda^1 = -0.3: (USH) holds at the start of the run below (w^1 = 0 for
    every particle of type 0) and fails once a particle of type 0 has passed 4 of the 8 of type 1."""

    d = 2

    def speed_primitive(self, gamma, levels):
        own = levels[..., gamma]
        return own * (1.0 - 3.0 * levels[..., 1]) if gamma == 0 else -0.3 * own


def distance(a, b):
    return sum(w1_between_samples(x, y) for x, y in zip(a, b))


@pytest.mark.parametrize("flux", [burgers_flux, concave_flux])
def test_one_type_is_the_spd(rng, flux):
    x = np.sort(rng.normal(size=120))
    x[40:52] = x[40]  # a group at one place: the SPD splits it by its velocities
    times = [0.0, 0.2, 1.0, 7.0]
    out = mspd_exact(x[None], ScalarLaw(flux), times)
    for row, t in zip(out, times):
        np.testing.assert_allclose(row[0], spd_positions(x, velocities_from_flux(flux, x.size), t), atol=1e-12)


def test_moves_at_the_rank_velocities_until_the_first_event(rng):
    x = np.sort(rng.normal(size=(2, 8)), axis=1)
    t = 1e-7  # far below the first meeting time of this draw
    moved = mspd_exact(x, SYSTEM, [t])[0]
    np.testing.assert_allclose((moved - x) / t, rank_velocities(x, SYSTEM), rtol=1e-7)


@pytest.mark.parametrize("ties", [False, True])
def test_three_types_are_the_limit_of_the_iterated_tspd(rng, ties):
    # With ties, clusters of the three types start at the same places: simultaneous meetings.
    system = ThreeFields()
    x = np.sort(rng.normal(size=(3, 12)) * [[1.0], [0.5], [1.5]], axis=1)
    if ties:
        x = np.sort(np.round(x), axis=1)
    exact, events = mspd_exact(x, system, [1.0], return_events=True)
    assert events.crossings > 10
    errors = [distance(mspd_positions(x, system, delta, round(1.0 / delta)), exact[0]) for delta in (0.01, 0.001)]
    assert errors[1] < 0.2 * errors[0]


@pytest.mark.parametrize("case", sorted(CASES))
def test_iterated_tspd_converges_at_first_order_in_delta(case):
    # Proposition 4.1 at fixed n: the iterated TSPD is within C Delta of the MSPD.
    x = psystem_initial_configuration(case, CASES[case], 20)
    exact = mspd_exact(x, SYSTEM, [1.0])[0]
    deltas = np.array([0.02, 0.01, 0.005, 0.0025])
    errors = [distance(mspd_positions(x, SYSTEM, delta, round(1.0 / delta)), exact) for delta in deltas]
    slope = np.polyfit(np.log(deltas), np.log(errors), 1)[0]
    assert 0.8 < slope < 1.3, (slope, errors)


def test_rarefaction_case_keeps_order_and_never_sticks():
    # Section 5.2.2: x+_k <= x-_k for all k is preserved, and particles of one type never meet.
    x = psystem_initial_configuration("rarefaction", CASES["rarefaction"], 40)
    assert np.all(x[PLUS] <= x[MINUS])
    times = np.linspace(0.0, 4.0, 41)
    out, events = mspd_exact(x, SYSTEM, times, return_events=True)
    assert events.merges == 0 and events.splits == 0
    assert np.all(out[:, PLUS] <= out[:, MINUS])
    assert all(cluster_sizes(row).max() == 1 for state in out for row in state)
    assert np.all(np.diff(out, axis=2) > 0)


def test_every_crossing_is_one_pair_changing_order():
    # With singletons only, a crossing is a - particle passing a + particle: count the pairs whose
    # order changed between 0 and t.
    x = psystem_initial_configuration("rarefaction", CASES["rarefaction"], 30)
    t = 1.5
    out, events = mspd_exact(x, SYSTEM, [t], return_events=True)
    before = x[MINUS][:, None] < x[PLUS][None, :]
    after = out[0, MINUS][:, None] > out[0, PLUS][None, :]
    assert events.crossings == np.sum(before & after) > 0
    assert events.member_updates == 2 * events.crossings


def test_shock_case_cluster_forms_then_splits():
    # Figure 6: the + particles start as one cluster at 0 and break up after crossing the - particles.
    n = 40
    x = psystem_initial_configuration("shocks", CASES["shocks"], n)
    out, events = mspd_exact(x, SYSTEM, [0.3, 12.0], return_events=True)
    assert cluster_sizes(out[0, PLUS]).max() == n
    assert cluster_sizes(out[1, PLUS]).max() == 1 and cluster_sizes(out[1, MINUS]).max() == 1
    assert np.all(out[1, PLUS] <= out[1, MINUS])
    assert events.splits > 0 and events.merges > 0


@pytest.mark.parametrize("case", sorted(CASES))
def test_flow_property(case):
    # Restarting from the state at s gives the state at s + t (clusters stay one block).
    x = psystem_initial_configuration(case, CASES[case], 25)
    s, t = 0.9, 1.3
    middle, end = mspd_exact(x, SYSTEM, [s, s + t])
    np.testing.assert_allclose(mspd_exact(middle, SYSTEM, [t])[0], end, atol=1e-9)


@pytest.mark.parametrize("case", sorted(CASES))
def test_events_grow_like_n_squared(case):
    counts = []
    for n in (100, 200):
        _, events = mspd_exact(psystem_initial_configuration(case, CASES[case], n), SYSTEM, [2.0], return_events=True)
        counts.append(events.crossings)
    assert 3.5 < counts[1] / counts[0] < 4.5


def test_times_are_kept_in_order_and_time_zero_is_the_start(rng):
    x = np.sort(rng.normal(size=(2, 10)), axis=1)
    out = mspd_exact(x, SYSTEM, [0.0, 0.5, 0.5, 2.0])
    assert out.shape == (4, 2, 10)
    np.testing.assert_array_equal(out[0], x)
    np.testing.assert_array_equal(out[1], out[2])


@settings(max_examples=40, deadline=None, derandomize=True)
@given(rows=st.lists(st.lists(st.sampled_from([-1.0, -0.5, 0.0, 0.25, 1.0, 2.0]), min_size=5, max_size=5),
                     min_size=2, max_size=2),
       t=st.floats(0.0, 5.0))
def test_random_ties_give_sorted_rows_and_match_the_iterated_tspd(rows, t):
    # Ties inside and across types on purpose: the post-collisional order and the splits decide.
    x = np.sort(np.array(rows), axis=1)
    out = mspd_exact(x, SYSTEM, [t])[0]
    assert np.all(np.isfinite(out)) and np.all(np.diff(out, axis=1) >= 0)
    steps = 2000
    approx = mspd_positions(x, SYSTEM, max(t, 1e-9) / steps, steps) if t > 0 else x
    assert distance(out, approx) < 2e-2


def test_refuses_a_system_without_uniform_strict_hyperbolicity():
    class Equal:
        d = 2

        def speed_primitive(self, gamma, levels):
            return levels[..., gamma]  # both speeds 1

    with pytest.raises(ValueError, match="USH"):
        mspd_exact(np.zeros((2, 3)), Equal(), [1.0])


@pytest.mark.parametrize("args, error, message", [
    ((np.zeros((3, 4)), SYSTEM, [1.0]), ValueError, "one row per type"),
    ((np.array([[1.0, 0.0], [0.0, 1.0]]), SYSTEM, [1.0]), ValueError, "sorted"),
    ((np.array([[0.0, np.nan], [0.0, 1.0]]), SYSTEM, [1.0]), ValueError, "NaN"),
    ((np.zeros((2, 4)), None, [1.0]), TypeError, "system must be"),
    ((np.zeros((2, 4)), SYSTEM, []), ValueError, "times must contain"),
    ((np.zeros((2, 4)), SYSTEM, [1.0, 0.5]), ValueError, "non-decreasing"),
    ((np.zeros((2, 4)), SYSTEM, [-1.0]), ValueError, "non-negative"),
    ((np.zeros((2, 4)), SYSTEM, [np.inf]), ValueError, "times contains NaN or infinite"),
    ((np.zeros((2, 4)), SYSTEM, "1"), TypeError, "times must be"),
    ((np.zeros((2, math.isqrt(int(MAX_EVENTS)) + 1)), SYSTEM, [1.0]), ValueError, "MAX_EVENTS"),
    ((np.zeros((2, math.isqrt(MAX_PYTHON_EVENTS) + 1)), PythonPSystem(), [1.0]), ValueError, "MAX_PYTHON_EVENTS"),
    ((np.zeros((2, 50_000)), SYSTEM, np.zeros(1001)), ValueError, "MAX_POSITIONS"),
    ((np.array([[0.0, 1.0], [0.0, 1.0]]), SYSTEM, [1e308]), ValueError, "may overflow"),
])
def test_bad_input_is_refused(args, error, message):
    with pytest.raises(error, match=message):
        mspd_exact(*args)


def test_return_events_must_be_a_bool():
    with pytest.raises(TypeError, match="return_events"):
        mspd_exact(np.zeros((2, 3)), SYSTEM, [1.0], return_events="yes")


def test_the_old_table_limit_is_gone():
    # The velocity table of d (n+1)^d values stopped the call at n = 4999 per type; the crossing bound
    # d(d-1)n^2/2 + d n is now the only limit on n, and admits the cost study's 25,600 per type for a p-system.
    n = 25_600
    assert n * n + 2 * n <= MAX_EVENTS
    assert MAX_PYTHON_EVENTS < n * n  # a Python primitive is called at every crossing: far fewer


@pytest.mark.parametrize("case", sorted(CASES))
def test_compiled_primitive_gives_the_python_primitives_dynamics(case):
    # The compiled p-system path evaluates the primitive with libm; the Python path calls
    # PSystem.speed_primitive (NumPy) at the same levels, which is what the velocity table held: the two
    # agree to rounding, with the same events.
    x = psystem_initial_configuration(case, CASES[case], 100)
    compiled, events = mspd_exact(x, SYSTEM, [0.5, 2.0], return_events=True)
    python, python_events = mspd_exact(x, PythonPSystem(), [0.5, 2.0], return_events=True)
    assert events == python_events and events.crossings > 3000
    assert np.abs(compiled - python).max() <= 1e-12 * np.abs(python).max()


def test_primitive_table_gives_the_formulas_values_bit_for_bit():
    # The compiled loops keep the primitive's values per difference of counts, for the last PRIMITIVE_WAYS
    # doubles the spread rounds to: every value it returns is the formula's at that very double, also on a
    # difference with more doubles than a row keeps (the oldest evicted), in any order, asked again.
    n = 6400
    levels = np.arange(n + 1) / n
    counts = np.arange(n + 1)
    # Of the differences 1 to 399, the one whose spreads fl(c/n) - fl(k/n) round to the most distinct doubles.
    difference = max(range(1, 400), key=lambda i: np.unique(levels[counts[i:]] - levels[counts[i:] - i]).size)
    pairs = [(c, c - difference) for c in range(difference, n + 1)]
    assert len({levels[c] - levels[k] for c, k in pairs}) > PRIMITIVE_WAYS
    rng = np.random.default_rng(3)
    random = [tuple(pair) for pair in rng.integers(0, n + 1, size=(2000, 2))]
    asked = [pairs[i] for i in rng.integers(0, len(pairs), size=2000)] + random + random[::-1]
    table = _primitive_table(n)
    a, coefficient = SYSTEM.a, SYSTEM.primitive_coefficient
    for c, k in asked:
        spread = levels[c] - levels[k]
        kept = _primitive_of_spread(spread, c - k + n, table, a, coefficient)
        assert np.float64(kept).tobytes() == np.float64(_primitive_formula(spread, a, coefficient)).tobytes()


def test_refuses_velocities_that_break_ush_during_the_run():
    # The velocities are computed event by event: (USH) is checked on each, not only on those at the start.
    n = 8
    x = np.array([np.linspace(-1.0, -0.3, n), np.linspace(0.0, 0.7, n)])
    start = rank_velocities(x, SlowsDown())
    assert start[0].min() > start[1].max()  # (USH) holds at the ranks of x
    np.testing.assert_allclose(mspd_exact(x, SlowsDown(), [0.1])[0], x + 0.1 * start, atol=1e-14)  # no event yet
    with pytest.raises(ValueError, match="USH"):
        mspd_exact(x, SlowsDown(), [10.0])


def pairs_behind(first, second):
    """Pairs (i, j) with first[i] < second[j] (both sorted): O(n log n), no n x n table."""
    return int(np.sum(second.size - np.searchsorted(second, first, side="right")))


def test_20000_particles_per_type_run_in_o_n_memory():
    # A configuration with no event (type 0 ahead, moving right; type 1 behind, moving left, each
    # spreading): the free flight at the velocities (1.8), n = 20,000 per type.
    n = 20_000
    x = np.array([np.linspace(1.0, 2.0, n), np.linspace(-2.0, -1.0, n)])
    mspd_exact(x[:, :10], SYSTEM, [1.0])  # compiled before measuring
    tracemalloc.start()
    try:
        out, events = mspd_exact(x, SYSTEM, [3.0], return_events=True)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert events == (0, 0, 0, 0)
    np.testing.assert_allclose(out[0], x + 3.0 * rank_velocities(x, SYSTEM), rtol=1e-10)
    # 6 MB measured: about 20 words per particle, where the table held d (n+1)^d / (d n) = 20,001.
    assert peak < 40 * 8 * x.size


def test_run_arrays_grow_linearly_in_n():
    # Every array of a run has d n rows (clusters) of at most d entries, or n entries: O(d^2 n) words; a
    # p-system's run (compiled, d = 2) adds the primitive's table, 2 n + 1 rows of 2 PRIMITIVE_WAYS words.
    kinds = [(2, False), (3, False), (2, True)]
    sizes = {(d, compiled, n): _Run.allocate(np.zeros((d, n)), compiled).nbytes() for d, compiled in kinds
             for n in (1000, 2000, 20_000)}
    for d, compiled in kinds:
        growth = sizes[d, compiled, 20_000] - sizes[d, compiled, 2000]
        assert growth == 18 * (sizes[d, compiled, 2000] - sizes[d, compiled, 1000])  # affine in n
        table = 8 * 2 * PRIMITIVE_WAYS * 2 / d if compiled else 0  # per particle: 2 n rows over d n particles
        assert growth / (18_000 * d) <= 8 * (16 + d) + table  # 13 arrays of d n entries, counts (d n, d), 2 of n


def test_20000_particles_per_type_cross_one_pair_at_a_time():
    # The rarefaction case with n = 20,000 per type up to t = 1e-3 (about 6e5 crossings): singletons only,
    # every crossing one (-, +) pair changing order, and the flow property.
    n = 20_000
    x = psystem_initial_configuration("rarefaction", CASES["rarefaction"], n)
    s, t = 4e-4, 1e-3
    (middle, end), events = mspd_exact(x, SYSTEM, [s, t], return_events=True)
    assert events.merges == 0 and events.splits == 0 and events.member_updates == 2 * events.crossings
    # A crossing puts a - particle ahead of a + particle: one more pair with the + particle behind.
    assert events.crossings == pairs_behind(end[PLUS], end[MINUS]) - pairs_behind(x[PLUS], x[MINUS]) > 10**5
    assert np.all(np.diff(end, axis=1) > 0)
    assert np.abs(end - x).max() <= t * SYSTEM.speed_scale * (1 + 1e-9)
    np.testing.assert_allclose(mspd_exact(middle, SYSTEM, [t - s])[0], end, rtol=0, atol=1e-9)
