"""Every paper claim of the sticky paper can fail: each measure passes on an outcome of the shape the
paper states and fails on a plausible wrong one (a rate without its log factor, a plateau, a state
that never recovers, a cluster that splits at the wrong crossing, a quadratic cost)."""

import functools
import math
from pathlib import Path

import numpy as np
import pytest

from particle_methods.finite_volume.fluxes import burgers_flux, concave_flux
from particle_methods.sticky import admissibility_violation, spd_state
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.hopf import hopf_gap
from particle_methods.sticky.spd import spd_positions
from particle_methods.systems import MINUS, PLUS, PSystem
from particle_replication.claims import ROUNDING
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import sticky as v

CONFIG = read_yaml(Path(__file__).parents[2] / "config" / "config.yaml")["sticky"]
RULES = CONFIG["claims"]  # the tolerances no figure's section holds, as the claims script passes them
N = 2.0 ** np.arange(1, 10)
BAND = (0.25, 1.0)


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"sticky.{name}"]


def quiet():
    return Recorder(log=lambda text: None)


def burgers(errors):
    return {"error_n": N, "errors": errors, "error_times": np.array([10.0, 20.0]),
            "initial_errors": np.zeros(N.size), "flux_lipschitz": 1.0}


def fig2d_claims(errors):
    """The Figure 2 (d) claims on ``errors`` (nine n: the order fitted on all), with the config's tolerance."""
    return v.burgers_claims(burgers(errors), quiet(), 9, RULES["order_tolerance"])


@pytest.mark.parametrize("power, expected", [(1.0, "pass"), (0.5, "fail"), (2.0, "fail")])
def test_fig2d_order_needs_order_one(power, expected):
    errors = np.array([t / 4 * N**-power for t in (10.0, 20.0)])
    assert status(fig2d_claims(errors), "fig2d.order") == expected


def test_fig2d_curves_must_be_ordered_by_time():
    errors = np.array([t / 4 / N for t in (10.0, 20.0)])
    assert status(fig2d_claims(errors), "fig2d.ordering") == "pass"
    assert status(fig2d_claims(errors[::-1]), "fig2d.ordering") == "fail"


def concave(shape):
    """Figure 3 (d) data: for t = 0, 1, 2 a plateau up to a critical n, then the decay ``shape(n, t)``."""
    times = np.array([0.0, 1.0, 2.0])
    critical = {0.0: 1, 1.0: 3, 2.0: 5}  # index of the last plateau point
    errors, clusters = np.empty((3, N.size)), np.ones((3, N.size), dtype=np.int64)
    for i, t in enumerate(times):
        k = critical[t]
        decay = shape(N, t)
        errors[i] = np.where(np.arange(N.size) <= k, decay[k], decay)
        clusters[i, k + 1:] = 2
    rate_n = 2.0 ** np.array([18, 19, 20])
    heaviside = np.array([errors[i, critical[t]] for i, t in enumerate(times)])
    return {"errors": errors, "clusters": clusters, "error_n": N, "error_times": times, "rate_n": rate_n,
            "rate_errors": np.array([shape(rate_n, t) for t in times]), "heaviside_errors": heaviside}


LOG_OVER_N = lambda n, t: (0.5 * np.log(n) + 1 / (1 + t)) / n  # noqa: E731


def test_fig3d_shape_passes_with_a_plateau_then_log_n_over_n():
    claims = v.concave_claims(concave(LOG_OVER_N), quiet(), 3, BAND)
    assert all(claim.status == "pass" for claim in claims), [(c.id, c.measured) for c in claims]


@pytest.mark.parametrize("shape", [lambda n, t: 1 / (1 + t) / n, lambda n, t: np.log(n) ** 2 / (1 + t) / n,
                                   lambda n, t: n**-0.5 / (1 + t)])
def test_fig3d_decay_fails_for_another_rate(shape):
    claims = v.concave_claims(concave(shape), quiet(), 3, BAND)
    assert status(claims, "fig3d.decay_asymptotic") == "fail"
    assert status(claims, "fig3d.decay_plotted") == "fail"


def test_fig3d_fails_when_the_error_grows_past_the_plateau_or_the_critical_n_shrinks():
    data = concave(LOG_OVER_N)
    data["errors"][2, -1] = data["errors"][2, -2] * 1.5
    assert status(v.concave_claims(data, quiet(), 3, BAND), "fig3d.plateau_then_decay") == "fail"
    data = concave(LOG_OVER_N)
    data["heaviside_errors"][2] *= 1.1  # a plateau that is not the distance to the step function
    assert status(v.concave_claims(data, quiet(), 3, BAND), "fig3d.plateau_then_decay") == "fail"
    no_plateau = concave(lambda n, t: (0.5 * np.log(n) + 1 / (1 + t)) / n)
    no_plateau["errors"] = np.array([(0.5 * np.log(N) + 1 / (1 + t)) / N for t in (0.0, 1.0, 2.0)])
    assert status(v.concave_claims(no_plateau, quiet(), 3, BAND), "fig3d.plateau_then_decay") == "fail"
    data = concave(LOG_OVER_N)
    data["errors"][2, 3] = data["errors"][1, 3] * 1.01  # a curve of a larger t above one of a smaller t
    assert status(v.concave_claims(data, quiet(), 3, BAND), "fig3d.ordering") == "fail"
    data = concave(LOG_OVER_N)
    data["errors"][1:] = data["errors"][[2, 1]]  # t = 1 now has the longer plateau
    assert status(v.concave_claims(data, quiet(), 3, BAND), "fig3d.critical_n_grows") == "fail"


