"""Every method of the three papers on the aggregation equation with K = |x|/2: the identities that tie them
together (particle method = weighted SPD before the first collision, one velocity formula for both), the
first collision, the collapse of the indicator, Godunov's scheme for F, the grid particles and LTP's refusal."""

import numpy as np
import pytest

from particle_methods.blob import CollisionError
from particle_methods.cross import distances, methods
from particle_methods.cross.exact import AggregationSolution
from particle_methods.finite_volume import CONCAVE, godunov
from particle_methods.ltp import StabilityError
from particle_methods.sticky import velocities_from_levels

COMPACT = ("smooth20", "indicator", "smooth10")


def first_meeting(x, v):
    """Earliest meeting time of neighbours moving at constant velocities (inf if none approach)."""
    closing = v[:-1] > v[1:]
    return float(np.min(np.diff(x)[closing] / (v[:-1] - v[1:])[closing])) if np.any(closing) else np.inf


def brute_force_velocities(x, masses):
    """-sum_j m_j K'(x_i - x_j) with K' = sign/2 and K'(0) = 0, pair by pair."""
    return np.array([-0.5 * np.sum(masses * np.sign(xi - x)) for xi in x])


# One velocity formula


def test_weighted_velocities_are_the_spd_velocities_of_the_aggregation_flux(rng):
    """(Lambda(c_k) - Lambda(c_{k-1}))/m_k loses ulp(Lambda) ~ eps M^2 / m_k to cancellation: moderate masses."""
    for _ in range(5):
        masses = rng.uniform(0.1, 1.0, rng.integers(1, 50))
        levels = np.concatenate(([0.0], np.cumsum(masses)))
        expected = velocities_from_levels(methods.aggregation_flux(levels[-1]), levels)
        tolerance = 4.0 * np.finfo(float).eps * levels[-1] ** 2 / masses.min()
        np.testing.assert_allclose(methods.weighted_velocities(masses), expected, rtol=0, atol=tolerance)


@pytest.mark.parametrize("data", COMPACT)
def test_weighted_velocities_are_the_particle_velocities_on_the_initial_grid(data):
    x, _, masses = methods.grid_particles(data, 1.0 / 40)
    assert np.all(np.diff(x) > 0)
    velocities = methods.weighted_velocities(masses)
    np.testing.assert_allclose(methods.particle_velocities(x, masses), velocities, rtol=0, atol=1e-14)
    np.testing.assert_allclose(brute_force_velocities(x, masses), velocities, rtol=0, atol=1e-14)
    # and (M - 2 F)/2 in between: the velocity of the level at the middle of each particle's mass
    middle = np.cumsum(masses) - 0.5 * masses
    np.testing.assert_allclose(velocities, 0.5 * (masses.sum() - 2.0 * middle), rtol=0, atol=1e-14)


def test_weighted_velocities_keep_masses_below_the_rounding_of_the_levels():
    masses = np.array([1e-100, 1.0, 1e-100])
    np.testing.assert_array_equal(methods.weighted_velocities(masses), [0.5, 0.0, -0.5])
    with pytest.raises(ValueError, match="masses"):
        methods.weighted_velocities([1.0, 0.0])


def test_particle_velocities_exert_no_force_between_coincident_particles(rng):
    x = np.array([0.3, -1.0, 0.3, 2.0, 0.3, -1.0])
    masses = rng.uniform(0.1, 1.0, x.size)
    velocities = methods.particle_velocities(x, masses)
    np.testing.assert_allclose(velocities, brute_force_velocities(x, masses), rtol=0, atol=1e-15)
    # the three at 0.3 feel only the mass left of them (pulling left) and right of them (pulling right)
    left, right = masses[[1, 5]].sum(), masses[3]
    np.testing.assert_allclose(velocities[[0, 2, 4]], 0.5 * (right - left), rtol=0, atol=1e-15)
    # a single cluster does not move
    np.testing.assert_array_equal(methods.particle_velocities(np.zeros(4), masses[:4]), 0.0)


# The particle method is the weighted SPD until the first collision


