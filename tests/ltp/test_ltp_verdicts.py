"""Every paper and derived claim of the LTP paper can fail: each measure passes on an outcome of the shape
the paper (or our derivation) states and fails on a plausible wrong one (an order too low, a size that
shrinks exponentially instead of collapsing, a width that settles instead of shrinking, a state that
keeps moving, ripples in the wrong method)."""

import math
from pathlib import Path

import numpy as np
import pytest

from particle_methods.ltp.measures import excess_variation, peak_count
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.steady import first_steady_time
from particle_replication.verdicts import ltp as v

CONFIG = read_yaml(Path(__file__).parents[2] / "config" / "config.yaml")["ltp"]
QUADRATIC, NONAFFINE = CONFIG["quadratic"], CONFIG["nonaffine"]
FIG5, FIG8, CONCENTRATION = CONFIG["fig5"], CONFIG["fig8"], CONFIG["concentration"]
RULES = CONFIG["claims"]  # the tolerances no figure's section holds, as the claims script passes them
DT_ORDER = RULES["dt_order_band"]


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"ltp.{name}"]


def quiet():
    return Recorder(log=lambda text: None)


def failing(claims):
    return [(claim.id, claim.measured, claim.tolerance) for claim in claims if claim.status != "pass"]


# Figures 2 and 3, Theorems 1 and 2: W = x^2

H = np.array([0.1, 0.05, 0.025, 0.0125, 0.00625])
GRID = np.linspace(-1.5, 1.5, 3001)
EXACT = 0.75 * np.clip(1.0 - GRID**2, 0.0, None)


def wobble(amplitude):
    """The exact density with a small smooth error."""
    return EXACT * (1.0 + amplitude * np.cos(2 * np.pi * GRID / 0.1))


HOLES = EXACT * (0.1 + 0.9 * np.sin(np.pi * GRID / 0.01) ** 2)  # vanishes between particles spaced 0.01
SMEARED = 0.75 / 1.3**3 * np.clip(1.3**2 - GRID**2, 0.0, None)  # same mass, spread over 1.3 instead of 1


def time_gaps(coefficient, h=(0.02, 0.01, 0.005), dt=(0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625, 0.0003125)):
    """dt study: L1, Linf distance to the smallest-dt run, c(h) (dt - dt_min) for a first-order time error."""
    h, dt = np.array(h), np.array(dt)
    gaps = np.array([[[c * (step - dt[-1]), 3 * c * (step - dt[-1])] for step in dt[:-1]] for c in coefficient(h)])
    return {"dt_h": h, "dt_values": dt, "dt_gaps": gaps, "dt_fit_points": 3}


def quadratic(power=2.0, sp_first=HOLES, sp_last=SMEARED, ltp_over_sp=None, coefficient=lambda h: 1.0 + 0.01 / h):
    ltp_errors = np.column_stack([0.5 * H**power, 2.0 * H**power])
    sp_errors = np.column_stack([2.0 * H, 8.0 * H])  # first order: above LTP at every h
    if ltp_over_sp is not None:
        index, ratio = ltp_over_sp
        ltp_errors[index] = ratio * sp_errors[index]
    eps_values = np.geomspace(5e-4, 0.1, 25)
    v_shape = 1.1 * (1.0 + np.abs(np.log(eps_values / eps_values[12])))[:, None]
    scan_ltp, scan_ltp_fine = np.array([1e-2, 3e-2]), np.array([1e-3, 3e-3])
    return {
        "order_points": 3, "h_values": H, "ltp_errors": ltp_errors, "sp_errors": sp_errors,
        "exact": EXACT, "grid": GRID, "sp_densities": np.array([sp_first, wobble(0.01), wobble(0.02), sp_last]),
        "sp_eps": np.array([0.001, 0.004, 0.02, 0.05]), "sp_h": 0.01, "t": 0.5, "scan_h": 0.01,
        "eps_values": eps_values, "scan_ltp": scan_ltp, "scan_sp": v_shape * scan_ltp, "scan_dt": 0.01,
        "scan_ltp_fine": scan_ltp_fine, "scan_sp_fine": v_shape * scan_ltp_fine, "fine_dt": 1e-4,
        "mass_error": np.full(H.size, 1e-9), "centre_drift": np.full(H.size, 1e-14), "edge_jump": 1.8e-3,
        **time_gaps(coefficient),
    }


def test_quadratic_claims_all_pass_on_second_order_errors_holes_and_smearing():
    claims = v.quadratic_claims(quadratic(), quiet(), QUADRATIC, RULES)
    assert not failing(claims)


