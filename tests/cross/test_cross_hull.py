"""The exact solution by the continuous hull (particle_methods.cross.hull): against the symmetric solutions,
against an independent quantile before the blow-ups, against the SPD of many particles, and the aggregates of
the asymmetric data 'two_bumps' against their closed forms."""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.spatial import ConvexHull

from particle_methods.cross import AggregationSolution, HullSolution, exact_mass_function, merger_time, methods
from particle_methods.cross.distances import w1_atoms
from particle_methods.cross.hull import (
    SKEWED_BUMPS,
    TWO_BUMPS,
    Bump,
    BumpData,
    _density_at,
    _in_bump_kernel,
    _root_kernel,
    aggregate_paths,
    bump_data,
)
from particle_methods.cross.profiles import monotone_root

MASS_A, MASS_B = 0.64, 0.8 / 3.0  # 2 * 0.3 * 16/15 and 0.25 * 16/15
MASS = MASS_A + MASS_B


@pytest.mark.parametrize("name", ["smooth20", "indicator", "smooth10"])
@pytest.mark.parametrize("t", [0.0, 0.5, 0.99, 1.1, 1.5, 3.0])
def test_hull_agrees_with_the_symmetric_solution(name, t):
    hull, exact = HullSolution(name, t), AggregationSolution(name, t)
    x = np.linspace(-1.5, 1.5, 2000)  # no point at the Dirac mass's position 0
    w = np.linspace(1e-6, exact.mass - 1e-6, 1001)  # the flat ends of F_0 leave the extreme levels to rounding
    np.testing.assert_allclose(hull.antiderivative(x), exact.antiderivative(x), rtol=0, atol=1e-14)
    np.testing.assert_allclose(hull.cdf(x), exact.cdf(x), rtol=0, atol=1e-13)
    np.testing.assert_allclose(hull.quantile_integral(w), exact.quantile_integral(w), rtol=0, atol=1e-14)
    np.testing.assert_allclose(hull.quantile(w), exact.quantile(w), rtol=0, atol=1e-11)
    assert hull.dirac_mass == pytest.approx(exact.dirac_mass, abs=1e-14)


def test_before_the_first_blowup_every_level_flies_freely():
    t = 0.45  # the left bump blows up at 1/2
    solution = HullSolution("two_bumps", t)
    assert solution.aggregates[0].size == 0
    for w in (0.05, 0.3, 0.6, 0.7, 0.85):
        bump = 0 if w < MASS_A else 1
        a = brentq(lambda s, bump=bump, w=w: TWO_BUMPS.in_bump(bump, np.array([s]))[0][0] - w, -0.7, 0.75,
                   xtol=1e-15)
        assert solution.quantile(np.array([w]))[0] == pytest.approx(a + t * (MASS / 2 - w), abs=1e-13)
        assert solution.cdf(np.array([a + t * (MASS / 2 - w)]))[0] == pytest.approx(w, abs=1e-12)


def test_blowup_times_are_one_over_each_peak():
    counts = [HullSolution("two_bumps", t).aggregates[0].size for t in (0.499, 0.501, 0.999, 1.001)]
    assert counts == [0, 1, 1, 2]


def test_aggregates_move_at_half_the_mass_right_minus_left_and_merge_at_the_exact_time():
    # Once bump A is one aggregate (t >= 1) it moves at (mass right - mass left)/2 = M_B/2 from its centre of mass;
    # once both are, they close in at (M_A + M_B)/2: the merger at 0.9/(M/2).
    positions, masses = aggregate_paths("two_bumps", [1.2, 1.5, 2.5])
    assert positions[0][0] == pytest.approx(-0.4 + 1.2 * MASS_B / 2, abs=1e-13)
    assert masses[0][0] == pytest.approx(MASS_A, abs=1e-13)
    assert positions[1][0] == pytest.approx(-0.4 + 1.5 * MASS_B / 2, abs=1e-13)
    assert masses[2][0] == pytest.approx(MASS, abs=1e-13)
    centre = (MASS_A * -0.4 + MASS_B * 0.5) / MASS  # the centre of mass never moves (the velocity is odd)
    assert positions[2][0] == pytest.approx(centre, abs=1e-13)
    assert merger_time("two_bumps", 1.5, 2.5) == pytest.approx(0.9 / (MASS / 2), rel=1e-12)


