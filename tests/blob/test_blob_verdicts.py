"""Every paper and derived claim of the blob paper can fail: each measure passes on an outcome of the shape
the paper (or our derivation) states and fails on a plausible wrong one (an order 0.5 below m q, an m = 6 rate
outside its band, a particle method that wins where it should lose, a regularisation part at the wrong order,
a quadrature part off its prediction by a factor 2, a cloud that does not contract, a ring of the wrong radius,
two clusters instead of three). The inputs are synthetic: the smallest result dictionaries each function reads."""

from pathlib import Path

import numpy as np
import pytest

from particle_methods.blob.aliasing import quadrature_prediction, quadrature_prediction_terms, saddle_ratio
from particle_methods.blob.initial import data_1d, data_2d, grid_2d
from particle_methods.blob.rings import uniform_ring_radius
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import blob as v

CONFIG = read_yaml(Path(__file__).parents[2] / "config" / "config.yaml")["blob"]
RULES = CONFIG["claims"]  # every tolerance, threshold and cut-off of the claims, as the claims script passes them
Q = 0.9


#: The recorder the claim functions get (the claims script passes one that logs and writes the rates).
RECORDER = Recorder(lambda *_: None)


@pytest.fixture(autouse=True)
def quiet(monkeypatch):
    monkeypatch.setattr(v, "progress", lambda *_: None)


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"blob.{name}"]


def failing(claims):
    return [(claim.id, claim.measured, claim.tolerance) for claim in claims if claim.status != "pass"]


# Figures 1-3: K = -|x|/2 in 1D, blob (smooth data), particle, blob (patch data)

H = 0.05 * 2.0 ** -np.arange(6)
TIMES = np.linspace(0.0, 1.0, 21)
EXACT_TIMES = TIMES[:-1]  # the exact trajectories meet at t = 1
ALPHA = np.linspace(-1.0, 1.0, 11)  # spacing h = 0.2
EXACT = ALPHA[None, :] * (1.0 - EXACT_TIMES[:, None])
TURNING = ALPHA[None, :] * (1.0 - 0.9 * TIMES[:, None])  # gap h / 10 at t = 1, twice the exact one at t = 0.95


EXACT_PEAK = 5.0 * np.exp(-(ALPHA / 0.3) ** 2)  # exact density at t = 0.8 at the particles, peaked
PLATEAU = np.full(ALPHA.size, 5.0)  # exact density of the indicator data at t = 0.8: uniform
# blob density of the indicator data: rounded at the edges, overshooting the plateau near them (the mollifier's lobe)
ROUNDED = 5.0 * (1.0 - 0.5 * np.exp(-((1.0 - np.abs(ALPHA)) / 0.15) ** 2)
                 + 0.03 * np.exp(-((0.6 - np.abs(ALPHA)) / 0.1) ** 2))


def with_densities(run, blob, exact):
    """The densities of a run at every output time (t = 0.8 is the one read) and the exact ones."""
    return {**run, "densities": np.tile(blob, (TIMES.size, 1)), "density_times": np.array([0.0, 0.4, 0.8]),
            "exact_densities": np.tile(exact, (3, 1))}


def blob_run(trajectory=4 * Q, density=4 * Q, paths=TURNING, energies=-1.0 - 0.1 * TIMES, peak=0.75 * EXACT_PEAK):
    """Figure 1: errors C h^order; trajectories that contract but turn away from the exact collision."""
    trajectory_errors, density_errors = 0.1 * H**trajectory, 2.0 * H**density
    return with_densities({"h_values": H, "fit_points": 3, "q": Q, "order": 4, "h": 0.2,
            "trajectory_errors": trajectory_errors, "density_errors": density_errors, "times": TIMES,
            "positions": paths,
            "exact_times": EXACT_TIMES,
            "exact_paths": EXACT, "tight_errors": np.array([trajectory_errors[-1], density_errors[-1]]) * (1 + 1e-6),
            "energies": energies, "mass_defect": 1e-10}, peak, EXACT_PEAK)


def particle_run(trajectory=2.0, paths=None):
    """Figure 2: straight trajectories (constant velocities in 1D)."""
    if paths is None:
        paths = ALPHA[None, :] * (1.0 - TIMES[:, None])
    return {"h_values": H, "fit_points": 3, "times": TIMES, "positions": paths, "trajectory_errors": H**trajectory}


def patch_run(trajectory=1.8, density=0.9, profile=ROUNDED):
    """Figure 3: discontinuous data, slower rates, a rounded density at t = 0.8."""
    return with_densities({"h_values": H, "fit_points": 3, "trajectory_errors": 0.1 * H**trajectory,
                           "density_errors": H**density, "times": TIMES, "positions": TURNING}, profile, PLATEAU)


def newtonian(d1=None, d2=None, d3=None):
    return v.newtonian_claims(d1 or blob_run(), d2 or particle_run(), d3 or patch_run(), RULES, RECORDER)


def test_newtonian_claims_all_pass_on_the_published_rates():
    assert not failing(newtonian())


def test_fig1d_blob_order_half_below_m_q_fails():
    claims = newtonian(d1=blob_run(trajectory=4 * Q - 0.5, density=4 * Q - 0.5))
    assert status(claims, "fig1d.order_trajectory") == "fail" and status(claims, "fig1d.order_density") == "fail"


def test_fig2_particle_order_one_and_a_half_fails():
    assert status(newtonian(d2=particle_run(trajectory=1.5)), "fig2.order") == "fail"


def test_fig2_particle_faster_than_blob_fails():
    claims = newtonian(d1=blob_run(trajectory=3.4), d2=particle_run(trajectory=3.6))
    assert status(claims, "fig1d.order_trajectory") == "pass" and status(claims, "fig2.below_blob") == "fail"


def test_fig3_patch_data_as_fast_as_smooth_data_fails():
    claims = newtonian(d3=patch_run(trajectory=3.8, density=3.8))
    assert status(claims, "fig3.slower_trajectory") == "fail" and status(claims, "fig3.slower_density") == "fail"


def test_fig1c_blob_trajectories_that_follow_the_exact_ones_collide_and_do_not_bend_away():
    paths = ALPHA[None, :] * (1.0 - TIMES[:, None])  # every particle reaches 0 at t = 1
    claims = newtonian(d1=blob_run(paths=paths))
    assert status(claims, "fig1c.no_collision") == "fail" and status(claims, "fig1c.bends_away") == "fail"


