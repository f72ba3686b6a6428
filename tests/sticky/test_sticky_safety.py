"""Safe API of the sticky-particle package: every public entry point fuzzed, and the reviewer's cases.

Each call must return finite values or raise ValueError/TypeError naming one of its parameters;
:func:`fuzzing.safe_call` fails on anything else, on a non-finite result and on a hang.
"""

import numpy as np
import pytest
from fuzzing import FUZZ, bad_array, bad_scalar, extreme, naming, safe_call, watchdog
from hypothesis import given
from hypothesis import strategies as st

from particle_methods.norms import w1_to_measure
from particle_methods.sticky import (
    Atoms,
    BurgersSolution,
    ConcaveLaplaceSolution,
    Laplace,
    Pareto,
    PSystem,
    QuantileMeasure,
    TruncatedExponential,
    TruncatedPareto,
    Uniform,
    Weibull,
    averaged_quantiles,
    burgers_flux,
    cluster_sizes,
    concave_flux,
    median_quantiles,
    mspd_exact,
    mspd_positions,
    mspd_trajectory,
    rank_velocities,
    spd_positions,
    spd_trajectories,
    velocities_from_flux,
    velocities_from_levels,
)
from particle_methods.sticky.cases import empirical_cdf, psystem_initial_measures
from particle_methods.sticky.events import sticky_collisions
from particle_methods.sticky.hull_reference import cumulative_free_positions, hull_vertices
from particle_methods.sticky.mspd import MAX_STEPS
from particle_methods.validation import ParameterTypeError

# Counts beyond every work limit: refused at once, whatever else is passed.
HUGE_COUNTS = [10**9, 2**63, 10**400]
finite_lists = st.lists(st.one_of(extreme, st.floats(-10, 10)), min_size=1, max_size=6)
huge_lists = st.lists(st.sampled_from([1.7e308, -1.7e308, 1e308, -1e308]), min_size=1, max_size=4)  # overflows


def scalar(good):
    return st.one_of(st.just(good), bad_scalar, extreme, st.sampled_from([5e-324, 1e8, 1e300, 1.7e308]))


def count(good):
    return st.one_of(st.just(good), bad_scalar, st.integers(-2, 8), st.sampled_from(HUGE_COUNTS))


def array(good, ordered=False):
    drawn = st.one_of(finite_lists, huge_lists).map(sorted if ordered else list).map(np.array)
    return st.one_of(st.just(np.asarray(good, dtype=float)), bad_array, drawn)


class System:
    """A diagonal system whose attributes the tests choose: d and speed_primitive."""

    def __init__(self, d, primitive):
        self.d, self.primitive_kernel = d, primitive

    def speed_primitive(self, gamma, levels):
        return self.primitive_kernel(levels)


SYSTEMS = [
    PSystem(),
    None,
    "p-system",
    System(2, lambda levels: levels[:, 0] - levels[:, 1]),  # valid
    System(2.0, lambda levels: levels[:, 0]),  # d not an integer
    System(2, lambda levels: np.full(levels.shape[0], np.nan)),
    System(2, lambda levels: 1e308 * (-1.0) ** np.arange(levels.shape[0])),  # differences overflow
    System(2, lambda levels: levels[:, 0] + 1j),
    System(2, lambda levels: 1.0),  # one value instead of one per particle
    System(3, lambda levels: levels[:, 0]),
]
FLUXES = [burgers_flux, concave_flux, None, "u^2/2", lambda u: np.nan * u, lambda u: 1.0, lambda u: u + 1j,
          lambda u: 1e308 * (-1.0) ** np.arange(np.size(u))]


def two_rows(length):
    row = st.lists(st.one_of(extreme, st.floats(-10, 10)), min_size=length, max_size=length).map(sorted)
    return st.tuples(row, row).map(np.array)


CONFIGURATIONS = st.one_of(st.just(np.vstack([np.linspace(0.0, 1.0, 5)] * 2)), bad_array,
                           st.integers(1, 4).flatmap(two_rows))


