"""Every claim of the cross-method comparison can fail: each measure of particle_replication.verdicts.cross
passes on synthetic results of the shape the theory states and fails on a plausible wrong one (an SPD at
order 0.5, an SPD error that grows in time or is not zero once all the mass has collapsed, blob, LTP, SP and
Godunov orders off their bands, blob particles that coincide or spread beyond delta, a method faster than the
SPDs, a particle method 1e-6 off the SPD, a collision event in the wrong place, a solver that does not chatter,
LTP refused at 0.9).

The inputs are the result dictionaries the scripts save (scripts/cross/study_data.py and behaviour_data.py,
same keys, checked below), built from the config's sizes, times and bands, so the tests follow the config."""

import ast
import math
from pathlib import Path

import numpy as np
import pytest

from particle_methods.cross.exact import AggregationSolution
from particle_methods.cross.methods import SHAPE
from particle_methods.ltp.shapes import shape_named
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import cross as v
from particle_replication.workflow import LoadGuard, load_results, save_results

ROOT = Path(__file__).parents[2]
CONFIG = read_yaml(ROOT / "config" / "config.yaml")["cross"]
RULES = CONFIG["claims"]
BLOB = [f"blob, m = {m}" for m in CONFIG["blob"]["orders"]]
METHODS = ["SPD, equal masses", "SPD, grid weights", "particle method", "Godunov for F", *BLOB, "LTP", "SP"]
TIMES = sorted({0.0, *CONFIG["times"], *CONFIG["particle_times"], *CONFIG["ltp"]["times"],
                *CONFIG["ltp"]["sp_times"]})
BEFORE = [t for t in CONFIG["times"] if t < 1.0]
AFTER = [t for t in CONFIG["times"] if t > 1.0]


def middle(band):
    return 0.5 * (band[0] + band[1])


def sizes_at(spec_sizes, t):
    """The sizes of a method at t (SP's may depend on the time, as in the config)."""
    return spec_sizes[t] if isinstance(spec_sizes, dict) else spec_sizes


LTP = CONFIG["ltp"]
# method -> (times, sizes (the config's), coefficient, seconds per size^power, power): error = coefficient
# size^-order, wall time seconds size^power. The SPDs reach the target W1 within their runs at O(n) cost; the
# others cost O(n^2) or O(n/h); the speed claim compares every run of theirs.
SPECS = {
    "SPD, equal masses": ([0.0, *CONFIG["times"]], CONFIG["spd_n"], 0.1, 1e-7, 1.0),
    "SPD, grid weights": ([0.0, *CONFIG["times"]], CONFIG["grid_inverse_h"], 0.05, 1e-7, 1.0),
    "particle method": (CONFIG["particle_times"], CONFIG["particle_inverse_h"], 0.05, 1e-5, 2.0),
    "Godunov for F": (CONFIG["times"], CONFIG["godunov"]["cells"], 0.2, 1e-5, 1.0),
    **{name: (CONFIG["times"], {t: CONFIG["blob"]["inverse_h"] if t < 1.0 else CONFIG["blob"]["after_inverse_h"]
                                for t in CONFIG["times"]}, 0.05, 1e-5, 2.0) for name in BLOB},
    "LTP": (LTP["times"], LTP["inverse_h"], 0.5, 1e-3, 1.0),
    "SP": (LTP["sp_times"], {t: LTP["inverse_h"] if t < 1.0 else LTP.get("sp_after_inverse_h", LTP["inverse_h"])
                             for t in LTP["sp_times"]}, 0.5, 1e-3, 1.0),
}


#: int |s| phi(s) ds of the SP particles' shape: the W1 of a unit Dirac mass spread over one particle of width 1.
SPREAD = shape_named(SHAPE).absolute_moment


def default_order(method, t):
    """The order each method should show (the middle of its band)."""
    if method.startswith("SPD"):
        return middle(RULES["spd_order"])
    if method.startswith("blob"):
        return middle(RULES["blob_order_before"]) if t < 1.0 else RULES["blob_order_after_min"] + 0.1
    if method == "LTP":
        return middle(RULES["ltp_order"])
    if method == "SP":
        return middle(RULES["sp_order_before"]) if t < 1.0 else middle(RULES["sp_order_after"])
    if method == "Godunov for F":
        return middle(RULES["godunov_order"])
    return 1.0


def collapsed(data, t):
    solution = AggregationSolution(data, t)
    return solution.dirac_mass == solution.mass