def test_fig2_order_half_fails_the_first_order_claims():
    claims = v.quadratic_claims(quadratic(power=0.5), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig2.order_l1") == "fail" and status(claims, "fig2.order_linf") == "fail"


def test_fig2_first_order_passes_theorem_1_but_fails_the_affine_order_two():
    claims = v.quadratic_claims(quadratic(power=1.1), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig2.order_l1") == "pass" and status(claims, "fig2.order_linf") == "pass"
    assert status(claims, "fig2.affine_order_l1") == "fail" and status(claims, "fig2.affine_order_linf") == "fail"


def test_fig2_order_three_fails_the_affine_order_two():
    claims = v.quadratic_claims(quadratic(power=3.0), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig2.affine_order_l1") == "fail" and status(claims, "fig2.affine_order_linf") == "fail"


def test_fig2_smooth_sp_density_at_small_eps_has_no_holes():
    claims = v.quadratic_claims(quadratic(sp_first=wobble(0.01)), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig2.sp_holes") == "fail"


def test_fig2_accurate_sp_density_at_large_eps_is_not_smeared():
    claims = v.quadratic_claims(quadratic(sp_last=wobble(0.015)), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig2.sp_smeared") == "fail"


@pytest.mark.parametrize("index", [0, 2, 4])
def test_fig3_ltp_above_sp_at_one_h_fails(index):
    claims = v.quadratic_claims(quadratic(ltp_over_sp=(index, 1.2)), quiet(), QUADRATIC, RULES)
    assert status(claims, "fig3.ltp_below_sp") == "fail"


def test_fig3_best_sp_check_fails_when_sp_beats_ltp_at_some_eps():
    data = quadratic()
    data["scan_sp"][5] = data["scan_ltp"] / 3
    assert status(v.quadratic_claims(data, quiet(), QUADRATIC, RULES), "fig3.best_sp_l1") == "fail"


def theorem1_gaps(coefficient, h=(0.04, 0.02, 0.01), dt=(0.02, 0.01, 0.005, 0.0025, 0.0003125)):
    """Theorem 1's study: L1, Linf distance to the smallest-dt run, c(h) (dt - dt_min) for a first-order time error."""
    data = time_gaps(coefficient, h, dt)
    return {"theorem1_h": data["dt_h"], "theorem1_dt": data["dt_values"], "theorem1_gaps": data["dt_gaps"],
            "theorem1_fit_points": 3, "theorem1_t": 0.5, "theorem1_label": "|x|^3/3 on rho3"}


@pytest.mark.parametrize("coefficient, expected", [
    (lambda h: 1.0 + 0.01 / h, "pass"),  # a dt term and a dt/h term: slope between -1 and 0
    (lambda h: np.full(h.size, 2.0), "pass"),  # a dt term only: slope 0
    (lambda h: 0.3 / h, "pass"),  # exactly dt/h: the bound
    (lambda h: 1e-4 / h**2, "fail"),  # dt/h^2: worse than Theorem 1
    (lambda h: 1.0 + 1e-3 / h**2, "fail"),  # a dt term plus a dominant dt/h^2 term
])
def test_thm1_time_error_coefficient_must_grow_at_most_like_one_over_h(coefficient, expected):
    assert status(v.theorem1_claims(theorem1_gaps(coefficient), quiet()), "thm1.dt_over_h") == expected


def test_thm1_dt_order_check_fails_for_a_second_order_time_error():
    data = time_gaps(lambda h: 1.0 + 0.01 / h)
    dt = data["dt_values"]
    data["dt_gaps"] = data["dt_gaps"] * (dt[:-1] - dt[-1])[None, :, None]
    assert status(v.dt_claims(data, quiet(), DT_ORDER), "thm1.dt_order") == "fail"


# Non-affine flow


def nonaffine(power=1.3, theorem4_power=1.0, biorthogonal_power=1.0, theorem3_power=1.0, theorem3_gap=0.1,
              atomic_power=1.0, time_share=0.01):
    """The non-affine study at orders ``power`` (our dt) and, for Theorem 4 (dt = h^2), ``theorem4_power`` with the
    weights (2.14) and ``biorthogonal_power`` with (2.16); for Theorem 3 on the indicator (dt = h/4) the W1 order
    ``theorem3_power``, its reference gap ``theorem3_gap`` of the smallest distance; on atoms the order
    ``atomic_power`` and the time share ``time_share``."""
    h = np.array([0.08, 0.04, 0.02, 0.01])
    errors = np.column_stack([h**power, 3 * h**power])
    centre_h = np.array([0.04, 0.02, 0.01, 0.005])
    h4 = np.array([0.1, 0.05, 0.025])
    cell = np.column_stack([h4**theorem4_power, 2 * h4**theorem4_power])
    biorthogonal = np.column_stack([h4**biorthogonal_power, 2 * h4**biorthogonal_power])
    h3 = np.array([0.04, 0.02, 0.01])
    distances = 0.3 * h3**theorem3_power
    ha = np.array([0.01, 0.005, 0.0025, 0.00125])
    return {"order_points": 3, "h_values": h, "errors": errors, "label": "|x|^1.5/1.5", "reference_h": 0.0025,
            "dt": 2e-3, "reference_gap": 0.1 * errors[-1], "centre_h": centre_h, "centre_drift": 0.5 * centre_h**2,
            "centre_label": "|x|^3/3 - |x|^2.5/2.5", "t": 0.5, "theorem4_h": h4, "theorem4_dt": h4**2,
            "theorem4_times": np.array([0.1, 0.2, 0.3, 0.4, 0.5]), "theorem4_label": "|x|^1.5/1.5 on rho3",
            "theorem4_weights": np.array(["cell", "biorthogonal"]), "theorem4_cell_differences": cell,
            "theorem4_biorthogonal_differences": biorthogonal, "theorem3_h": h3,
            "theorem3_dt": 0.25 * h3, "theorem3_times": np.array([0.1, 0.2, 0.3, 0.4, 0.5]),
            "theorem3_reference_h": 0.00125, "theorem3_label": "|x|^3/3 on rho2", "theorem3_distances": distances,
            "theorem3_reference_gap": theorem3_gap * distances[-1], "theorem3_atomic_h": ha,
            "theorem3_atomic_dt": 1e-3, "theorem3_atomic_times": np.array([0.1, 0.2, 0.3, 0.4, 0.5]),
            "theorem3_atomic_label": "|x|^3/3 on 40 atoms", "theorem3_atomic_distances": 0.47 * ha**atomic_power,
            "theorem3_atomic_time_share": time_share, **theorem1_gaps(lambda x: np.full(x.size, 0.28))}


@pytest.mark.parametrize("weights", ["cell", "biorthogonal"])
def test_theorem4_order_below_one_fails_for_either_weights(weights):
    data = nonaffine(**{"theorem4_power" if weights == "cell" else "biorthogonal_power": 0.5})
    claims = v.nonaffine_claims(data, quiet(), NONAFFINE, RULES)
    assert status(claims, f"thm4.order_l1_{weights}") == "fail"
    assert status(claims, f"thm4.order_linf_{weights}") == "fail"
    other = "biorthogonal" if weights == "cell" else "cell"
    assert status(claims, f"thm4.order_l1_{other}") == "pass"


def test_theorem3_order_below_one_fails():
    """A W1 (bounded-Lipschitz) order of 0.8, as a dt^(0.8) time error or a rough-data error of h^0.8 would give."""
    claims = v.nonaffine_claims(nonaffine(theorem3_power=0.8, atomic_power=0.8), quiet(), NONAFFINE, RULES)
    assert status(claims, "thm3.order_w1") == "fail" and status(claims, "thm3.atomic_order_w1") == "fail"
    assert status(claims, "thm4.order_l1_cell") == "pass"


def test_theorem3_atomic_order_two_is_not_the_sharp_order_one():
    claims = v.nonaffine_claims(nonaffine(atomic_power=2.0), quiet(), NONAFFINE, RULES)
    assert status(claims, "thm3.atomic_order_w1") == "pass" and status(claims, "thm3.atomic_order_sharp") == "fail"


def test_theorem3_atomic_time_share_check_fails_when_dt_moves_the_distance():
    claims = v.nonaffine_claims(nonaffine(time_share=0.5), quiet(), NONAFFINE, RULES)
    assert status(claims, "thm3.atomic_time_share") == "fail"


def test_theorem3_reference_check_fails_when_the_reference_is_half_as_far_as_the_errors():
    claims = v.nonaffine_claims(nonaffine(theorem3_gap=0.5), quiet(), NONAFFINE, RULES)
    assert status(claims, "thm3.reference") == "fail"


def test_nonaffine_claims_pass_on_an_order_above_one():
    assert not failing(v.nonaffine_claims(nonaffine(), quiet(), NONAFFINE, RULES))


def test_nonaffine_order_half_fails():
    claims = v.nonaffine_claims(nonaffine(power=0.5), quiet(), NONAFFINE, RULES)
    assert status(claims, "nonaffine.order_l1") == "fail" and status(claims, "nonaffine.order_linf") == "fail"


def test_nonaffine_reference_check_fails_when_the_reference_is_as_far_as_the_errors():
    data = nonaffine()
    data["reference_gap"] = data["errors"][-1]
    assert status(v.nonaffine_claims(data, quiet(), NONAFFINE, RULES), "nonaffine.reference") == "fail"


# Figure 4: hat against B3 shapes


def fig4(hat_ratio=0.2, b3_ratio=0.6):
    sp = np.array([1e-2, 5e-2])
    eps_values = np.geomspace(0.005, 0.08, 17)
    v_shape = (1.0 + np.abs(np.log(eps_values / eps_values[8])))[:, None]
    data = {"eps_values": eps_values, "sp_eps": 0.04}
    for shape, ratio, best in (("hat", hat_ratio, 0.8), ("b3", b3_ratio, 1.5)):
        ltp = ratio * sp
        data.update({f"{shape}_ltp_errors": ltp, f"{shape}_sp_errors": sp,
                     f"{shape}_scan_errors": v_shape * ltp / best})
    return data


def test_fig4_claims_pass_when_hat_gains_more_than_b3():
    assert not failing(v.fig4_claims(fig4(), RULES))


def test_fig4_hat_ratio_above_half_fails():
    claims = v.fig4_claims(fig4(hat_ratio=0.7, b3_ratio=0.9), RULES)
    assert status(claims, "fig4.hat") == "fail" and status(claims, "fig4.hat_gain_larger") == "pass"


def test_fig4_hat_gain_smaller_than_b3_fails():
    claims = v.fig4_claims(fig4(hat_ratio=0.45, b3_ratio=0.4), RULES)
    assert status(claims, "fig4.hat") == "pass" and status(claims, "fig4.hat_gain_larger") == "fail"


# Figure 5: collapse


def fig5(small=lambda t: (2.0 - t) ** 2, large=lambda t: (1.0 + t) ** -2.0, contraction=0.1):
    data = {"labels": np.array(["|x|^1.5/1.5", "|x|^2.5/2.5"])}
    for i, (size, t_end) in enumerate(((small, 1.9), (large, 4.0))):
        t = np.linspace(0.0, t_end, 191 if i == 0 else 201)
        shrink = np.linspace(1.0, contraction, t.size)[:, None]
        data.update({f"case{i}_times": t, f"case{i}_widths": size(t)[:, None] * np.array([1.0, 2.0, 3.0]),
                     f"case{i}_centres": shrink * np.array([-0.6, -0.2, 0.2, 0.6])})
    return data


def test_fig5_claims_pass_on_power_collapse_and_algebraic_shrinking():
    assert not failing(v.fig5_claims(fig5(), FIG5, RULES))


@pytest.mark.parametrize("small", [lambda t: np.exp(-t), lambda t: np.exp(-3.0 * t), lambda t: (1.0 + t) ** -2.0],
                         ids=["exp", "fast_exp", "algebraic"])
def test_fig5_exponential_or_algebraic_shrinking_is_no_blowup(small):
    assert status(v.fig5_claims(fig5(small=small), FIG5, RULES), "fig5.blowup_a1.5") == "fail"


@pytest.mark.parametrize("large", [lambda t: (5.0 - t) ** 2, lambda t: 0.1 * (4.5 - t) ** 0.5],
                         ids=["square", "sqrt"])
def test_fig5_finite_time_collapse_fails_no_blowup(large):
    assert status(v.fig5_claims(fig5(large=large), FIG5, RULES), "fig5.no_blowup_a2.5") == "fail"


def test_fig5_exponential_shrinking_of_the_a2_5_run_is_no_blowup():
    assert status(v.fig5_claims(fig5(large=lambda t: np.exp(-t)), FIG5, RULES), "fig5.no_blowup_a2.5") == "pass"


def test_fig5_centres_that_do_not_contract_fail_dirac():
    assert status(v.fig5_claims(fig5(contraction=0.5), FIG5, RULES), "fig5.dirac") == "fail"


def test_fig5_collapse_time_check_fails_when_the_extrapolations_disagree():
    # s = (2 - t)^2 exp(-4 t^2): g bends, so the successive windows extrapolate to different times
    claims = v.fig5_claims(fig5(small=lambda t: (2.0 - t) ** 2 * np.exp(-4.0 * t**2)), FIG5, RULES)
    assert status(claims, "fig5.collapse_time_stable") == "fail"


# Figures 6 and 7: concentration

TIMES = np.linspace(0.0, 60.0, 121)
SHRINKING = 0.2 * np.exp(-0.1 * TIMES)  # Dirac masses: halves faster than every 10 time units
SETTLING = 0.3 + 0.2 * np.exp(-0.5 * TIMES)  # an L1 profile: settles
SLOWING = 0.2 / (1.0 + TIMES)  # shrinks, but algebraically: its rate per window falls like 1/t
GATHERING = 0.49 * (1.0 - np.exp(-0.1 * TIMES))  # mass near each peak tends to half the total
SPREAD = np.full(TIMES.size, 0.1)  # an L1 profile keeps a small share near its peaks


def both_sides(series):
    return np.column_stack([series, series])


SETTLING_CHANGES = 0.1 * np.exp(-0.5 * TIMES)  # L1 change of a profile per window: falls to 0
MOVING_CHANGES = np.full(TIMES.size, 0.3)  # Dirac masses forming: the density changes by O(1) per window


def fig6(b25_widths=SHRINKING, b25_masses=GATHERING, b15_widths=SETTLING, b15_masses=SPREAD, edge_ratio=3.0,
         b25_weights=(0.25, 0.25, 0.25, 0.25), edge_power=0.5, edge_widths=SETTLING, edge_final_power=None,
         b15_changes=SETTLING_CHANGES):
    """Figure 6's runs; b = 1.5 refined (h = 0.04, 0.02, 0.01) with peaks growing like h^-edge_power, at the
    last record like h^-edge_final_power if given, its concentration widths ``edge_widths`` at every h."""
    edge_h = np.array([0.04, 0.02, 0.01])
    peaks = np.outer(edge_h**-edge_power, np.ones(TIMES.size))
    if edge_final_power is not None:
        peaks[:, -1] = edge_h**-edge_final_power
    data = {"labels": np.array(["|x|^3/3 - |x|^1.1/1.1", "|x|^3/3 - |x|^1.5/1.5", "|x|^3/3 - |x|^2.5/2.5"]),
            "edge_h": edge_h, "edge_peaks": peaks,
            "edge_widths": np.array([both_sides(edge_widths)] * edge_h.size), "edge_case": 1}
    for i, widths, masses in ((1, b15_widths, b15_masses), (2, b25_widths, b25_masses)):
        data.update({f"case{i}_times": TIMES, f"case{i}_concentration_widths": both_sides(widths),
                     f"case{i}_concentration_masses": both_sides(masses),
                     f"case{i}_centres": np.tile([-0.5, -0.45, 0.45, 0.5], (TIMES.size, 1)),
                     f"case{i}_weights": np.array(b25_weights), f"case{i}_edge_ratio": np.full(TIMES.size, edge_ratio),
                     f"case{i}_profile_times": TIMES[TIMES >= 10.0],
                     f"case{i}_profile_changes": b15_changes[TIMES >= 10.0]})
    return data


def test_fig6_claims_pass_on_dirac_masses_for_b2_5_and_a_steady_profile_for_b1_5():
    assert not failing(v.fig6_claims(fig6(), quiet(), CONCENTRATION, RULES))


def test_fig6_width_that_settles_does_not_concentrate():
    claims = v.fig6_claims(fig6(b25_widths=SETTLING), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b2.5_concentrates") == "fail"
    assert status(claims, "fig6.b2.5_concentrates_exponentially") == "fail"


def test_fig6_algebraic_shrinking_is_dirac_masses_in_infinite_time_but_not_exponential():
    claims = v.fig6_claims(fig6(b25_widths=SLOWING), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b2.5_concentrates") == "pass"
    assert status(claims, "fig6.b2.5_concentrates_exponentially") == "fail"


def test_fig6_l1_profile_mass_near_the_peaks_is_no_dirac_mass():
    claims = v.fig6_claims(fig6(b25_masses=SPREAD), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b2.5_dirac_mass") == "fail"


def test_fig6_b1_5_profile_still_moving_is_not_steady():
    claims = v.fig6_claims(fig6(b15_changes=MOVING_CHANGES), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b1.5_steady") == "fail"
    steady = [c for c in claims if c.id == "ltp.fig6.b1.5_steady"][0]
    assert math.isinf(float(steady.value)) and steady.measured == "not measured"


def test_fig6_b1_5_bounded_edge_peaks_do_not_diverge():
    """Peaks that converge under refinement (a bounded profile, exponent 0.05) or runs that never settle fail."""
    claims = v.fig6_claims(fig6(edge_power=0.05), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b1.5_edges_diverge") == "fail"
    claims = v.fig6_claims(fig6(edge_widths=SHRINKING), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b1.5_edges_diverge") == "fail" and status(claims, "fig6.b1.5_steady") == "pass"


def test_fig6_b1_5_edge_peaks_are_read_at_the_common_end_of_the_runs():
    """The peaks of the settled runs, read at one time for every h (the end), not at each run's own settling time
    (where the finest run, read earliest, showed a smaller growth in the full run)."""
    converging = v.fig6_claims(fig6(edge_power=0.5, edge_final_power=0.05), quiet(), CONCENTRATION, RULES)
    assert status(converging, "fig6.b1.5_edges_diverge") == "fail"
    growing = v.fig6_claims(fig6(edge_power=0.05, edge_final_power=0.5), quiet(), CONCENTRATION, RULES)
    assert status(growing, "fig6.b1.5_edges_diverge") == "pass"


def test_fig6_b1_5_mass_gathering_near_the_peaks_is_no_l1_profile():
    claims = v.fig6_claims(fig6(b15_masses=GATHERING), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b1.5_profile") == "fail"


def test_fig6_b1_5_profile_is_measured_at_its_steady_time():
    # mass gathers near the peaks only after the steady time: the profile claim looks at the steady time
    late = np.where(TIMES < 40.0, 0.1, 0.45)
    assert status(v.fig6_claims(fig6(b15_masses=late), quiet(), CONCENTRATION, RULES), "fig6.b1.5_profile") == "pass"


def test_fig6_b1_5_flat_profile_has_no_edge_growth():
    assert status(v.fig6_claims(fig6(edge_ratio=1.0), quiet(), CONCENTRATION, RULES), "fig6.b1.5_edges") == "fail"


def test_fig6_equal_split_check_fails_on_unequal_masses():
    claims = v.fig6_claims(fig6(b25_weights=(0.3, 0.3, 0.2, 0.2)), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b2.5_equal_split") == "fail"


def fig7(widths=SHRINKING, masses=GATHERING):
    return {"record_times": TIMES, "concentration_widths": both_sides(widths),
            "concentration_masses": both_sides(masses), "label": "|x|^3/3 - |x|^2.5/2.5"}


def test_fig7_claims_pass_on_dirac_masses():
    assert not failing(v.fig7_claims(fig7(), CONCENTRATION))


def test_fig7_width_that_settles_does_not_concentrate():
    claims = v.fig7_claims(fig7(widths=SETTLING), CONCENTRATION)
    assert status(claims, "fig7.concentrates") == "fail" and status(claims, "fig7.concentrates_exponentially") == "fail"


def test_fig7_algebraic_shrinking_concentrates_but_not_exponentially():
    claims = v.fig7_claims(fig7(widths=SLOWING), CONCENTRATION)
    assert status(claims, "fig7.concentrates") == "pass" and status(claims, "fig7.concentrates_exponentially") == "fail"


def test_fig7_l1_profile_mass_near_the_peaks_is_no_dirac_mass():
    assert status(v.fig7_claims(fig7(masses=SPREAD), CONCENTRATION), "fig7.dirac_mass") == "fail"


@pytest.mark.parametrize("end", [30.0, 40.0, 50.0, 60.0])
def test_fig7_concentrates_verdict_does_not_depend_on_where_the_run_stops(end):
    # Shrinking that speeds up, as measured (rates growing with t): the verdict is the same for every run end.
    keep = TIMES <= end
    data = {"record_times": TIMES[keep], "concentration_widths": both_sides(0.4 * np.exp(-0.002 * TIMES[keep] ** 2)),
            "concentration_masses": both_sides(GATHERING[keep]), "label": "|x|^3/3 - |x|^2.5/2.5"}
    assert status(v.fig7_claims(data, CONCENTRATION), "fig7.concentrates") == "pass"


def test_fig7_one_side_settling_fails_concentrates():
    data = fig7()
    data["concentration_widths"][:, 1] = SETTLING
    assert status(v.fig7_claims(data, CONCENTRATION), "fig7.concentrates") == "fail"


# Figure 8: stationary states, oscillations of SP only

X = np.linspace(-1.1, 1.1, 2201)
TWO_BUMPS = np.exp(-(((np.abs(X) - 0.5) / 0.1) ** 2))
RIPPLED = TWO_BUMPS * (1.0 + 0.3 * np.cos(2 * np.pi * X / 0.02))
SMOOTH = excess_variation(X, TWO_BUMPS), peak_count(TWO_BUMPS, FIG8["prominence"])
OSCILLATING = excess_variation(X, RIPPLED), peak_count(RIPPLED, FIG8["prominence"])
T8 = np.linspace(0.0, 40.0, 41)
SETTLED_CENTRES = np.array([-0.5, -0.4, 0.4, 0.5]) * (1.0 + 0.5 * np.exp(-T8))[:, None]
MOVING_CENTRES = np.array([-0.5, -0.4, 0.4, 0.5]) * (1.0 - 0.01 * T8)[:, None]


def steady(centres):
    return first_steady_time(T8, centres, FIG8["steady"]["window"], FIG8["steady"]["tolerance"])


def fig8(sp_centres=SETTLED_CENTRES, ltp_centres=SETTLED_CENTRES, sp=None, ltp=None,
         shifted_centres=SETTLED_CENTRES, shifted=None):
    sp = [OSCILLATING] * T8.size if sp is None else sp
    ltp = [SMOOTH] * T8.size if ltp is None else ltp
    shifted = [SMOOTH] * T8.size if shifted is None else shifted
    return {"sp_times": T8, "sp_steady": steady(sp_centres), "ltp_steady": steady(ltp_centres), "t": 5.0,
            "steps": 100, "sp_oscillation": np.array([o for o, _ in sp]), "sp_peaks": np.array([n for _, n in sp]),
            "ltp_oscillation": np.array([o for o, _ in ltp]), "ltp_peaks": np.array([n for _, n in ltp]),
            "widest_centre": 0.0, "widest_weight": 0.01, "widest_width": 0.05, "widest_share": 0.8,
            "shifted_offset": 0.5, "shifted_ltp_steady": steady(shifted_centres),
            "shifted_ltp_oscillation": np.array([o for o, _ in shifted]),
            "shifted_ltp_widths": np.full((T8.size, 4), 0.01), "shifted_ltp_centres": SETTLED_CENTRES}


def test_fig8_densities_are_what_their_names_say():
    assert SMOOTH[1] == 2 and SMOOTH[0] < FIG8["oscillation"]
    assert OSCILLATING[1] > 10 and OSCILLATING[0] > FIG8["oscillation"]
    assert math.isfinite(steady(SETTLED_CENTRES)) and math.isinf(steady(MOVING_CENTRES))


def test_fig8_claims_pass_on_steady_runs_with_sp_rippled_and_ltp_smooth():
    # both grids settle: every claim holds but the explanation by the particle at 0, which needs a contrast
    assert [claim_id for claim_id, *_ in failing(v.fig8_claims(fig8(), FIG8, RULES))] == ["ltp.fig8.centre_particle"]


def test_fig8_centre_particle_holds_when_only_the_grid_without_it_settles():
    claims = v.fig8_claims(fig8(ltp_centres=MOVING_CENTRES), FIG8, RULES)
    assert status(claims, "fig8.centre_particle") == "pass" and status(claims, "fig8.shifted.ltp_steady") == "pass"


def test_fig8_centre_particle_fails_when_neither_grid_settles():
    claims = v.fig8_claims(fig8(ltp_centres=MOVING_CENTRES, shifted_centres=MOVING_CENTRES), FIG8, RULES)
    assert status(claims, "fig8.centre_particle") == "fail"


def test_fig8_centre_particle_fails_when_only_the_regular_grid_settles():
    assert status(v.fig8_claims(fig8(shifted_centres=MOVING_CENTRES), FIG8, RULES), "fig8.centre_particle") == "fail"


def test_fig8_shifted_ltp_centres_that_keep_moving_are_not_steady():
    claims = v.fig8_claims(fig8(shifted_centres=MOVING_CENTRES), FIG8, RULES)
    assert status(claims, "fig8.shifted.ltp_steady") == "fail"


def test_fig8_shifted_ltp_ripples_at_its_stationary_state_are_not_smooth():
    """The paper speaks of the stationary state: ripples from the steady time on, or at one record after it, fail,
    up to the first record whose widths fall to the rounding level of the positions (the rule fixed in the
    config), where the measure stops; a run that never settles fails."""
    at = int(np.argmin(np.abs(T8 - steady(SETTLED_CENTRES))))
    rippled = [SMOOTH] * at + [OSCILLATING] * (T8.size - at)
    assert status(v.fig8_claims(fig8(shifted=rippled), FIG8, RULES), "fig8.shifted.ltp_smooth") == "fail"
    last = [SMOOTH] * (T8.size - 1) + [OSCILLATING]
    assert status(v.fig8_claims(fig8(shifted=last), FIG8, RULES), "fig8.shifted.ltp_smooth") == "fail"
    collapsed = fig8(shifted=last)
    collapsed["shifted_ltp_widths"] = collapsed["shifted_ltp_widths"].copy()
    collapsed["shifted_ltp_widths"][-1, 0] = 1e-15  # at the rounding level of positions near 0.5
    assert status(v.fig8_claims(collapsed, FIG8, RULES), "fig8.shifted.ltp_smooth") == "pass"
    once = [SMOOTH] * T8.size
    once[at + 1] = OSCILLATING  # one record after the steady time, within the window that is measured
    assert status(v.fig8_claims(fig8(shifted=once), FIG8, RULES), "fig8.shifted.ltp_smooth") == "fail"
    moving = v.fig8_claims(fig8(shifted_centres=MOVING_CENTRES), FIG8, RULES)
    assert status(moving, "fig8.shifted.ltp_smooth") == "fail"


def test_fig8_sp_centres_that_keep_moving_are_not_steady():
    assert status(v.fig8_claims(fig8(sp_centres=MOVING_CENTRES), FIG8, RULES), "fig8.sp_steady") == "fail"


def test_fig8_ltp_centres_that_keep_moving_are_not_steady():
    assert status(v.fig8_claims(fig8(ltp_centres=MOVING_CENTRES), FIG8, RULES), "fig8.ltp_steady") == "fail"


def test_fig8_sp_without_ripples_does_not_oscillate():
    assert status(v.fig8_claims(fig8(sp=[SMOOTH] * T8.size), FIG8, RULES), "fig8.sp_oscillates") == "fail"


def test_fig8_sp_ripples_only_before_its_steady_time_do_not_count():
    sp = [OSCILLATING if t < 5.0 else SMOOTH for t in T8]
    claims = v.fig8_claims(fig8(sp=sp), FIG8, RULES)
    assert status(claims, "fig8.sp_oscillates") == "fail" and status(claims, "fig8.sp_transient") == "fail"


def test_fig8_ltp_with_ripples_is_not_smooth():
    assert status(v.fig8_claims(fig8(ltp=[OSCILLATING] * T8.size), FIG8, RULES), "fig8.ltp_smooth") == "fail"


def test_fig8_ltp_ripples_at_a_single_record_are_not_smooth():
    ltp = [SMOOTH] * T8.size
    ltp[30] = OSCILLATING
    assert status(v.fig8_claims(fig8(ltp=ltp), FIG8, RULES), "fig8.ltp_smooth") == "fail"


def test_fig8_inf_steady_time_fails():
    data = fig8()
    data["sp_steady"] = data["ltp_steady"] = data["shifted_ltp_steady"] = math.inf
    claims = v.fig8_claims(data, FIG8, RULES)
    assert all(status(claims, f"fig8.{name}") == "fail" for name in ("sp_steady", "ltp_steady", "shifted.ltp_steady"))


# Every paper and derived claim is covered above

COVERED = {
    "fig2.order_l1", "fig2.order_linf", "fig2.affine_order_l1", "fig2.affine_order_linf", "fig2.sp_holes",
    "fig2.sp_smeared", "fig3.ltp_below_sp", "thm1.dt_over_h", "nonaffine.order_l1", "nonaffine.order_linf",
    "fig4.hat", "fig4.hat_gain_larger", "fig5.blowup_a1.5", "fig5.no_blowup_a2.5", "fig5.dirac",
    "fig6.b2.5_concentrates", "fig6.b2.5_dirac_mass", "fig6.b1.5_steady", "fig6.b1.5_profile", "fig6.b1.5_edges",
    "fig7.concentrates", "fig7.dirac_mass", "fig6.b2.5_concentrates_exponentially", "fig7.concentrates_exponentially",
    "thm3.atomic_order_w1", "thm3.atomic_order_sharp", "fig8.sp_steady", "fig8.ltp_steady", "fig8.sp_oscillates",
    "fig8.ltp_smooth", "fig8.shifted.ltp_steady", "fig8.shifted.ltp_smooth", "thm4.order_l1_cell",
    "fig6.b1.5_edges_diverge",
    "thm4.order_linf_cell", "thm4.order_l1_biorthogonal", "thm4.order_linf_biorthogonal", "thm3.order_w1",
}


def test_every_paper_and_derived_claim_has_a_failing_test_here():
    claims = [*v.quadratic_claims(quadratic(), quiet(), QUADRATIC, RULES), *v.theorem1_claims(theorem1_gaps(
              lambda h: np.full(h.size, 0.28)), quiet()),
              *v.nonaffine_claims(nonaffine(), quiet(), NONAFFINE, RULES), *v.fig4_claims(fig4(), RULES),
              *v.fig5_claims(fig5(), FIG5, RULES), *v.fig6_claims(fig6(), quiet(), CONCENTRATION, RULES),
              *v.fig7_claims(fig7(), CONCENTRATION), *v.fig8_claims(fig8(), FIG8, RULES)]
    assert {claim.id.removeprefix("ltp.") for claim in claims if claim.kind in ("paper", "derived")} == COVERED
