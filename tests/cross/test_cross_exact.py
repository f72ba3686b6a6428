"""The exact solution of the cross-method comparison: the entropy solution of
F_t + (M F/2 - F^2/2)_x = 0 (the aggregation equation with K = |x|/2 in mass coordinates).

It is checked against independent computations: the sticky paper's Laplace solution (Lambert W),
the blob paper's characteristics before the blow-up, the weak form of the conservation law
(integrated in time by quadrature), the Rankine-Hugoniot and Oleinik conditions at the shock,
scipy quadratures of its own functions, and a fine weighted SPD (no time stepping at all).
"""

import math

import numpy as np
import pytest
from scipy import integrate

from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import DATA_1D
from particle_methods.cross import distances, methods
from particle_methods.cross.exact import AggregationSolution, exact_mass_function
from particle_methods.cross.methods import aggregation_flux
from particle_methods.cross.profiles import monotone_root
from particle_methods.sticky import ConcaveLaplaceSolution

POLYNOMIAL = ("smooth20", "indicator", "smooth10")
ALL_DATA = (*POLYNOMIAL, "laplace")


def window(solution):
    """A closed interval holding every point where F is neither 0 nor M (a wide one for the Laplace law)."""
    reach = 40.0 if math.isinf(solution.profile.radius) else 1.0
    return -reach, reach


def breakpoints(solution, *extra):
    """Where F is not smooth (the support ends and 0), and ``extra``, for quad."""
    return sorted({0.0, solution.left_end, -solution.left_end, *extra} - {-math.inf, math.inf})


# The Laplace law: the same equation with M = 1 as the sticky paper's (5.3)-(5.4)


@pytest.mark.parametrize("t", [0.5, 1.9, 2.0, 2.5, 4.0])
def test_laplace_equals_the_sticky_papers_solution(t):
    ours, theirs = AggregationSolution("laplace", t), ConcaveLaplaceSolution(t)
    x = np.linspace(-12.0, 12.0, 2001)
    w = np.linspace(0.0, 1.0, 2001)[1:-1]
    assert ours.mass == 1.0
    np.testing.assert_allclose(ours.cdf(x), theirs.cdf(x), rtol=0, atol=1e-15)
    np.testing.assert_allclose(ours.quantile(w), theirs.quantile(w), rtol=0, atol=1e-15)
    np.testing.assert_allclose(ours.quantile_integral(w), theirs.quantile_integral(w), rtol=0, atol=1e-15)
    assert ours.level == pytest.approx(theirs.shock_level, abs=1e-15)


# Before the blow-up: the characteristics of the blob paper's section 4.1


@pytest.mark.parametrize("data", POLYNOMIAL)
@pytest.mark.parametrize("t", [0.3, 0.75, 0.99])
def test_before_the_blowup_cdf_follows_the_blob_papers_characteristics(data, t):
    alpha = np.linspace(-1.0, 1.0, 401)[1:-1]
    position, _ = newtonian_exact(DATA_1D[data], "newtonian_attractive", alpha, t)
    solution = AggregationSolution(data, t)
    expected = 0.5 * solution.mass + DATA_1D[data].mass_from_origin(alpha)
    np.testing.assert_allclose(solution.cdf(position), expected, rtol=0, atol=1e-13)
    # The quantile solves M/2 + m(a) = w, whose target carries the rounding of M/2 (~1e-17): a level is
    # placed to 1e-17 / rho0(a), so compare where rho0 is not tiny (the far tails of (4.3) hold < 1e-7 of M).
    resolved = DATA_1D[data](alpha) > 1e-3
    np.testing.assert_allclose(solution.quantile(expected[resolved]), position[resolved], rtol=0, atol=1e-12)
    assert solution.dirac_mass == 0.0 and solution.collapse_radius == 0.0
    assert solution.level == pytest.approx(0.5 * solution.mass, abs=1e-16)


# After the blow-up: the Dirac mass at 0


def test_smooth20_at_t_1_1_holds_57_percent_of_its_mass_at_0():
    solution = AggregationSolution("smooth20", 1.1)
    assert solution.dirac_mass / solution.mass == pytest.approx(0.5687, abs=5e-5)
    assert solution.dirac_mass == pytest.approx(solution.mass - 2.0 * solution.level, abs=1e-16)