def test_theorem31_bound_can_fail():
    good = burgers(np.array([t / (4 * N) for t in (10.0, 20.0)]))
    assert status(v.theorem31_claims(good, good), "thm31.bound") == "pass"
    bad = burgers(np.array([2 * t / N for t in (10.0, 20.0)]))
    assert status(v.theorem31_claims(good, bad), "thm31.bound") == "fail"


def concave_spd(n, t):
    """The SPD of the concave flux from the Laplace data (2.1): the pipeline's states."""
    return spd_state(*SCALAR_CASES["concave_laplace"].initial_state(n), t)


def two_atoms_spd(n, t):
    """The SPD of Burgers' flux from the two atoms of Figure 2: every upward jump is a rarefaction."""
    return spd_state(*SCALAR_CASES["burgers_two_atoms"].initial_state(n), t)


def admissibility(state, flux=concave_flux, n_values=(4, 32), times=(0.0, 2.0, 3.0, 17.0)):
    """The keys of the exact tests: (RH) and (E) by admissibility_violation on the states ``state(n, t)``,
    Hopf's formula by hopf_gap on the same positions from the pipeline's initial atoms of ``flux``."""
    table = [[admissibility_violation(*state(n, t), flux) for t in times] for n in n_values]
    case = SCALAR_CASES["concave_laplace" if flux is concave_flux else "burgers_two_atoms"]
    gaps = [[hopf_gap(case.initial_state(n)[0], state(n, t)[0], t, flux) for t in times] for n in n_values]
    return {"admissibility_n": np.array(n_values), "admissibility_times": np.array(times),
            "admissibility_rankine_hugoniot": np.array([[r.rankine_hugoniot for r in row] for row in table]),
            "admissibility_entropy": np.array([[r.entropy for r in row] for row in table]),
            "admissibility_clusters": np.array([[r.clusters for r in row] for row in table]),
            "convex_admissibility": np.full((len(n_values), len(times)), 0.1),
            "hopf_gaps": np.array(gaps), "convex_hopf_gaps": np.full((len(n_values), len(times)), 0.1)}


def remark33(distance_shape, dirac_factor=4.0, state=concave_spd, flux=concave_flux):
    n, t = np.array([1, 10, 100]), np.array([1.0, 10.0])
    cells = np.array([50, 100, 200, 400])
    return {"dirac_n": n, "dirac_times": t, "dirac_errors": t[:, None] / (dirac_factor * n[None, :]),
            "cells_per_unit": cells, "godunov_n": np.array([4, 32]), "godunov_times": np.array([1.0, 5.0]),
            "distances": np.array([[distance_shape(1.0 / cells)] * 2] * 2),
            "total_errors": np.full((2, 2), 0.5), "initial_errors": np.ones(2),
            "convex_n": 4, "convex_t": 1.0, "convex_distances": 1 / 16 + 1.0 / cells,
            "refined_cells": cells[-3:], "refined_distances": 1.0 / cells[-3:], "refined_n": 256, "refined_t": 1.0,
            **admissibility(state, flux)}


R33 = CONFIG["remark33"]


def remark33_claims(data):
    """The Remark 3.3 claims on ``data`` with the config's factor and tolerance."""
    return v.remark33_claims(data, R33["godunov_decrease"], R33["convex"]["tolerance"])


def test_remark33_concave_passes_on_the_spd_of_the_concave_flux():
    claims = remark33_claims(remark33(lambda h: 0.3 * h))
    assert all(claim.status == "pass" for claim in claims), [(c.id, c.measured) for c in claims]


def laplace_spd(n, t, time_factor=1.0, velocity_factor=1.0):
    """The pipeline's SPD of the concave flux from the Laplace data (2.1), at time_factor t with
    velocity_factor times the velocities of section 1.1.3 (a position update or clock off by a factor)."""
    x, v = SCALAR_CASES["concave_laplace"].initial_state(n)
    return spd_positions(x, velocity_factor * v, time_factor * t), v


def sorted_free_flight(n, t):
    """No sticking, the free positions sorted: the SPD until the first collision, then not."""
    x, v = SCALAR_CASES["concave_laplace"].initial_state(n)
    return np.sort(x + t * v), v


def random_integers(n, t):
    """Sorted random integers: order-preserving positions unrelated to the data."""
    return np.sort(np.random.default_rng(n).integers(-5, 6, size=n)).astype(float), np.zeros(n)


WRONG_STATES = {
    "at 2t": functools.partial(laplace_spd, time_factor=2.0),
    "x2 velocities": functools.partial(laplace_spd, velocity_factor=2.0),
    "x1/2 velocities": functools.partial(laplace_spd, velocity_factor=0.5),
    "sorted free flight": sorted_free_flight,
    "random sorted integers": random_integers,
}


@pytest.mark.parametrize("name", WRONG_STATES)
def test_remark33_concave_fails_on_order_preserving_wrong_states(name):
    """Each state keeps the particles' order; those from the SPD move each cluster at the mean of its
    velocities, so (RH) and (E) (the check remark33.oleinik) cannot see them; Hopf's formula does."""
    data = remark33(lambda h: 0.3 * h, state=WRONG_STATES[name])
    assert status(remark33_claims(data), "remark33.concave") == "fail", data["hopf_gaps"]


def test_remark33_oleinik_is_blind_to_a_wrong_clock():
    """Why the (RH)-(E) test is a check: the SPD at 2t satisfies it exactly."""
    data = remark33(lambda h: 0.3 * h, state=lambda n, t: concave_spd(n, 2 * t))
    assert status(remark33_claims(data), "remark33.oleinik") == "pass"
    assert status(remark33_claims(data), "remark33.concave") == "fail"


