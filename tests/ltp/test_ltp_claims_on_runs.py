"""The claims changed by issue 43 fail on plausible wrong outcomes produced by the real data code: the study
functions of particle_methods.ltp.theorems and the solver with the measures the data scripts call, at the quick
run's sizes, with a wrong solver, wrong data or a wrong potential; the right ones pass."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from particle_methods.ltp import potential, simulate
from particle_methods.ltp.measures import concentration_series, profile_changes
from particle_methods.ltp.potentials import Potential
from particle_methods.ltp.theorems import theorem1_time_error, theorem3_atomic, theorem4_differences
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import ltp as v

ROOT = Path(__file__).parents[2]
CONFIG = read_yaml(ROOT / "config" / "config.yaml")["ltp"]
QUICK = read_yaml(ROOT / "config" / "quick.yaml")["ltp"]
NONAFFINE, RULES, CONCENTRATION = CONFIG["nonaffine"], CONFIG["claims"], CONFIG["concentration"]


def quiet():
    return Recorder(log=lambda text: None)


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"ltp.{name}"]


def quick(section):
    return {**NONAFFINE[section], **QUICK["nonaffine"][section]}


def doubled(initial, w, *args, **kwargs):
    """A solver with twice the velocity: W replaced by 2 W."""
    return simulate(initial, Potential(w.name, tuple(2 * c for c in w.coefficients), w.exponents), *args, **kwargs)


def finer_grid(initial, w, h, *args, **kwargs):
    """A run on the grid step h^1.5 instead of h: the atoms sit within h^1.5 of the centres, spread over h^1.5."""
    return simulate(initial, w, h**1.5, *args, **kwargs)


@pytest.fixture(scope="module")
def rough():
    """Synthetic data of the claim on the indicator with dt proportional to h (first order), which passes."""
    h = np.array([0.04, 0.02, 0.01])
    return {"theorem3_h": h, "theorem3_times": np.array([0.1, 0.2]), "theorem3_reference_h": 0.00125,
            "theorem3_label": "|x|^3/3 on rho2", "theorem3_distances": 0.3 * h, "theorem3_reference_gap": 0.003 * h[-1]}


def theorem3(atomic, rough):
    return v.theorem3_claims({**rough, **atomic}, quiet(), NONAFFINE, RULES)


def test_theorem3_atomic_claims_hold_on_the_quick_run_and_fail_with_twice_the_velocity(rough):
    right = theorem3(theorem3_atomic(quick("theorem3_atomic")), rough)
    assert status(right, "thm3.atomic_order_w1") == "pass" and status(right, "thm3.atomic_order_sharp") == "pass"
    assert status(right, "thm3.atomic_time_share") == "pass"
    wrong = theorem3(theorem3_atomic(quick("theorem3_atomic"), run=doubled), rough)
    assert status(wrong, "thm3.atomic_order_w1") == "fail" and status(wrong, "thm3.atomic_order_sharp") == "fail"


def test_theorem3_atomic_order_of_a_finer_grid_is_not_the_sharp_order(rough):
    wrong = theorem3(theorem3_atomic(quick("theorem3_atomic"), run=finer_grid), rough)
    assert status(wrong, "thm3.atomic_order_w1") == "pass" and status(wrong, "thm3.atomic_order_sharp") == "fail"


def theorem4(section):
    data = theorem4_differences(section, QUICK["nonaffine"]["grid_points"])
    return v.theorem4_claims(data, quiet(), {**NONAFFINE, "theorem4": section}, RULES)


def test_theorem4_holds_on_smooth_data_and_fails_in_linf_across_the_jump_of_the_indicator():
    """Data (6.2) break the theorem's rho^0 in W^{2,p}: the jump keeps the Linf distances from falling."""
    right = theorem4(quick("theorem4"))
    assert all(status(right, f"thm4.order_{norm}_{weights}") == "pass"
               for norm in ("l1", "linf") for weights in ("cell", "biorthogonal"))
    wrong = theorem4({**quick("theorem4"), "initial": "rho2"})
    assert status(wrong, "thm4.order_linf_cell") == "fail" and status(wrong, "thm4.order_linf_biorthogonal") == "fail"