@pytest.mark.parametrize("data", ALL_DATA)
@pytest.mark.parametrize("t", [0.5, 1.0, 1.1, 1.5, 2.5, 4.0, 6.0])
def test_the_jump_of_f_at_0_is_the_dirac_mass(data, t):
    solution = AggregationSolution(data, t)
    right, left = solution.cdf(np.array([0.0, -1e-300]))
    # At the blow-up time itself the characteristic a - t m(a) ~ a^3 is flat at 0 and computed with an error
    # eps |a| (a cancellation): the root next to 0 is found to |a| ~ 1e-8 only, and F(0-) carries that.
    tolerance = 1e-7 if t == solution.blowup_time else 1e-12
    assert right - left == pytest.approx(solution.dirac_mass, abs=tolerance)
    assert left == pytest.approx(solution.level, abs=tolerance)
    # nothing else jumps: F is continuous off 0 (checked at points 1e-9 apart)
    x = np.linspace(-3.0, 3.0, 6001)
    x = x[np.abs(x) > 1e-6]
    assert np.max(solution.cdf(x + 1e-9) - solution.cdf(x)) < 1e-7


@pytest.mark.parametrize("t", [1.0, 1.0 + 1e-12, 1.1, 3.0])
def test_the_indicator_collapses_into_one_dirac_mass_at_the_blowup(t):
    solution = AggregationSolution("indicator", t)
    assert solution.dirac_mass == solution.mass == 2.0 and solution.level == 0.0
    assert solution.collapse_radius == 1.0
    np.testing.assert_array_equal(solution.cdf(np.array([-1e-300, 0.0])), [0.0, 2.0])
    np.testing.assert_array_equal(solution.quantile(np.linspace(0.0, 2.0, 11)), 0.0)


@pytest.mark.parametrize("data", ALL_DATA)
@pytest.mark.parametrize("excess", [1e-6, 0.1, 0.5, 1.5, 4.0])
def test_collapse_radius_is_the_positive_root_of_a_equals_t_m_of_a(data, excess):
    solution = AggregationSolution(data, (1.0 + excess) * AggregationSolution(data, 0.0).blowup_time)
    a0, t, shape = solution.collapse_radius, solution.t, solution.profile
    if a0 == shape.radius:  # all the mass has collapsed: t m(radius) >= radius
        assert t * shape.mass / 2.0 >= shape.radius
        return
    assert 0.0 < a0 < shape.radius
    assert t * shape.mass_from_origin(a0) == pytest.approx(a0, rel=1e-14)
    assert t * shape.mass_from_origin(a0 * (1 - 1e-6)) > a0 * (1 - 1e-6)  # inside: the level has reached 0
    assert t * shape.mass_from_origin(a0 * (1 + 1e-6)) < a0 * (1 + 1e-6)  # outside: not yet
    assert solution.level == pytest.approx(0.5 * shape.mass - shape.mass_from_origin(a0), abs=1e-16)


def test_smooth20_collapses_entirely_once_t_m_over_2_reaches_1():
    mass = DATA_1D["smooth20"].mass
    full = 2.0 / mass
    for t in (full, 1.01 * full, 10.0 * full):
        solution = AggregationSolution("smooth20", t)
        assert solution.dirac_mass == solution.mass and solution.level == 0.0
        np.testing.assert_array_equal(solution.cdf(np.array([-0.5, -1e-300, 0.0, 0.5])), [0.0, 0.0, mass, mass])
    partial = AggregationSolution("smooth20", 0.99 * full)
    assert 0.0 < partial.level and partial.dirac_mass < mass and partial.collapse_radius < 1.0


# An entropy solution: weak form, Rankine-Hugoniot and Oleinik at the shock, a proper CDF


@pytest.mark.parametrize("data", ALL_DATA)
def test_weak_form_of_the_conservation_law_across_the_blowup(data):
    """Integrating F_t + Lambda(F)_x = 0 over (-inf, x) x (t1, t2): A(t2, x) - A(t1, x) = -int Lambda(F(s, x)) ds,
    with A = int_{-inf}^x F, from before the blow-up to after it."""
    t1, t2 = (0.4, 1.6) if data != "laplace" else (1.0, 3.5)
    early, late = AggregationSolution(data, t1), AggregationSolution(data, t2)
    flux = aggregation_flux(early.mass)
    for x in (-0.6, 0.0, 0.3):
        change = float(late.antiderivative(x) - early.antiderivative(x))
        flow, _ = integrate.quad(lambda s, x=x: float(flux(AggregationSolution(data, s).cdf(x))), t1, t2,
                                 epsabs=1e-10, epsrel=1e-10, limit=100)
        assert change == pytest.approx(-flow, abs=1e-9), x