def states(n):
    """Positions and velocities of n particles, extreme values included."""
    row = st.lists(st.one_of(extreme, st.floats(-10, 10), st.sampled_from([1e300, -1e300])), min_size=n, max_size=n)
    return st.tuples(row.map(sorted), row).map(lambda pair: tuple(map(np.array, pair)))


def weighted_states(n):
    """Positions, velocities and None (equal masses) or n positive masses, extreme ones included."""
    masses = st.lists(st.one_of(st.sampled_from([5e-324, 1e-300, 1e300, 1.7e308]), st.floats(1e-3, 1e3)),
                      min_size=n, max_size=n).map(np.array)
    return st.tuples(states(n), st.one_of(st.none(), masses)).map(lambda pair: (*pair[0], pair[1]))


@FUZZ
@given(state=st.one_of(st.tuples(array([0.0, 0.5, 1.0], ordered=True), array([1.0, 0.0, -1.0]),
                                 st.one_of(st.none(), array([1.0, 0.5, 2.0]))),
                       st.integers(1, 5).flatmap(weighted_states)),
       t=scalar(1.0), times=array([0.0, 0.5, 2.0]))
def test_spd_entry_points(state, t, times):
    x, v, masses = state
    safe_call(naming(spd_positions, "x", "v", "t", "particles", "masses"), x, v, t, masses)
    safe_call(naming(spd_trajectories, "x", "v", "times", "particles", "masses"), x, v, times, masses)
    safe_call(naming(sticky_collisions, "x", "v", "t", "particles", "masses"), x, v, t, masses)
    safe_call(naming(cumulative_free_positions, "x", "v", "t", "particles"), x, v, t)
    safe_call(naming(hull_vertices, "q"), x)
    safe_call(naming(cluster_sizes, "positions"), x)
    safe_call(naming(empirical_cdf, "points", "x"), x, v)


@FUZZ
@given(flux=st.sampled_from(FLUXES), n=count(5), u=array([0.0, 0.5, 1.0]),
       levels=st.one_of(array([0.0, 0.25, 1.0], ordered=True),  # and from c_0 = 0, extreme widths included:
                        st.lists(st.one_of(extreme, st.floats(0, 10)), min_size=1, max_size=5)
                        .map(lambda c: np.array([0.0, *sorted(c)]))))
def test_fluxes_and_initial_velocities(flux, n, u, levels):
    safe_call(naming(velocities_from_flux, "flux", "n"), flux, n)
    safe_call(naming(velocities_from_levels, "flux", "levels"), flux, levels)
    safe_call(naming(burgers_flux, "u"), u)
    safe_call(naming(concave_flux, "u"), u)



MEASURES = st.one_of(  # (class, constructor arguments): built inside the test, under safe_call
    st.tuples(st.just(Laplace), st.tuples(scalar(0.0))),
    st.tuples(st.just(Uniform), st.tuples(scalar(0.0), scalar(1.0))),
    st.tuples(st.just(TruncatedExponential), st.tuples(scalar(1.0))),
    st.tuples(st.just(Pareto), st.tuples(scalar(3.0))),
    st.tuples(st.just(TruncatedPareto), st.tuples(scalar(1.0), scalar(100.0))),
    st.tuples(st.just(Weibull), st.tuples(scalar(0.5))),
    st.tuples(st.just(Atoms), st.tuples(array([-1.0, 1.0], ordered=True))),
    st.tuples(st.just(Atoms), st.tuples(array([-1.0, 1.0], ordered=True), array([0.25, 0.75]))),
    st.tuples(st.just(BurgersSolution),
              st.tuples(st.sampled_from([Atoms([-1.0, 1.0]), Laplace(), None, "delta_0"]), scalar(2.0))),
    st.tuples(st.just(ConcaveLaplaceSolution), st.tuples(scalar(3.0))),
)
PARAMETERS = ("loc", "a", "b", "alpha", "upper", "positions", "weights", "initial", "t")