def test_remark33_concave_fails_for_a_convex_flux():
    """Burgers from the two atoms of Figure 2: every upward jump is a rarefaction, which G lies above."""
    data = remark33(lambda h: 0.3 * h, state=two_atoms_spd, flux=burgers_flux)
    assert status(remark33_claims(data), "remark33.concave") == "fail"
    assert status(remark33_claims(data), "remark33.oleinik") == "fail"


def test_remark33_concave_fails_on_a_violation_just_above_rounding():
    data = remark33(lambda h: 0.3 * h)
    data["hopf_gaps"][1, 2] = 10 * ROUNDING
    assert status(remark33_claims(data), "remark33.concave") == "fail"


def test_remark33_godunov_distance_must_fall_towards_zero_under_refinement():
    assert status(remark33_claims(remark33(lambda h: 0.3 * h)), "remark33.godunov_refinement") == "pass"
    plateau = remark33(lambda h: 1 / 16 + 0.3 * h)  # a non-entropic SPD: the distance stops at its own error
    assert status(remark33_claims(plateau), "remark33.godunov_refinement") == "fail"


def test_remark33_distances_at_rounding_level_count_as_exact_agreement():
    data = remark33(lambda h: 0.3 * h)
    data["distances"][0, 1] = 1e-16 / data["cells_per_unit"]  # grows under refinement, but only rounding
    assert status(remark33_claims(data), "remark33.godunov_refinement") == "pass"
    data["distances"][1, 1] = 1 / 16 + 1e-16 / data["cells_per_unit"]  # but a plateau elsewhere still fails
    assert status(remark33_claims(data), "remark33.godunov_refinement") == "fail"


def test_remark33_contraction_can_fail():
    data = remark33(lambda h: h)
    data["total_errors"][1, 1] = 1.5  # an error above the initial discretisation error
    assert status(remark33_claims(data), "remark33.contraction") == "fail"


def test_remark33_dirac_error_must_be_t_over_4n():
    assert status(remark33_claims(remark33(lambda h: h)), "remark33.dirac") == "pass"
    stuck = remark33(lambda h: h, dirac_factor=2.0)
    assert status(remark33_claims(stuck), "remark33.dirac") == "fail"


def lemma21(exponential_limit=0.25, weibull=lambda n, a: (0.25 * np.log(n) ** (1 / a) + 1) / n,
            heavy=lambda r: np.log(r)):
    n = np.array([16, 64, 256, 1024, 4096, 16384])
    upper = 10.0 ** np.arange(2, 7)
    data = {"n_values": n, "odd_n": n + 1, "uniform": 0.25 / n, "uniform_odd": 0.25 / (n + 1),
            "uniform_support": 1.0, "uniform_sqrt_variance": 1.0,
            "exponential_1": exponential_limit / n, "exponential_1_odd": exponential_limit / (n + 1),
            "exponential_1_support": 1.0, "pareto_alpha": np.array([1.5]), "pareto_1.5": n ** (-1 / 3),
            "weibull_alpha": np.array([1.0, 0.5]), "heavy_upper": upper, "heavy_errors": heavy(upper)}
    data["uniform_sqrt_variance"] = 0.25
    for alpha in (1.0, 0.5):
        data[f"weibull_{alpha:g}"] = weibull(n, alpha)
    return data


def lemma21_claims(data):
    """The Lemma 2.1 claims on ``data`` (six n: rates on the four largest), with the config's band, ratio
    and tolerances."""
    lemma21 = CONFIG["lemma21"]
    return v.lemma21_claims(data, quiet(), 4, lemma21["weibull_band"], lemma21["heavy_tail"]["growth_ratio"],
                            RULES["quadrature_margin"], RULES["positive_density_tolerance"], RULES["pareto_tolerance"])


def test_lemma21_passes_on_the_stated_behaviour():
    claims = lemma21_claims(lemma21())
    assert all(claim.status == "pass" for claim in claims), [(c.id, c.measured) for c in claims]


@pytest.mark.parametrize("weibull", [lambda n, a: 1.0 / n, lambda n, a: np.log(n) ** (2 / a) / n])
def test_lemma21_weibull_rates_need_their_log_factor(weibull):
    claims = lemma21_claims(lemma21(weibull=weibull))
    assert status(claims, "lemma21.weibull_1") == "fail"


def test_lemma21_iv_limit_and_i_growth_can_fail():
    claims = lemma21_claims(lemma21(exponential_limit=0.5))
    assert status(claims, "lemma21.iv.exponential_1") == "fail"
    finite_moment = lambda r: 0.2 - r ** -0.5  # noqa: E731  (a tail with alpha = 1.5 saturates)
    claims = lemma21_claims(lemma21(heavy=finite_moment))
    assert status(claims, "lemma21.i.heavy_tail") == "fail"


def test_lemma21_bounds_and_pareto_rate_can_fail():
    data = lemma21()
    data["uniform_odd"] = 0.6 / (data["odd_n"])  # above (b - a)/(2n)
    data["uniform"] = data["uniform"] * 8  # above n^(-1/2) int sqrt(F(1 - F)) at the largest n
    data["pareto_1.5"] = data["n_values"] ** -0.5  # the rate of a lighter tail than alpha = 1.5
    claims = lemma21_claims(data)
    assert [status(claims, name) for name in ("lemma21.iii", "lemma21.ii", "lemma21.pareto_1.5")] == ["fail"] * 3


def tspd(delta_power=1.0, n_power=1.0, constant=1.0):
    deltas, n = 0.1 / 2.0 ** np.arange(5), np.array([25.0, 50, 100, 200, 400])
    bound = np.log(n) / n
    return {"cases": np.array(["rarefaction"]), "times": np.array([1.0, 2.0]), "deltas": deltas,
            "delta_n": np.array([100, 400]), "reference_delta": 1e-3,
            "delta_errors": np.array([[[deltas**delta_power] * 2, [constant * deltas**delta_power] * 2]]),
            "n_values": n,
            "n_delta": 2e-3, "reference_n": 6400, "n_errors": np.array([[bound * (25 / n) ** (n_power - 1)] * 2]),
            "bounds": np.array([[bound] * 2]), "delta_reference_gap": np.full((1, 2), 1e-6),
            "n_reference_gap": np.full((1, 2), 1e-6)}