def study(change=None, change_case=None):
    """The study result: one row per data, time, method and size, passing every claim. ``change(row)`` may
    edit each row (a dict: data, t, method, size, error, seconds, width, spd_difference) to a wrong outcome, and
    ``change_case(case)`` each exact case (a dict: data, t, mass, dirac)."""
    rows = []
    for data in CONFIG["data"]:
        for t in TIMES:
            solution = AggregationSolution(data, t)
            for method, (times, sizes, coefficient, cost, power) in SPECS.items():
                if t not in times:
                    continue
                for size in sizes_at(sizes, t):
                    error = coefficient * size ** -default_order(method, t)
                    if method == "SP" and t > 1.0:
                        # the Dirac mass spread over one particle of width eps = sp_eps_over_h h (order 1)
                        error = solution.dirac_mass * SPREAD * LTP["sp_eps_over_h"] / size
                    if method.startswith("SPD"):
                        # contraction: below the initial error; exact once all the mass is in the Dirac mass
                        error = 0.0 if collapsed(data, t) else error * (1.0 if t == 0.0 else 0.5)
                    width = math.nan
                    if method.startswith("blob") and solution.dirac_mass > 0:
                        width = 0.5 * (1.0 / size) ** CONFIG["blob"]["q"]  # apart, within delta = h^q
                    row = {"data": data, "t": t, "method": method, "size": size, "error": error,
                           "seconds": cost * size**power, "width": width,
                           "spd_difference": 2e-16 if method == "particle method" else math.nan}
                    if change is not None:
                        change(row)
                    rows.append(row)
    cases = []
    for data in CONFIG["data"]:
        for t in TIMES:
            solution = AggregationSolution(data, t)
            case = {"data": data, "t": t, "mass": solution.mass, "dirac": solution.dirac_mass}
            if change_case is not None:
                change_case(case)
            cases.append(case)
    return {
        "data": np.array(CONFIG["data"]), "times": np.array(TIMES, dtype=float), "methods": np.array(METHODS),
        "data_index": np.array([CONFIG["data"].index(r["data"]) for r in rows]),
        "time_index": np.array([TIMES.index(r["t"]) for r in rows]),
        "method_index": np.array([METHODS.index(r["method"]) for r in rows]),
        "size": np.array([r["size"] for r in rows]),
        "count": np.array([2 * r["size"] + 1 for r in rows]),
        "error": np.array([r["error"] for r in rows]), "seconds": np.array([r["seconds"] for r in rows]),
        "dirac_width": np.array([r["width"] for r in rows]),
        "spd_difference": np.array([r["spd_difference"] for r in rows]),
        "case_data": np.array([c["data"] for c in cases]), "case_times": np.array([c["t"] for c in cases]),
        "case_mass": np.array([c["mass"] for c in cases]), "case_dirac": np.array([c["dirac"] for c in cases]),
        # timed alone on a two-core machine
        "cpu": np.array("a test CPU (AVX2, 2 cores)"), "cpu_share": np.array(0.99), "load": np.array(0.1),
        "cores": np.array(2), "threads": np.array(2),
    }


def behaviour(**changes):
    """The behaviour result, passing every claim; keyword arguments replace entries."""
    data = CONFIG["data"]
    inverse_h = np.array(CONFIG["behaviour"]["ltp_inverse_h"])
    dt = LTP["dt_over_h"] / inverse_h
    predicted = np.linspace(1.0, 1.03, len(data))
    result = {
        "data": np.array(data), "collision_predicted": predicted, "collision_measured": predicted + 3e-11,
        # DOP853 chatters: 500 right-hand sides up to the collision, the budget spent 1e-4 past it
        "stall_collision": predicted, "stall_before": np.full(len(data), 500.0),
        "stall_after": np.full(len(data), 4500.0), "stall_reached": predicted + 1e-4,
        "ltp_peak_position": np.zeros((len(data), inverse_h.size)),
        "ltp_peak_width": np.full((len(data), inverse_h.size), 0.01),
        "ltp_peak_edge": np.full((len(data), inverse_h.size), -0.8),
        "ltp_inverse_h": inverse_h, "ltp_dt": dt, "ltp_refusal": np.tile(1.0 - dt, (len(data), 1)),
        "stall_window": CONFIG["behaviour"]["stall_window"],
    }
    return result | changes


def run_study(d):
    return v.study_claims(d, Recorder(lambda *_: None), CONFIG)


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"cross.{name}"]


def failing(claims):
    return [(claim.id, claim.measured, claim.tolerance) for claim in claims if claim.status != "pass"]


def only_failing(claims, *names):
    """The claims ``names`` fail and every other one passes."""
    assert sorted(claim.id for claim in claims if claim.status != "pass") == sorted(f"cross.{n}" for n in names), \
        failing(claims)


@pytest.fixture(scope="module")
def passing_study():
    return study()


# The synthetic results have the keys the scripts save


def saved_keys(script):
    """Keyword names of the save_results calls in scripts/cross/<script> (the study's two parts: the
    errors, and the timed runs that add their seconds to them), with the load guard's readings where a call
    passes ``**guard.readings()``."""
    tree = ast.parse((ROOT / "scripts" / "cross" / script).read_text())
    calls = [node for node in ast.walk(tree) if isinstance(node, ast.Call)
             and getattr(node.func, "id", getattr(node.func, "attr", None)) == "save_results"]
    assert calls
    readings = [keyword for call in calls for keyword in call.keywords if keyword.arg is None
                and getattr(getattr(keyword.value, "func", None), "attr", None) == "readings"]
    return ({keyword.arg for call in calls for keyword in call.keywords if keyword.arg is not None}
            | (set(LoadGuard().readings()) if readings else set()))


def test_synthetic_results_have_the_keys_the_scripts_save(passing_study):
    assert set(passing_study) == saved_keys("study_data.py")
    assert set(behaviour()) == saved_keys("behaviour_data.py")


def test_claims_read_the_results_as_saved(tmp_path, passing_study):
    """Through an .npz file (strings and floats come back as numpy arrays) nothing changes."""
    save_results(tmp_path / "study.npz", **passing_study)
    save_results(tmp_path / "behaviour.npz", **behaviour())
    assert not failing(run_study(load_results(tmp_path / "study.npz")))
    assert not failing(v.behaviour_claims(load_results(tmp_path / "behaviour.npz"), CONFIG))


