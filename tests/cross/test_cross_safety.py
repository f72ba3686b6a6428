"""Safe API of the cross package: the exact solution and the W1 distances fuzzed.

Each call must return finite values or raise ValueError/TypeError naming one of its parameters;
:func:`fuzzing.safe_call` fails on anything else, on a non-finite result and on a hang. Where a call
returns, the values must also be what a cumulative mass function promises (within [0, M], non-decreasing
in x; a non-negative distance).
"""

import numpy as np
import pytest
from fuzzing import FUZZ, bad_array, bad_scalar, extreme, naming, safe_call
from hypothesis import given
from hypothesis import strategies as st

from particle_methods.blob.initial import DATA_1D, Data1D
from particle_methods.cross import aggregates, distances
from particle_methods.cross.exact import AggregationSolution, exact_mass_function
from particle_methods.cross.profiles import profile
from particle_methods.norms import l1_to_step_function
from particle_methods.sticky import ConcaveLaplaceSolution

DATA = st.sampled_from(["smooth20", "indicator", "smooth10", "laplace", DATA_1D["smooth20"], Data1D("p1", 1),
                        Data1D("p30", 30), None, "smooth30", 3, b"laplace", AggregationSolution])
HUGE = [1e300, -1e300, 1.7e308, -1.7e308]
finite_lists = st.lists(st.one_of(extreme, st.floats(-3, 3), st.sampled_from(HUGE)), min_size=0, max_size=6)


def scalar(good):
    """A good value, a bad one, an extreme one, or times around the blow-up (t = 1 for the polynomial data,
    2 for the Laplace law, 2/M for the full collapse of (4.3))."""
    return st.one_of(st.just(good), bad_scalar, extreme, st.floats(0, 10),
                     st.sampled_from([1.0, 2.0, 1.0 + 1e-12, 2.0 / DATA_1D["smooth20"].mass, 1e8, 1.7e308]))


def array(good, ordered=False):
    drawn = finite_lists.map(sorted if ordered else list).map(lambda values: np.array(values, dtype=float))
    return st.one_of(st.just(np.asarray(good, dtype=float)), bad_array, drawn, st.floats(-2, 2), extreme)


def levels(mass):
    """Levels w in [0, M] (the ends and values a rounding away included), and some outside it."""
    inside = st.one_of(st.floats(0.0, 1.0).map(lambda u: u * mass),
                       st.sampled_from([0.0, 5e-324, 1e-300, 1e-17, 0.5 * mass, mass * (1 - 1e-16), mass]))
    outside = st.sampled_from([-1e-300, -1.0, mass * (1 + 1e-15), 2 * mass + 1, np.nan, np.inf])
    return st.one_of(st.lists(inside, min_size=0, max_size=6).map(np.array), inside, outside, bad_array)


def check_cdf(solution, x, values):
    """F(t, x) lies in [0, M] and does not decrease in x (to 1e-7 M: exactly at the blow-up time the root
    next to 0 is found only to |a| ~ 1e-8, where the characteristic a - t m(a) ~ a^3 is flat; see
    test_cross_exact.py)."""
    values = np.asarray(values)
    assert values.shape == np.shape(x)
    assert np.all(values >= 0.0) and np.all(values <= solution.mass)
    flat_x, flat_values = np.ravel(x), values.ravel()
    order = np.argsort(flat_x, kind="stable")
    assert np.all(np.diff(flat_values[order]) >= -1e-7 * solution.mass)


@FUZZ
@given(data=DATA, t=scalar(1.1), x=array([-0.5, 0.0, 0.5]))
def test_exact_mass_function(data, t, x):
    safe_call(naming(profile, "data"), data)
    values = safe_call(naming(exact_mass_function, "data", "t", "x"), data, t, x)
    if values is not None:
        solution = AggregationSolution(data, t)
        check_cdf(solution, x, values)


@FUZZ
@given(data=DATA, t=scalar(1.1), x=array([-0.5, 0.0, 0.5]), w=st.data())
def test_aggregation_solution_methods(data, t, x, w):
    solution = safe_call(naming(AggregationSolution, "data", "t"), data, t)
    if solution is None:
        return
    assert 0.0 <= solution.level <= 0.5 * solution.mass
    assert 0.0 <= solution.dirac_mass <= solution.mass and 0.0 <= solution.collapse_radius
    values = safe_call(naming(solution.cdf, "x"), x)
    if values is not None:
        check_cdf(solution, x, values)
    safe_call(naming(solution.antiderivative, "x"), x)
    levels_drawn = w.draw(levels(solution.mass))
    quantiles = safe_call(naming(solution.quantile, "w"), levels_drawn)
    if quantiles is not None:
        assert np.shape(quantiles) == np.shape(levels_drawn)
    safe_call(naming(solution.quantile_integral, "w"), levels_drawn)


