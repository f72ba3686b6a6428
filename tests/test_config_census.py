"""The census of the configuration (issue 46, item 5, :mod:`config_census`): every value of the configuration
replaced by bad values is refused before any job, naming its key; the test tries a fixed sample of them
(``python tests/config_census.py``: all of them)."""

import pytest
from config_census import FAILURES, bad_values, census, classify, leaves

from particle_replication.configuration import repository_configuration

FULL = repository_configuration("full")
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