@pytest.mark.parametrize("t", [0.6, 1.2, 2.5])
def test_hull_agrees_with_the_spd_of_many_particles(t):
    solution = HullSolution("two_bumps", t)
    errors = [w1_atoms(solution, *methods.spd_equal("two_bumps", n, t)) for n in (4000, 16000)]
    assert errors[1] < 5e-5
    # The SPD converges like 1/n, up to where the gap between the bumps falls among the particles' levels.
    assert errors[1] < errors[0]


def test_a_wrong_speed_is_seen():
    # The aggregate of bump A at t = 1.2 is not where a speed of (mass right + mass left)/2 would put it.
    position = HullSolution("two_bumps", 1.2).aggregates[0][0]
    assert abs(position - (-0.4 + 1.2 * MASS / 2)) > 0.1


def test_exact_mass_function_takes_the_hull_for_two_bumps():
    x = np.array([-1.0, -0.24 - 1e-9, -0.24 + 1e-9, 1.0])
    values = exact_mass_function("two_bumps", 1.2, x)
    assert values[0] == 0.0 and values[-1] == pytest.approx(MASS, abs=1e-15)
    assert values[2] - values[1] == pytest.approx(MASS_A, abs=1e-7)  # the Dirac mass of bump A


def test_bad_bumps_and_times_are_refused():
    with pytest.raises(ValueError, match="height"):
        Bump(-1.0, 0.0, 1.0, 2)
    with pytest.raises(ValueError, match="disjoint"):
        BumpData("overlap", (Bump(1.0, 0.0, 1.0, 2), Bump(1.0, 1.5, 1.0, 2)))
    with pytest.raises(ValueError, match="t"):
        HullSolution("two_bumps", -1.0)
    with pytest.raises(ValueError, match="initial data"):
        HullSolution("three_bumps", 1.0)
    with pytest.raises(ValueError, match="merger"):
        merger_time("two_bumps", 0.1, 0.2)
    with pytest.raises(ValueError, match="times"):
        aggregate_paths("two_bumps", [])
    assert math.isfinite(HullSolution("two_bumps", 1e6).dirac_mass)




# --- the compiled kernels (issue 47) against the NumPy formulas, bit for bit -----------------------------------------

#: NumPy raises float arrays to integer powers by libm's pow here, and the kernels do: bit for bit. On AVX-512 CPUs
#: NumPy's power is SVML's, whose last bits may differ: there the kernels are compared with the NumPy formulas to
#: rounding only.
_SAMPLE = np.random.default_rng(47).random(20000)
NUMPY_POW_IS_LIBM = all(np.array_equal(_SAMPLE**k, [math.pow(v, k) for v in _SAMPLE]) for k in (3, 21))


def _assert_same(actual, expected):
    if NUMPY_POW_IS_LIBM:
        np.testing.assert_array_equal(actual, expected)
    else:
        np.testing.assert_allclose(actual, expected, rtol=1e-13, atol=1e-15)


KERNEL_DATA = {"two_bumps": TWO_BUMPS, "skewed_bumps": SKEWED_BUMPS, "smooth20": bump_data("smooth20"),
               "indicator": bump_data("indicator"),  # powers 0 and 1: NumPy's x**0 and x**1 by pow
               "powers_1_3": BumpData("powers 1 and 3", (Bump(0.7, -0.5, 0.3, 1, right_radius=0.2),  # x**2: a product
                                                         Bump(1.5, 0.4, 0.25, 3, right_radius=0.5)))}