@FUZZ
@given(made=MEASURES, w=array([0.0, 0.3, 1.0]), x=array([-2.0, 0.0, 3.0]), n=count(7),
       points=array([-1.0, 0.0, 2.0], ordered=True))
def test_measures_and_their_discretisations(made, w, x, n, points):
    kind, arguments = made
    measure = safe_call(naming(kind, *PARAMETERS), *arguments)
    for candidate in (measure, None, Laplace):  # a class is not a measure
        safe_call(naming(median_quantiles, "measure", "n"), candidate, n)
        safe_call(naming(averaged_quantiles, "measure", "n"), candidate, n)
        safe_call(naming(w1_to_measure, "measure", "points"), candidate, points)
    if measure is not None:
        safe_call(naming(measure.quantile, "w"), w)
        safe_call(naming(measure.quantile_integral, "w"), w)
        safe_call(naming(measure.cdf, "x"), x)


@FUZZ
@given(case=st.sampled_from(["rarefaction", "shocks", "vacuum", None]), x0=scalar(0.1))
def test_psystem_cases(case, x0):
    safe_call(naming(psystem_initial_measures, "case", "x0"), case, x0)


@FUZZ
@given(nu=scalar(0.5), kappa=scalar(5.0), u=array([0.0, 0.2, 0.5]), v=array([1.0, -1.0, 0.0]),
       w_minus=array([0.0, 0.5, 1.0]), w_plus=array([1.0, 0.5, 0.0]), gamma=count(1),
       levels=st.one_of(st.just(np.array([[0.2, 0.7], [1.0, 0.0]])), bad_array, array([0.5, 0.5])))
def test_psystem(nu, kappa, u, v, w_minus, w_plus, gamma, levels):
    system = safe_call(naming(PSystem, "nu", "kappa"), nu, kappa)
    if system is None:
        return
    for method in (system.pressure, system.sound_speed, system.g):
        safe_call(naming(method, "u"), u)
    safe_call(naming(system.riemann_invariants, "u", "v"), u, v)
    safe_call(naming(system.physical_variables, "w_minus", "w_plus"), w_minus, w_plus)
    safe_call(naming(system.speeds, "w_minus", "w_plus"), w_minus, w_plus)
    safe_call(naming(system.speed_primitive, "gamma", "levels"), gamma, levels)


@FUZZ
@given(x0=CONFIGURATIONS, system=st.sampled_from(SYSTEMS), delta=scalar(0.1),
       steps=st.one_of(count(3), st.just(MAX_STEPS + 1)))
def test_mspd(x0, system, delta, steps):
    names = ("x", "system", "Delta", "steps", "particles", "velocities")
    safe_call(naming(rank_velocities, *names), x0, system)
    safe_call(naming(mspd_trajectory, *names), x0, system, delta, steps)
    safe_call(naming(mspd_positions, *names), x0, system, delta, steps)
    safe_call(naming(mspd_exact, "x0", "system", "times", "velocities"), x0, system, [0.0, delta])


CONFIGURATION = np.vstack([np.linspace(0.0, 1.0, 6)] * 2)


class Wild(QuantileMeasure):
    """A user's measure whose quantile integral swings by 2e308: differences overflow."""

    def _quantile(self, w):
        return w

    def _quantile_integral(self, w):
        return 1e308 * (-1.0) ** np.arange(w.size)