def test_theorem44_measures_can_fail():
    claims = v.tspd_claims(tspd(), quiet(), 3, 0.9, 0.1, 0.5, 2.0)
    assert all(claim.status == "pass" for claim in claims), [(c.id, c.measured) for c in claims]
    assert status(v.tspd_claims(tspd(delta_power=0.5), quiet(), 3, 0.9, 0.1, 0.5, 2.0),
                  "thm44.delta_order_rarefaction") == "fail"
    assert status(v.tspd_claims(tspd(n_power=0.5), quiet(), 3, 0.9, 0.1, 0.5, 2.0),
                  "thm44.n_bound_rarefaction") == "fail"
    # a constant that grows with n (four times more particles, four times the error per Delta)
    assert status(v.tspd_claims(tspd(constant=4.0), quiet(), 3, 0.9, 0.1, 0.5, 2.0),
                  "thm44.delta_constant_rarefaction") == "fail"


def rarefaction(collide=False, cross=False):
    times = np.linspace(0, 1, 11)
    base = np.linspace(0.0, 1.0, 4)
    path = np.array([[base + 2 + t, base - 2 - t] for t in times])
    if collide:
        path[5:, PLUS, 1] = path[5:, PLUS, 2]
    if cross:
        path[5:, PLUS] += 10.0
    return {"trajectories": path, "field_path": path, "times": times}


def shocks(split_after=2, recover=True, clusters_left=False):
    """A + cluster of 4 at -t; - particles cross it one per step from the right; it splits in the step
    after rank ``split_after`` has crossed; then (if ``recover``) everything separates."""
    n, steps = 4, 12
    times = 0.1 * np.arange(steps + 1)
    path = np.empty((steps + 1, 2, n))
    for step in range(steps + 1):
        crossed = min(max(step - 1, 0), n)
        minus = np.concatenate([-1.0 - np.arange(n - crossed)[::-1] * 0.1, 1.0 + np.arange(crossed) * 0.1])
        path[step, MINUS] = np.sort(minus)
        split = step > split_after + 1
        path[step, PLUS] = np.arange(n) * 0.02 * (step - split_after - 1) if split else 0.0
        if not recover:
            path[step, PLUS] += 10.0
    path[1:4, MINUS, 0] = path[1:4, MINUS, 1]  # two - particles stuck together early: a - cluster
    if clusters_left:
        path[:, MINUS, 0] = path[:, MINUS, 1]
    end = math.inf if (not recover or clusters_left) else float(times[-3])
    return {"trajectories": path, "field_path": path, "times": times, "trajectories_end": end, "field_end": end,
            "max_time": 10.0}


def test_psystem_claims_pass_on_the_described_dynamics():
    claims = v.psystem_claims(rarefaction(), shocks(), 0.05, PSystem())
    paper = [claim for claim in claims if claim.kind == "paper"]
    assert all(claim.status == "pass" for claim in paper), [(c.id, c.measured) for c in paper]


@pytest.mark.parametrize("data, name", [
    (dict(rarefaction=rarefaction(cross=True)), "fig4.order_preserved"),
    (dict(rarefaction=rarefaction(collide=True)), "fig4.no_same_type_collision"),
    (dict(rarefaction=rarefaction(collide=True)), "fig5.no_shock"),
    (dict(shocks=shocks(split_after=0)), "fig6.breakup_at_median"),
    (dict(shocks=shocks(split_after=4)), "fig6.breakup_at_median"),
    (dict(shocks=shocks(recover=False)), "fig6.order_recovered"),
    (dict(shocks=shocks(clusters_left=True)), "fig6.drift_apart"),
    (dict(shocks=shocks(clusters_left=True)), "fig7.late_rarefactions"),
])
def test_psystem_claims_fail_on_wrong_dynamics(data, name):
    claims = v.psystem_claims(data.get("rarefaction", rarefaction()), data.get("shocks", shocks()), 0.05, PSystem())
    assert status(claims, name) == "fail"


def test_fig6_and_fig7_clusters_are_needed():
    separate = shocks()
    separate["trajectories"][1:4, MINUS, 0] -= 0.05  # no - cluster
    assert status(v.psystem_claims(rarefaction(), separate, 0.05, PSystem()), "fig6.minus_clusters_form") == "fail"
    assert status(v.psystem_claims(rarefaction(), shocks(), 2.0, PSystem()), "fig7.early_shocks") == "fail"
    # the + particles' initial Dirac mass is no shock that forms: without - clusters the claim fails
    assert status(v.psystem_claims(rarefaction(), separate, 0.05, PSystem()), "fig7.early_shocks") == "fail"


def test_plus_cluster_threshold_follows_the_velocities():
    # With most - particles still on its left the + cluster holds; the rank that breaks it is the
    # same fraction of n for large n (about 32 %, not the median).
    thresholds = {n: v.plus_cluster_threshold(PSystem(), n) for n in (20, 200, 2000)}
    assert thresholds[20] == 7 and 0.31 < thresholds[2000] / 2000 < 0.33


#: The load guard's readings of a timing made alone on a two-core machine.
QUIET = {"cpu": np.array("a test CPU (AVX2, 2 cores)"), "cpu_share": np.array(0.99), "load": np.array(0.1),
         "cores": np.array(2), "threads": np.array(1)}