def _numpy_best(solution, x):
    """HullSolution._best as it was computed by NumPy before the kernels (monotone_root on the free flight of each
    piece, the levels by BumpData.in_bump): the independent slow evaluation the kernel must reproduce to the bit."""
    data, t, mass = solution.data, solution.t, solution.mass

    def levels(index, a):
        w, moment = data.in_bump(index, a)
        return w, moment + t * (0.5 * mass * w - 0.5 * w * w), a + t * (0.5 * mass - w)

    value, level = np.full(x.shape, -np.inf), np.zeros(x.shape)
    for piece in solution._pieces:
        bump = data.bumps[piece.bump]
        y0, y1 = levels(piece.bump, np.array([piece.a0, piece.a1]))[2]
        inside = (x > y0) & (x < y1)
        a = np.where(x <= y0, piece.a0, piece.a1)
        if np.any(inside):
            a[inside] = monotone_root(lambda s, index=piece.bump: levels(index, s)[2],
                                      lambda s, bump=bump: 1.0 - t * bump.density(s), x[inside], piece.a0, piece.a1)
        w, psi, _ = levels(piece.bump, a)
        v = x * w - psi
        better = (v > value) | ((v == value) & (w > level))
        value, level = np.where(better, v, value), np.where(better, w, level)
    return value, level


@pytest.mark.parametrize("name", KERNEL_DATA)
def test_compiled_bump_integrals_and_density_are_the_numpy_ones(name):
    data = KERNEL_DATA[name]
    for index, bump in enumerate(data.bumps):
        a = np.linspace(bump.left_end - 0.1, bump.right_end + 0.1, 1001)
        w, moment = np.empty(a.size), np.empty(a.size)
        _in_bump_kernel(data._table, data._powers, index, a, w, moment)
        expected = data.in_bump(index, a)
        _assert_same(w, expected[0])
        _assert_same(moment, expected[1])
        _assert_same([_density_at(data._table, data._powers, index, v) for v in a], bump.density(a))


@pytest.mark.parametrize("name", KERNEL_DATA)
def test_compiled_roots_are_monotone_roots(name):
    data = KERNEL_DATA[name]
    t = 0.8 / data.peak
    for index, bump in enumerate(data.bumps):
        low, high = bump.left_end, bump.right_end
        levels = np.linspace(data.in_bump(index, low)[0], data.in_bump(index, high)[0], 203)[1:-1]
        ends = np.full(levels.size, low), np.full(levels.size, high)
        _assert_same(
            _root_kernel(data._table, data._powers, index, t, data.mass, False, levels, *ends),
            monotone_root(lambda s, index=index: data.in_bump(index, s)[0], bump.density, levels, *ends))
        flights = low + t * (0.5 * data.mass - data.in_bump(index, np.array([low, high]))[0]) + [0.0, high - low]
        x = np.linspace(*flights, 203)[1:-1]
        _assert_same(
            _root_kernel(data._table, data._powers, index, t, data.mass, True, x, *ends),
            monotone_root(lambda s, index=index: s + t * (0.5 * data.mass - data.in_bump(index, s)[0]),
                          lambda s, bump=bump: 1.0 - t * bump.density(s), x, *ends))


@pytest.mark.parametrize("name", KERNEL_DATA)
@pytest.mark.parametrize("share", [0.0, 0.9, 1.3, 2.5])  # times as shares of the last blow-up 1/min(height)
def test_compiled_hull_maximum_is_the_numpy_one(name, share):
    data = KERNEL_DATA[name]
    solution = HullSolution(data, share / min(b.height for b in data.bumps))
    low, high = data.support
    x = np.union1d(np.linspace(low - solution.t * data.mass - 0.1, high + solution.t * data.mass + 0.1, 1501),
                   solution.kinks)
    value, level = solution._best(x)
    expected = _numpy_best(solution, x)
    _assert_same(value, expected[0])
    # (At an aggregate two pieces tie: where NumPy's last bits differ from libm's, the tie may break the other way.)
    off = NUMPY_POW_IS_LIBM | np.all(np.abs(x[:, None] - solution.aggregates[0]) > 1e-9, axis=1)
    _assert_same(level[off], expected[1][off])


# --- skewed bumps (issue 44) ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("bump", [Bump(1.3, -0.1, 0.8, 2, right_radius=0.1), Bump(0.7, 0.2, 0.15, 3, right_radius=0.45),
                                  Bump(2.0, 0.0, 0.3, 0, right_radius=0.6)])