@pytest.mark.parametrize("data", COMPACT)
def test_particle_method_equals_the_weighted_spd_before_the_first_collision(data):
    h = 1.0 / 20
    x, _, masses = methods.grid_particles(data, h)
    collision = first_meeting(x, methods.weighted_velocities(masses))
    assert collision >= 1.0 - 1e-12  # no neighbours meet before the blow-up
    for t in (0.3, 0.9 * collision):
        particle, particle_masses = methods.particle_method(data, h, t)
        spd, spd_masses = methods.spd_grid(data, h, t)
        np.testing.assert_array_equal(particle_masses, spd_masses)
        np.testing.assert_allclose(particle, spd, rtol=0, atol=1e-12)


@pytest.mark.parametrize("data", COMPACT)
def test_particle_method_stops_at_the_first_meeting_of_neighbours(data):
    h = 1.0 / 20
    x, _, masses = methods.grid_particles(data, h)
    predicted = first_meeting(x, methods.weighted_velocities(masses))
    with pytest.raises(CollisionError) as caught:
        methods.particle_method(data, h, predicted + 0.05)
    assert caught.value.time == pytest.approx(predicted, abs=1e-9)
    assert "collide" in str(caught.value)


@pytest.mark.parametrize("k", [5, 20])
def test_weighted_spd_of_the_indicator_collapses_to_one_point(k):
    """Interior particles x_j = -1 + jh move at -x_j and meet at 0 at t = 1; the end particles (half masses)
    at 1 - h/4, so they arrive at t = 1/(1 - h/4): a single point from then on, up to rounding (the velocities
    of the parts of the cluster cancel only to rounding, and the hull may keep them an ulp apart)."""
    h = 1.0 / k
    full = 1.0 / (1.0 - h / 4.0)
    at_one, _ = methods.spd_grid("indicator", h, 1.0)
    np.testing.assert_allclose(np.unique(np.round(at_one, 12)), [-h / 4, 0.0, h / 4], rtol=0, atol=1e-12)
    solution = AggregationSolution("indicator", full)
    for t in (full * (1 + 1e-9), full + 1e-3, 2.0, 10.0):  # (at t = full itself, by rounding, 2e-16 apart)
        positions, masses = methods.spd_grid("indicator", h, t)
        # one point to rounding, which moves at a rounding velocity ~1e-16
        assert np.ptp(positions) <= 1e-15 and np.max(np.abs(positions)) <= 1e-15 * t
        assert distances.w1_atoms(solution, positions, masses) <= 2.0 * abs(positions[0])
    equal, _ = methods.spd_equal("indicator", 2 * k, 1.0)  # the median quantiles all arrive at t = 1
    assert np.ptp(equal) <= 1e-15


# Godunov's scheme for F


@pytest.mark.parametrize("data", COMPACT)
@pytest.mark.parametrize("t", [0.5, 1.1, 3.0])
def test_godunov_keeps_f_a_cumulative_mass(data, t):
    edges, values = methods.godunov_mass(data, 200, t)
    mass = AggregationSolution(data, 0.0).mass
    assert edges[0] == -1.0 and edges[-1] == 1.0 and values.size == 200
    assert values[0] == pytest.approx(0.0, abs=1e-12) and values[-1] == pytest.approx(mass, abs=1e-12)
    # within [0, M] and non-decreasing, up to the rounding of the conservative updates
    assert values.min() >= -1e-13 and values.max() <= mass + 1e-13
    assert np.all(np.diff(values) >= -1e-13)
    # the total mass is conserved: F(1) = M, and the mean of F is the exact one, -int x rho = 0 in the middle
    exact = AggregationSolution(data, t)
    average = np.sum(values) * 2.0 / 200
    assert average == pytest.approx(float(exact.antiderivative(1.0)), abs=1e-12)


def test_godunov_leaves_a_stationary_shock_in_place():
    """F = 0 left of 0 and M right of it is the exact (entropy) solution of a Dirac mass at 0: it stays."""
    u0 = np.concatenate([np.zeros(32), np.ones(32)])
    u = godunov(CONCAVE, u0, np.linspace(-1.0, 1.0, 65), 5.0, left=0.0, right=1.0)
    np.testing.assert_array_equal(u, u0)
    edges, values = methods.godunov_mass("indicator", 64, 3.0)  # the indicator, long after its collapse
    assert distances.w1_cells(AggregationSolution("indicator", 3.0), edges, values) < 0.1