# Study claims


def test_study_claims_all_pass_on_the_expected_outcome(passing_study):
    claims = run_study(passing_study)
    assert not failing(claims)
    assert {claim.id for claim in claims} == {f"cross.{name}" for name in (
        "exact.dirac_share", "order.spd", "spd.contraction", "spd.collapse_exact", "order.blob_before",
        "order.blob_after", "order.ltp", "order.sp_before", "order.sp_after", "sp_after.dirac_spread",
        "order.godunov", "identity.particle_spd", "blob.no_dirac", "fastest")}
    assert all(claim.kind in ("derived", "check") and claim.source for claim in claims)


def test_study_records_one_rate_per_fitted_series(passing_study):
    recorder = Recorder(lambda *_: None)
    v.study_claims(passing_study, recorder, CONFIG)
    assert recorder.fits and all(fit.window == CONFIG["fit_points"] for fit in recorder.fits)


@pytest.mark.parametrize("method", ["SPD, equal masses", "SPD, grid weights"])
def test_spd_at_order_one_half_fails(method):
    def half(row):
        if row["method"] == method and row["error"] > 0:
            row["error"] = 0.1 * row["size"] ** -0.5 * (1.0 if row["t"] == 0.0 else 0.5)

    only_failing(run_study(study(half)), "order.spd")


def test_spd_error_growing_in_time_fails():
    def growing(row):
        if row["method"] == "SPD, grid weights" and row["t"] > 1.0:
            row["error"] *= 2.5  # 0.5 -> 1.25 times the initial error: same order, no contraction

    only_failing(run_study(study(growing)), "spd.contraction")


def test_spd_not_exact_once_the_mass_has_collapsed_fails():
    def inexact(row):
        # one particle (mass M/n, M = 2) left one grid step 2/n from the Dirac mass: W1 = 2M/n^2
        if row["method"] == "SPD, equal masses" and collapsed(row["data"], row["t"]):
            row["error"] = 4.0 / row["size"] ** 2

    claims = run_study(study(inexact))
    assert status(claims, "spd.collapse_exact") == "fail"
    assert status(claims, "order.spd") == "pass"  # the collapsed case is not fitted


def test_collapsed_cases_are_left_out_of_the_spd_and_godunov_orders():
    """The single Dirac mass: SPD errors 0 (exact) and a Godunov error that does not decrease are not orders."""
    def flat(row):
        if row["method"] == "Godunov for F" and collapsed(row["data"], row["t"]):
            row["error"] = 1e-3

    assert any(collapsed(data, t) for data in CONFIG["data"] for t in CONFIG["times"])
    assert not failing(run_study(study(flat)))


def test_blob_at_order_one_half_before_the_blowup_fails():
    def slow(row):
        if row["method"] == BLOB[0] and row["t"] < 1.0:
            row["error"] = 0.05 * row["size"] ** -0.5

    only_failing(run_study(study(slow)), "order.blob_before")


def test_blob_at_order_one_half_after_the_blowup_fails():
    def slow(row):
        if row["method"] == BLOB[-1] and row["t"] > 1.0 and row["data"] == CONFIG["data"][0]:
            row["error"] = 0.05 * row["size"] ** -0.5

    only_failing(run_study(study(slow)), "order.blob_after")


@pytest.mark.parametrize(("method", "when", "order", "claim"), [
    ("LTP", "before", 1.0, "order.ltp"),  # first order: the reconstruction's O(h^2) lost
    ("SP", "before", 1.0, "order.sp_before"),
    ("SP", "after", 2.0, "order.sp_after"),  # second order after the blow-up: no Dirac mass to smear
    ("SP", "after", 0.5, "order.sp_after"),
    ("Godunov for F", "before", 0.5, "order.godunov"),
    ("Godunov for F", "after", 1.5, "order.godunov"),
])
def test_orders_off_their_bands_fail(method, when, order, claim):
    times = BEFORE if when == "before" else AFTER

    def off(row):
        if row["method"] == method and row["t"] in times and not collapsed(row["data"], row["t"]):
            row["error"] = 0.5 * row["size"] ** -order

    claims = run_study(study(off))
    assert status(claims, claim) == "fail"
    assert all(c.status == "pass" for c in claims if c.id.startswith("cross.order") and c.id != f"cross.{claim}")


@pytest.mark.parametrize("factor", [
    1.2,   # the Dirac mass smeared wider than one particle (a collapse still under way, centres apart)
    0.8,   # narrower than one particle: not the shape the method carries
])
def test_sp_after_the_blowup_off_the_predicted_dirac_spread_fails(factor):
    def off(row):
        if row["method"] == "SP" and row["t"] in AFTER:
            row["error"] *= factor

    only_failing(run_study(study(off)), "sp_after.dirac_spread")


def test_the_b3_particle_spreads_a_dirac_mass_over_7_15_of_its_width():
    assert SPREAD == pytest.approx(7.0 / 15.0, rel=1e-15)
    assert shape_named("hat").absolute_moment == pytest.approx(1.0 / 3.0, rel=1e-15)