def cost(power, time_power=1.0, processes=3, **readings):
    """The cost study's results: every kernel counting operations linear in its size but the hull's (``power``),
    every time linear in the operations but the hull's (``time_power``), timed alike in ``processes``
    processes (one row of times each)."""
    sizes = np.array([1e3, 1e4, 1e5, 1e6])
    linear = (4 * sizes).astype(np.int64)
    hull = (3 * sizes**power).astype(np.int64)

    def rows(seconds):
        return np.tile(seconds, (processes, 1))

    return {"hull_n": sizes, "hull_operations": hull, "hull_free_operations": linear,
            "hull_times": rows(1e-9 * hull**time_power), "hull_free_times": rows(1e-9 * linear), "rank_n": sizes,
            "rank_operations": linear, "rank_times": rows(1e-9 * linear), "tspd_n": sizes,
            "tspd_operations": linear, "tspd_times": rows(1e-9 * linear), "tspd_steps": 20, "steps_values": sizes,
            "steps_operations": linear, "steps_times": rows(1e-9 * linear), "steps_n": 1000, **QUIET, **readings}


def test_cost_claims_fail_for_a_quadratic_kernel():
    """Decided on the operations the kernels count: a quadratic count fails, whatever the times say."""
    assert status(v.cost_claims(cost(1.0), quiet(), 3, (0.8, 1.2)), "cost.hull") == "pass"
    assert status(v.cost_claims(cost(2.0), quiet(), 3, (0.8, 1.2)), "cost.hull") == "fail"
    slow = cost(1.0)
    for key in ("rank_operations", "tspd_operations"):
        slow[key] = (slow["rank_n"] ** 2).astype(np.int64)
    claims = v.cost_claims(slow, quiet(), 3, (0.8, 1.2))
    assert status(claims, "cost.rank_step") == "fail" and status(claims, "cost.tspd_n") == "fail"


def test_wall_time_decides_only_its_check_and_abstains_on_a_loaded_machine():
    """Times growing faster than the counted operations fail the wall-time check, not the paper's claims; timed
    while another process held the core, the check abstains and says why."""
    claims = v.cost_claims(cost(1.0, time_power=1.5), quiet(), 3, (0.8, 1.2))
    assert status(claims, "cost.hull") == "pass" and status(claims, "cost.wall_time") == "fail"
    loaded = v.cost_claims(cost(1.0, time_power=1.5, cpu_share=np.array(0.6)), quiet(), 3, (0.8, 1.2))
    check = next(claim for claim in loaded if claim.id == "sticky.cost.wall_time")
    assert check.status == "abstain" and "0.60 of a core" in check.claim
    assert {claim.status for claim in loaded if claim.id != check.id} == {"pass"}


def wall_time(d):
    return next(claim for claim in v.cost_claims(d, quiet(), 3, (0.8, 1.2)) if claim.id == "sticky.cost.wall_time")


def test_wall_time_is_decided_only_when_every_timing_process_gives_the_same_verdict():
    """The largest TSPD run 3 times slower in one timing process of three (its memory, not the algorithm: the
    exponent over the window's two decades moves by log10(3) / 2 = 0.24): that process alone would fail the
    check, so one process never decides it (it abstains, saying so); the three abstain and say which series split
    them; slower in all three, the check fails."""
    one = cost(1.0)
    one["tspd_times"][0, -1] *= 3.0
    alone = wall_time({key: value[:1] if key.endswith("_times") else value for key, value in one.items()})
    assert alone.status == "abstain" and float(alone.measured) == pytest.approx(1.24, abs=0.01)
    assert "timed in one process" in alone.claim
    assert wall_time({key: value[:1] if key.endswith("_times") else value
                      for key, value in cost(1.0).items()}).status == "abstain"  # even where it would pass
    split = wall_time(one)
    assert split.status == "abstain" and "exponent of tspd_n on both sides" in split.claim
    assert float(split.measured) == pytest.approx(1.0)  # the median of 1.24, 1 and 1
    every = cost(1.0)
    every["tspd_times"][:, -1] *= 3.0
    assert wall_time(every).status == "fail"
    assert wall_time(cost(1.0)).status == "pass"


PREDICTIONS = {"spd_burgers_two_atoms": (1, 0), "spd_concave_laplace": (1, 1.0),
               "godunov_burgers_two_atoms": (2, 0.357), "godunov_concave_laplace": (2, 0),
               **{f"{method}_{case}": (2, 1.0 if method != "upwind" else 0)
                  for method in ("tspd", "exact", "upwind") for case in ("rarefaction", "shocks")}}
BEYOND = {"window": 3, "limit_order_min": 0.8, "separation": 3.0, "reference_share": 0.2,
          "predictions": {key: {"k": k, "log_scale": s} for key, (k, s) in PREDICTIONS.items()},
          "exponent_tolerance": CONFIG["beyond"]["exponent_tolerance"],
          "exponent_uncertainty": CONFIG["beyond"]["exponent_uncertainty"],
          "competing_exponent": CONFIG["beyond"]["competing_exponent"],
          "events_band": (1.8, 2.2), "time_floor": 0.01, "time_band": (0.8, 1.25),
          "scalar_ratio_min": 10.0, "same_cost_band": (0.1, 10.0), "domain": (-3.0, 3.0)}


def runs(errors, work, seconds, *extra):
    return np.array([errors, work, seconds, *extra], dtype=float)