def test_skewed_bump_integrals_agree_with_quadrature(bump):
    low, high = bump.centre - bump.radius, bump.centre + bump.right_radius

    def rho(x):
        radius = bump.radius if x < bump.centre else bump.right_radius
        return bump.height * (1.0 - ((x - bump.centre) / radius) ** 2) ** bump.power if low <= x <= high else 0.0

    assert (bump.left_end, bump.right_end) == (low, high)
    for a in np.linspace(low - 0.1, high + 0.1, 23):
        mass, moment = bump.left_integrals(np.array([a]))
        options = {"points": [bump.centre], "epsabs": 1e-14, "epsrel": 1e-13} if low < a else {}
        assert mass[0] == pytest.approx(quad(rho, low, max(a, low), **options)[0], abs=1e-13)
        assert moment[0] == pytest.approx(quad(lambda x: x * rho(x), low, max(a, low), **options)[0], abs=1e-13)
        assert bump.density(np.array([a]))[0] == pytest.approx(rho(a), abs=1e-15)
    assert bump.mass == pytest.approx(quad(rho, low, high, points=[bump.centre])[0], rel=1e-13)
    t = 2.0 / bump.height
    dense = bump.dense_interval(t)
    assert t * rho(dense[0]) == pytest.approx(1.0, abs=1e-12) if bump.power else dense == (low, high)
    if bump.power:
        assert t * rho(dense[1]) == pytest.approx(1.0, abs=1e-12)
    assert bump.dense_interval(0.99 / bump.height) is None


def test_the_symmetric_bump_is_unchanged():
    # The closed forms of the symmetric bump (before skewed bumps existed), to the bit.
    bump = Bump(2.0, -0.4, 0.3, 2)
    assert bump == Bump(2.0, -0.4, 0.3, 2, right_radius=0.3) and bump.right_radius == 0.3
    a = np.linspace(-0.8, 0.0, 1001)
    s = np.clip((a + 0.4) / 0.3, -1.0, 1.0)
    left = 0.5 * bump.unit.mass + bump.unit.mass_from_origin(s)
    mass, moment = bump.left_integrals(a)
    np.testing.assert_array_equal(mass, 2.0 * 0.3 * left)
    np.testing.assert_array_equal(moment, 2.0 * 0.3 * (-0.4 * left + 0.3 * bump.unit.moment_from_left(s)))
    assert bump.mass == 2.0 * 0.3 * bump.unit.mass


def test_bad_right_radii_are_refused():
    with pytest.raises(ValueError, match="right_radius"):
        Bump(1.0, 0.0, 1.0, 2, right_radius=-0.5)
    with pytest.raises(TypeError, match="right_radius"):
        Bump(1.0, 0.0, 1.0, 2, right_radius="wide")
    with pytest.raises(ValueError, match="disjoint"):  # the right radius counts in the supports
        BumpData("overlap", (Bump(1.0, 0.0, 0.5, 2, right_radius=1.0), Bump(1.0, 1.2, 0.25, 2)))


# The independent computation: the lower convex hull (Qhull) of the points (w, Psi_t(w)) at the levels of a fine grid
# of initial positions, with w = F_0 and int x rho0 by 3-point Gauss-Legendre quadrature on each cell (exact for
# (1 - s^2)^2 between the grid's nodes, which hold the peaks and the ends) instead of the hull module's closed forms.
# An aggregate is an edge of the hull spanning a jump in w; its end levels are grid levels, so its mass is within
# two level spacings (< 2 max(rho0) max(da) = 2.1e-5 at HALF_CELLS = 1e5) of the exact one, and its position (the
# edge's slope) within the quadrature's rounding and a second-order term in the spacing (measured 3e-12).
HALF_CELLS = 10**5