@pytest.mark.parametrize("width", [2.0, math.nan])
def test_blob_particles_that_spread_beyond_delta_fail(width):
    """2 delta: the particles are not in a cluster of width delta; NaN: no particle in the Dirac mass's levels.
    (Coinciding particles would be an ODE with a Lipschitz field merging trajectories: not a claim.)"""
    def wrong(row):
        if row["method"] == BLOB[0] and row["t"] > 1.0 and row["size"] == CONFIG["blob"]["after_inverse_h"][-1]:
            row["width"] = width * (1.0 / row["size"]) ** CONFIG["blob"]["q"]

    only_failing(run_study(study(wrong)), "blob.no_dirac")


def test_an_spd_as_slow_as_the_others_fails():
    def slow(row):
        if row["method"] in v.SPD_METHODS:
            row["seconds"] *= 1e6

    only_failing(run_study(study(slow)), "fastest")


def test_an_spd_slower_than_one_run_of_another_method_fails(passing_study):
    """Every SPD time scaled so that the smallest ratio becomes 1/2: the ratio scales with the SPD's times."""
    factor = v.speed_ratio(passing_study) / 0.5

    def slower(row):
        if row["method"] in v.SPD_METHODS:
            row["seconds"] *= factor

    claims = run_study(study(slower))
    only_failing(claims, "fastest")
    assert float(next(c for c in claims if c.id == "cross.fastest").value) == pytest.approx(0.5, rel=1e-9)


def test_particle_method_1e_6_off_the_spd_fails():
    def off(row):
        if row["method"] == "particle method" and row["size"] == CONFIG["particle_inverse_h"][-1]:
            row["spd_difference"] = 1e-6

    only_failing(run_study(study(off)), "identity.particle_spd")


def test_no_particle_method_measured_fails():
    def unmeasured(row):
        row["spd_difference"] = math.nan

    only_failing(run_study(study(unmeasured)), "identity.particle_spd")


@pytest.mark.parametrize("share", [0.5, 0.65, 0.0])
def test_a_dirac_mass_off_the_issues_57_percent_fails(share):
    """(4.3) at t = 1.1: 0.5 (a0 from a wrong m), 0.65, or no Dirac mass at all (a0 = 0, blow-up missed)."""
    late = max(CONFIG["times"])

    def wrong(case):
        if case["data"] == CONFIG["data"][0] and case["t"] == late:
            case["dirac"] = share * case["mass"]

    claims = run_study(study(change_case=wrong))
    assert status(claims, "exact.dirac_share") == "fail"


def test_every_run_counts_however_short(passing_study):
    """A Godunov run made nearly free counts, however short (no cut-off): Godunov is then faster than the SPD."""
    def short(row):
        if row["method"] == "Godunov for F":
            row["seconds"] = 1e-9

    assert v.speed_ratio(study(short)) < 1.0
    only_failing(run_study(study(short)), "fastest")


def test_the_speed_check_abstains_on_a_loaded_machine(passing_study):
    """Timed while other processes held every core: the check abstains (and says why) rather than decide."""
    loaded = {**study(), "load": np.array(2.0), "cores": np.array(2)}
    made = next(claim for claim in run_study(loaded) if claim.id == "cross.fastest")
    assert made.status == "abstain" and "other processes were runnable" in made.claim


# time_to_error: the work-precision line


def test_time_to_error_interpolates_log_linearly_between_bracketing_runs():
    seconds, extrapolated = v.time_to_error([1e-4, 1e-6, 1e-8], [1.0, 10.0, 100.0], 1e-7)
    assert seconds == pytest.approx(10.0 * math.sqrt(10.0), rel=1e-12) and not extrapolated
    assert v.time_to_error([1e-4, 1e-6, 1e-8], [1.0, 10.0, 100.0], 1e-6) == (pytest.approx(10.0), False)


def test_time_to_error_of_a_run_already_below_the_target_is_its_time():
    assert v.time_to_error([1e-9, 1e-10], [0.5, 2.0], 1e-6) == (0.5, False)
    assert v.time_to_error([0.0, 0.0], [0.25, 2.0], 1e-6) == (0.25, False)  # exact (the collapsed SPD)


def test_time_to_error_extrapolates_from_the_two_largest_runs():
    seconds, extrapolated = v.time_to_error([1e-1, 1e-2, 1e-3, 1e-4], [0.1, 1.0, 10.0, 100.0], 1e-6)
    assert seconds == pytest.approx(1e4, rel=1e-12) and extrapolated
    # the local slope of the last two runs counts, not the first ones: error ~ time^-1/2 there
    seconds, _ = v.time_to_error([1e-1, 1e-2, 1e-3], [1.0, 2.0, 200.0], 1e-5)
    assert seconds == pytest.approx(2e4 * 100.0, rel=1e-12)


def test_time_to_error_is_infinite_when_the_error_stops_decreasing():
    assert v.time_to_error([1e-2, 1e-3, 1e-3], [1.0, 10.0, 100.0], 1e-6) == (math.inf, True)
    assert v.time_to_error([1e-2, 1e-3, 2e-3], [1.0, 10.0, 100.0], 1e-6) == (math.inf, True)