@pytest.mark.parametrize("data", ALL_DATA)
@pytest.mark.parametrize("after", [1.1, 2.5, 4.0])
def test_the_shock_at_0_is_stationary_and_admissible(data, after):
    t = after * AggregationSolution(data, 0.0).blowup_time
    solution = AggregationSolution(data, t)
    assert solution.dirac_mass > 0.0
    flux = aggregation_flux(solution.mass)
    left, right = solution.level, solution.mass - solution.level
    # Rankine-Hugoniot: speed (Lambda(right) - Lambda(left)) / (right - left) = 0, the shock stays at 0
    assert float(flux(right) - flux(left)) / (right - left) == pytest.approx(0.0, abs=1e-15)
    # Oleinik (concave flux, F jumps up): characteristics run into the shock, and Lambda lies above its chord
    assert 0.5 * solution.mass - left > 0.0 > 0.5 * solution.mass - right
    levels = np.linspace(left, right, 101)
    assert np.all(flux(levels) >= flux(left) - 1e-15)
    # the levels of the Dirac mass sit at 0 at every later time
    for later in (t, 1.5 * t, 3.0 * t):
        inside = np.linspace(left, right, 11)[1:-1]
        np.testing.assert_array_equal(AggregationSolution(data, later).quantile(inside), 0.0)


@pytest.mark.parametrize("data", ALL_DATA)
@pytest.mark.parametrize("t", [0.0, 0.6, 1.1, 3.0])
def test_cdf_is_a_non_decreasing_function_from_0_to_the_mass(data, t):
    solution = AggregationSolution(data, t)
    low, high = window(solution)
    x = np.concatenate([np.linspace(low, high, 20001), -np.logspace(-12, 0, 200), np.logspace(-12, 0, 200)])
    values = solution.cdf(np.sort(x))
    assert np.all(np.diff(values) >= -1e-15)
    assert values.min() >= 0.0 and values.max() <= solution.mass
    far = solution.cdf(np.array([-1e3, 1e3]))
    np.testing.assert_allclose(far, [0.0, solution.mass], rtol=0, atol=1e-15)
    # mass conservation: the total mass is that of the data, int rho0
    assert solution.mass == pytest.approx(integrate.quad(solution.profile.density, -high, high, points=[0.0])[0],
                                          rel=1e-12)


@pytest.mark.parametrize("data", ALL_DATA)
@pytest.mark.parametrize("t", [0.0, 0.6, 1.1, 3.0])
def test_quantile_is_the_pseudo_inverse_of_the_cdf(data, t):
    solution = AggregationSolution(data, t)
    w = np.linspace(0.0, solution.mass, 401)[1:-1]
    x = solution.quantile(w)
    assert np.all(np.diff(x) >= 0.0)
    # X(w) = inf{x : F(x) >= w}: F reaches w at X(w), and not before
    assert np.all(solution.cdf(x) >= w - 1e-13)
    assert np.all(solution.cdf(x - 1e-7) < w)


# (data, t) for the quadratures: each data once before and once after its blow-up
QUADRATURE_CASES = [("smooth20", 0.6), ("smooth20", 1.1), ("indicator", 0.0), ("indicator", 0.6),
                    ("smooth10", 2.0), ("laplace", 1.0), ("laplace", 3.0)]


@pytest.mark.parametrize(("data", "t"), QUADRATURE_CASES)
def test_quantile_integral_is_the_antiderivative_of_the_quantile(data, t):
    solution = AggregationSolution(data, t)
    mass = solution.mass
    kinks = [solution.level, mass - solution.level, 0.5 * mass]
    for w in (0.3 * mass, 0.8 * mass):  # below the Dirac mass's levels, and across them
        inside = [k for k in kinks if 0.0 < k < w]
        expected, _ = integrate.quad(lambda s: float(solution.quantile(s)), 0.0, w, points=inside or None,
                                     epsabs=1e-12, epsrel=1e-12, limit=100)
        assert float(solution.quantile_integral(w)) == pytest.approx(expected, abs=1e-11), w
    assert float(solution.quantile_integral(mass)) == pytest.approx(0.0, abs=1e-15)  # symmetric: mean 0


