"""The robustness run's pieces: the nudge of the initial data, the variants' environments, the spreads and
margins of the claims, the comparison of the variants' verdicts, and the recorded spreads themselves."""

import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from fuzzing import BAD_ARRAYS, safe_call

from particle_methods import perturbation
from particle_methods.blob.solver import setup_1d
from particle_methods.ltp import density_named
from particle_methods.ltp.initial import grid_particles
from particle_methods.ltp.shapes import shape_named
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_replication import claims as c
from particle_replication import robustness
from particle_replication.configuration import compared_run, overlay, repository_configuration
from particle_replication.paths import read_yaml

ROOT = Path(__file__).resolve().parents[1]
CONFIG = read_yaml(ROOT / "config" / "config.yaml")


# The nudge


def test_no_nudge_returns_the_data_unchanged():
    x = np.linspace(-1.0, 1.0, 11)
    assert perturbation.nudged(x) is x or np.array_equal(perturbation.nudged(x), x)


def test_a_nudge_moves_data_by_at_most_its_ulps_and_keeps_zeros_signs_and_order():
    x = np.concatenate([[-3.0, -1e-300, 0.0], np.linspace(0.1, 1.0, 1000)])
    with perturbation.nudge(4, seed=1):
        moved = perturbation.nudged(x, keep_sorted=True)
    assert not np.array_equal(moved, x)
    assert np.all(np.abs(moved - x) <= 5 * np.finfo(float).eps * np.abs(x))  # 4 ulps and the rounding of the product
    assert moved[2] == 0.0 and np.all(np.sign(moved) == np.sign(x)) and np.all(np.diff(moved) >= 0)
    assert perturbation.nudged(x) is x  # restored: no nudge outside the block


def test_a_nudge_is_repeatable_and_its_seed_matters():
    x = np.linspace(0.1, 1.0, 100)
    draws = []
    for seed in (1, 1, 2):
        with perturbation.nudge(4, seed):
            draws.append(perturbation.nudged(x))
    assert np.array_equal(draws[0], draws[1]) and not np.array_equal(draws[0], draws[2])


def test_ties_nudged_apart_stay_sorted():
    with perturbation.nudge(8, seed=5):
        moved = perturbation.nudged(np.repeat([-1.0, 1.0], 50), keep_sorted=True)
    assert np.all(np.diff(moved) >= 0) and np.unique(moved).size > 2


@pytest.mark.parametrize("make", [
    lambda: setup_1d("smooth20", "newtonian_attractive", 0.05)[0],                            # blob positions
    lambda: grid_particles(density_named("rho2"), 0.05, shape_named("b3"))[1],                # LTP weights
    lambda: psystem_initial_configuration("rarefaction", 0.1, 50),                            # MSPD positions (1.9)
], ids=["blob", "ltp", "sticky"])
def test_the_constructors_of_initial_data_apply_the_nudge(make):
    plain = make()
    with perturbation.nudge(4, seed=3):
        moved = make()
    assert moved.shape == plain.shape and not np.array_equal(moved, plain)
    np.testing.assert_allclose(moved, plain, rtol=8 * np.finfo(float).eps, atol=0.0)


@pytest.mark.parametrize("bad, error", [(-1, ValueError), (perturbation.MAX_ULPS + 1, ValueError), (1.5, TypeError)])
def test_a_bad_nudge_is_refused_naming_it(bad, error):
    with pytest.raises(error, match="ulps"):
        perturbation.set_nudge(bad)


@pytest.mark.parametrize("bad", BAD_ARRAYS)
def test_nudged_refuses_what_is_no_array_of_finite_reals(bad):
    """Finite results or a ValueError/TypeError naming the values, nudged or not (tests/fuzzing.py)."""
    for ulps in (0, 4):
        with perturbation.nudge(ulps, seed=1):
            result = safe_call(perturbation.nudged, bad)
        assert result is None or np.all(np.isfinite(result))


# The variants