def test_time_to_error_does_not_extrapolate_from_runs_shorter_than_min_seconds():
    errors, seconds = [1e-1, 1e-2, 1e-3], [1e-4, 1e-3, 1e-2]
    assert v.time_to_error(errors, seconds, 1e-6, min_seconds=0.02)[0] != v.time_to_error(errors, seconds, 1e-6)[0]
    assert math.isnan(v.time_to_error(errors, seconds, 1e-6, min_seconds=0.02)[0])
    assert v.time_to_error(errors, seconds, 1e-6, min_seconds=0.01) == (pytest.approx(10.0), True)
    # interpolation and runs already below the target do not need long runs
    assert v.time_to_error(errors, seconds, 1e-2, min_seconds=1.0) == (pytest.approx(1e-3), False)
    assert v.time_to_error(errors, seconds, 1.0, min_seconds=1.0) == (1e-4, False)


def test_fastest_table_uses_every_method_at_every_time_after_0(passing_study):
    table = v.fastest_table(passing_study, CONFIG["target_error"], CONFIG["min_timed_seconds"])
    assert set(table) == {(data, t) for data in CONFIG["data"] for t in TIMES if t > 0.0}
    for (_, t), times in table.items():
        assert set(times) == {m for m, spec in SPECS.items() if t in spec[0]}
        assert all(seconds > 0 or math.isnan(seconds) for seconds, _ in times.values())
        assert all(times[m][0] > 0 for m in v.SPD_METHODS)  # the SPDs reach the target within their runs


# Behaviour claims


def behaviour_status(b, name):
    return status(v.behaviour_claims(b, CONFIG), name)


def test_behaviour_claims_all_pass_on_the_expected_outcome():
    claims = v.behaviour_claims(behaviour(), CONFIG)
    assert not failing(claims)
    assert {claim.id for claim in claims} == {"cross.identity.first_collision", "cross.particle.stall",
                                              "cross.ltp.refusal", "cross.ltp.edge_collapse"}


def test_collision_event_away_from_the_predicted_meeting_fails():
    b = behaviour()
    assert behaviour_status(b | {"collision_measured": b["collision_predicted"] + 1e-6},
                            "identity.first_collision") == "fail"
    assert behaviour_status(b | {"collision_measured": np.full(len(CONFIG["data"]), np.inf)},
                            "identity.first_collision") == "fail"  # no collision at all


def test_a_solver_that_does_not_chatter_past_the_collision_fails():
    """As many right-hand sides per unit time after the collision as before it: no stall."""
    b = behaviour()
    before_rate = b["stall_before"] / b["stall_collision"]
    window = CONFIG["behaviour"]["stall_window"]
    steady = b | {"stall_after": 2.0 * before_rate * window, "stall_reached": b["stall_collision"] + window}
    assert behaviour_status(steady, "particle.stall") == "fail"


def test_ltp_refused_at_0_9_fails():
    b = behaviour()
    refusal = b["ltp_refusal"].copy()
    refusal[0, -1] = 0.9
    assert behaviour_status(b | {"ltp_refusal": refusal}, "ltp.refusal") == "fail"
    refusal[0, -1] = 1.0 + 2 * b["ltp_dt"][-1]  # or never refused before the blow-up
    assert behaviour_status(b | {"ltp_refusal": refusal}, "ltp.refusal") == "fail"
    refusal[0, -1] = np.nan  # or not refused at all
    assert behaviour_status(b | {"ltp_refusal": refusal}, "ltp.refusal") == "fail"


def test_early_refusal_explained_by_the_edge_particle_passes_and_other_causes_fail():
    """An early refusal whose densest particle sits at an end of the support, narrower than the exact flow's, is
    explained; the same refusal with the densest particle at the centre, or wider than the exact flow's, is not."""
    b = behaviour()
    refusal = b["ltp_refusal"].copy()
    refusal[0, -1] = 0.98  # several steps early at the finest h
    edge = b["ltp_peak_edge"].copy()
    shape = edge.shape
    early = b | {"ltp_refusal": refusal, "ltp_peak_position": edge.copy(), "ltp_peak_width": np.full(shape, 1e-3)}
    assert behaviour_status(early, "ltp.edge_collapse") == "pass"
    assert behaviour_status(early | {"ltp_peak_position": -edge}, "ltp.edge_collapse") == "pass"  # the other end
    assert behaviour_status(early | {"ltp_peak_position": np.zeros(shape)}, "ltp.edge_collapse") == "fail"
    assert behaviour_status(early | {"ltp_peak_width": np.full(shape, 0.03)}, "ltp.edge_collapse") == "fail"
    # the edge's neighbourhood and the largest width are the config's
    proximity, width = RULES["edge_proximity"], RULES["edge_width"] * (1.0 - 0.98)
    for position, expected in ((1.0 - 0.5 * proximity, "pass"), (1.0 - 2.0 * proximity, "fail")):
        assert behaviour_status(early | {"ltp_peak_position": position * edge}, "ltp.edge_collapse") == expected
    for factor, expected in ((0.9, "pass"), (1.1, "fail")):
        peak_width = np.full(shape, factor * width)
        assert behaviour_status(early | {"ltp_peak_width": peak_width}, "ltp.edge_collapse") == expected


def test_an_early_refusal_at_a_coarser_h_is_explained_too():
    """Every h counts, not only the finest: a coarse early refusal at the centre fails the check."""
    b = behaviour()
    refusal = b["ltp_refusal"].copy()
    refusal[0, 0] = 1.0 - 5.0 * b["ltp_dt"][0]
    position = b["ltp_peak_position"].copy()
    assert behaviour_status(b | {"ltp_refusal": refusal}, "ltp.edge_collapse") == "fail"  # at the centre
    position[0, 0] = b["ltp_peak_edge"][0, 0]
    width = np.full(position.shape, 1e-3)
    assert behaviour_status(b | {"ltp_refusal": refusal, "ltp_peak_position": position, "ltp_peak_width": width},
                            "ltp.edge_collapse") == "pass"