def beyond(spd_exponent=1.0, godunov_exponent=2.0, method_exponent=2.0, exact_slowdown=1.0, events_exponent=2.0,
           rarefaction_plateau=False, shock_gap=0.05, mspd_gap=1e-3, reference_gap=1e-4, hll_gap=2e-4, time_power=1.0,
           laplace_log=True, plus_shift=0.1, spd_time_power=1.0, speed=1.02, timings=3):
    """Study results shaped as the theory predicts, with one knob per claim to make it wrong. Errors are
    (1 + log n)/n where the prediction carries a log factor; every method's three largest runs last
    more than the time floor. Every run was timed ``timings`` times, its slowest ``speed`` times its best (the
    machine's speed moved that much between rounds)."""
    n = np.array([50.0, 100.0, 200.0, 400.0, 800.0])
    errors = (1.0 + np.log(n) * laplace_log) / n
    d = {"t": 2.0, "cases": np.array(["rarefaction", "shocks"]), "limit_n": np.array([100, 200, 400, 800]),
         "reference_cells": 600, "upwind_reference_cells": 600, "exact_n": n, "tspd_n": n, "upwind_cells": 40 * n}
    centres = np.linspace(-3.0, 3.0, 601)[:-1] + 0.005
    uniform = np.linspace(-1.0, 1.0, 800)                             # particles of a uniform law on [-1, 1]
    sizes = np.array([100.0, 400.0, 1600.0, 6400.0, 25600.0])
    cells = np.array([250.0, 500.0, 1000.0, 2000.0, 4000.0])
    for name in v.SCALAR_NAMES:
        d[f"{name}_spd_n"], d[f"{name}_cells"] = sizes, cells
        d[f"{name}_spd"] = runs(1.0 / sizes, sizes ** spd_exponent, 1e-5 * sizes ** (spd_exponent * spd_time_power))
        work = (cells / 10.0) ** godunov_exponent
        d[f"{name}_godunov"] = runs(10.0 / cells, work, 1e-6 * work ** time_power)
    for case in ("rarefaction", "shocks"):
        limit = 2.0 / d["limit_n"]
        if case == "rarefaction" and rarefaction_plateau:
            limit = 0.01 + 0 * limit
        if case == "shocks":
            limit = limit + shock_gap
        d.update({f"{case}_limit_to_hll": limit, f"{case}_limit_to_upwind": limit, f"{case}_mspd_gap": mspd_gap,
                  f"{case}_hll_gap": hll_gap, f"{case}_reference": "exact MSPD",
                  f"{case}_reference_error": reference_gap,
                  f"{case}_mspd": np.array([uniform, uniform]),
                  f"{case}_hll_w": np.clip(0.5 * (1.0 + centres - plus_shift), 0.0, 1.0)[None, :].repeat(2, axis=0),
                  f"{case}_upwind_w": np.clip(0.5 * (1.0 + centres), 0.0, 1.0)[None, :].repeat(2, axis=0)})
        d[f"{case}_tspd"] = runs(errors, n ** method_exponent, 1e-6 * n**2)
        d[f"{case}_exact"] = runs(errors, n**2, exact_slowdown * 1e-6 * n**2, n**events_exponent)
        d[f"{case}_upwind"] = runs(2.0 / n, n**2, 1e-6 * n**2)
    series = [f"{name}_{method}" for name in v.SCALAR_NAMES for method in ("spd", "godunov")]
    series += [f"{case}_{method}" for case in ("rarefaction", "shocks") for method in ("tspd", "exact", "upwind")]
    for key in series:
        d[f"{key}_timing"] = np.array([speed * d[key][2], np.full(d[key].shape[1], timings)])
    return {**d, **QUIET}


def beyond_status(d, name):
    return status(v.beyond_claims(d, quiet(), BEYOND), f"beyond.{name}")


def test_the_spds_memory_bound_time_exponent_does_not_decide_the_wall_time_check():
    """The SPD's largest runs cross from the cache to memory (time per particle 7.1, 9.4, 10.5 ns at n = 1.6e6,
    3.3e6, 6.6e6): an exponent of 1.3 against its operations is reported, not decisive; the other methods' still
    are (time_power above)."""
    claims = v.beyond_claims(beyond(spd_time_power=1.3), quiet(), BEYOND)
    check = next(claim for claim in claims if claim.id == "sticky.beyond.cost.wall_time")
    assert check.status == "pass" and "spd_concave_laplace 1.30" in check.claim


def test_beyond_claims_pass_on_the_predicted_shapes():
    claims = v.beyond_claims(beyond(), quiet(), BEYOND)
    assert {claim.status for claim in claims} == {"pass"}, [c.id for c in claims if c.status != "pass"]
    assert all(claim.kind in ("derived", "check") for claim in claims)


@pytest.mark.parametrize("knobs, name", [
    ({"spd_exponent": 2.0}, "exponent.spd_burgers_two_atoms"),        # a quadratic hull
    ({"godunov_exponent": 3.0}, "exponent.godunov_concave_laplace"),  # half an order
    ({"godunov_exponent": 3.0}, "exponent.godunov_burgers_two_atoms"),  # beyond its log factor too
    ({"method_exponent": 3.0}, "exponent.tspd_rarefaction"),          # O(eps^-3)
    ({"events_exponent": 3.0}, "exact.events_shocks"),                # cubic event count
    ({"exact_slowdown": 100.0}, "ratio.same_cost_rarefaction"),       # exact much dearer
    ({"godunov_exponent": 1.0}, "ratio.scalar_burgers_two_atoms"),     # Godunov as cheap as the SPD
    ({"rarefaction_plateau": True}, "limit.rarefaction"),             # no convergence
    ({"shock_gap": 0.0}, "limit.shocks"),                             # the limits agree
    ({"reference_gap": 0.01}, "cost.resolved_rarefaction"),           # a reference too coarse for the runs
    ({"reference_gap": 1e-3}, "exponent.separation_shocks"),          # fits left on sizes where 2.5 is in range
    ({"hll_gap": 0.05}, "limit.reference_rarefaction"),               # a coarse conservative reference
    ({"time_power": 1.5}, "cost.wall_time"),                          # the counted operations are not the cost
    ({"plus_shift": 0.0}, "limit.plus_wave_shocks"),                  # the + waves coincide
])
def test_each_beyond_claim_fails_on_a_wrong_outcome(knobs, name):
    assert beyond_status(beyond(), name) == "pass"
    assert beyond_status(beyond(**knobs), name) == "fail"