@pytest.mark.parametrize(("data", "t"), QUADRATURE_CASES)
def test_antiderivative_is_x_f_minus_g_of_f_and_the_integral_of_the_cdf(data, t):
    solution = AggregationSolution(data, t)
    start = window(solution)[0]
    x = np.array([-0.9, -0.4, -0.01, 0.0, 0.01, 0.4, 0.9, 1.5])
    levels = solution.cdf(x)
    np.testing.assert_allclose(solution.antiderivative(x), x * levels - solution.quantile_integral(levels),
                               rtol=0, atol=1e-14)
    for point in (-0.4, 0.0, 0.9):
        expected, _ = integrate.quad(lambda s: float(solution.cdf(s)), start, point,
                                     points=[p for p in breakpoints(solution) if start < p < point] or None,
                                     epsabs=1e-12, epsrel=1e-12, limit=100)
        assert float(solution.antiderivative(point)) == pytest.approx(expected, abs=1e-11), point


# Independent of any time stepping: the weighted SPD of a fine grid is the exact solution of its data


@pytest.mark.parametrize("data", ["smooth20", "indicator"])
@pytest.mark.parametrize("t", [0.5, 1.1, 2.0])
def test_a_fine_weighted_spd_is_close_to_the_exact_solution(data, t):
    h = 1.0 / 4096
    positions, masses = methods.spd_grid(data, h, t)
    initial = distances.w1_atoms(AggregationSolution(data, 0.0), *methods.spd_grid(data, h, 0.0))
    error = distances.w1_atoms(AggregationSolution(data, t), positions, masses)
    assert error < 1e-3
    assert error <= initial * (1 + 1e-9)  # the L1 contraction of entropy solutions


# The public function and its refusals


@pytest.mark.parametrize("data", ALL_DATA)
def test_exact_mass_function_is_the_cdf(data):
    x = np.linspace(-2.0, 2.0, 101)
    for t in (0.0, 0.7, 1.3):
        np.testing.assert_array_equal(exact_mass_function(data, t, x), AggregationSolution(data, t).cdf(x))
    assert exact_mass_function(DATA_1D["smooth10"], 0.5, 0.25) == AggregationSolution("smooth10", 0.5).cdf(0.25)
    assert np.shape(exact_mass_function(data, 0.5, np.zeros((2, 3)))) == (2, 3)


@pytest.mark.parametrize(("call", "name", "error"), [
    (lambda: exact_mass_function("smooth30", 0.5, 0.0), "data", ValueError),
    (lambda: exact_mass_function(None, 0.5, 0.0), "data", TypeError),
    (lambda: exact_mass_function("smooth20", -0.1, 0.0), "t", ValueError),
    (lambda: exact_mass_function("smooth20", math.nan, 0.0), "t", ValueError),
    (lambda: exact_mass_function("smooth20", "1", 0.0), "t", TypeError),
    (lambda: exact_mass_function("smooth20", 0.5, [0.0, math.nan]), "x", ValueError),
    (lambda: exact_mass_function("smooth20", 0.5, "0"), "x", TypeError),
    (lambda: AggregationSolution("indicator", 0.5).quantile([0.5, 2.5]), "w", ValueError),
    (lambda: AggregationSolution("indicator", 0.5).quantile(-1e-12), "w", ValueError),
    (lambda: AggregationSolution("smooth20", 0.5).quantile_integral(0.4), "w", ValueError),
    (lambda: AggregationSolution("laplace", 0.5).quantile(0.0), "w", ValueError),  # X(0) = -inf
    (lambda: AggregationSolution("laplace", 0.5).antiderivative(math.inf), "x", ValueError),
    (lambda: AggregationSolution("indicator", 1e308), "t", ValueError),  # t M overflows
])
def test_bad_inputs_are_refused_naming_the_parameter(call, name, error):
    with pytest.raises(error, match=rf"\b{name}\b"):
        call()


def _counted(function):
    calls = []

    def counted(x):
        calls.append(np.size(x))
        return function(x)

    return counted, calls