def test_godunov_converges_at_first_order_before_the_blowup():
    solution = AggregationSolution("smooth20", 0.5)
    cells = np.array([64, 256, 1024])
    errors = [distances.w1_cells(solution, *methods.godunov_mass("smooth20", n, 0.5)) for n in cells]
    slope = -np.polyfit(np.log(cells), np.log(errors), 1)[0]
    assert 0.9 <= slope <= 1.1


# Grid particles


@pytest.mark.parametrize("data", COMPACT)
def test_grid_particles_carry_the_mass_of_the_data(data):
    mass = AggregationSolution(data, 0.0).mass
    for k in (4, 20, 64):
        x, density, masses = methods.grid_particles(data, 1.0 / k)
        assert np.all(masses > 0) and np.all(np.diff(x) > 0)
        # the trapezoid rule: exact for the indicator (the halved ends), and for (1 - x^2)^p, whose derivatives
        # vanish at +-1 up to order p - 1, exact to rounding once h is below the width of the bump
        if data == "indicator" or k >= 20:
            assert masses.sum() == pytest.approx(mass, rel=1e-12)
        else:
            assert masses.sum() == pytest.approx(mass, rel=1e-3)
        if data == "indicator":
            assert x.size == 2 * k + 1 and masses[0] == masses[-1] == 0.5 / k
            np.testing.assert_array_equal(density, 1.0)
        else:
            assert x.size == 2 * k - 1  # rho0(+-1) = 0: the ends carry no mass and are left out


def test_grid_particles_refusals():
    with pytest.raises(ValueError, match="whole number"):
        methods.grid_particles("smooth20", 0.3)
    with pytest.raises(ValueError, match="h"):
        methods.grid_particles("smooth20", -0.1)
    with pytest.raises(ValueError, match="support"):
        methods.grid_particles("laplace", 0.1)


# LTP


@pytest.mark.parametrize("data", ["smooth20", "indicator"])
def test_ltp_runs_before_the_blowup(data):
    particles = methods.ltp_method(data, 0.1, 0.05, 0.5)
    solution = AggregationSolution(data, 0.5)
    assert particles.mass == pytest.approx(solution.mass, rel=1e-12)
    knots = np.unique(particles.centres[:, None] + particles.widths[:, None] * particles.shape.breaks[None, :])
    assert distances.w1_smooth(solution, particles.cumulative_mass, knots, particles.widths.min()) < 0.02


@pytest.mark.parametrize(("data", "k"), [("smooth20", 20), ("smooth20", 40), ("indicator", 10), ("indicator", 20)])
def test_ltp_is_refused_at_the_blowup(data, k):
    """rho_h(0) follows the exact 1/(1 - t), so dt rho_h reaches 1 (explicit Euler's bound) at t = 1 - dt:
    LTP refuses the step that would carry it past the blow-up, within one step of 1 - dt."""
    h = 1.0 / k
    dt = h / 2
    with pytest.raises(StabilityError) as caught:
        methods.ltp_method(data, h, dt, 1.1)
    assert 1.0 - 2.0 * dt - 1e-12 <= caught.value.time <= 1.0 + 1e-12


def test_ltp_on_coarse_smooth_data_is_not_refused():
    """With h = 0.1 the reconstruction of (4.3) stays below 1/dt = 20 until t = 1.05 (11.8 at the blow-up):
    LTP steps past the blow-up."""
    particles = methods.ltp_method("smooth20", 0.1, 0.05, 1.05)
    assert particles.density(particles.centres).max() < 20.0
    methods.ltp_method("smooth20", 0.1, 0.05, 1.1)


def test_ltp_on_the_indicator_is_refused_early_at_the_support_edge():
    """Observed, against the claim ltp.refusal (|t_refused - (1 - dt)| <= dt): on the indicator with h = 1/80
    rho_h peaks at the edge of the support, about three times the exact 1/(1 - t), and LTP is refused at
    t = 0.98125 = 1 - 3 dt (for h = 1/160 and 1/320 at the same time, 5 and 11 steps early)."""
    h = 1.0 / 80
    dt = h / 2
    with pytest.raises(StabilityError) as caught:
        methods.ltp_method("indicator", h, dt, 1.1)
    assert caught.value.time == pytest.approx(1.0 - 3.0 * dt, abs=1e-12)
    particles = methods.ltp_method("indicator", h, dt, 0.975)
    density = particles.density(particles.centres)
    densest = particles.centres[np.argmax(density)]
    edge = -AggregationSolution("indicator", 0.975).left_end
    assert abs(abs(densest) - edge) < 2 * h and density.max() > 2.5 / (1.0 - 0.975)