def test_the_log_factor_range_holds_the_exponent_of_a_log_n_over_n_error():
    n = np.array([100.0, 200.0, 400.0])
    lower, upper = v.predicted_exponents(2, 1.0, n[0], 0.0)
    for a, b in ((0.0, 1.0), (1.0, 1.0), (1.0, 0.0)):
        errors = (a + b * np.log(n)) / n
        exponent = np.polyfit(np.log(1.0 / errors), np.log(n**2), 1)[0]
        assert lower - 1e-12 <= exponent <= upper
    assert upper == pytest.approx(2.0 / (1.0 - 1.0 / math.log(100.0)))
    assert v.predicted_exponents(2, 0, 100.0, 0.1) == pytest.approx((1.8, 2.2))
    with pytest.raises(ValueError, match="log"):
        v.predicted_exponents(2, 1.0, 2.0, 0.1)


def test_a_pure_power_outside_the_log_range_fails_and_without_the_log_factor_the_log_data_fail():
    # (log n)/n errors of the TSPD: inside the log range, outside the pure band [1.8, 2.2] on small n.
    d = beyond()
    assert beyond_status(d, "exponent.tspd_rarefaction") == "pass"
    pure = {**BEYOND, "predictions": {**BEYOND["predictions"], "tspd_rarefaction": {"k": 2, "log_scale": 0}}}
    assert status(v.beyond_claims(d, quiet(), pure), "beyond.exponent.tspd_rarefaction") == "fail"


def test_runs_the_reference_cannot_resolve_never_enter_a_fit():
    """A reference error of 1e-3 blurs the pairwise exponents of the most accurate runs: the exact MSPD's fit
    moves to the coarsest runs it still resolves, where the log-factor range holds 2.5 (the separation check
    fails), and the upwind runs (errors 2/n) keep no window at all, which the check cost.resolved reports (a
    defect of the reference, not a verdict)."""
    assert sorted(v.exponent_window(*beyond()["rarefaction_exact"][:2], 1e-4, 3, 0.1).tolist()) == [2, 3, 4]
    d = beyond(reference_gap=1e-3)
    assert sorted(v.exponent_window(*d["rarefaction_exact"][:2], 1e-3, 3, 0.1).tolist()) == [0, 1, 2]
    assert beyond_status(d, "exponent.exact_rarefaction") == "pass"
    assert beyond_status(d, "cost.resolved_rarefaction") == "fail"
    assert beyond_status(d, "exponent.separation_rarefaction") == "fail"
    assert beyond_status(beyond(reference_gap=2e-3), "exponent.separation_rarefaction") == "fail"  # no window


def test_runs_shorter_than_the_floor_never_enter_a_time_fit():
    work = np.array([1e3, 1e4, 1e5, 1e6, 1e7, 1e8])
    overhead = 2e-3 + 1e-8 * work                                     # a fixed 2 ms per call dominates below 1e5
    steady = np.array([overhead, np.full(6, 3)])
    assert v.time_exponent(work, overhead, steady, 0.01, 3) == pytest.approx((1.0, 0.0), abs=0.1)
    assert v.time_exponent(work, overhead, steady, 0.0, 6)[0] < 0.8
    assert all(map(math.isnan, v.time_exponent(work, overhead, steady, 1.0, 3)))


def test_the_time_exponents_uncertainty_bounds_what_the_machines_speed_can_do_to_it():
    """Each fitted time up to s times its steady value (s: the largest slowest-over-best ratio of the series'
    repeated runs) moves the fitted slope by at most the uncertainty; the bound is reached when the larger runs
    are all slowed; it is infinite when no run was timed twice."""
    rng = np.random.default_rng(3)
    work = np.array([1e5, 4e5, 1.6e6, 6.4e6])
    steady = 1e-8 * work
    for s in (1.05, 1.6, 2.0):
        timing = np.array([s * steady, np.full(4, 3)])
        slope, uncertainty = v.time_exponent(work, steady, timing, 0.0, 3)
        assert slope == pytest.approx(1.0) and uncertainty == pytest.approx(math.log(s) / math.log(16.0))
        for _ in range(200):
            moved = steady * np.exp(rng.uniform(0.0, math.log(s), 4))
            assert abs(v.time_exponent(work, moved, timing, 0.0, 3)[0] - 1.0) <= uncertainty + 1e-12
        worst = steady * np.where(np.log(work) > np.log(work[1:]).mean(), s, 1.0)
        assert v.time_exponent(work, worst, timing, 0.0, 3)[0] - 1.0 == pytest.approx(uncertainty)
    assert v.time_exponent(work, steady, np.array([steady, np.ones(4)]), 0.0, 3)[1] == math.inf


def wall_time_check(d, floor=BEYOND["time_floor"]):
    claims = v.beyond_claims(d, quiet(), {**BEYOND, "time_floor": floor})
    return next(claim for claim in claims if claim.id == "sticky.beyond.cost.wall_time")