def widened(initial, w, h, dt, t, **kwargs):
    """A run whose final widths are off by 0.02 dt / h^2 (relative) at every other particle: a time error growing
    like dt/h^2, beyond Theorem 1, as an integrator whose per-step errors differ from particle to particle leaves
    (the reconstruction (2.27) is no longer a partition of unity: a ripple of that relative size)."""
    sim = simulate(initial, w, h, dt, t, **kwargs)
    widths = sim.widths.copy()
    widths[-1, ::2] *= 1.0 + 0.02 * dt / h**2
    return replace(sim, widths=widths)


def test_theorem1_dt_over_h_holds_on_the_quick_run_and_fails_on_a_dt_over_h_squared_time_error():
    section = quick("theorem1")
    grid = QUICK["nonaffine"]["grid_points"]
    assert status(v.theorem1_claims(theorem1_time_error(section, grid), quiet()), "thm1.dt_over_h") == "pass"
    wrong = v.theorem1_claims(theorem1_time_error(section, grid, run=widened), quiet())
    assert status(wrong, "thm1.dt_over_h") == "fail"


@pytest.fixture(scope="module")
def fig6_runs():
    """Figure 6's b = 1.5 and b = 2.5 runs at the quick run's sizes, measured as rows_data.py measures them."""
    cfg = {**CONFIG["fig6"], **QUICK["fig6"]}
    out = {}
    for b in (1.5, 2.5):
        dt = 20.0 / cfg["steps"]
        sim = simulate(cfg["initial"], potential("attractive_repulsive", a=cfg["a"], b=b), cfg["h"], dt,
                       cfg["t_long"], record_every=1)
        widths, masses = concentration_series(sim, CONCENTRATION["fraction"], CONCENTRATION["radius"])
        profile_times, changes = profile_changes(sim, CONCENTRATION["window"])
        out[b] = {"times": sim.times, "widths": widths, "masses": masses, "profile_times": profile_times,
                  "changes": changes}
    return out


def fig6(runs, b25, b15):
    """Figure 6's data with the run ``b25`` in the place of b = 2.5 and ``b15`` in that of b = 1.5."""
    data = {"labels": np.array(["|x|^3/3 - |x|^1.5/1.5", "|x|^3/3 - |x|^2.5/2.5"]), "edge_h": np.array([0.2, 0.1]),
            "edge_case": 0}
    for i, b in ((0, b15), (1, b25)):
        run = runs[b]
        data.update({f"case{i}_times": run["times"], f"case{i}_concentration_widths": run["widths"],
                     f"case{i}_concentration_masses": run["masses"], f"case{i}_profile_times": run["profile_times"],
                     f"case{i}_profile_changes": run["changes"], f"case{i}_centres": np.array([[-0.5, 0.5]]),
                     f"case{i}_weights": np.array([0.5, 0.5]), f"case{i}_edge_ratio": np.ones(run["times"].size)})
    data.update({"edge_peaks": np.ones((2, runs[b15]["times"].size)),
                 "edge_widths": np.array([runs[b15]["widths"]] * 2)})
    return data


def test_fig6_profile_of_b2_5_in_place_of_b1_5_is_not_steady(fig6_runs):
    claims = v.fig6_claims(fig6(fig6_runs, 2.5, 2.5), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b1.5_steady") == "fail"


def test_fig6_b1_5_run_in_place_of_b2_5_does_not_concentrate(fig6_runs):
    claims = v.fig6_claims(fig6(fig6_runs, 1.5, 1.5), quiet(), CONCENTRATION, RULES)
    assert status(claims, "fig6.b2.5_concentrates") == "fail"
    assert status(claims, "fig6.b2.5_concentrates_exponentially") == "fail"