def test_blob_paths_match_separate_runs_and_take_two_bumps():
    positions, masses = methods.blob_paths("two_bumps", 1 / 20, [0.3, 1.2], order=4, q=0.9)
    for k, t in enumerate((0.3, 1.2)):
        alone, _ = methods.blob_method("two_bumps", 1 / 20, t, order=4, q=0.9)
        np.testing.assert_allclose(positions[k], alone, rtol=0, atol=1e-9)  # dense output against a run ending at t
    assert masses.sum() == pytest.approx(0.9066666666666667, rel=1e-14)  # grid masses scaled to the exact total
    with pytest.raises(ValueError, match="times"):
        methods.blob_paths("two_bumps", 1 / 20, [1.2, 0.3], order=4, q=0.9)


def test_ltp_paths_match_separate_runs_and_refuse_times_off_the_steps():
    h = 1 / 40
    paths = methods.ltp_paths("two_bumps", h, h / 2, [0.0, 0.25, 0.45])
    for particles, t in zip(paths, (0.0, 0.25, 0.45)):
        if t > 0:
            np.testing.assert_array_equal(particles.centres, methods.ltp_method("two_bumps", h, h / 2, t).centres)
    assert paths[0].cumulative_mass(np.array([1.0]))[0] == pytest.approx(0.9066666666666667, rel=1e-12)
    with pytest.raises(ValueError, match="whole number of steps"):
        methods.ltp_paths("two_bumps", h, h / 2, [0.0, 0.2501])
    with pytest.raises(ValueError, match="increasing"):
        methods.ltp_paths("two_bumps", h, h / 2, [0.25, 0.0])


def test_issue_46_godunov_advance_and_time_step_check_edges_values_and_work():
    edges, values = np.linspace(-1.0, 1.0, 9), np.linspace(0.02, 0.37, 8)
    for call, message in [(lambda: methods.godunov_advance(edges, [], 0.389, 0.1), "values must hold one value per "
                           "cell of edges"),
                          (lambda: methods.godunov_advance(edges, values, 1e300, 0.1), "with mass = 1e\\+300"),
                          (lambda: methods.godunov_advance(edges, values, 0.389, 0.1, cfl=1e-300), "cfl = 1e-300"),
                          (lambda: methods.godunov_time_step(np.zeros(9), 0.389), "edges must increase"),
                          (lambda: methods.godunov_time_step(edges, 5e-324), "mass is too small")]:
        with pytest.raises(ValueError, match=message):
            call()  # errors naming godunov's u0, dx or t (its time is mass t), or an infinite step, before


def test_issue_46_particle_velocities_refuse_positions_beyond_the_span_limit():
    with pytest.raises(ValueError, match="x must lie in \\[-MAX_VELOCITY_SPAN"):
        methods.particle_velocities(np.full(4, 1e300), np.full(4, 0.1))  # "the masses are too large" before
    np.testing.assert_array_equal(methods.particle_velocities(np.full(2, 1e150), np.full(2, 0.1)), [0.0, 0.0])


def test_issue_46_ltp_paths_check_the_last_time_before_counting_steps():
    with pytest.raises(ValueError, match="times / dt = 2e\\+300 steps"):
        methods.ltp_paths("smooth20", 0.25, 0.125, [0.0, 2.5e299])  # an overflowing cast and an unclear error before


def test_issue_46_single_time_methods_name_their_t_in_the_limits():
    for call in (lambda: methods.particle_method("smooth20", 0.25, 1e300),
                 lambda: methods.blob_method("smooth20", 0.25, 1e300, order=4, q=0.9)):
        with pytest.raises(ValueError, match="t = 1e\\+300 is beyond the particle solver's MAX_TIME"):
            call()  # "times must end by MAX_TIME" before: the solver's parameter
    with pytest.raises(ValueError, match="t up to 1e\\+300 on 8 cells need"):
        methods.godunov_mass("smooth20", 8, 1e300)
    with pytest.raises(ValueError, match="times up to 1e\\+300 on 8 cells need"):
        methods.godunov_paths("smooth20", 8, [1e300])