def test_the_wall_time_check_abstains_when_the_machines_speed_puts_an_exponent_across_the_band():
    """The full run that failed the check (its exponent 0.76 for the Godunov scheme, 0.97 when its job ran
    again): an exponent near an end of the band is decided only on a machine whose speed held between the
    rounds; one far outside fails whatever the speed did, and an unmeasured speed decides nothing."""
    steady = wall_time_check(beyond(time_power=0.76), floor=1e-3)
    moving = wall_time_check(beyond(time_power=0.76, speed=1.6), floor=1e-3)
    assert steady.status == "fail" and moving.status == "abstain"
    assert "across an end of [0.8, 1.25]" in moving.claim and "godunov_concave_laplace 0.76 +- 0.17" in moving.claim
    short = wall_time_check(beyond(time_power=0.76))  # its Godunov runs all under the floor: nothing to decide on
    assert short.status == "abstain" and "fewer than two runs of godunov_burgers_two_atoms" in short.claim
    assert wall_time_check(beyond(speed=1.6)).status == "pass"         # 1 +- 0.17 lies inside
    assert wall_time_check(beyond(time_power=1.5, speed=1.6)).status == "fail"
    once = wall_time_check(beyond(timings=1))
    assert once.status == "abstain" and "was timed twice, so the machine's speed is unmeasured" in once.claim
    loaded = wall_time_check({**beyond(time_power=1.5), "load": np.array(3.0)})
    assert loaded.status == "abstain" and "runnable" in loaded.claim


def test_values_at_an_error_are_interpolated_never_extrapolated():
    errors, seconds = np.array([1e-1, 1e-2, 1e-3]), np.array([1.0, 10.0, 100.0])
    assert v.value_at_error(errors, seconds, 10 ** -1.5) == pytest.approx(10**0.5)
    assert math.isnan(v.value_at_error(errors, seconds, 1e-4))
    assert v.common_error(errors, np.array([0.5, 0.05])) == 0.05


def test_the_reference_error_enters_the_exponent_as_an_interval():
    n = np.array([100.0, 200.0])
    errors, work = 1.0 / n, n**2
    assert v.exponent_interval(errors, work, 0.0) == pytest.approx((2.0, 2.0))
    # The reference's error moves every measured error the same way, by at most r = 1e-3.
    assert v.exponent_interval(errors, work, 1e-3) == pytest.approx((math.log(4.0) / math.log(9e-3 / 4e-3),
                                                                     math.log(4.0) / math.log(11e-3 / 6e-3)))
    assert v.exponent_interval(errors, work, 5e-3) == (-math.inf, math.inf)  # an error the reference cannot see


def test_the_window_skips_the_runs_the_reference_blurs():
    n = np.array([25.0, 50.0, 100.0, 200.0, 400.0, 800.0])
    errors = 1.0 / n
    assert sorted(v.exponent_window(errors, n**2, 1e-5, 3, 0.1).tolist()) == [3, 4, 5]  # a sharp reference
    # A reference error of 2e-4 moves the pairwise exponents of the most accurate runs by more than 0.1.
    assert sorted(v.exponent_window(errors, n**2, 2e-4, 3, 0.1).tolist()) == [1, 2, 3]
    assert v.exponent_window(errors, n**2, 1e-2, 3, 0.1).size == 0
    # Two runs at the same error near the reference's: their pairwise exponent is unbounded, never fitted.
    errors[-2:] = 2e-3
    assert sorted(v.exponent_window(errors, n**2, 1e-4, 3, 0.1).tolist()) == [2, 3, 4]


@pytest.mark.parametrize("case", ["shocks", "rarefaction"])
@pytest.mark.parametrize("method", ["tspd", "exact"])
def test_an_order_0_8_method_falls_outside_the_log_factor_ranges_from_n_200(method, case):
    """The competing exponents 2 (order 1 with the data's log factor) and 2.5 (order 0.8, the upwind scheme on
    the shock data) land on different sides of the range when the fit's smallest N is 200 or more (its upper end
    2/(1 - 1/log 200) = 2.46); from N = 100 on (2.55) they do not, so the reference must resolve the runs from
    N = 200 on for the range to separate them."""
    sizes = np.array([200.0, 400.0, 800.0])
    label = f"p-system, {case}"
    log_factor = v.beyond_exponent_claim(quiet(), BEYOND, method, case, label,
                                         runs((1.0 + np.log(sizes)) / sizes, sizes**2, sizes), sizes, 0.0, "exact")
    slower = v.beyond_exponent_claim(quiet(), BEYOND, method, case, label, runs(sizes**-0.8, sizes**2, sizes), sizes,
                                     0.0, "exact")
    assert (log_factor.status, slower.status) == ("pass", "fail"), (log_factor.measured, slower.measured)
    assert v.predicted_exponents(2, 1.0, 100.0, BEYOND["exponent_tolerance"])[1] > 2.5


def test_a_ratio_of_wall_times_abstains_when_the_machines_speed_puts_it_across_its_bound():
    """The ratio checks compare two best wall times at a common error: each is within its series' speed factor of
    its value at a steady speed. The exact MSPD 12 times dearer than the TSPD, against [0.1, 10]: decided (fails) on
    a steady machine, undecided when the speed moved by 1.6 (7.5 to 19); 100 times dearer fails even then; timed
    once, the speed is unmeasured."""
    name = "ratio.same_cost_rarefaction"
    assert beyond_status(beyond(exact_slowdown=12.0), name) == "fail"
    moved = next(claim for claim in v.beyond_claims(beyond(exact_slowdown=12.0, speed=1.6), quiet(), BEYOND)
                 if claim.id == f"sticky.beyond.{name}")
    assert moved.status == "abstain" and "anywhere from 7.5 to 19.2" in moved.claim
    assert beyond_status(beyond(speed=1.6), name) == "pass"                # 1 (0.62 to 1.6) inside
    assert beyond_status(beyond(exact_slowdown=100.0, speed=1.6), name) == "fail"
    assert beyond_status(beyond(timings=1), name) == "abstain"
    assert beyond_status(beyond(timings=1), "ratio.scalar_burgers_two_atoms") == "abstain"
