"""LaTeX snippets of the report: values typeset from the claims table and the configuration."""

import re
from pathlib import Path

import pytest
import yaml

from particle_replication.claims import Change, Claim, Expected, read_changes, read_verdicts, write_claims
from particle_replication.rates import order, write_rates
from particle_replication.report import cell, number, tex, write_snippets


@pytest.mark.parametrize("value, expected", [
    (-0.693147, r"\ensuremath{-0.6931}"),
    (4.21516e-10, r"\ensuremath{4.215\times 10^{-10}}"),
    (1e-9, r"\ensuremath{10^{-9}}"),
    (262144, r"\ensuremath{262144}"),
    (0.25, r"\ensuremath{0.25}"),
])
def test_numbers_have_four_significant_digits_and_integers_stay_exact(value, expected):
    assert number(value) == expected


@pytest.mark.parametrize("text, expected", [
    ("<= 1e-09", r"\ensuremath{\le} \ensuremath{10^{-9}}"),
    ("+-0.1", r"\ensuremath{\pm}\ensuremath{0.1}"),
    ("rel 0.001", r"rel \ensuremath{0.001}"),
    ("w+ >= w-", r"w+ \ensuremath{\ge} w-"),
    ("t/(4n)", "t/(4n)"),
    ("smooth20", "smooth20"),
    ("newtonian_attractive", r"newtonian\_attractive"),
    ("-0.06, 0.06", r"\ensuremath{-0.06}, \ensuremath{0.06}"),
])
def test_cells_typeset_numbers_and_comparisons_and_escape_the_rest(text, expected):
    assert cell(text) == expected


def test_special_characters_are_escaped():
    assert tex("50% of a_b & {c} ~ #1 $x$ ^") == (
        r"50\% of a\_b \& \{c\} \textasciitilde{} \#1 \$x\$ \textasciicircum{}")


@pytest.fixture
def snippets(tmp_path):
    claims = [
        Claim("demo.fig1.order", "demo", "paper", "Theorem 1", "1", "order of the scheme", "2", "1.98765", "+-0.1",
              "pass"),
        Claim("demo.fig2.peaks", "demo", "paper", "Figure 2", "2", "two peaks", "2", "3", "+-0", "fail"),
        Claim("other.mass", "other", "check", "conservation", "3", "mass conserved", "0", "1.5e-15", "<= 1e-12",
              "pass"),
    ]
    write_claims(tmp_path / "claims.csv", claims)
    rate = order("demo.fig1.order", "h", [0.1, 0.05, 0.025], [1e-2, 2.6e-3, 6.4e-4], window=2, label="t = 1")
    write_rates(tmp_path / "rates.json", [rate])
    (tmp_path / "versions.md").write_text("Commit: 0123abc\n\nCommit date: 2026-11-23T17:37:41+00:00\n\n"
                                          "Modified since the commit: no\n\nCPU: AMD EPYC (AVX-512, 2 cores)\n\n"
                                          "| package | version |\n|---|---|\n| python | 3.11.7 |\n| numpy | 2.0 |\n")
    config = {"demo": {"fig1": {"h": [0.1, 0.05], "kernel": "cubic_b"}, "cases": [{"t": 2.0}]},
              "robustness": {"margin_min": 10}}
    expected = {"demo.fig1.order": Expected("pass"), "other.mass": Expected("pass"),
                "demo.fig2.peaks": Expected("fail", "three, not two", "contradicts")}
    changes = [Change(("demo.fig2.peaks",), "3 against 2", "peaks counted above 1e-3", "noise made a third")]
    write_snippets(tmp_path / "claims.csv", tmp_path / "rates.json", tmp_path / "versions.md", config,
                   tmp_path / "out", expected, changes)
    return {path.stem: path.read_text() for path in (tmp_path / "out").iterdir()}


def definitions(text):
    return dict(re.findall(r"\\csname (\S+)\\endcsname\{(.*)\}\n", text))


def test_every_claim_value_and_parameter_gets_a_macro(snippets):
    measured = definitions(snippets["measured"])
    assert measured["measured@demo.fig1.order"] == r"\ensuremath{1.988}"
    assert measured["published@other.mass"] == r"\ensuremath{0}"
    assert measured["tolerance@other.mass"] == r"\ensuremath{\le} \ensuremath{10^{-12}}"
    assert measured["status@demo.fig2.peaks"] == "fail"
    parameters = definitions(snippets["parameters"])
    assert parameters == {"param@demo.fig1.h": r"\ensuremath{0.1}, \ensuremath{0.05}",
                          "param@demo.fig1.kernel": r"cubic\_b", "param@demo.cases.0.t": r"\ensuremath{2}",
                          "param@demo.cases.t": r"\ensuremath{2}",
                          "param@robustness.margin_min": r"\ensuremath{10}"}