def test_fig1b_a_sharp_blob_density_does_not_lose_resolution():
    assert status(newtonian(d1=blob_run(peak=EXACT_PEAK)), "fig1b.loses_resolution") == "fail"


def test_fig3b_sharp_edges_are_not_rounded():
    assert status(newtonian(d3=patch_run(profile=PLATEAU)), "fig3b.rounded") == "fail"


def test_fig3b_monotone_rounding_is_not_the_mollifier_oscillation():
    monotone = 5.0 * (1.0 - 0.5 * np.exp(-((1.0 - np.abs(ALPHA)) / 0.15) ** 2))
    claims = newtonian(d3=patch_run(profile=monotone))
    assert status(claims, "fig3b.rounded") == "pass" and status(claims, "fig3b.mollifier_oscillation") == "fail"


def test_fig1c_trajectories_that_cross_collide():
    paths = ALPHA[None, :] * (1.0 - 1.5 * TIMES[:, None])
    assert status(newtonian(d1=blob_run(paths=paths)), "fig1c.no_collision") == "fail"


def test_fig1c_rounding_gap_is_no_clear_gap():
    paths = ALPHA[None, :] * np.maximum(1.0 - TIMES[:, None], 1e-4)  # gap 1e-4 h at t = 1
    assert status(newtonian(d1=blob_run(paths=paths)), "fig1c.no_collision") == "fail"


def test_fig1c_blob_trajectories_that_stop_just_short_of_the_collision_do_not_bend_away():
    paths = ALPHA[None, :] * np.maximum(1.0 - TIMES[:, None], 0.06)  # a clear gap (0.06 h), the exact one at 0.95
    claims = newtonian(d1=blob_run(paths=paths))
    assert status(claims, "fig1c.no_collision") == "pass" and status(claims, "fig1c.bends_away") == "fail"


def test_energy_that_rises_once_fails():
    energies = -1.0 - 0.1 * TIMES
    energies[10] = energies[8]
    assert status(newtonian(d1=blob_run(energies=energies)), "energy.decrease") == "fail"


def test_newtonian_checks_fail_on_bent_paths_loose_tolerances_and_lost_mass():
    bent = ALPHA[None, :] * (1.0 - TIMES[:, None] ** 2)
    assert status(newtonian(d2=particle_run(paths=bent)), "fig2.no_bending") == "fail"
    loose = blob_run()
    loose["tight_errors"] = loose["tight_errors"] * 1.1
    assert status(newtonian(d1=loose), "integrator") == "fail"
    leaky = blob_run()
    leaky["mass_defect"] = 1e-3
    assert status(newtonian(d1=leaky), "mass") == "fail"


# Figure 4: K = -|x|/2 and K = |x|^3/3, particle, m = 4 and m = 6

H4 = 0.05 * 2.0 ** -np.arange(5)
KERNELS = ("newtonian_repulsive", "cubic")
PARTS = ("trajectory", "density")


def fig4(**errors):
    """Errors (coefficient, order) per key ``<kernel>_<method>_<part>``; the defaults give m q = 3.6 for m = 4,
    5.3 for m = 6 (below m q = 5.4, as ours), order 2 for the particle method with -|x|/2, and for |x|^3/3 a particle
    method at order 4 on
    trajectories (better than m = 4, worse than m = 6) and order 2 on the density."""
    shapes = {f"{kernel}_blob4_{part}": (0.5, 4 * Q) for kernel in KERNELS for part in PARTS}
    shapes |= {f"{kernel}_blob6_{part}": (0.5, 5.3) for kernel in KERNELS for part in PARTS}
    shapes |= {"newtonian_repulsive_particle_trajectory": (0.1, 2.0), "cubic_particle_trajectory": (0.01, 4.0),
               "cubic_particle_density": (0.1, 2.0), "diagnostic_m4_density": (1.0, 3.0),
               "diagnostic_m6_density": (1.0, 4.5)}
    shapes |= errors
    data = {key: a * H4**p for key, (a, p) in shapes.items()}
    return data | {"h_values": H4, "fit_points": 3, "q": Q, "kernels": np.array(KERNELS), "diagnostic_q": 0.75,
                   "cubic_reference_error": np.array([1e-16, 1e-16])}


def test_fig4_claims_all_pass_on_the_published_picture():
    assert not failing(v.fig4_claims(fig4(), RULES, RECORDER))


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("part", PARTS)
def test_fig4_m4_order_half_below_m_q_fails(kernel, part):
    claims = v.fig4_claims(fig4(**{f"{kernel}_blob4_{part}": (0.5, 4 * Q - 0.5)}), RULES, RECORDER)
    assert status(claims, f"fig4.m4_{kernel}_{part}") == "fail"


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("part", PARTS)
def test_fig4_m6_order_below_m4_fails(kernel, part):
    # small finest error, slow rate
    # (the paper's words, a rate below m q, still hold; our reading, a rate at least m = 4's, fails)
    claims = v.fig4_claims(fig4(**{f"{kernel}_blob6_{part}": (1e-3, 3.4)}), RULES, RECORDER)
    assert status(claims, f"fig4.m6_rate_above_m4_{kernel}_{part}") == "fail"
    assert status(claims, f"fig4.m6_{kernel}_{part}") == "pass"
    assert status(claims, f"fig4.m6_better_{kernel}_{part}") == "pass"


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("part", PARTS)
def test_fig4_m6_order_above_m_q_fails(kernel, part):
    claims = v.fig4_claims(fig4(**{f"{kernel}_blob6_{part}": (0.5, 6 * Q + 0.3)}), RULES, RECORDER)
    assert status(claims, f"fig4.m6_{kernel}_{part}") == "fail"
    assert status(claims, f"fig4.m6_rate_above_m4_{kernel}_{part}") == "pass"


@pytest.mark.parametrize("kernel", KERNELS)
@pytest.mark.parametrize("part", PARTS)
def test_fig4_m6_finest_error_above_m4_is_not_better(kernel, part):
    claims = v.fig4_claims(fig4(**{f"{kernel}_blob6_{part}": (1e4, 5.0)}), RULES, RECORDER)
    assert status(claims, f"fig4.m6_{kernel}_{part}") == "pass"
    assert status(claims, f"fig4.m6_better_{kernel}_{part}") == "fail"