def test_time_to_error_does_not_extrapolate_a_cost_that_did_not_grow():
    """The largest run faster than the one before (a parallel threshold, a cache): no growth measured."""
    assert math.isnan(v.time_to_error([1e-2, 1e-3], [0.2, 0.15], 1e-6, min_seconds=0.1)[0])


# Aggregates that move and merge (bump data, one case per data)

AGG = CONFIG["aggregates"]
MERGER = 0.9 / (0.9066666666666667 / 2)


def aggregates(case="two_bumps", spd_w1=0.25, spd_order=1.0, growth=0.0, merger_order=1.0, grid_merger=1e-14,
               ltp_order=2.0, sp_order=1.0, godunov_order=1.0, particle_difference=2e-16, levels=None, centres=None,
               window=None, gap=0.2933, **changes):
    """An aggregates result as aggregates_data.py saves it, for ``case`` (two_bumps: every aggregate a centre-of-mass
    identity; skewed: the first aggregate is none): the equal-mass SPD's W1 spd_w1 (M L/2)/n (times (1 + growth t)
    if growth), the grid SPD's c/size^spd_order, falling in time; Godunov's c/cells^godunov_order; LTP's
    c/size^ltp_order before the first blow-up (NaN after); SP's c/size^sp_order; the equal-mass SPD's merger errors
    0.4/n^merger_order alternating in sign over each block, the grid SPD's grid_merger; ``levels``, ``centres`` and
    ``window``: {method key: order} of the level spreads, centre errors and W1 around the merger (default the
    expected orders); the blob's gap at the merger over delta ``gap``; the particle method particle_difference from
    the grid SPD."""
    q = v.aggregate_settings(AGG, case)
    times = np.union1d(np.union1d(np.linspace(0.0, q["t_end"], q["steps"] + 1), q["fixed_times"]),
                       MERGER + np.asarray(q["merger_window"]))
    blob = f"blob, m = {q['blob']['order']}"
    keys = {"SPD, equal masses": "spd_equal", "SPD, grid weights": "spd_grid", blob: "blob", "SP": "sp",
            "Godunov for F": "godunov"}
    levels = {"spd_equal": 1.0, "spd_grid": 2.0, "blob": 0.9, "sp": 1.0, "godunov": 1.0, **(levels or {})}
    # (the blob's centres where they are identities: the trapezoid rule's O(h^4))
    centres = {"blob": 4.0 if case == "two_bumps" else 0.9, "sp": 1.0, "godunov": 1.0, **(centres or {})}
    window = window or {}
    runs = [("SPD, equal masses", n) for n in q["spd_n"]] + [("SPD, grid weights", k) for k in q["grid_inverse_h"]]
    runs += [(blob, k) for k in q["blob"]["inverse_h"]] + [("Godunov for F", k) for k in q["godunov_cells"]]
    runs += [("LTP", k) for k in q["ltp"]["inverse_h"]] + [("SP", k) for k in q["ltp"]["sp_inverse_h"]]
    runs += [("particle method", k) for k in q["particle_inverse_h"]]
    mass, support = 0.9066666666666667, np.array([-0.7, 0.75])
    exact = np.full((times.size, 2), np.nan)
    exact[(times > 0.5) & (times < 1.0), 0] = -0.3
    exact[(times > 1.0) & (times < MERGER)] = [-0.2, 0.02]
    exact[times > MERGER, 0] = -0.135
    identity = np.isfinite(exact) if case == "two_bumps" else np.isfinite(exact) & (np.arange(2) == 1)
    around = np.isin(times, MERGER + np.asarray(q["merger_window"]))
    errors, centre, spread, mergers, gaps, counts = [], [], [], [], [], []
    for name, size in runs:
        count = size if name.startswith(("SPD, equal", "Godunov")) else 2 * size + 1
        counts.append(count)
        key = keys.get(name)
        if name == "LTP":
            row = np.where(times < 0.5, 0.3 * size ** -ltp_order, np.nan)
        elif name == "particle method":
            row = np.where(times < 0.5, 0.3 / size, np.nan)
        elif name == "SP":
            row = np.full(times.size, 0.3 * size ** -sp_order)
        elif name.startswith("Godunov"):
            row = 0.3 * size ** -godunov_order * np.exp(-times)
        elif name == "SPD, equal masses":
            row = spd_w1 * mass * np.diff(support)[0] / 2 / size * np.exp(-times) * (1.0 + growth * times)
        elif name == blob:
            row = 0.3 * count ** -0.9 * np.exp(-times)
        else:
            row = 0.3 * size ** -spd_order * np.exp(-times) * (1.0 + growth * times)
        if key in ("spd_grid", "blob", "sp", "godunov"):
            # W1 around the merger: the row's own order unless changed (a merger a fixed time off raises it there).
            usual = {"spd_grid": spd_order, "blob": 0.9, "sp": sp_order, "godunov": godunov_order}[key]
            row = np.where(around, row * count ** (usual - window.get(key, usual)), row)
        errors.append(row)
        centre_offset = 0.05 * count ** -centres[key] if key in centres else 0.0
        # (SP's centre-of-mass identities are exact to rounding)
        centre.append(exact + np.where(identity & (key == "sp"), 1e-16, centre_offset))
        spread.append(np.where(np.isfinite(exact), 0.05 * count ** -levels[key] if key else np.nan, np.nan))
        # The grid SPD's merger: exact to rounding on two_bumps (an identity), O(h) on skewed data.
        late = grid_merger if case == "two_bumps" else grid_merger + 0.3 / count
        mergers.append(MERGER + late if name == "SPD, grid weights" else np.nan)
        gaps.append(gap if name == blob else np.nan)
    block = np.array([[n + j for j in range(17)] for n in q["spd_n"]])  # two_bumps' period of n m_1/M mod 1
    signs = np.where(np.arange(17) % 2 == 0, 1.0, -0.5)
    spd_mergers = MERGER + 0.4 * block[:, :1] ** -merger_order * signs
    result = {"data": np.array(q["data"]), "times": times, "fixed_times": np.array(q["fixed_times"], float),
              "window_times": MERGER + np.asarray(q["merger_window"], float), "exact_positions": exact,
              # (skewed: a quarter of the mass still free as the aggregates merge)
              "exact_masses": np.where(np.isfinite(exact), [mass / 2, mass / 2 if case == "two_bumps" else mass / 4],
                                       np.nan),
              "exact_lowers": np.where(np.isfinite(exact), [0.0, mass / 2], np.nan), "exact_identity": identity,
              "exact_offsets": np.where(np.isfinite(exact), 0.0 if case == "two_bumps" else 0.02, np.nan),
              "merger": MERGER, "path_times": times, "path_positions": exact,
              "path_masses": np.where(np.isfinite(exact), 0.3, np.nan),
              "spd_clusters": np.full((times.size, 4), np.nan), "blowups": np.array([0.5, 1.0]),
              "methods": np.array([name for name, _ in runs]), "size": np.array([size for _, size in runs]),
              "count": np.array(counts), "error": np.array(errors), "centre": np.array(centre),
              "spread": np.array(spread), "method_merger": np.array(mergers), "merger_gap": np.array(gaps),
              "spd_merger_n": block, "spd_merger": spd_mergers,
              "spd_levels": 0.05 * block[:, :1] ** -levels["spd_equal"] * (1.0 + 0.5 * signs),
              "spd_difference": np.array([particle_difference if name == "particle method" else np.nan
                                          for name, _ in runs]), "mass": mass, "support": support}
    return result | changes