SOLUTIONS = [AggregationSolution(data, t) for data, t in
             [("smooth20", 0.5), ("smooth20", 1.1), ("indicator", 1.0), ("indicator", 1.5), ("laplace", 3.0),
              ("smooth10", 0.0)]]
MEASURES = st.sampled_from([*SOLUTIONS, ConcaveLaplaceSolution(2.5), None, "smooth20", AggregationSolution])


def masses_for(measure):
    """Masses adding up to the measure's mass (normalised random ones, one atom, some zeros), or not."""
    mass = float(getattr(measure, "mass", 1.0))
    weights = st.lists(st.one_of(st.floats(0.0, 1.0), st.sampled_from([0.0, 5e-324, 1e-300])), min_size=1,
                       max_size=6).map(np.array)
    normalised = weights.filter(lambda w: w.sum() > 1e-300).map(lambda w: w * (mass / w.sum()))
    return st.one_of(normalised, st.just(np.array([mass])), array([mass]), st.lists(st.sampled_from(
        [-1.0, 1e300, 1.7e308, mass]), min_size=1, max_size=4).map(np.array))


def step_values(measure, size):
    """``size`` values of a step function ending at the measure's mass (or not, or bad values)."""
    mass = float(getattr(measure, "mass", 1.0))
    values = st.lists(st.one_of(st.floats(0.0, 1.0).map(lambda u: u * mass), st.sampled_from(
        [0.0, mass, -1.0, 2.0 * mass, 1e300, -1.7e308])), min_size=size, max_size=size).map(np.array)
    ending = values.map(lambda v: np.append(v[:-1], mass) if v.size else v)
    return st.one_of(ending, values, bad_array)


@FUZZ
@given(measure=MEASURES, breaks=array([-1.0, 0.0, 1.0], ordered=True), drawn=st.data())
def test_l1_to_step_function(measure, breaks, drawn):
    size = np.size(breaks) if isinstance(breaks, np.ndarray) else 1
    values = drawn.draw(step_values(measure, max(size, 1)))
    distance = safe_call(naming(l1_to_step_function, "measure", "breaks", "values"), measure, breaks, values)
    assert distance is None or distance >= -1e-12


@FUZZ
@given(solution=MEASURES, positions=array([-0.5, 0.0, 0.5]), drawn=st.data())
def test_w1_atoms(solution, positions, drawn):
    masses = drawn.draw(masses_for(solution))
    if isinstance(positions, np.ndarray) and isinstance(masses, np.ndarray) and positions.ndim == masses.ndim == 1:
        positions = np.resize(positions, masses.size) if positions.size else positions
    distance = safe_call(naming(distances.w1_atoms, "solution", "positions", "masses"), solution,
                         positions, masses)
    assert distance is None or distance >= -1e-12


@FUZZ
@given(solution=MEASURES, edges=array([-1.0, 0.0, 1.0], ordered=True), drawn=st.data())
def test_w1_cells(solution, edges, drawn):
    cells = max(np.size(edges) - 1, 1) if isinstance(edges, np.ndarray) else 1
    values = drawn.draw(st.one_of(step_values(solution, cells), bad_array))
    distance = safe_call(naming(distances.w1_cells, "solution", "edges", "values"), solution, edges, values)
    assert distance is None or distance >= -1e-12


@FUZZ
@given(positions=array([-0.5, 0.0, 0.5]), masses=array([0.2, 0.3, 0.5]),
       ranges=st.one_of(st.just(np.array([[0.1, 0.4], [0.5, 0.9]])), bad_array, finite_lists.map(np.array)),
       threshold=scalar(0.1), share=scalar(0.25))