@pytest.mark.parametrize(("target", "low", "high"), [
    (0.0, -1.0, 0.0),     # the root is the bracket's end (the level of the Dirac mass at x = 0)
    (0.3, -1.0, 1.0),     # an interior root
])
def test_monotone_root_reaches_a_root_at_the_bracket_end_in_a_few_newton_steps(target, low, high):
    """A root at an end of the bracket used to be approached by bisection, one halving per iteration towards
    the denormals, for all MAX_ITERATIONS iterations."""
    function, calls = _counted(lambda x: 2.0 * x + x**3)
    root = monotone_root(function, lambda x: 2.0 + 3.0 * x**2, np.array([target]), np.array([low]), np.array([high]))
    assert 2.0 * root[0] + root[0] ** 3 == pytest.approx(target, abs=1e-15)
    assert len(calls) <= 8


def test_monotone_root_bisects_where_newton_crawls():
    """f(x) = (1 + x)^21 near its flat end (the mass of (4.3) at the support's edge): plain Newton shrinks the
    distance by 20/21 a step (72 evaluations without the halving rule); with it, bisection takes over where
    Newton crawls and 19 evaluations reach the root."""
    function, calls = _counted(lambda x: (1.0 + x) ** 21)
    target = np.array([1e-30])
    root = monotone_root(function, lambda x: 21.0 * (1.0 + x) ** 20, target, np.array([-1.0]), np.array([0.0]))
    assert root[0] == pytest.approx(-1.0 + 1e-30 ** (1.0 / 21.0), rel=1e-14)
    assert len(calls) <= 30


def test_issue_46_monotone_root_checks_its_functions_targets_and_bracket():
    derivative = lambda s: 1.0 - np.tanh(s) ** 2  # noqa: E731
    nan = lambda s: np.full(s.shape, np.nan)  # noqa: E731
    assert monotone_root(np.tanh, derivative, [0.0], -1.0, 1.0)[0] == 0.0
    for arguments, message in [((None, derivative, [0.0], -1.0, 1.0), "function must be callable"),
                               ((np.tanh, "x", [0.0], -1.0, 1.0), "derivative must be callable"),
                               ((nan, derivative, [0.0], -1.0, 1.0), "function returned"),
                               ((np.tanh, nan, [0.5], -1.0, 1.0), "derivative returned"),
                               ((np.tanh, derivative, [1.0, np.nan], -1.0, 1.0), "target contains NaN"),
                               ((np.tanh, derivative, [0.0, 0.5], [-1.0, -1.0, -1.0], 1.0), "low must be a number or "
                                "of the shape"),
                               ((np.tanh, derivative, [0.0], -1.0, [1 + 1j]), "high must hold real numbers")]:
        with pytest.raises(ValueError, match=message):
            monotone_root(*arguments)  # a root of NaN, a complex cast or an unclear error before
    # what the functions return goes to the compiled steps: real numbers of one value per point, or refused by name
    for arguments, error, message in [((lambda s: s + 0j, derivative, [0.0], -1.0, 1.0), TypeError, "function must"),
                                      ((np.tanh, lambda s: s * 0j + 1, [0.5], -1.0, 1.0), TypeError, "derivative must"),
                                      ((np.tanh, lambda s: None, [0.5], -1.0, 1.0), TypeError, "derivative must"),
                                      ((np.tanh, lambda s: np.ones(3), [0.5, 0.1], -1.0, 1.0), ValueError,
                                       "derivative returned values of shape")]:
        with pytest.raises(error, match=message):
            monotone_root(*arguments)
    assert monotone_root(np.tanh, lambda s: 1.0, [0.3], -1.0, 1.0)[0] == pytest.approx(np.arctanh(0.3), abs=1e-15)


def test_issue_46_a_profile_probes_its_functions_and_radius():
    from particle_methods.cross.profiles import PROFILES, Profile

    shape = PROFILES["smooth20"]
    fields = {"name": "p", "mass": shape.mass, "peak": shape.peak, "radius": 1.0, "density": shape.density,
              "mass_from_origin": shape.mass_from_origin, "moment_from_left": shape.moment_from_left,
              "level_position": shape.level_position}
    assert Profile(**fields).radius == 1.0
    with pytest.raises(ValueError, match="density must return finite real values"):
        Profile(**{**fields, "density": lambda x: np.full(np.shape(x), np.nan)})  # NaN in every solution before
    with pytest.raises(ValueError, match="radius is beyond the double-precision range"):
        Profile(**{**fields, "radius": 10**400})