def test_numpy_features_the_installed_numpy_does_not_dispatch_are_dropped():
    environment = robustness.variant_environment({"env": {"NPY_DISABLE_CPU_FEATURES": "NOT_A_FEATURE X86_V4"}}, {})
    kept = environment["NPY_DISABLE_CPU_FEATURES"].split()
    assert "NOT_A_FEATURE" not in kept and set(kept) <= set(robustness.numpy_dispatch())


def test_a_variant_changes_only_its_nudge_of_the_configuration():
    variant = robustness.variant_configuration(CONFIG, {"nudge": {"ulps": 4, "seed": 2}})
    assert variant["nudge"] == {"ulps": 4, "seed": 2}
    assert compared_run(variant) == ("full", [])  # still the full run: its verdicts apply
    assert robustness.variant_configuration(CONFIG, {"load": True})["nudge"] == {"ulps": 0, "seed": 0}


def test_every_configured_variant_changes_something_a_machine_could():
    for name, variant in CONFIG["robustness"]["variants"].items():
        assert set(variant) <= {"env", "nudge", "load"} and variant, name


def test_a_variants_environment_is_exported_for_a_shell(tmp_path):
    """The export lines a shell evaluates to run the tests under a variant: its variables, quoted, in a shell that
    sees them as the variant's run does; unknown variants refused naming the variants there are."""
    import subprocess

    lines = robustness.environment_exports("combined", ROOT / "config" / "config.yaml")
    expected = robustness.variant_environment(CONFIG["robustness"]["variants"]["combined"], {})
    script = tmp_path / "show.sh"
    script.write_text(lines + "\n" + "".join(f'printf "%s\\n" "${key}"\n' for key in expected))
    shown = subprocess.run(["sh", str(script)], capture_output=True, text=True, check=True).stdout.splitlines()
    assert shown == list(expected.values()) and expected["NUMBA_NUM_THREADS"] == "1"
    assert robustness.environment_exports("nudged-1", ROOT / "config" / "config.yaml") == ""  # a nudge is no variable
    with pytest.raises(ValueError, match="variant must be one of threads-1"):
        robustness.environment_exports("two-threads", ROOT / "config" / "config.yaml")


# The configuration whose verdicts apply


def test_a_users_overlay_is_compared_with_nothing_and_says_where_it_differs():
    quick = repository_configuration("quick")
    assert compared_run(quick) == ("quick", [])
    mine = overlay(quick, {"sticky": {"fig2": {"trajectory_particles": 3}}, "output_root": "mine"})
    assert compared_run(mine) == (None, ["sticky.fig2.trajectory_particles"])


# Spreads, margins, comparison


def made(value, status="pass", threshold=1.0, kind="paper", name="demo.x"):
    return c.at_least(name, "demo", "1", "a value", threshold, value, kind=kind, source="test") if status != "abstain" \
        else c.abstain(c.at_least(name, "demo", "1", "t", threshold, value, kind="check", source="test"), "loaded")


def test_the_signed_distance_is_positive_when_passing_and_minus_inf_unmeasured():
    assert float(made(1.5).distance) == 0.5 and float(made(0.5).distance) == -0.5
    unmeasured = made(math.nan)
    assert unmeasured.status == "fail" and float(unmeasured.distance) == -math.inf
    assert unmeasured.measured == "not measured"
    band = c.between("demo.b", "demo", "1", "t", 0.8, 1.2, 1.15, kind="paper", source="s")
    assert float(band.distance) == pytest.approx(0.05)


def test_spreads_and_margins_over_variants():
    tables = {"run": [made(1.5)], "a": [made(1.6)], "b": [made(1.4)]}
    spread = robustness.spreads(tables)["demo.x"]
    assert spread.distance == pytest.approx(0.2) and spread.margin == pytest.approx(0.4 / 0.2)
    exact = robustness.spreads({"run": [made(1.5)], "a": [made(1.5)]})["demo.x"]
    assert exact.distance == 0.0 and exact.margin == math.inf
    flipped = robustness.spreads({"run": [made(1.5)], "a": [made(math.nan)]})["demo.x"]
    assert flipped.distance == math.inf and flipped.margin == 0.0
    never = robustness.spreads({"run": [made(math.nan)], "a": [made(math.nan)]})["demo.x"]
    assert never.distance == 0.0 and never.margin == math.inf  # not measured in every variant: the same verdict