def test_aggregate_readings(positions, masses, ranges, threshold, share):
    """The readings of :mod:`particle_methods.cross.aggregates` on drawn atoms, level ranges and gaps."""
    centres = safe_call(naming(aggregates.level_centres, "positions", "masses", "ranges"), positions, masses, ranges)
    if centres is not None:  # each centre lies within the atoms' span, up to rounding
        slack = 1e-12 * np.max(np.abs(positions))
        assert np.all(centres >= np.min(positions) - slack) and np.all(centres <= np.max(positions) + slack)
    safe_call(naming(aggregates.gap_path, "positions", "masses", "ranges"), positions, masses, ranges)
    safe_call(naming(aggregates.heavy_clusters, "positions", "masses", "share"), positions, masses, share)
    safe_call(naming(aggregates.cell_atoms, "edges", "values", "mass"), positions, masses, threshold)
    safe_call(naming(aggregates.first_within, "times", "gaps", "threshold"), positions, masses, threshold)


# The cases the fuzzing found (each crashed, returned a wrong value or named no parameter before its fix)


def test_full_collapse_of_the_indicator_at_t_1_is_reported():
    """At t = 1 every level of (4.4) reaches 0 together: the Dirac mass is all of M, as the CDF says."""
    solution = AggregationSolution("indicator", 1.0)
    assert solution.dirac_mass == 2.0 and solution.level == 0.0 and solution.collapse_radius == 1.0
    assert solution.cdf(0.0) - solution.cdf(-1e-300) == 2.0


def test_brackets_near_the_largest_double_do_not_overflow():
    """The root's first midpoint 0.5 (low + high) overflowed to -inf for x = -1.7e308 (NaN antiderivative)."""
    for data, t in [("laplace", 2.0), ("laplace", 1e8), ("smooth20", 1.1)]:
        solution = AggregationSolution(data, t)
        np.testing.assert_array_equal(solution.cdf(np.array([-1.7e308, 1.7e308])), [0.0, solution.mass])
        assert float(solution.antiderivative(-1.7e308)) == 0.0
    assert float(AggregationSolution("laplace", 2.0).antiderivative(1.7e308)) == 1.7e308


def test_cdf_and_level_stay_within_their_ranges_under_rounding():
    """M/2 + m(a) and M/2 - m(a0) round to -ulp(M) in the far left tail and just short of a full collapse."""
    x = np.linspace(-1.0, -0.8, 2001)
    for data, t in [("smooth10", 1.1), ("smooth20", 0.5), (Data1D("p30", 30), 0.999999999)]:
        assert AggregationSolution(data, t).cdf(x).min() >= 0.0
    solution = AggregationSolution(Data1D("p30", 30), 5.140625)
    assert solution.level >= 0.0 and solution.dirac_mass <= solution.mass


@pytest.mark.parametrize("measure", [None, "smooth20", AggregationSolution, 1.0])
def test_measures_without_the_needed_methods_are_refused_naming_measure(measure):
    with pytest.raises(TypeError, match="measure"):
        l1_to_step_function(measure, [0.0], [1.0])


