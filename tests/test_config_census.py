"""The census of the configuration (issue 46, item 5, :mod:`config_census`): every value of the configuration
replaced by bad values is refused before any job, naming its key; the test tries a fixed sample of them
(``python tests/config_census.py``: all of them)."""

import jsonschema
import pytest
import yaml
from config_census import FAILURES, bad_values, census, classify, leaves, validator

from particle_replication.configuration import check_configuration, overlay, repository_configuration

FULL = repository_configuration("full")
QUICK = repository_configuration("quick")
#: One bad value in this many (by hash) is tried by the test: about 200 of the 8,300.
EVERY = 40


def test_a_sample_of_the_bad_values_is_refused_naming_the_key():
    results = census(FULL, every=EVERY)
    assert len(results) > 100
    failures = [f"{outcome}: {key} = {bad!r}: {message}" for key, bad, outcome, message in results
                if outcome in FAILURES]
    assert not failures, "\n".join(failures)


def test_every_kind_of_leaf_gets_its_bad_values():
    kinds = {type(value) for _, value in leaves(FULL)}
    assert {int, float, str, bool} <= kinds
    assert "no-such-name" in bad_values("blob.fig1.data", "smooth20")
    assert "no-such-name" not in bad_values("output_root", ".")  # free text
    huge, tiny = bad_values("blob.fig1.h", 0.05)[-2:]
    assert huge > 1e6 and tiny < 1e-9


@pytest.mark.parametrize("key, value, named", [
    ("verdicts", "no-such-name", "verdicts = 'no-such-name': no such file"),
    ("verdicts_run", "no-such-name", "verdicts_run = 'no-such-name'"),
    ("robustness.spreads", "config/none.yaml", "robustness.spreads"),
    # reached at t_end, the refusal names the LTP keys whose product it is
    ("cross.aggregates.ltp.inverse_h.4", 10**11, "cross.aggregates.ltp.inverse_h = [20, 40, 80, 160, 100000000000]"),
])
def test_named_files_sections_and_products_are_refused_by_key(key, value, named):
    outcome, message = classify(FULL, key, value)
    assert outcome == "refused, named" and named in message, message


def test_less_work_is_told_from_more():
    assert classify(FULL, "blob.fig1.h", 0.05e9)[0] == "less work"
    assert classify(FULL, "blob.fig1.h", 0.05e-9)[0] == "refused, named"
    assert classify(FULL, "verdicts_run", "quick")[0] == "accepted"  # a good value is accepted (and not counted)


@pytest.mark.parametrize(
    "override, key",
    [
        ("sticky:\n  fig2:\n    field_particles: -1\n", "sticky.fig2.field_particles"),
        ("sticky:\n  fig2:\n    tmax: 3\n", "tmax"),
        ("sticky:\n  fig3:\n    case: heat_equation\n", "sticky.fig3.case"),
        ("sticky:\n  fig2:\n    t_max: .nan\n", "sticky.fig2.t_max"),
        ("blob:\n  fig5:\n    inverse_h: [5, 10, 10]\n", "blob.fig5.inverse_h"),
        ("sticky:\n  cost:\n    window: 9\n", "sticky.cost.window"),
        ("blob:\n  fig1:\n    zoom: [0.06, -0.06, 0.8, 1.0]\n", "blob.fig1.zoom"),
        ("ltp:\n  quadratic:\n    eps_scan: {h: 0.05, dt: 0.01, fine_dt: 1.0e-3, eps_min: 0.5, eps_max: 0.2, "
         "count: 5}\n", "ltp.quadratic.eps_scan.eps_min"),
        ("blob:\n  fig1:\n    density_times: [0.0, 0.4, 5.0]\n", "blob.fig1.density_times"),
        ("sticky:\n  cost:\n    hull_n: [100, 1000, 1000000000000]\n", "sticky.cost.hull_n"),
        ("sticky:\n  beyond:\n    repeats: 100000000\n", "sticky.beyond.repeats"),  # held to a solver's limit
    ],
)
def test_a_bad_overlay_of_the_quick_run_is_refused_naming_the_key(override, key):
    """A file given with --configfile over the quick run, through the workflow's two checks at its start (the schema,
    then check_configuration) in process; tests/test_pipeline.py starts Snakemake on one value of each kind."""
    config = overlay(QUICK, yaml.safe_load(override))
    error = jsonschema.exceptions.best_match(validator().iter_errors(config))
    if error is not None:
        message = f"{'.'.join(map(str, error.absolute_path))}: {error.message}"
    else:
        with pytest.raises((ValueError, TypeError)) as refused:
            check_configuration(config)
        message = str(refused.value)
    assert key in message, message
