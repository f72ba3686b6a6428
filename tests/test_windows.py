"""Claims decided on a fitted slope state on how many windows of resolutions their verdict holds (issue 28,
item 7): the windows come with the slope, survive negation and differences, and are decided by the claim's own
rule."""

import numpy as np
import pytest

from particle_replication import claims as c
from particle_replication import rates
from particle_replication.report import write_snippets

H = np.array([1 / 10, 1 / 20, 1 / 40, 1 / 80, 1 / 160, 1 / 320])


def recorded(errors, window=3):
    return rates.Recorder(log=lambda line: None).add(rates.order("demo.rate", "h", H, errors, window))


def test_window_values_run_over_every_window_of_the_deciding_length():
    rate = rates.order("demo.rate", "h", H, H**2 * (1 + H), 3)
    values = rate.window_values()
    assert len(values) == H.size - 3 + 1
    assert values[-1] == rate.slope
    assert values == tuple(rate.slopes[i][i + 2] for i in range(4))


def test_a_slope_carries_its_windows_through_negation_and_differences():
    a, b = recorded(H**2), recorded(H**3)
    assert isinstance(a, rates.Slope) and len(a.windows) == 4
    assert (-a).windows == tuple(-value for value in a.windows)
    difference = a - b
    assert float(difference) == pytest.approx(-1.0) and difference.windows == pytest.approx((-1.0,) * 4)
    other = rates.Recorder(log=lambda line: None).add(rates.order("demo.rate", "h", H[:5], H[:5] ** 2, 3))
    assert not isinstance(a - other, rates.Slope)  # fitted on other resolutions: no window-by-window difference
    assert not isinstance(a + 1.0, rates.Slope) and not isinstance(1.0 - a, rates.Slope)


def claimed(measured, lower=1.8, upper=2.2):
    return c.claim("demo", c.between, "rate", "paper", "somewhere", "1", "an order about 2", lower, upper, measured)


def test_a_verdict_that_holds_on_the_finest_window_only_is_counted_as_window_dependent():
    # order 1 on the coarse steps, 2 on the fine ones: the deciding (finest) window passes, the coarsest fails
    errors = np.where(H > 0.03, 0.05 * H, H**2)
    slope = recorded(errors)
    made = claimed(slope)
    assert made.status == "pass"
    held, total = c.window_counts(made)
    assert total == 4 and 1 <= held < total
    assert c.window_dependent([made]) == [made]


def test_a_verdict_the_same_on_every_window_is_not_window_dependent():
    made = claimed(recorded(3.0 * H**2))
    assert made.windows == "4 of 4" and c.window_dependent([made]) == []
    failing = claimed(recorded(3.0 * H**1.5))  # fails on every window: the same verdict, 4 of 4
    assert failing.status == "fail" and failing.windows == "4 of 4"


def test_a_plain_number_has_no_windows():
    assert claimed(2.0).windows == "" and c.window_counts(claimed(2.0)) is None


def test_claims_refuse_malformed_window_counts_and_unknown_rules():
    with pytest.raises(ValueError, match="k of K"):
        c.Claim("demo.x", "demo", "paper", "s", "1", "t", "1", "1", "+-1", "pass", "1.0", "5 of 4")
    with pytest.raises(c.ParameterTypeError, match="compare"):
        c.claim("demo", lambda *a, **k: None, "rate", "paper", "somewhere", "1", "text", 1.0)


def test_the_report_lists_the_window_dependent_verdicts(tmp_path):
    rows = [claimed(recorded(np.where(H > 0.03, 0.05 * H, H**2))), claimed(recorded(3.0 * H**2))]
    rows[1] = c.Claim(**{**rows[1].__dict__, "id": "demo.steady"})
    c.write_claims(tmp_path / "claims.csv", rows)
    assert [claim.windows for claim in c.read_claims(tmp_path / "claims.csv")] == [rows[0].windows, "4 of 4"]
    rates.write_rates(tmp_path / "rates.json", [])
    (tmp_path / "versions.md").write_text("Commit: abc\n")
    write_snippets(tmp_path / "claims.csv", tmp_path / "rates.json", tmp_path / "versions.md",
                   {"x": 1.0, "robustness": {"margin_min": 10}},
                   tmp_path / "out", {}, [])
    table = (tmp_path / "out" / "windows.tex").read_text()
    assert "demo.\\allowbreak{}rate" in table and "steady" not in table
    assert "windows.dependent\\endcsname{1}" in (tmp_path / "out" / "summary.tex").read_text()


def test_a_bound_that_is_a_fitted_slope_moves_window_by_window():
    # m6 above m4 on the finest window only: the bound (the m4 slope) is taken on each window with the measure
    m4 = recorded(H**2)
    m6 = recorded(np.where(H > 0.03, 0.01 * H, H**2.5))
    made = c.claim("demo", c.at_least, "above", "derived", "somewhere", "1", "m6 above m4", m4, m6)
    assert made.status == "pass"
    held, total = c.window_counts(made)
    assert held < total


def test_the_worst_of_several_slopes_is_chosen_window_by_window():
    steady, late = recorded(H**2), recorded(np.where(H > 0.03, 0.05 * H, H**2))
    lowest = rates.chosen([steady, late], min)
    assert float(lowest) == min(float(steady), float(late))
    assert lowest.windows == tuple(min(a, b) for a, b in zip(steady.windows, late.windows))
    assert claimed(lowest).windows == claimed(late).windows  # the slow start decides the coarse windows
    scaled = 2.0 * steady
    assert scaled.windows == tuple(2.0 * value for value in steady.windows)
    assert not isinstance(rates.chosen([steady, float(late)], min), rates.Slope)  # a plain number among them
    with pytest.raises(c.ParameterTypeError, match="pick"):
        rates.chosen([steady], "min")