@pytest.mark.parametrize("kernel, part", v.M6_REGULARISED)
def test_fig4_m6_shortfall_like_the_papers_fails_the_approach_to_m_q(kernel, part):
    """The paper's m = 6 rates fall short of m q = 5.4 (its words): an m = 6 rate of 4.9 still passes them, but not
    our derived claim that with exact kernels the rates approach m q."""
    claims = v.fig4_claims(fig4(**{f"{kernel}_blob6_{part}": (0.5, 4.9)}), RULES, RECORDER)
    assert status(claims, f"fig4.m6_{kernel}_{part}") == "pass"
    assert status(claims, "fig4.m6_rates_approach_mq") == "fail"


def test_fig4_m6_approach_leaves_out_the_quadrature_limited_repulsive_density():
    claims = v.fig4_claims(fig4(newtonian_repulsive_blob6_density=(1e-3, 2.7)), RULES, RECORDER)
    assert status(claims, "fig4.m6_rates_approach_mq") == "pass"


def test_fig4_newtonian_particle_below_blob_does_not_improve():
    claims = v.fig4_claims(fig4(newtonian_repulsive_particle_trajectory=(1e-3, 4.0)), RULES, RECORDER)
    assert status(claims, "fig4.newtonian_blob_improves") == "fail"


def test_fig4_larger_gain_for_the_cubic_kernel_fails():
    # the particle method with |x|^3/3 far behind m = 4: the smooth kernel gains more than -|x|/2
    claims = v.fig4_claims(fig4(cubic_particle_trajectory=(1e3, 2.0)), RULES, RECORDER)
    assert status(claims, "fig4.newtonian_blob_improves") == "pass"
    assert status(claims, "fig4.more_singular_more_gain") == "fail"


def test_fig4_cubic_particle_behind_m4_on_trajectories_fails():
    claims = v.fig4_claims(fig4(cubic_particle_trajectory=(0.1, 2.0)), RULES, RECORDER)
    assert status(claims, "fig4.cubic_particle_beats_m4_trajectory") == "fail"


def test_fig4_cubic_particle_ahead_of_m4_on_density_fails():
    claims = v.fig4_claims(fig4(cubic_particle_density=(1e-3, 4.0)), RULES, RECORDER)
    assert status(claims, "fig4.cubic_particle_loses_density") == "fail"


def test_fig4_cubic_m6_behind_the_particle_trajectories_is_not_best():
    claims = v.fig4_claims(fig4(cubic_particle_trajectory=(1e-5, 4.0)), RULES, RECORDER)
    assert status(claims, "fig4.m6_better_cubic_trajectory") == "pass"
    assert status(claims, "fig4.cubic_m6_best") == "fail"


def test_fig4_cubic_m6_behind_m4_on_density_is_not_best():
    claims = v.fig4_claims(fig4(cubic_blob6_density=(1e4, 5.0)), RULES, RECORDER)
    assert status(claims, "fig4.cubic_m6_best") == "fail"


def test_fig4_diagnostic_that_reaches_m_q_on_the_finest_window_only_fails():
    """The q = 0.75 diagnostic is stated on every window (the h range is unstated): an m = 6 error whose pairwise
    orders rise towards m q = 4.5 (3.6, 4.0, 4.25, 4.4, the shape of ours) passes on the finest window alone and
    fails; the claim's text says so."""
    orders = np.array([3.6, 4.0, 4.25, 4.4])
    errors = np.concatenate([[1e-3], 1e-3 * np.exp(-np.cumsum(orders * np.log(H4[:-1] / H4[1:])))])
    data = fig4()
    data["diagnostic_m6_density"] = errors
    claim = {c.id: c for c in v.fig4_claims(data, RULES, RECORDER)}["blob.fig4.repulsive_density_q0.75_m6"]
    assert claim.status == "fail" and "1 of 3 windows would pass alone" in claim.claim
    assert status(v.fig4_claims(fig4(), RULES, RECORDER), "fig4.repulsive_density_q0.75_m6") == "pass"


def test_fig4_checks_fail_on_a_loose_reference_and_a_slow_diagnostic():
    data = fig4(diagnostic_m4_density=(1.0, 2.4), diagnostic_m6_density=(1.0, 3.9))
    data["cubic_reference_error"] = np.array([1e-13, 1e-16])
    claims = v.fig4_claims(data, RULES, RECORDER)
    assert status(claims, "fig4.cubic_reference") == "fail"
    assert status(claims, "fig4.repulsive_density_q0.75_m4") == "fail"
    assert status(claims, "fig4.repulsive_density_q0.75_m6") == "fail"


# Figure 4, K = -|x|/2: quadrature and regularisation parts of the density error

INVERSE_H = np.array([20, 40, 80, 160, 320, 640, 1280, 2560, 5120])
BASE = 5
HR = 1.0 / INVERSE_H
#: The quadrature part predicted without fitted parameters at Figure 4's data, q and t.
PREDICTED = np.array([quadrature_prediction(CONFIG["fig4"]["data"], h, Q, CONFIG["fig4"]["t"]) for h in HR])
#: Its neglected terms, relative: of the order of the saddle ratio squared (a tenth of it, as measured).
EXPANSION = 0.1 * np.array([saddle_ratio(CONFIG["fig4"]["data"], h, Q) for h in HR]) ** 2


def rho_final(h):
    """The exact density at t along the exact trajectories of the grid points of [-1, 1] (section 4.1)."""
    rho0 = data_1d(CONFIG["fig4"]["data"])(np.linspace(-1.0, 1.0, int(round(2 / h)) + 1))
    return rho0 / (1.0 + CONFIG["fig4"]["t"] * rho0)


def repulsive(m4_order=4 * Q, m6_order=6 * Q, m6_over_m4=16 / 15):
    """Quadrature parts above the prediction by a tenth of the saddle ratio squared (as measured: 0.16 at h = 1/20,
    outside the expansion, 2e-3 at 1/320), regularisation parts C h^(m q), below the quadrature part at h = 1/320
    and above it from 1/5120 for m = 4, totals their sum (the L1_h norms added: one sign), ``m*_predicted`` the
    prediction P plus the regularisation part."""
    quadrature = PREDICTED * (1.0 + EXPANSION)
    finest = quadrature[BASE - 1]
    data = {"inverse_h": INVERSE_H, "base_count": BASE, "q": Q, "t": CONFIG["fig4"]["t"]}
    for m, order, share, scale in ((4, m4_order, 0.6, 1.0), (6, m6_order, 0.001, m6_over_m4)):
        regularisation = share * finest * (HR / HR[BASE - 1]) ** order
        total = scale * quadrature + regularisation
        data |= {f"m{m}_quadrature": scale * quadrature, f"m{m}_regularisation": regularisation,
                 f"m{m}_combined": total, f"m{m}_total": total.copy(),
                 f"m{m}_predicted": scale * PREDICTED + regularisation}
    return data