def run_aggregates(a, case="two_bumps"):
    return v.aggregate_claims(a, Recorder(lambda *_: None), CONFIG, v.aggregate_settings(AGG, case), case)


def test_aggregate_results_have_the_keys_the_script_saves():
    assert set(aggregates()) == saved_keys("aggregates_data.py")


@pytest.mark.parametrize("case", list(AGG["cases"]))
def test_aggregate_claims_pass_on_the_expected_outcome(tmp_path, case):
    save_results(tmp_path / "aggregates.npz", **aggregates(case))
    assert not failing(run_aggregates(load_results(tmp_path / "aggregates.npz"), case))


def test_identities_are_checks_on_two_bumps_and_claims_on_skewed_data():
    kinds = {case: {claim.id.split(".", 2)[2]: claim.kind for claim in run_aggregates(aggregates(case), case)}
             for case in AGG["cases"]}
    for key in ("blob_centres", "sp_centres"):
        assert kinds["two_bumps"][f"aggregate.{key}"] == "check"
        assert kinds["skewed"][f"aggregate.{key}"] == "derived"
    # Godunov has no pair forces: its centres are its numerical diffusion on both data.
    assert kinds["two_bumps"]["aggregate.godunov_centres"] == kinds["skewed"]["aggregate.godunov_centres"] == "derived"
    # Identities: the particle method as the grid SPD, and the equal-mass SPD's W1 bound (construction + contraction).
    assert kinds["two_bumps"]["particle_spd"] == kinds["two_bumps"]["spd_w1.equal_masses"] == "check"
    assert kinds["two_bumps"]["spd_merger.grid_weights"] == "check"
    assert kinds["skewed"]["spd_merger.grid_weights"] == "derived"
    # The two-body prediction of the blob's gap holds only where the two aggregates hold all the mass.
    assert "aggregate.blob_merger_gap" in kinds["two_bumps"]


def test_an_equal_mass_spd_off_by_twice_its_discretisation_fails():
    """W1 above (M/n) L/2: particles not at the medians of their levels, or a wrong speed."""
    only_failing(run_aggregates(aggregates(spd_w1=2.0)), "two_bumps.spd_w1.equal_masses")


def test_a_grid_spd_at_order_one_half_after_t_0_fails():
    only_failing(run_aggregates(aggregates(spd_order=0.5)), "two_bumps.spd_order.grid_weights",
                 "two_bumps.merger_w1.spd_grid")


def test_spd_error_growing_after_the_start_breaks_the_contraction():
    # W1 (1 + 2 t) e^-t peaks above its t = 0 value at t = 1/2.
    only_failing(run_aggregates(aggregates(growth=2.0)), "two_bumps.spd_contraction")


@pytest.mark.parametrize("merger_order", [0.0, 0.5])
def test_an_equal_mass_spd_merger_whose_envelope_does_not_fall_as_1_over_n_fails(merger_order):
    only_failing(run_aggregates(aggregates(merger_order=merger_order)), "two_bumps.spd_merger.equal_masses")