def test_counts_tables_and_failures(snippets):
    counts = definitions(snippets["summary"])
    assert {key: counts[f"claimcount@{key}"] for key in ("demo.all", "demo.fail", "demo.pass", "other.all")} == {
        "demo.all": "2", "demo.fail": "1", "demo.pass": "1", "other.all": "1"}
    assert counts["claimcount@demo.paper.pass"] == "1" and counts["claimcount@demo.check.all"] == "0"
    assert counts["claimcount@all.paper.all"] == "2" and counts["claimcount@all.check.pass"] == "1"
    assert r"\textit{paper}: Theorem 1" in snippets["claims_demo"]
    body = snippets["claims_demo"].split(r"\endlastfoot")[1]
    assert body.count(r" \\") == 2 and "other.mass" not in body
    assert "demo.\\allowbreak{}fig2.\\allowbreak{}peaks" in snippets["failures"]
    assert "fig1" not in snippets["failures"].split(r"\endlastfoot")[1]
    assert "contradicts" in snippets["failures"] and "three, not two" in snippets["failures"]
    assert counts["claimcount@cause.contradicts"] == "1" and counts["claimcount@cause.defect"] == "0"
    assert "numpy & 2.0" in snippets["versions"]
    assert snippets["configuration"].count(r"\par") == 4
    assert snippets["fragile"].startswith("No spreads are recorded")  # the demo claims have no margins


def test_the_report_lists_each_papers_own_claims_one_line_each(snippets):
    body = snippets["paperclaims_demo"].split(r"\endlastfoot")[1]
    assert body.count(r" \\") == 2
    assert "fig1.\\allowbreak{}order} & Theorem 1 & \\ensuremath{2} & \\ensuremath{1.988} & pass & -" in body
    assert r"\textbf{fail}" in body and "two peaks" not in body   # the statement is in the supplement
    assert snippets["paperclaims_other"] == "This study states no claim of a paper.\n"   # checks only


def test_rate_tables_mark_the_deciding_window(snippets):
    table = snippets["rates"]
    assert "demo.\\allowbreak{}fig1.\\allowbreak{}order} (t = 1)" in table
    assert table.count(r"\textbf{") == 1 and r"\textbf{2.022}" in table  # log2(2.6e-3 / 6.4e-4)
    assert table.count(r" \\") == 2 + 1  # header and two rows of first points


def test_the_title_page_names_the_commit(snippets):
    assert snippets["commit"] == ("\\newcommand{\\builtfrom}{Built from commit \\texttt{0123abc} of 2026-11-23}\n"
                                  "\\newcommand{\\builton}{run on AMD EPYC (AVX-512, 2 cores)}\n")


def test_versions_name_the_commit_or_say_unknown_outside_a_clone(tmp_path, monkeypatch):
    from particle_replication import environment

    state = environment.commit()
    assert len(state["hash"]) == 40 and state["epoch"].isdigit() and state["modified"] in ("yes", "no")
    monkeypatch.setenv("PARTICLE_METHODS_SOURCE", str(tmp_path))
    assert environment.commit() == {"hash": "unknown", "date": "unknown", "epoch": "0", "modified": "unknown"}
    assert "Commit: unknown" in environment.markdown()


def test_the_cpu_is_read_back_from_the_versions_record():
    from particle_replication import environment

    assert environment.recorded_cpu(environment.markdown()) == environment.cpu()
    assert environment.recorded_cpu("# Software versions\n\nCommit: 0123abc\n") == "CPU not recorded"
    assert environment.recorded_cpu("CPU: \n") == "CPU not recorded"
    with pytest.raises(TypeError, match="versions"):
        environment.recorded_cpu(None)


def test_the_changes_after_failing_runs_are_listed_with_their_failing_values(snippets):
    body = snippets["changes"].split(r"\endlastfoot")[1]
    assert body.count(r" \\") == 1
    assert "demo.\\allowbreak{}fig2.\\allowbreak{}peaks" in body and "noise made a third" in body


def test_the_register_of_changes_refuses_unknown_claims_and_missing_fields(tmp_path):
    path = tmp_path / "changes.yaml"
    entry = {"claims": ["demo.fig2.peaks"], "failing": "3", "change": "a threshold", "why": "noise"}
    path.write_text(yaml.safe_dump({"changes": [entry]}))
    assert read_changes(path, {"demo.fig2.peaks"}) == [Change(("demo.fig2.peaks",), "3", "a threshold", "noise")]
    with pytest.raises(ValueError, match="do not exist"):
        read_changes(path, {"other.mass"})
    path.write_text(yaml.safe_dump({"changes": [{**entry, "why": ""}]}))
    with pytest.raises(ValueError, match="non-empty"):
        read_changes(path)
    path.write_text(yaml.safe_dump({"changes": [{"claims": ["demo.fig2.peaks"], "failing": "3"}]}))
    with pytest.raises(ValueError, match="keys"):
        read_changes(path)


def test_the_repository_register_names_only_claims_with_expected_verdicts():
    root = Path(__file__).resolve().parents[1]
    assert read_changes(root / "config" / "changes.yaml", read_verdicts(root / "config" / "verdicts.yaml"))