@pytest.mark.parametrize("call, error, message", [
    # Overflow of x + v t: was NaN.
    (lambda: spd_positions([0, 0.5, 1], [1e308, 0, -1e308], 10.0), ValueError, "reduce t or v"),
    (lambda: spd_positions([0, 0.5, 1], [1e308, 0, -1e308], 10.0, [1.0, 1e-3, 1e3]), ValueError, "reduce t or v"),
    # Masses: positive, one per particle, at most MAX_MASS_RATIO apart.
    (lambda: spd_positions([0.0, 1.0], [0.0, 0.0], 1.0, [1.0, 0.0]), ValueError, "masses must be positive"),
    (lambda: spd_trajectories([0.0, 1.0], [0.0, 0.0], [1.0], [1.0]), ValueError, "masses has 1"),
    (lambda: sticky_collisions([0.0, 1.0], [0.0, 0.0], 1.0, [5e-324, 1.7e308]), ValueError, "MAX_MASS_RATIO"),
    (lambda: velocities_from_levels(burgers_flux, [0.25, 1.0]), ValueError, "levels must start at c_0 = 0"),
    (lambda: mspd_trajectory(CONFIGURATION, PSystem(), 1e308, 5), ValueError, "reduce Delta"),
    # Gamma(1 + 1/alpha) overflowed: was NaN.
    (lambda: averaged_quantiles(Weibull(1e-300), 10), ValueError, "alpha must be at least"),
    # Hung: 10**7 steps.
    (lambda: mspd_positions(CONFIGURATION, PSystem(), 0.1, 10**7), ValueError, "steps must be at most 1000000"),
    # None for data, system or measure: was AttributeError or an unnamed TypeError.
    (lambda: spd_positions(None, [0.0], 1.0), ParameterTypeError, "x must be"),
    (lambda: mspd_positions(None, PSystem(), 0.1, 1), ParameterTypeError, "x0 must be"),
    (lambda: mspd_positions(CONFIGURATION, None, 0.1, 1), ParameterTypeError, "system must be"),
    (lambda: rank_velocities(CONFIGURATION, System(None, np.sum)), ParameterTypeError, "system.d"),
    (lambda: median_quantiles(None, 4), ParameterTypeError, "measure must be a QuantileMeasure"),
    (lambda: averaged_quantiles(None, 4), ParameterTypeError, "measure must be a QuantileMeasure"),
    (lambda: w1_to_measure(None, [0.0]), ParameterTypeError, "measure must provide"),
    (lambda: BurgersSolution(None, 1.0), ParameterTypeError, "initial must be a QuantileMeasure"),
    (lambda: hull_vertices(None), ParameterTypeError, "q must be"),
    (lambda: PSystem().speed_primitive(0, None), ParameterTypeError, "levels must be"),
    # Complex input lost its imaginary part with a warning only.
    (lambda: spd_positions([0.0, 1.0], [1j, 0.0], 1.0), ParameterTypeError, "v must hold real numbers"),
    (lambda: Laplace().quantile(0.5 + 0.1j), ParameterTypeError, "w must hold real numbers"),
    (lambda: burgers_flux([1j]), ParameterTypeError, "u must hold real numbers"),
    # 10**400 gave OverflowError.
    (lambda: spd_positions([0.0, 1.0], [0.0, 0.0], 10**400), ValueError, "t is beyond the double-precision range"),
    (lambda: median_quantiles(Laplace(), 10**400), ValueError, "n must be at most"),
    (lambda: mspd_positions(CONFIGURATION, PSystem(), 0.1, 10**400), ValueError, "steps must be at most"),
    (lambda: Laplace(10**400), ValueError, "loc is beyond"),
    (lambda: PSystem(nu=10**400), ValueError, "nu is beyond"),
    # Work limits other than the step count, refused before any work.
    (lambda: mspd_positions(np.zeros((2, 10**5)), PSystem(), 0.1, 10**5), ValueError, "MAX_WORK"),
    (lambda: mspd_trajectory(np.zeros((2, 1000)), PSystem(), 0.1, 10**5), ValueError, "MAX_POSITIONS"),
    (lambda: spd_trajectories(np.zeros(20001), np.zeros(20001), np.zeros(5000)), ValueError, "MAX_POSITIONS"),
    (lambda: sticky_collisions(np.zeros(10**4 + 1), np.zeros(10**4 + 1), 1.0), ValueError, "MAX_PARTICLES"),
    # Measure parameters that made quantiles or moments non-finite, or left no digits.
    (lambda: Laplace().quantile([0.0, 0.5]), ValueError, "w is 0 or 1 at an unbounded end"),
    (lambda: Pareto(3.0).quantile(1.0), ValueError, "w is 0 or 1 at an unbounded end"),
    (lambda: Uniform(-1e308, 1e308), ValueError, "b - a must be finite"),
    (lambda: Uniform(0.0, np.nan), ValueError, "b must be finite"),
    (lambda: TruncatedExponential(1e-300), ValueError, "b must be at least"),
    (lambda: TruncatedExponential(-1.0), ValueError, "b must be positive"),
    (lambda: TruncatedPareto(1e-300, 2.0), ValueError, "alpha log"),
    (lambda: TruncatedPareto(2.0, 1.0), ValueError, "upper must exceed 1"),
    (lambda: Weibull(np.nan), ValueError, "alpha must be finite"),
    (lambda: Atoms([0.0, 1.0], [0.5, np.nan]), ValueError, "weights contains NaN"),
    (lambda: Atoms([-1.0, 1.0], [0.5, 0.5, 0.0]), ValueError, "one per position"),
    (lambda: averaged_quantiles(Wild(), 3), ValueError, r"a position \(1.9\) is not finite"),
    (lambda: PSystem(nu=1e-300), ValueError, "nu = 1e-300 and kappa = 5.0 give speeds beyond"),
    # Exact solutions: times and positions.
    (lambda: BurgersSolution(Laplace(), np.inf), ValueError, "t must be finite"),
    (lambda: ConcaveLaplaceSolution(-1.0), ValueError, "t must be non-negative"),
    (lambda: ConcaveLaplaceSolution(5e-324), ValueError, "t must be 0 or at least"),
    (lambda: ConcaveLaplaceSolution(3.0).cdf([0.0, np.nan]), ValueError, "x contains NaN"),
    (lambda: BurgersSolution(Laplace(1.5e308), 1e308).quantile(0.9), ValueError, "the quantile F"),
    (lambda: ConcaveLaplaceSolution(3.0).quantile_integral(1.5), ValueError, r"w must lie in \[0.0, 1.0\]"),
    # Values a system or a flux returns are checked before the compiled kernel sees them.
    (lambda: rank_velocities(CONFIGURATION, System(2, lambda levels: np.nan * levels[:, 0])), ValueError,
     "velocities"),
    (lambda: rank_velocities(CONFIGURATION, System(2, lambda levels: levels[:3, 0])), ValueError,
     r"speed_primitive\(0, levels\) must return one value per particle"),
    (lambda: velocities_from_flux(lambda u: u[:-1], 4), ValueError, "flux must return one value per level"),
    (lambda: burgers_flux(1e200), ValueError, "u is too large"),
])
def test_rejected_with_the_parameter_named(call, error, message):
    with watchdog(), pytest.raises(error, match=message):
        call()


def test_values_stay_finite_where_they_are_defined():
    assert np.isfinite(Laplace().quantile_integral([0.0, 1.0])).all()  # G is finite at both ends
    assert np.isfinite(Weibull(1 / 170).quantile_integral([0.5, 1.0])).all()  # the smallest alpha allowed
    assert np.isfinite(ConcaveLaplaceSolution(1e300).quantile(np.linspace(0, 1, 5))).all()  # all in the shock
    np.testing.assert_array_equal(ConcaveLaplaceSolution(0.0).cdf([0.0]), Laplace().cdf([0.0]))


def test_the_harness_fails_on_nan_and_on_an_unnamed_error():
    with pytest.raises(AssertionError, match="non-finite"):
        safe_call(lambda: np.array([1.0, np.nan]))

    def anonymous(x):
        raise ValueError("something is wrong")

    with pytest.raises(AssertionError, match="names none of"):
        safe_call(naming(anonymous, "x0"), 1.0)
    np.testing.assert_array_equal(safe_call(spd_positions, [0.0], [1.0], 1.0), [1.0])