def _discrete_curve(data):
    nodes, weights = np.polynomial.legendre.leggauss(3)
    levels, moments, w0, m0 = [], [], 0.0, 0.0
    for b in data.bumps:
        a = np.concatenate((np.linspace(b.centre - b.radius, b.centre, HALF_CELLS + 1)[:-1],
                            np.linspace(b.centre, b.centre + b.right_radius, HALF_CELLS + 1)))
        mid, half = 0.5 * (a[1:] + a[:-1]), 0.5 * np.diff(a)
        x = mid[:, None] + half[:, None] * nodes[None, :]
        s = (x - b.centre) / np.where(x < b.centre, b.radius, b.right_radius)
        rho = b.height * np.clip(1.0 - s * s, 0.0, None) ** b.power
        w = w0 + np.concatenate(([0.0], np.cumsum((rho @ weights) * half)))
        m = m0 + np.concatenate(([0.0], np.cumsum(((x * rho) @ weights) * half)))
        levels.append(w[1:] if levels else w)  # across the gap between bumps (w, Psi) stays one point
        moments.append(m[1:] if moments else m)
        w0, m0 = w[-1], m[-1]
    return np.concatenate(levels), np.concatenate(moments)


def _discrete_aggregates(curve, t):
    w, moment = curve
    psi = moment + t * (0.5 * w[-1] * w - 0.5 * w * w)  # Psi_t = int_0^w (X_0 + t (M/2 - u)) du
    vertices = ConvexHull(np.column_stack((w, psi))).vertices  # counterclockwise in 2D
    vertices = np.roll(vertices, -np.argmin(w[vertices]))
    lower = vertices[: np.argmax(w[vertices]) + 1]  # from the leftmost point to the rightmost: the lower chain
    big = np.nonzero(np.diff(w[lower]) > 1e-3 * w[-1])[0]
    i, j = lower[big], lower[big + 1]
    return (psi[j] - psi[i]) / (w[j] - w[i]), w[j] - w[i]


@pytest.fixture(scope="module")
def skewed_curve():
    return _discrete_curve(SKEWED_BUMPS)


@pytest.fixture(scope="module")
def skewed_merger():
    return merger_time("skewed_bumps", 1.1, 1.14)


@pytest.mark.parametrize("t", [0.6, 0.8, 1.0, 1.12, 1.3, 2.0])
def test_skewed_aggregates_agree_with_a_discrete_hull(skewed_curve, t):
    positions, masses = _discrete_aggregates(skewed_curve, t)
    exact = HullSolution("skewed_bumps", t)
    assert positions.size == exact.aggregates[0].size == (1 if t < 1 / 1.3 or t > 1.13 else 2)
    np.testing.assert_allclose(positions, exact.aggregates[0], rtol=0, atol=1e-9)
    np.testing.assert_allclose(masses, exact.aggregates[1], rtol=0, atol=2.1e-5)
    assert skewed_curve[0][-1] == pytest.approx(exact.mass, abs=1e-13)


def test_skewed_merger_time_agrees_with_a_discrete_hull(skewed_curve, skewed_merger):
    # The aggregates close in at about 0.5, so 1e-6 before the merger they are 5e-7 apart: far above the discrete
    # hull's position error (1e-9).
    merger = skewed_merger
    assert merger == pytest.approx(1.1205477, abs=1e-7)
    assert _discrete_aggregates(skewed_curve, merger - 1e-6)[0].size == 2
    assert _discrete_aggregates(skewed_curve, merger + 1e-6)[0].size == 1


@pytest.mark.parametrize("t", [0.9, 1.3])
def test_skewed_hull_agrees_with_the_spd_of_many_particles(t):
    solution = HullSolution("skewed_bumps", t)
    errors = [w1_atoms(solution, *methods.spd_equal("skewed_bumps", n, t)) for n in (4000, 16000)]
    assert errors[1] < 5e-5 and errors[1] < errors[0]