@pytest.mark.parametrize(("call", "name"), [
    (lambda s: l1_to_step_function(s, [1.7e308], [2.0]), "breaks"),
    (lambda s: distances.w1_atoms(s, [1.7e308], [2.0]), "positions"),
    (lambda s: distances.w1_cells(s, [0.0, 1.7e308], [1.0]), "edges"),
    (lambda s: s.antiderivative(1.7e308), "x"),
])
def test_positions_whose_products_with_the_mass_overflow_are_refused_naming_them(call, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        call(AggregationSolution("indicator", 0.5))


@pytest.mark.parametrize("mass", [float("nan"), None, 1 + 2j, -1.0, 0.0, float("inf")], ids=repr)
def test_aggregation_flux_refuses_a_mass_that_is_not_a_positive_number(mass):
    """Found by the fuzz of issue 30: NaN, None, complex and negative masses gave a flux silently."""
    from particle_methods.cross.methods import aggregation_flux

    with pytest.raises((ValueError, TypeError), match="mass"):
        aggregation_flux(mass)


def test_ltp_method_names_its_own_time_parameter():
    """Found by the fuzz of issue 30: a bad t was refused naming simulate's t_final."""
    from particle_methods.cross.methods import ltp_method

    for t in (-1.0, 0.0, float("nan")):
        with pytest.raises(ValueError, match=r"^t must"):
            ltp_method("smooth20", 0.1, 0.01, t)


@pytest.mark.parametrize("change", [{"peak": -1.0}, {"peak": 0.0}, {"mass": float("nan")}, {"mass": 0.0},
                                    {"radius": -1.0}, {"radius": None}, {"density": 3.0}],
                         ids=["negative peak", "zero peak", "NaN mass", "zero mass", "negative radius", "None radius",
                              "density not callable"])
def test_a_profile_is_checked_at_construction(change):
    import dataclasses

    from particle_methods.cross import PROFILES

    with pytest.raises(ValueError, match=next(iter(change))):
        dataclasses.replace(PROFILES["smooth20"], **change)


# Work and range refused before the work starts (issue 30)

def test_work_beyond_the_limits_is_refused_naming_the_parameter():
    from particle_methods.cross import methods

    with pytest.raises(ValueError, match="MAX_PARTICLES"):
        methods.particle_velocities(np.linspace(0.0, 1.0, 10**6), np.ones(10**6))  # O(n^2): hung before
    with pytest.raises(ValueError, match="n must be at most"):
        methods.spd_equal("smooth20", 3 * 10**7, 1.1)  # ran for minutes before
    with pytest.raises(ValueError, match="MAX_TIME"):
        methods.spd_grid("smooth20", 1 / 1024, 1e300)  # put every particle at 1.9e284 before
    with pytest.raises(ValueError, match="MAX_POINTS"):
        exact_mass_function("smooth20", 1.1, np.zeros(10**7 + 1))


def test_w1_smooth_refuses_a_complex_cdf_and_names_largest_for_too_many_pieces():
    solution = AggregationSolution("smooth20", 0.5)
    with pytest.raises(TypeError, match="cumulative must return one real value"):
        distances.w1_smooth(solution, lambda x: x + 0j, [-1.0, 1.0], 0.1)  # dropped the imaginary part before
    with pytest.raises(ValueError, match="largest"):
        distances.w1_smooth(solution, lambda x: x, [-1.0, 1.0], 1e-9)  # named `pieces`, never passed, before


def test_the_fuzz_of_the_newest_entry_points_finds_only_named_refusals_and_finite_answers():
    # tests/fuzz_counts.py (issue 30): every value of the shared harness, one parameter at a time.
    import fuzz_counts

    counts = fuzz_counts.run()
    assert {key for key, value in counts.items() if value} <= {"refused, named", "answered"}, counts


# Issue 46: work refused before it starts, and silent NaN or invalid input in the newest entry points

def test_issue_46_work_of_the_exact_hull_and_of_godunov_is_refused_before_it_starts():
    from particle_methods.cross import hull, methods
    from particle_methods.cross.hull import Bump, BumpData, HullSolution, aggregate_paths, merger_time

    with pytest.raises(ValueError, match=r"times ask for 1000000 exact solution.*MAX_HULL_WORK"):
        aggregate_paths("two_bumps", np.linspace(0, 3, 10**6))  # 42 ms of CPU per time: about 12 h before
    with pytest.raises(ValueError, match="MAX_HULL_WORK"):
        aggregate_paths("two_bumps", [0.5] * 10**4)  # a list: refused once it is an array, before any solution
    many = BumpData("100 bumps", tuple(Bump(1.0, -1.0 + (2 * k + 1) / 100, 0.009, 2) for k in range(100)))
    with pytest.raises(ValueError, match=r"data ask for 1 exact solution\(s\) of 100 bumps.*MAX_HULL_WORK"):
        HullSolution(many, 1.0)  # quadratic in the bumps: 20 bumps took 2.6 s, 40 bumps 10.8 s
    seven = BumpData("7 bumps", many.bumps[:7])
    with pytest.raises(ValueError, match=r"low and high ask for .* of 7 bumps.*MAX_HULL_WORK"):
        merger_time(seven, 1.0, 2.0)  # about 55 solutions of the bisection
    assert hull.MAX_HULL_WORK >= 60 * 2**2  # merger_time on two bumps, as the pipeline runs it
    with pytest.raises(ValueError, match="times holds 10000000 times, more than MAX_PATH_TIMES"):
        methods.godunov_paths("two_bumps", 64, np.linspace(0, 1, 10**7))  # every state kept: 40 min before
    with pytest.raises(ValueError, match="MAX_PATH_VALUES"):
        methods.godunov_paths("two_bumps", 10**6, np.linspace(0, 1, 1000))
    with pytest.raises(ValueError, match="MAX_CELL_STEPS"):
        methods.godunov_paths("two_bumps", 64, [1.0], cfl=5e-324)  # a time step that underflows to 0
    with pytest.raises(ValueError, match=r"1\.45e\+07 steps .* MAX_GAP_READINGS"):
        aggregates.godunov_merger("two_bumps", 64, 1.5, 2.5, cfl=1e-6)
    with pytest.raises(ValueError, match="cells must be at most"):
        aggregates.godunov_merger("two_bumps", 10**8, 1.5, 2.5)  # its grid was allocated before


def test_issue_46_particle_velocities_refuse_what_gave_nan_and_negative_masses():
    from particle_methods.cross.methods import MAX_VELOCITY_SPAN, particle_velocities

    for x, masses, message in [([-1e300, 0.0, 1e300], [1.0, 1.0, 1.0], "x spans 2e\\+300.*MAX_VELOCITY_SPAN"),
                               ([0.0, 1e200, 2e200], [1.0, 1.0, 1.0], "MAX_VELOCITY_SPAN"),
                               ([0.0, 1.0], [1.7e308, 1.7e308], "masses must have a finite sum"),
                               ([0.0, 1.0, 2.0], [1.0, -1.0, 1.0], "masses must be non-negative, got -1.0 at index 1")]:
        with pytest.raises(ValueError, match=message):
            particle_velocities(x, masses)  # NaN (or velocities of negative masses) before
    span = MAX_VELOCITY_SPAN / 2
    np.testing.assert_array_equal(particle_velocities([0.0, span, 2 * span], [1.0, 1.0, 1.0]), [1.0, 0.0, -1.0])
    np.testing.assert_array_equal(particle_velocities([0.0, 5e-324, 1e-323], [1.0, 0.0, 1.0]), [0.5, 0.0, -0.5])


def test_issue_46_first_within_interpolates_without_overflow():
    assert aggregates.first_within([0.0, 1.0], [1e308, -1e308], 0.5) == 0.5  # 0.0 before
    assert aggregates.first_within([0.0, 1.0], [1.7e308, -1.7e308], 1e-300) == 0.5
    assert aggregates.first_within([0.0, 1.0], [1e-323, 0.0], 5e-324) == 0.5  # denormals: no scaling up
    assert aggregates.first_within([0.0, 1.0, 2.0], [3.0, 2.5, 1.0], 2.0) == pytest.approx(4.0 / 3.0, rel=1e-15)


def test_issue_46_godunov_advance_takes_and_returns_f_in_zero_mass():
    from particle_methods.cross import methods

    edges = np.linspace(-1.0, 1.0, 5)
    with pytest.raises(ValueError, match=r"values must lie in \[0, mass\] = \[0, 1.0\]"):
        methods.godunov_advance(edges, [-1.0, 0.2, 0.5, 2.0], 1.0, 0.5)  # returned F from -1 to 2 before
    # Rounding of a run or the robustness nudge (1e-13 of the mass) is taken; the result lies in [0, M].
    values = methods.godunov_advance(edges, [0.0, 0.2, 0.5, 1.0 + 1e-13], 1.0, 0.5)
    assert values.min() >= 0.0 and values.max() <= 1.0
    for _, f in methods.godunov_paths("smooth20", 4096, [1.0, 3.0]):  # rounding took F 5e-12 M beyond before
        mass = exact_mass_function("smooth20", 0.0, [2.0])[0]
        assert f.min() >= 0.0 and f.max() <= mass


def test_issue_46_w1_particles_and_ltp_method_name_their_parameters():
    from particle_methods.cross.methods import ltp_method, ltp_paths

    with pytest.raises(TypeError, match="particles must be of type Particles"):
        distances.w1_particles(AggregationSolution("smooth20", 0.5), None)  # AttributeError before
    for call, message in [(lambda: ltp_method("smooth20", 0.1, 0.01, 0.505), r"^t = 0.505 must be a whole number"),
                          (lambda: ltp_method("smooth20", 0.1, 1e-9, 1.0), r"^t / dt = 1e\+09 steps"),
                          (lambda: ltp_paths("smooth20", 0.1, 1e-9, [0.5, 1.0]), r"^times / dt = 1e\+09 steps")]:
        with pytest.raises(ValueError, match=message) as refusal:
            call()
        assert "t_final" not in str(refusal.value)