def test_an_abstention_is_no_difference_but_a_changed_verdict_is():
    baseline = [made(1.5, kind="check")]
    assert robustness.compare(baseline, {"loaded": [made(0.5, status="abstain")]}) == []
    assert robustness.compare(baseline, {"a": [made(0.5, kind="check")]})[0].startswith("a: CHANGED demo.x")
    assert robustness.compare(baseline, {"a": []}) == ["a: MISSING demo.x"]


def test_the_report_names_every_change_of_a_variant_and_its_moved_verdicts():
    """A variant that sets variables and nudges the data (the combined one) is described by both; a moved verdict
    is counted in its variant's row and listed, and a claim within the margin is listed as fragile."""
    baseline = [made(1.5, kind="check")]
    variants = {"combined": [made(0.5, kind="check")], "nudged-1": [made(1.5, kind="check")]}
    environments = {"combined": {"env": {"NUMBA_NUM_THREADS": "1"}, "nudge": {"ulps": 4, "seed": 3}},
                    "nudged-1": {"nudge": {"ulps": 4, "seed": 1}}}
    problems = robustness.compare(baseline, variants)
    text = robustness.report(variants, environments, problems, robustness.spreads({"run": baseline, **variants}),
                             10.0, "quick")
    rows = {line.split(" | ")[0].lstrip("| "): line for line in text.splitlines() if line.startswith("| ")}
    assert "NUMBA_NUM_THREADS=1; initial data nudged by up to 4 ulps (seed 3)" in rows["combined"]
    assert rows["combined"].endswith("| 1 | 0 |") and rows["nudged-1"].endswith("| 0 | 0 |")
    assert "1 verdicts differ" in text and "- combined: CHANGED demo.x" in text and "| `demo.x` | check |" in text


def test_margins_in_the_table_and_the_fragile_list():
    spreads = {"demo.x": c.Spread(0.1, 0.1)}
    near, far = made(1.5), made(3.0, name="demo.y")
    rows = c.with_margins([near, far], {**spreads, "demo.y": c.Spread(0.0, 0.0)})
    assert [row.margin for row in rows] == ["5", "exact"]
    assert [row.id for row in c.fragile(rows, 10.0)] == ["demo.x"]
    assert c.with_margins([near], {})[0].margin == "-"


def test_a_claim_can_only_abstain_if_it_is_a_check():
    with pytest.raises(ValueError, match="only a check may abstain"):
        c.abstain(made(1.5), "loaded")


def test_recorded_spreads_replace_only_their_runs_section(tmp_path):
    target = tmp_path / "spreads.yaml"
    target.write_text(yaml.safe_dump({"full": {"demo.x": {"distance": 1.0, "value": 1.0, "margin": 2.0,
                                                           "kind": "paper"}}}))
    source = tmp_path / "new.yaml"
    robustness.write_spreads(source, "quick", {"demo.x": c.Spread(0.5, 0.5, 3.0)})
    robustness.record(source, target)
    assert c.read_spreads(target, "full")["demo.x"].margin == 2.0 and c.read_spreads(target, "quick")["demo.x"] == \
        c.Spread(0.5, 0.5, 3.0)


def test_no_paper_or_derived_claim_is_fragile():
    """The recorded spreads of the full and the quick run: every paper and derived claim at least margin_min
    spreads from its threshold in every variant (checks may be fragile: they are listed, not tests of the
    papers)."""
    margin_min = CONFIG["robustness"]["margin_min"]
    for run in ("full", "quick"):
        spreads = c.read_spreads(ROOT / "config" / "spreads.yaml", run)
        assert spreads, f"no spreads recorded for the {run} run"
        shaky = {i: s.margin for i, s in spreads.items() if s.margin < margin_min and s.kind != "check"}
        assert not shaky, f"fragile paper or derived claims in the {run} run: {shaky}"