def test_skewed_aggregate_is_off_its_centre_of_mass_and_merges_before_it_has_collapsed(skewed_merger):
    skewed, other = SKEWED_BUMPS.bumps
    mass = skewed.mass + other.mass
    low, high = skewed.left_end, skewed.right_end
    centre = quad(lambda x: x * skewed.density(x), low, high, points=[-0.1])[0] / skewed.mass  # -0.31875
    speed = mass / 2 - skewed.mass / 2  # the mean speed M/2 - w of the skewed bump's levels [0, m]
    positions, masses = aggregate_paths("skewed_bumps", [0.78, 0.8, 0.9])
    offsets = [x[0] - (centre + t * speed) for x, t in zip(positions, (0.78, 0.8, 0.9))]
    assert min(offsets) > 0.01  # 0.0304, 0.0263, 0.0148: the aggregate forms at the peak, right of the centre
    merger = skewed_merger
    before = HullSolution("skewed_bumps", merger * (1 - 1e-9))
    assert before.aggregates[0].size == 2  # the other bump's aggregate is there too (it formed at 1/1.8)
    outside = skewed.mass - before.aggregates[1][0]
    assert outside > 0.05  # 0.0503 of the skewed bump's 0.624 is still outside at the merger
    # Alone, it would be one aggregate once its left end (moving at m/2 relative to its centre of mass) got there.
    assert 2 * (centre - low) / skewed.mass > merger + 0.7
    # The centres of mass of the two bumps, moving freely, would meet at another time and place.
    other_centre, other_speed = other.centre, mass / 2 - skewed.mass - other.mass / 2
    meeting = (other_centre - centre) / (speed - other_speed)
    assert abs(meeting - merger) > 5e-3  # 1.1285 against 1.1205
    assert abs(centre + meeting * speed - HullSolution("skewed_bumps", merger).aggregates[0][0]) > 2e-3


def test_no_false_aggregate_at_the_gap_between_the_skewed_bumps():
    """Between the skewed bump's right end and the other bump, F_0 is flat: Brent's x once stopped a rounding error
    inside the other bump's free tail and reported a third aggregate of 1e-12 of the mass there (at t* - 0.2 and
    t* - 0.1). Two aggregates from the second blow-up to the merger, at every time of a fine grid."""
    merger = merger_time("skewed_bumps", 0.9, 1.5)
    for t in np.concatenate((np.linspace(0.78, merger - 1e-3, 60), merger - np.array([0.2, 0.1, 0.05]))):
        assert HullSolution("skewed_bumps", float(t)).aggregates[0].size == 2, t


def test_issue_46_bump_methods_check_their_positions_index_and_time():
    bump = Bump(2.0, -0.4, 0.3, 2)
    for call, message in [(lambda: bump.scaled(None), "a must be an array"),
                          (lambda: bump.density(np.array([1.0, np.nan])), "a contains NaN"),
                          (lambda: bump.left_integrals(np.broadcast_to(0.0, (10**9,))), "a has 1000000000"),
                          (lambda: bump.scaled(np.array([-1.7e308])), "a is too far from the centre"),
                          (lambda: bump.dense_interval(np.nan), "t must be finite"),
                          (lambda: bump.dense_interval(True), "t must be a real number"),
                          (lambda: TWO_BUMPS.in_bump(2, np.array([0.5])), "index must be at most 1"),
                          (lambda: TWO_BUMPS.in_bump(True, np.array([0.5])), "index must be an integer"),
                          (lambda: TWO_BUMPS.in_bump(1, np.array([1 + 1j])), "a must hold real numbers")]:
        with pytest.raises(ValueError, match=message):
            call()  # NaN, a complex cast, an 8 GB copy, IndexError or an unclear TypeError before
    assert bump.density(np.array([-1.7e308]))[0] == 0.0  # far from the centre: outside the bump, no overflow
    np.testing.assert_array_equal(bump.left_integrals(np.array([-1e300, 1e300]))[0], [0.0, bump.mass])


def test_issue_46_hull_work_and_aggregate_paths_name_their_parameters():
    from particle_methods.cross.hull import check_hull_work

    for call, message in [(lambda: check_hull_work(None, 1), "data must be of type BumpData"),
                          (lambda: check_hull_work(TWO_BUMPS, np.nan, "times"), "times must be an integer"),
                          (lambda: check_hull_work(TWO_BUMPS, -10**49, "times"), "times must be at least 0"),
                          (lambda: aggregate_paths("two_bumps", np.array([1e300])), "times must lie in \\[0, MAX_TIME"),
                          (lambda: aggregate_paths("two_bumps", np.array([-0.5])), "times must lie in")]:
        with pytest.raises(ValueError, match=message):
            call()  # AttributeError, NaN accepted, or an error naming HullSolution's t before