def test_repulsive_synthetic_prediction_is_the_aliasing_modules():
    """The synthetic P is what the data job adds particle by particle: the terms weighted by rho(X_i, t)."""
    for h, p in zip(HR[:3], PREDICTED[:3]):
        terms = quadrature_prediction_terms(CONFIG["fig4"]["data"], h, Q, CONFIG["fig4"]["t"])
        assert h * (rho_final(h) * terms).sum() == pytest.approx(p, rel=1e-12)


def test_repulsive_claims_all_pass_on_the_predicted_aliasing():
    assert not failing(v.repulsive_claims(repulsive(), CONFIG["fig4"], RULES, RECORDER))


def test_repulsive_regularisation_at_order_two_fails():
    claims = v.repulsive_claims(repulsive(m4_order=2.0), CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_regularisation_m4") == "fail"


def test_repulsive_m6_regularisation_at_the_m4_rate_fails():
    claims = v.repulsive_claims(repulsive(m6_order=4 * Q), CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_regularisation_m6") == "fail"


@pytest.mark.parametrize("ratio", [1.0, 4 / 3, 5.0, 0.2])
def test_repulsive_different_quadrature_parts_fail(ratio):
    """1: m = 6 with m = 4's weight of the narrowest Gaussian; 4/3: with the weight of psi4's, not 16/15 of it."""
    claims = v.repulsive_claims(repulsive(m6_over_m4=ratio), CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_same_quadrature") == "fail"


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_repulsive_quadrature_part_twice_or_half_the_prediction_fails(factor):
    data = repulsive()
    data["m4_quadrature"] = factor * data["m4_quadrature"]
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_quadrature_prediction") == "fail"


def test_repulsive_quadrature_part_returning_to_m_q_after_the_paper_range_fails():
    """An immediate return to m q: the quadrature part continues at h^(m q) from h = 1/320 (about 0.79 and 0.85
    of the prediction at 1/640 and 1/1280, whose own local order is 3.3 and 3.7 there)."""
    data = repulsive()
    quadrature = data["m4_quadrature"]
    quadrature[BASE:] = quadrature[BASE - 1] * (HR[BASE:] / HR[BASE - 1]) ** (4 * Q)
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_quadrature_prediction") == "fail"


def test_repulsive_quadrature_prediction_unmeasured_outside_its_expansion_fails():
    """Only h = 1/20 (saddle ratio 1.28): no h where the prediction is an expansion, so no verdict but a failure."""
    data = {key: value[:1] if isinstance(value, np.ndarray) else value for key, value in repulsive().items()}
    assert v.quadrature_prediction_claim(data, CONFIG["fig4"], RULES).status == "fail"


def test_repulsive_slow_rate_that_persists_beyond_the_paper_range_fails_the_error_prediction():
    """The runs' error keeps the paper range's slow order (2.5) beyond it: P + R falls faster, and the error is no
    longer their sum."""
    data = repulsive()
    for m in (4, 6):
        total = data[f"m{m}_total"]
        total[BASE:] = total[BASE - 1] * (HR[BASE:] / HR[BASE - 1]) ** 2.5
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_error_prediction") == "fail"
    assert status(claims, "fig4.repulsive_m6_quadrature") == "fail"


def test_repulsive_error_twice_p_plus_r_at_one_extended_size_fails():
    data = repulsive()
    data["m4_total"][-2] *= 2.0
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_error_prediction") == "fail"


def test_repulsive_error_without_the_regularisation_part_fails():
    """An error that is the quadrature part alone (R lost) beyond the crossover at 1/5120 is not P + R."""
    data = repulsive()
    data["m4_total"][BASE:] = data["m4_quadrature"][BASE:]
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_error_prediction") == "fail"


@pytest.mark.parametrize("wrong", ["m4_weight", "regularisation_at_m4_rate", "later_time"])
def test_repulsive_m6_error_other_than_sixteen_fifteenths_p_fails(wrong):
    """m = 6 with m = 4's weight (15/16 of the claim), an m = 6 regularisation part at the m = 4 rate (as large as
    m = 4's), or the state at t = 0.6 instead of 0.5 (a larger P: J_i grows)."""
    if wrong == "m4_weight":
        data = repulsive(m6_over_m4=1.0)
    elif wrong == "regularisation_at_m4_rate":
        data = repulsive()
        data["m6_total"] = data["m6_total"] + data["m4_regularisation"]
    else:
        data = repulsive()
        later = np.array([quadrature_prediction(CONFIG["fig4"]["data"], h, Q, 0.6) for h in HR])
        data["m6_total"] = 16 / 15 * later * (1.0 + EXPANSION)
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_m6_quadrature") == "fail"


def test_repulsive_m6_quadrature_unmeasured_where_the_prediction_is_no_expansion_fails():
    """Only 1/h = 20 to 160: the saddle ratio squared exceeds the tolerance at every h, so no verdict but a failure."""
    data = {key: value[:4] if isinstance(value, np.ndarray) else value for key, value in repulsive().items()}
    data["base_count"] = 4
    assert v.m6_quadrature_claim(data, CONFIG["fig4"], RULES).status == "fail"


def test_repulsive_checks_fail_on_a_gap_between_parts_and_total_and_a_small_quadrature_share():
    data = repulsive()
    data["m4_combined"] = 1.5 * data["m4_combined"]
    assert status(v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER), "fig4.repulsive_decomposition") == "fail"
    data = repulsive()
    data["m4_regularisation"] = 10 * data["m4_regularisation"]
    data["m4_combined"] = data["m4_quadrature"] + data["m4_regularisation"]
    data["m4_total"] = data["m4_combined"].copy()
    claims = v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER)
    assert status(claims, "fig4.repulsive_quadrature_dominates") == "fail"


def test_repulsive_decomposition_ignores_the_coarse_sizes_the_regularisation_part_dominates():
    data = repulsive()
    data["m4_combined"][:3] *= 1.25  # the gap of 1/20 to 1/80, where the neglected displacement term is largest
    assert status(v.repulsive_claims(data, CONFIG["fig4"], RULES, RECORDER), "fig4.repulsive_decomposition") == "pass"


# Figure 5: 2D, K = log|x|/(2 pi)

H5 = np.array([0.2, 0.1, 0.05, 0.025])


def fig5(regular=(3.6, 3.6), particle=2.0, disk=(1.7, 0.9)):
    return {"h_values": H5, "fit_points": 3, "q": Q,
            "labels": np.array(["regular, blob", "regular, particle", "disk, blob"]),
            "case0_trajectory": 0.1 * H5 ** regular[0], "case0_density": H5 ** regular[1],
            "case1_trajectory": 0.1 * H5**particle, "case1_density": np.full(H5.size, np.nan),
            "case2_trajectory": 0.1 * H5 ** disk[0], "case2_density": H5 ** disk[1]}


def test_fig5_claims_all_pass_on_the_published_rates():
    assert not failing(v.fig5_claims(fig5(), RULES, RECORDER))


def test_fig5_regular_order_half_below_m_q_fails():
    claims = v.fig5_claims(fig5(regular=(3.1, 3.1)), RULES, RECORDER)
    assert status(claims, "fig5.m4_regular_trajectory") == "fail"
    assert status(claims, "fig5.m4_regular_density") == "fail"


def test_fig5_particle_faster_than_blob_fails():
    assert status(v.fig5_claims(fig5(particle=3.9), RULES, RECORDER), "fig5.particle_slower") == "fail"


def test_fig5_disk_as_fast_as_regular_data_fails():
    assert status(v.fig5_claims(fig5(disk=(3.8, 3.8)), RULES, RECORDER), "fig5.disk_slower") == "fail"


# Figure 6: 2D end states (Newtonian, quadratic, cubic)

TOP = CONFIG["fig6"]["top"]
T6 = np.linspace(0.0, TOP["t_max"], TOP["times"])  # the full run's records
RHO00 = float(data_2d("bump")(np.zeros((1, 2)))[0])
BUMP_GRID = grid_2d(TOP["h"], "bump")  # the Newtonian run's particles, one at the origin


def polar_cloud(radii=(0.2, 0.4, 0.6, 0.8, 1.0), angles=8):
    """A centre particle and rings of particles."""
    theta = 2 * np.pi * np.arange(angles) / angles
    rings = [r * np.column_stack([np.cos(theta), np.sin(theta)]) for r in radii]
    return np.vstack([np.zeros((1, 2)), *rings])


CLOUD = polar_cloud()


def radial(radius):
    """Positions (time, particle, 2) moving along rays; ``radius(r0, t)`` gives each particle's radius."""
    r0 = np.linalg.norm(CLOUD, axis=1)
    direction = np.divide(CLOUD, r0[:, None], out=np.zeros_like(CLOUD), where=r0[:, None] > 0)
    return radius(r0[None, :], T6[:, None])[..., None] * direction[None]


def fig6(quadratic=lambda r, t: r * np.exp(-t), cubic=lambda r, t: 0.5 + (r - 0.5) * np.exp(-t), growth=RHO00,
         energies=-1.0 - 0.1 * T6, late=0.0):
    """Quadratic: contraction to a point; cubic: approach to the ring r = 0.5; the Newtonian run on the bump's grid,
    each particle's density 1/(1/rho0 - growth (t + late)) (exact for growth = rho0(0)... along its trajectory: blow-up
    at 1/rho0(0) at the origin; ``late``: every record the state of a later time)."""
    rho0 = data_2d("bump")(BUMP_GRID)
    densities = 1.0 / np.maximum(1.0 / rho0[None, :] - (T6[:, None] + late) * growth / RHO00, 1e-3)
    return {"times": T6, "quadratic_positions": radial(quadratic), "cubic_positions": radial(cubic),
            "newtonian_positions": BUMP_GRID[None], "newtonian_densities": densities, "newtonian_energies": energies,
            "quadratic_energies": -1.0 - 0.2 * T6, "newtonian_mass_defect": 1e-10, "quadratic_mass_defect": 1e-10,
            "cubic_mass_defect": 1e-5, "star_t": 0.8, "newtonian_star_densities": np.linspace(1.4, 4.3, 45),
            "quadratic_star_densities": np.full(45, 1.44)}


def test_fig6_uniform_newtonian_star_density_is_not_rounded():
    data = fig6()
    data["newtonian_star_densities"] = np.full(45, 5.0)
    assert status(v.fig6_claims(data, CONFIG["fig6"], RULES), "fig6.star_rounding_newtonian") == "fail"


def test_fig6_rounded_quadratic_star_density_fails():
    data = fig6()
    data["quadratic_star_densities"] = np.linspace(1.40, 1.44, 45)
    assert status(v.fig6_claims(data, CONFIG["fig6"], RULES), "fig6.star_no_rounding_quadratic") == "fail"


def test_fig6_claims_all_pass_on_point_ring_and_blowup():
    assert not failing(v.fig6_claims(fig6(), CONFIG["fig6"], RULES))


@pytest.mark.parametrize("quadratic", [lambda r, t: r + 0 * t, lambda r, t: r * np.exp(-0.5 * t)],
                         ids=["still", "slow"])
def test_fig6_quadratic_cloud_that_does_not_contract_is_no_point(quadratic):
    assert status(v.fig6_claims(fig6(quadratic=quadratic), CONFIG["fig6"], RULES), "fig6.quadratic_point") == "fail"


@pytest.mark.parametrize("cubic", [lambda r, t: r ** (1 + t), lambda r, t: r * np.exp(-t)],
                         ids=["inner_first", "self_similar"])
def test_fig6_cubic_cloud_whose_radii_spread_or_keep_their_shape_is_no_ring(cubic):
    assert status(v.fig6_claims(fig6(cubic=cubic), CONFIG["fig6"], RULES), "fig6.cubic_ring") == "fail"


def test_fig6_cubic_collapse_to_a_point_is_no_ring():
    # the coefficient of variation is scale-free: a collapse whose radii bunch lowers it as a ring does,
    # so the ring's radius is a claim of its own
    collapse = lambda r, t: np.exp(-t) * (0.5 + (r - 0.5) * np.exp(-t))  # noqa: E731
    claims = v.fig6_claims(fig6(cubic=collapse), CONFIG["fig6"], RULES)
    assert status(claims, "fig6.cubic_ring_radius") == "fail"


@pytest.mark.parametrize("growth", [RHO00 / 2, 0.0, RHO00 * 1.5, RHO00 * 2], ids=["late", "never", "early", "twice"])
def test_fig6_newtonian_concentration_away_from_the_blowup_time_fails(growth):
    # "never": the particle method's Dirac masses, whose density does not grow; "twice": a velocity twice the
    # exact one, blow-up at half the time
    assert status(v.fig6_claims(fig6(growth=growth), CONFIG["fig6"], RULES), "fig6.newtonian_blowup") == "fail"


def test_fig6_newtonian_state_one_record_late_fails():
    """A density read one record late (the state at the wrong time) moves the extrapolated blow-up time by the
    record spacing, more than the band from the regularisation."""
    claims = v.fig6_claims(fig6(late=T6[1] - T6[0]), CONFIG["fig6"], RULES)
    assert status(claims, "fig6.newtonian_blowup") == "fail"
    assert status(v.fig6_claims(fig6(), CONFIG["fig6"], RULES), "fig6.newtonian_blowup") == "pass"


def test_fig6_newtonian_without_a_resolved_record_is_unmeasured():
    """A rate-error cut-off that no record after t = 0 meets leaves the claim unmeasured: it fails."""
    rules = RULES | {"blowup_rate_error": 1e-6}
    claim = {c.id: c for c in v.fig6_claims(fig6(), CONFIG["fig6"], rules)}["blob.fig6.newtonian_blowup"]
    assert claim.status == "fail" and np.isnan(float(claim.value))


def test_fig6_energy_that_rises_once_fails():
    energies = -1.0 - 0.1 * T6
    energies[30] = energies[28]
    assert status(v.fig6_claims(fig6(energies=energies), CONFIG["fig6"], RULES), "energy.decrease_2d") == "fail"


def test_fig6_mass_checks_fail_on_a_large_defect():
    data = fig6()
    data["quadratic_mass_defect"], data["cubic_mass_defect"] = 1e-4, 1e-3
    claims = v.fig6_claims(data, CONFIG["fig6"], RULES)
    assert status(claims, "mass_2d") == "fail" and status(claims, "mass_2d_tabulated") == "fail"


# Figures 7 and 8: end states of repulsive-attractive kernels, measured once steady

DELTA = 0.32
T7 = np.linspace(0.0, 40.0, 81)
RING = uniform_ring_radius(4.0, 1.5)
THETA = 2 * np.pi * np.arange(48) / 48


def ring(radius, wobble=0.0, centre=True):
    """Particles on a circle (radius * (1 + wobble cos 3 theta)), with a centre particle."""
    r = radius * (1.0 + wobble * np.cos(3 * THETA))
    points = np.column_stack([r * np.cos(THETA), r * np.sin(THETA)])
    return np.vstack([np.zeros((1, 2)), points]) if centre else points


def disk(radius):
    """A compact radial state: a centre particle and particles spread over radii up to ``radius``."""
    r = radius * np.linspace(0.2, 1.0, THETA.size)
    return np.vstack([np.zeros((1, 2)), np.column_stack([r * np.cos(7 * THETA), r * np.sin(7 * THETA)])])


def clusters(count, radius=0.6, spread=0.005):
    """``count`` point masses on a circle, each a small cloud of 8 particles."""
    angles = 2 * np.pi * np.arange(count) / count
    centres = radius * np.column_stack([np.cos(angles), np.sin(angles)])
    offsets = spread * np.column_stack([np.cos(THETA[::6]), np.sin(THETA[::6])])
    return (centres[:, None, :] + offsets[None, :, :]).reshape(-1, 2)


def settling(end, tau, start=None):
    """Positions (time, particle, 2) relaxing from ``start`` (a disk) to ``end`` on the time scale ``tau``:
    steady by the criterion (radii moving at most 0.01 delta per 5 time units) from t about 5 tau, never
    within T7 for tau = 30."""
    start = disk(0.3)[: len(end)] if start is None else start
    decay = np.exp(-T7 / tau)[:, None, None]
    return end[None] + decay * (start - end)[None]


def fig7(**states):
    """End states and time scales per ``<case>_<method>``; the defaults follow the paper: the blob reaches the
    delta ring of the stationary radius first, the large-delta log state is a ring, the septic one three points.
    Every run starts from a disk with a particle at the origin (particle 0); in the power kernels' blob runs it
    ends on the ring or in a cluster. The runs ``<case>_<method>_no_origin`` (quartic and septic power kernels,
    the same states unless given) leave it out."""
    states = {"log_blob": (ring(0.4, 0.002), 1.0), "log_particle": (disk(0.5), 1.0),
              "power_blob": (ring(RING, 0.001, centre=False), 1.0), "power_particle": (ring(RING, 0.05), 3.0),
              "septic_blob": (clusters(3), 1.0), "septic_particle": (ring(0.57, 0.01, centre=False), 1.0)} | states
    data = {"labels": np.array(["quartic_log|quartic", "quartic_power|quartic", "septic_power|quartic"]),
            "delta": DELTA, "h": 1 / 9, "paper_tables": np.array([2.5, 100])}
    for i, case in enumerate(("log", "power", "septic")):
        data[f"case{i}_times"] = T7
        for method in ("particle", "blob"):
            data[f"case{i}_{method}"] = settling(*states[f"{case}_{method}"])
            if case != "log":
                data[f"case{i}_times_no_origin"] = T7
                no_origin = states.get(f"{case}_{method}_no_origin", states[f"{case}_{method}"])
                data[f"case{i}_{method}_no_origin"] = settling(*no_origin)[:, 1:]
        coarse = states.get(f"{case}_blob_paper_tables", states[f"{case}_blob"])
        data[f"case{i}_blob_paper_tables"] = settling(*coarse)
    return data


def test_fig7_claims_all_pass_on_rings_and_three_points():
    assert not failing(v.fig7_claims(fig7(), CONFIG["fig7"], RULES))


@pytest.mark.parametrize("radius", [0.9 * RING, 1.1 * RING, 0.5])
def test_fig7_ring_of_the_wrong_radius_fails(radius):
    claims = v.fig7_claims(fig7(power_blob=(ring(radius, 0.001), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.delta_ring_radius") == "fail"


def test_fig7_particle_log_state_that_is_a_ring_fails():
    claims = v.fig7_claims(fig7(log_particle=(ring(0.5, 0.002), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.particle_log_disk") == "fail"


def test_fig7_particle_power_state_that_is_a_disk_fails():
    claims = v.fig7_claims(fig7(power_particle=(disk(0.5), 3.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.particle_power_ring") == "fail"


def test_fig7_thick_annulus_is_no_delta_ring():
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.3), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.delta_ring_thin") == "fail"


def test_fig7_blob_ring_that_settles_later_than_the_particle_ring_fails():
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001), 3.0), power_particle=(ring(RING, 0.05), 1.0)),
                           CONFIG["fig7"], RULES)
    assert status(claims, "fig7.delta_ring_radius") == "pass"
    assert status(claims, "fig7.blob_ring_faster") == "fail"


def test_fig7_blob_ring_that_settles_with_the_particle_ring_is_not_faster():
    """The same relaxation for both methods settles at the same record: a tie, less than the record interval that
    resolves two settling times (the ratio of the earlier encoding, at most 1, passed a tie)."""
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001, centre=False), 3.0),
                                power_particle=(ring(RING, 0.001, centre=False), 3.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.blob_ring_faster") == "fail"


def test_fig7_blob_state_farther_from_the_ring_at_t_8_fails_the_papers_comparison():
    """The paper compares the methods at t = 8: a blob state relaxing more slowly is farther from the ring then."""
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001), 3.0), power_particle=(ring(RING, 0.05), 1.0)),
                           CONFIG["fig7"], RULES)
    assert status(claims, "fig7.blob_closer_at_8") == "fail"
    assert status(claims, "fig7.no_origin.blob_closer_at_8") == "fail"


