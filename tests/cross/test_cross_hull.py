"""The exact solution by the continuous hull (particle_methods.cross.hull): against the symmetric solutions,
against an independent quantile before the blow-ups, against the SPD of many particles, and the aggregates of
the asymmetric data 'two_bumps' against their closed forms."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from particle_methods.cross import AggregationSolution, HullSolution, exact_mass_function, merger_time, methods
from particle_methods.cross.distances import w1_atoms
from particle_methods.cross.hull import TWO_BUMPS, Bump, BumpData, aggregate_paths

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