def test_a_grid_spd_merging_1e_6_late_fails_the_identity():
    only_failing(run_aggregates(aggregates(grid_merger=1e-6)), "two_bumps.spd_merger.grid_weights")


def test_a_grid_spd_merging_a_fixed_time_late_fails_on_skewed_data():
    only_failing(run_aggregates(aggregates("skewed", grid_merger=1e-2), "skewed"), "skewed.spd_merger.grid_weights")


@pytest.mark.parametrize("case", list(AGG["cases"]))
@pytest.mark.parametrize("key", ["spd_equal", "spd_grid", "blob", "sp", "godunov"])
def test_aggregates_whose_levels_stay_a_fixed_distance_away_fail(case, key):
    """A method that holds the wrong mass (or the right mass at the wrong place) at a distance that does not shrink."""
    only_failing(run_aggregates(aggregates(case, levels={key: 0.0}), case), f"{case}.aggregate.{key}_levels")


@pytest.mark.parametrize("key", ["blob", "sp", "godunov"])
def test_skewed_aggregates_off_their_position_by_a_fixed_offset_fail(key):
    only_failing(run_aggregates(aggregates("skewed", centres={key: 0.0}), "skewed"), f"skewed.aggregate.{key}_centres")


def test_sp_aggregates_1e_6_off_fail_the_identity():
    a = aggregates()
    a["centre"][a["methods"] == "SP"] += 1e-6
    only_failing(run_aggregates(a), "two_bumps.aggregate.sp_centres")


@pytest.mark.parametrize("case", list(AGG["cases"]))
@pytest.mark.parametrize("key, uniform", [("spd_grid", ["spd_order.grid_weights", "spd_contraction"]), ("blob", []),
                                          ("sp", ["sp_order_after"]), ("godunov", ["godunov_order"])])
def test_a_merger_a_fixed_time_off_fails_w1_around_it(case, key, uniform):
    """W1 around the merger that does not fall: the method merges a fixed time early or late (which the orders of W1
    over every t > 0, where a method has one, see too)."""
    only_failing(run_aggregates(aggregates(case, window={key: 0.0}), case), f"{case}.merger_w1.{key}",
                 *(f"{case}.{name}" for name in uniform))


@pytest.mark.parametrize("gap", [0.2787, 0.1, 1.0])
def test_a_blob_gap_at_the_merger_off_the_two_body_prediction_fails(gap):
    """The m = 6 mollifier's gap (0.2787), a merger read when the gap is delta/10 or delta."""
    only_failing(run_aggregates(aggregates(gap=gap)), "two_bumps.aggregate.blob_merger_gap")


def test_a_particle_method_apart_from_the_grid_spd_before_its_first_collision_fails():
    """A particle 1e-6 off the SPD: the method would not move the grid particles at (mass right - mass left)/2."""
    only_failing(run_aggregates(aggregates(particle_difference=1e-6)), "two_bumps.particle_spd")


def test_ltp_at_first_order_before_the_blowup_fails():
    only_failing(run_aggregates(aggregates(ltp_order=1.0)), "two_bumps.ltp_order")


def test_sp_at_second_order_after_the_blowup_fails():
    # A Dirac mass reconstructed better than its mass times phi_eps would contradict the O(eps) of SP.
    only_failing(run_aggregates(aggregates(sp_order=2.0)), "two_bumps.sp_order_after")


def test_godunov_at_order_one_half_after_t_0_fails():
    only_failing(run_aggregates(aggregates(godunov_order=0.5)), "two_bumps.godunov_order",
                 "two_bumps.merger_w1.godunov")


def test_an_error_at_t_0_alone_decides_no_order():
    """The data's discretisation at t = 0 is left out: a large W1 at t = 0 only changes no verdict."""
    a = aggregates()
    a["error"][:, 0] *= 1e3
    assert not failing(run_aggregates(a))


def test_skewed_data_whose_aggregates_sit_at_their_bumps_centres_of_mass_fail_the_data_check():
    a = aggregates("skewed")
    a["exact_offsets"] = np.where(np.isfinite(a["exact_offsets"]), 1e-3, np.nan)
    only_failing(run_aggregates(a, "skewed"), "skewed.data.off_centre")


def test_skewed_data_collapsed_before_the_merger_fail_the_data_check():
    a = aggregates("skewed")
    a["exact_masses"] = np.where(np.isfinite(a["exact_masses"]), a["mass"] / 2, np.nan)
    only_failing(run_aggregates(a, "skewed"), "skewed.data.free_at_merger")


@pytest.mark.parametrize("case", list(AGG["cases"]))
def test_a_grid_spd_whose_aggregates_are_first_order_fails(case):
    """Grid particles off their trapezoid masses or centres by O(h) (e.g. at x_j + h/2): first order, not second."""
    only_failing(run_aggregates(aggregates(case, levels={"spd_grid": 1.0}), case), f"{case}.aggregate.spd_grid_levels")


def test_blob_centres_at_first_order_fail_the_identity_on_two_bumps():
    """On two_bumps the blob's centres carry only the trapezoid rule's O(h^4): an O(h) error is a wrong method."""
    only_failing(run_aggregates(aggregates(centres={"blob": 1.0})), "two_bumps.aggregate.blob_centres")