def test_fig7_blob_nearer_the_uniform_ring_radius_but_slower_to_its_own_ring_is_not_closer_at_8():
    """The particle state settles fast on a ring 20 % wider than the uniform one, the blob state slowly on the
    uniform radius: at t = 8 the blob state is nearer that radius (the former measure passed), but it has more of
    its way left to its own end state."""
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001), 3.0), power_particle=(ring(1.2 * RING, 0.05), 1.0),
                                power_blob_no_origin=(ring(RING, 0.001), 3.0),
                                power_particle_no_origin=(ring(1.2 * RING, 0.05), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.blob_closer_at_8") == "fail"
    assert status(claims, "fig7.no_origin.blob_closer_at_8") == "fail"


def test_fig7_blob_ring_still_moving_at_the_final_time_is_unmeasured():
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001), 30.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.delta_ring_radius") == "fail" and status(claims, "fig7.blob_ring_faster") == "fail"


@pytest.mark.parametrize("log_blob", [(disk(0.45), 1.0), (ring(0.4, 0.002), 30.0)], ids=["compact", "moving"])
def test_fig7_large_delta_log_state_that_stays_compact_or_moving_fails(log_blob):
    claims = v.fig7_claims(fig7(log_blob=log_blob), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.log_ring_collapse") == "fail"


@pytest.mark.parametrize("septic_blob", [(clusters(2), 1.0), (clusters(4), 1.0), (ring(0.6, centre=False), 1.0),
                                         (clusters(3), 30.0)], ids=["two", "four", "ring", "moving"])
def test_fig7_septic_end_state_other_than_three_steady_points_fails(septic_blob):
    claims = v.fig7_claims(fig7(septic_blob=septic_blob), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.septic_three_points") == "fail"


def test_fig7_no_origin_claims_fail_on_their_own_runs():
    claims = v.fig7_claims(fig7(septic_blob_no_origin=(ring(0.6, centre=False), 1.0),
                                power_blob_no_origin=(ring(0.9 * RING, 0.001), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.no_origin.septic_three_points") == "fail"
    assert status(claims, "fig7.no_origin.delta_ring_radius") == "fail"
    assert status(claims, "fig7.septic_three_points") == "pass" and status(claims, "fig7.delta_ring_radius") == "pass"
    claims = v.fig7_claims(fig7(power_particle_no_origin=(disk(0.5), 3.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.no_origin.particle_power_ring") == "fail"
    claims = v.fig7_claims(fig7(power_blob_no_origin=(ring(RING, 0.3), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.no_origin.delta_ring_thin") == "fail"
    claims = v.fig7_claims(fig7(power_blob_no_origin=(ring(RING, 0.001), 3.0),
                                power_particle_no_origin=(ring(RING, 0.05), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.no_origin.blob_ring_faster") == "fail"
    assert not failing(v.fig7_claims(fig7(), CONFIG["fig7"], RULES))


def test_fig7_origin_particle_that_stays_at_the_origin_fails():
    claims = v.fig7_claims(fig7(power_blob=(ring(RING, 0.001), 1.0)), CONFIG["fig7"], RULES)  # it stays at 0
    assert status(claims, "fig7.origin_particle") == "fail"


def test_fig7_septic_claim_lists_the_verdict_for_earlier_final_times():
    text = next(claim.claim for claim in v.fig7_claims(fig7(), CONFIG["fig7"], RULES)
                if claim.id.endswith("fig7.septic_three_points"))
    assert "runs ending at other times (end: clusters) 40: 3" in text


LABELS8 = ("morse_1|quartic", "morse_2|quartic", "morse_2|star")


def fig8(changed=1, change=0.3, other=1e-3, tau=1.0, coarse_changed=None, coarse_change=None):
    """Steady end states (time scale ``tau``): particle rings of radius 1; the blob ring is larger by ``change``
    in case ``changed`` and by ``other`` in the others. The blob run on the paper's tables is the same unless
    ``coarse_changed`` and ``coarse_change`` say otherwise."""
    coarse_changed = changed if coarse_changed is None else coarse_changed
    coarse_change = change if coarse_change is None else coarse_change
    data = {"labels": np.array(LABELS8), "delta": DELTA, "h": 1 / 9, "paper_tables": np.array([5.0, 200])}
    for i in range(len(LABELS8)):
        shift = change if i == changed else other
        coarse = coarse_change if i == coarse_changed else other
        data |= {f"case{i}_times": T7, f"case{i}_particle": settling(ring(1.0), tau),
                 f"case{i}_blob": settling(ring(1.0 + shift), tau),
                 f"case{i}_blob_paper_tables": settling(ring(1.0 + coarse), tau)}
    return data


def test_fig8_claim_passes_when_only_morse_2_with_quartic_data_changes():
    assert not failing(v.fig8_claims(fig8(), CONFIG["fig8"], RULES))


@pytest.mark.parametrize("changed, change, tau", [(0, 0.3, 1.0), (2, 0.3, 1.0), (1, 0.0, 1.0), (1, 0.3, 30.0)],
                         ids=["morse_1", "star", "none", "moving"])
def test_fig8_regularisation_effect_elsewhere_nowhere_or_unsettled_fails(changed, change, tau):
    claims = v.fig8_claims(fig8(changed=changed, change=change, tau=tau), CONFIG["fig8"], RULES)
    assert status(claims, "fig8.regularisation_effect") == "fail"


def test_fig8_checks_fail_when_the_paper_tables_change_the_end_states():
    claims = v.fig8_claims(fig8(coarse_changed=2, coarse_change=0.3), CONFIG["fig8"], RULES)
    assert status(claims, "fig8.paper_tables") == "fail"
    assert status(claims, "fig8.regularisation_effect_paper_tables") == "fail"
    assert status(claims, "fig8.regularisation_effect") == "pass"


def test_fig7_check_fails_when_the_paper_tables_change_an_end_state():
    claims = v.fig7_claims(fig7(septic_blob_paper_tables=(clusters(3, radius=0.7), 1.0)), CONFIG["fig7"], RULES)
    assert status(claims, "fig7.paper_tables") == "fail"
    assert not failing(v.fig7_claims(fig7(), CONFIG["fig7"], RULES))


# Figure 4's row label, K = -log|x|/(2 pi), against its caption's (-Delta)^{-1}

def fig4log(density=1.2, trajectory=3.4, reference=1e-12):
    """The label's reading: m = 4 and m = 6 errors at the given orders, a reference error ``reference``."""
    data = {f"log_repulsive_blob{m}_{part}": 0.5 * H4**order for m in (4, 6)
            for part, order in (("trajectory", trajectory), ("density", density))}
    data["log_repulsive_particle_trajectory"] = 0.1 * H4
    return data | {"h_values": H4, "fit_points": 3, "q": Q, "kernels": np.array(["log_repulsive"]),
                   "log_repulsive_reference_error": np.array([reference, reference])}


def test_fig4log_checks_pass_when_the_caption_reading_fits_the_published_rates():
    assert not failing(v.fig4log_claims(fig4log(), fig4(newtonian_repulsive_blob4_density=(0.5, 2.9)), RULES, RECORDER))


def test_fig4log_check_fails_when_the_label_reading_fits_the_published_density_rate_better():
    claims = v.fig4log_claims(fig4log(density=3.6), fig4(newtonian_repulsive_blob4_density=(0.5, 2.9)), RULES, RECORDER)
    assert status(claims, "fig4log.caption_fits_density") == "fail"
    assert status(claims, "fig4log.caption_fits_trajectory") == "pass"


def test_fig4log_reference_as_far_off_as_the_errors_fails():
    claims = v.fig4log_claims(fig4log(reference=1.0), fig4(), RULES, RECORDER)
    assert status(claims, "fig4log.reference") == "fail"


# Every paper and derived claim is covered above

COVERED = {
    "fig1d.order_trajectory", "fig1d.order_density", "fig2.order", "fig2.below_blob", "fig3.slower_trajectory",
    "fig3.slower_density", "fig1c.no_collision", "fig1c.bends_away", "energy.decrease", "fig1b.loses_resolution",
    "fig3b.rounded", "fig3b.mollifier_oscillation",
    *(f"fig4.{prefix}_{kernel}_{part}" for prefix in ("m4", "m6", "m6_better", "m6_rate_above_m4") for kernel in KERNELS
      for part in PARTS),
    "fig4.cubic_particle_beats_m4_trajectory", "fig4.cubic_particle_loses_density", "fig4.cubic_m6_best",
    "fig4.newtonian_blob_improves", "fig4.more_singular_more_gain",
    "fig4.repulsive_regularisation_m4", "fig4.repulsive_regularisation_m6", "fig4.repulsive_same_quadrature",
    "fig4.repulsive_quadrature_prediction", "fig4.repulsive_error_prediction", "fig4.repulsive_m6_quadrature",
    "fig4.m6_rates_approach_mq",
    "fig5.m4_regular_trajectory", "fig5.m4_regular_density", "fig5.particle_slower", "fig5.disk_slower",
    "fig6.quadratic_point", "fig6.cubic_ring", "fig6.cubic_ring_radius", "fig6.star_rounding_newtonian",
    "fig6.star_no_rounding_quadratic", "fig6.newtonian_blowup", "energy.decrease_2d",
    "fig7.delta_ring_radius", "fig7.delta_ring_thin", "fig7.particle_log_disk", "fig7.particle_power_ring",
    "fig7.blob_ring_faster", "fig7.blob_closer_at_8", "fig7.log_ring_collapse",
    "fig7.septic_three_points", "fig7.no_origin.delta_ring_radius", "fig7.no_origin.delta_ring_thin",
    "fig7.no_origin.particle_power_ring", "fig7.no_origin.blob_ring_faster", "fig7.no_origin.blob_closer_at_8",
    "fig7.no_origin.septic_three_points",
    "fig8.regularisation_effect",
}


def test_every_paper_and_derived_claim_has_a_failing_test_here():
    claims = [*newtonian(), *v.fig4_claims(fig4(), RULES, RECORDER),
              *v.repulsive_claims(repulsive(), CONFIG["fig4"], RULES, RECORDER),
              *v.fig5_claims(fig5(), RULES, RECORDER), *v.fig6_claims(fig6(), CONFIG["fig6"], RULES),
              *v.fig7_claims(fig7(), CONFIG["fig7"], RULES), *v.fig8_claims(fig8(), CONFIG["fig8"], RULES)]
    assert {claim.id.removeprefix("blob.") for claim in claims if claim.kind in ("paper", "derived")} == COVERED
    catalogued = {name for name, (kind, _) in v.KINDS.items() if kind in ("paper", "derived")}
    assert catalogued == COVERED


def test_a_claim_without_a_catalogue_entry_is_refused_not_added():
    """The catalogue is fixed before measuring: a diagnostic q the catalogue does not name (the config changed
    without the table) stops the claims with an error instead of adding an entry at run time."""
    entries = dict(v.KINDS)
    with pytest.raises(ValueError, match="no kind and source"):
        v.fig4_claims(fig4() | {"diagnostic_q": 0.8}, RULES, RECORDER)
    assert v.KINDS == entries and v.CATALOGUE.kinds == entries
