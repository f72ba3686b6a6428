"""Shared helpers: order fitting, claims table, validation."""

import math

import numpy as np
import pytest

from particle_methods.convergence import fit_order, order_table, pairwise_orders
from particle_methods.validation import in_interval, integer_at_least, positive, sorted_array
from particle_replication import claims as c


def test_fit_order_recovers_a_power_law():
    h = np.array([0.1, 0.05, 0.025, 0.0125])
    errors = 3.0 * h**2.5
    assert fit_order(h, errors) == pytest.approx(2.5)
    np.testing.assert_allclose(pairwise_orders(h, errors), 2.5)
    table = order_table(h, errors)
    assert "2.500" in table and table.count("\n") == 4


def test_fit_order_rejects_bad_input():
    with pytest.raises(ValueError, match="positive"):
        fit_order([1.0, 2.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="same length"):
        fit_order([1.0, 2.0, 3.0], [1.0, 2.0])


K = {"kind": "paper", "source": "Figure 1"}


def test_claim_verdicts_turn_to_fail_on_a_wrong_outcome():
    assert c.close_to("x.a", "x", "1", "t", 1.0, 1.05, 0.1, **K).status == "pass"
    assert c.close_to("x.a", "x", "1", "t", 1.0, 1.2, 0.1, **K).status == "fail"
    assert c.close_to("x.a", "x", "1", "t", 1.0, float("nan"), 0.1, **K).status == "fail"
    assert c.relatively_close_to("x.a", "x", "1", "t", 2.0, 2.1, 0.1, **K).status == "pass"
    assert c.relatively_close_to("x.a", "x", "1", "t", 2.0, 2.3, 0.1, **K).status == "fail"
    assert c.at_most("x.a", "x", "1", "t", 1.0, 0.99, **K).status == "pass"
    assert c.at_most("x.a", "x", "1", "t", 1.0, 1.01, **K).status == "fail"
    assert c.at_least("x.a", "x", "1", "t", 1.0, 1.01, **K).status == "pass"
    assert c.at_least("x.a", "x", "1", "t", 1.0, 0.99, **K).status == "fail"
    assert c.between("x.a", "x", "1", "t", 0.25, 1.0, 0.5, **K).status == "pass"
    for wrong in (0.0, 1.5, float("inf"), float("nan")):
        assert c.between("x.a", "x", "1", "t", 0.25, 1.0, wrong, **K).status == "fail"
    with pytest.raises(ValueError, match="must start with the paper id"):
        c.close_to("y.a", "x", "1", "t", 1.0, 1.0, 0.1, **K)
    with pytest.raises(ValueError, match="kind"):
        c.close_to("x.a", "x", "1", "t", 1.0, 1.0, 0.1, kind="claim", source="Figure 1")
    with pytest.raises(ValueError, match="needs a source"):
        c.close_to("x.a", "x", "1", "t", 1.0, 1.0, 0.1, kind="check", source=" ")
    with pytest.raises(ValueError, match="lower"):
        c.between("x.a", "x", "1", "t", 1.0, 0.0, 0.5, **K)


def test_summary_counts_each_kind_apart():
    rows = [c.at_most("x.a", "x", "1", "t", 1.0, 0.5, **K), c.at_most("x.b", "x", "1", "t", 1.0, 2.0, **K),
            c.at_most("x.c", "x", "1", "t", 1.0, 0.5, kind="check", source="ours")]
    assert c.counts(rows) == {"paper": (1, 2), "check": (1, 1)}
    assert c.summary_line(rows) == "Paper claims reproduced: 1 of 2. Also checks passing: 1 of 1."
    # a part without paper claims (cross) says so rather than '0 of 0'
    assert c.summary_line(rows[2:]) == "No claim of a paper. Checks passing: 1 of 1."


@pytest.fixture
def tables(tmp_path):
    good = [c.close_to("x.a", "x", "1", "slope, with a | pipe", -1.0, -0.98, 0.05, **K)]
    bad = [c.at_most("y.b", "y", "2", "bound", 1.0, 2.0, kind="derived", source="our (3.1)")]
    c.write_claims(tmp_path / "x.csv", good)
    c.write_claims(tmp_path / "y.csv", bad)
    assert c.read_claims(tmp_path / "x.csv") == good
    c.merge([tmp_path / "x.csv", tmp_path / "y.csv"], tmp_path / "all.csv", tmp_path / "all.md")
    return tmp_path


def test_claims_round_trip_and_merge(tables):
    assert [claim.id for claim in c.read_claims(tables / "all.csv")] == ["x.a", "y.b"]
    markdown = (tables / "all.md").read_text()
    assert "Paper claims reproduced: 1 of 1. Also derived claims passing: 0 of 1." in markdown
    assert "\\|" in markdown and "| paper | Figure 1 |" in markdown
    with pytest.raises(ValueError, match="duplicate"):
        c.write_claims(tables / "z.csv", c.read_claims(tables / "x.csv") * 2)


def write_expected(path, text):
    path.write_text(text)
    return path


def test_verify_passes_when_every_verdict_is_as_expected(tables, capsys):
    expected = write_expected(tables / "v.yaml", "pass: [x.a]\nfail:\n  y.b: {cause: our-inference, reason: loose}\n")
    assert c.main(["verify", str(tables / "all.csv"), "--expected", str(expected)]) == 0
    out = capsys.readouterr().out
    assert "pass x.a (Figure 1): published -1, measured -0.98" in out and "y.b" not in out.split("\n")[1]
    assert "expected: 1 failures: 0 contradict the paper, 0 pre-asymptotic, 1 our inference was wrong" in out


def test_the_markdown_counts_failures_by_cause(tables):
    expected = write_expected(tables / "v.yaml", "pass: [x.a]\nfail:\n  y.b: {cause: pre-asymptotic, reason: coarse}\n")
    claims = c.read_claims(tables / "all.csv")
    text = c.failures_by_cause(claims, c.read_verdicts(expected))
    assert "1 failures: 0 contradict the paper, 1 pre-asymptotic" in text and "| `y.b` |" in text
    text = c.failures_by_cause(claims, c.read_verdicts(write_expected(tables / "w.yaml", "pass: [x.a, y.b]\n")))
    assert "1 not expected" in text and "| unexpected |" in text


@pytest.mark.parametrize("text, message", [
    ("pass: [x.a, y.b]\n", "CHANGED y.b: expected pass, got fail"),  # a verdict changed
    ("pass: []\nfail: {x.a: {cause: contradicts, reason: once failed}, y.b: {cause: defect, reason: loose}}\n",
     "CHANGED x.a: expected fail (once failed), got pass"),
    ("pass: [x.a]\nfail: {y.b: {cause: defect, reason: loose}, z.c: {cause: contradicts, reason: gone}}\n",
     "MISSING z.c"),  # an expected claim is missing
    ("pass: [x.a]\n", "CHANGED y.b: expected pass (not listed in"),  # a claim not listed is expected to pass
    ("fail: {y.b: {cause: defect, reason: loose}}\nquick: {fail: {x.a: {cause: defect, reason: coarse}}}\n",
     "CHANGED x.a: expected fail (coarse), got pass"),  # the quick run may expect an unlisted claim to fail
])
def test_verify_fails_on_a_changed_missing_or_unexpected_verdict(tables, capsys, text, message):
    expected = write_expected(tables / "v.yaml", text)
    assert c.verify(tables / "all.csv", expected, "quick" if "quick" in text else "full") == 1
    assert message in capsys.readouterr().out


@pytest.mark.parametrize("text, message", [
    ("pass: [x.a]\nfail: {x.a: {cause: defect, reason: twice}}\n", "listed twice"),
    ("pass: [x.a, x.a]\n", "listed twice"),
    ("fail: {y.b: {cause: defect, reason: ''}}\n", "one-line reason"),
    ("fail: {y.b: a reason without its cause}\n", "needs a cause and a one-line reason"),
    ("fail: {y.b: {cause: our-instrument, reason: coarse}}\n", "must be one of"),
    ("passing: [x.a]\n", "need the keys"),
    ("pass: x.a\n", "must be a list"),
])
def test_expected_verdicts_file_is_checked(tmp_path, text, message):
    with pytest.raises(ValueError, match=message):
        c.read_verdicts(write_expected(tmp_path / "v.yaml", text))


def test_the_quick_section_holds_only_differences_from_the_full_run():
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "config" / "verdicts.yaml"
    full, quick = c.read_verdicts(path), c.read_verdicts(path, "quick")
    assert set(full) <= set(quick) and quick != full


@pytest.mark.parametrize("section, message", [
    ("quick: {pass: [x.b]}\n", "keep only differences"),  # not listed: expected to pass in the full run
    ("quick: {pass: [x.a]}\n", "keep only differences"),
    ("quick: {fail: {y.b: {cause: defect, reason: ''}}}\n", "one-line reason"),
    ("quick: [x.a]\n", "a section per run"),
])
def test_a_run_section_is_checked(tmp_path, section, message):
    path = write_expected(tmp_path / "v.yaml", "pass: [x.a]\nfail: {y.b: {cause: defect, reason: r}}\n" + section)
    with pytest.raises(ValueError, match=message):
        c.read_verdicts(path, "quick")


def test_a_run_section_overrides_the_full_verdicts(tmp_path):
    path = write_expected(tmp_path / "v.yaml", "pass: [x.a]\nfail: {y.b: {cause: defect, reason: coarse}}\n"
                          "quick: {fail: {x.a: {cause: pre-asymptotic, reason: coarse}}}\n")
    assert c.read_verdicts(path, "quick") == {"x.a": ("fail", "coarse", "pre-asymptotic"),
                                              "y.b": ("fail", "coarse", "defect")}
    with pytest.raises(ValueError, match="no section for the run 'ci'"):
        c.read_verdicts(path, "ci")


def test_validation_messages_name_the_parameter():
    with pytest.raises(ValueError, match="h must be positive"):
        positive("h", 0.0)
    with pytest.raises(ValueError, match="dt must be a real number"):
        positive("dt", "0.1")
    with pytest.raises(ValueError, match="n must be an integer"):
        integer_at_least("n", 2.0, 1)
    with pytest.raises(ValueError, match="positions must be sorted"):
        sorted_array("positions", [0.0, 2.0, 1.0])
    with pytest.raises(ValueError, match="w must lie in"):
        in_interval("w", [0.5, 1.5], 0.0, 1.0)


def test_module_dependencies_follow_imports_transitively():
    from pathlib import Path

    from particle_replication.workflow import module_dependencies

    root = Path(__file__).resolve().parents[1]
    packages = [root / "src" / "particle_methods", root / "src" / "particle_replication"]
    found = {Path(p).relative_to(root / "src").as_posix() for p in
             module_dependencies(root / "scripts" / "sticky" / "scalar_data.py", packages)}
    # Direct imports of both packages, relative imports inside them (spd -> validation -> jit; workflow ->
    # threads across the packages), nothing unused.
    assert {"particle_methods/norms.py", "particle_methods/sticky/cases.py", "particle_methods/sticky/spd.py",
            "particle_methods/sticky/exact.py", "particle_methods/validation.py", "particle_methods/jit.py",
            "particle_replication/workflow.py", "particle_methods/threads.py"} <= found
    assert not {"particle_methods/sticky/mspd.py", "particle_methods/systems.py",
                "particle_methods/finite_volume/psystem.py", "particle_replication/plotting.py",
                "particle_methods/sticky/__init__.py", "particle_methods/finite_volume/__init__.py"} & found
    # One package alone: the other's modules are not followed.
    alone = module_dependencies(root / "scripts" / "sticky" / "scalar_data.py", packages[0])
    assert alone and not any("particle_replication" in path for path in alone)
    with pytest.raises(ValueError, match="package_dirs"):
        module_dependencies(root / "scripts" / "sticky" / "scalar_data.py", [packages[0], root / "scripts" / "sticky"])


def _scan_tree(root):
    """A checkout of two packages side by side and a script importing from both."""
    for name, text in {"src/alpha/__init__.py": "", "src/alpha/core.py": "from . import helpers\n",
                       "src/alpha/helpers.py": "", "src/beta/__init__.py": "", "src/beta/use.py": "import alpha.core\n",
                       "scripts/job.py": "from beta import use\n"}.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)
    return [root / "src" / "alpha", root / "src" / "beta"]


def _new_process(workflow):
    """What a new Snakemake start sees: no scan of this process kept, the record on disk read anew."""
    workflow._scan_cache.cache_clear()


def test_the_import_scan_is_kept_between_starts_and_redone_where_a_file_changed(tmp_path, monkeypatch):
    """A Snakemake start reads the imports found by the last one (SCAN_CACHE) and parses only the files changed
    since; a new module file, or a record that cannot be read, makes it scan anew, with the same result."""
    import ast
    import os

    from particle_replication import workflow

    packages = _scan_tree(tmp_path)
    script = tmp_path / "scripts" / "job.py"
    expected = [str((tmp_path / f).resolve()) for f in ("src/alpha/core.py", "src/alpha/helpers.py",
                                                         "src/beta/use.py")]
    assert workflow.module_dependencies(script, packages) == expected
    workflow._scan_cache(tuple(p.resolve() for p in packages)).save()
    assert (tmp_path / workflow.SCAN_CACHE).is_file()

    _new_process(workflow)
    parse = ast.parse
    monkeypatch.setattr(ast, "parse", lambda *a, **k: pytest.fail("parsed a file the record holds"))
    assert workflow.module_dependencies(script, packages) == expected

    # A changed file (time and size) is parsed again, and only it.
    parsed = []
    monkeypatch.setattr(ast, "parse", lambda source, filename, **k: parsed.append(filename) or parse(source, filename))
    _new_process(workflow)
    script.write_text("from beta import use\nimport alpha.helpers\n")
    os.utime(script, ns=(1, 1))
    assert workflow.module_dependencies(script, packages) == expected
    assert parsed == [str(script.resolve())]
    (tmp_path / "src" / "alpha" / "helpers.py").write_text("from . import extra\n")
    os.utime(tmp_path / "src" / "alpha" / "helpers.py", ns=(2, 2))
    (tmp_path / "src" / "alpha" / "extra.py").write_text("")  # a new module: the record is dropped
    _new_process(workflow)
    parsed.clear()
    extra = str(tmp_path.resolve() / "src" / "alpha" / "extra.py")
    assert workflow.module_dependencies(script, packages) == sorted([*expected, extra])
    assert len(parsed) == 5  # every file of the scan
    workflow._scan_cache(tuple(p.resolve() for p in packages)).save()

    # A damaged record is ignored.
    (tmp_path / workflow.SCAN_CACHE).write_text("{not json")
    _new_process(workflow)
    parsed.clear()
    assert len(workflow.module_dependencies(script, packages)) == 4 and len(parsed) == 5


def test_a_copied_checkout_uses_the_import_scan_as_it_is_and_files_gone_leave_the_record(tmp_path, monkeypatch):
    """The record keeps paths relative to the checkout: a copy with its file times parses nothing and finds its own
    files; the entry of a script that no longer exists is dropped when the record is written."""
    import ast
    import json
    import shutil

    from particle_replication import workflow

    original = tmp_path / "original"
    packages = _scan_tree(original)
    (original / "scripts" / "old.py").write_text("import alpha.core\n")
    workflow.module_dependencies(original / "scripts" / "old.py", packages)
    workflow.module_dependencies(original / "scripts" / "job.py", packages)
    workflow._scan_cache(tuple(p.resolve() for p in packages)).save()
    copy = tmp_path / "copy"
    shutil.copytree(original, copy)  # file times kept, as a copy of a clone keeps them
    _new_process(workflow)
    monkeypatch.setattr(ast, "parse", lambda *a, **k: pytest.fail("the copy parsed a file the record holds"))
    copied = [copy / "src" / "alpha", copy / "src" / "beta"]
    assert workflow.module_dependencies(copy / "scripts" / "job.py", copied) == [
        str((copy / f).resolve()) for f in ("src/alpha/core.py", "src/alpha/helpers.py", "src/beta/use.py")]
    (copy / "scripts" / "old.py").unlink()
    workflow._scan_cache(tuple(p.resolve() for p in copied)).save()
    entries = json.loads((copy / workflow.SCAN_CACHE).read_text())["entries"]
    assert "scripts/job.py" in entries and "scripts/old.py" not in entries
    assert not any(key.startswith("/") for key in entries)


def test_the_import_statements_are_found_at_any_depth():
    """The dependency scan visits statements only; it finds every import that a walk of the whole tree finds, in
    functions, classes, branches, handlers and match cases, and in every file of the repository."""
    import ast
    from pathlib import Path

    from particle_replication.workflow import _import_statements

    source = """
import a
def f():
    if x:
        from b import c
    try:
        import d
    except E:
        import e
    finally:
        import f
class G:
    def h(self):
        with y:
            import i
match z:
    case 1:
        import j
x = [k for k in range(3)]
"""
    tree = ast.parse(source)
    assert sorted(node.lineno for node in _import_statements(tree)) == [2, 5, 7, 9, 11, 15, 18]
    root = Path(__file__).resolve().parents[1]
    for path in [*root.glob("scripts/**/*.py"), *root.glob("src/**/*.py")]:
        tree = ast.parse(path.read_text())
        walked = [n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom)]
        assert sorted(map(id, _import_statements(tree))) == sorted(map(id, walked)), path


def test_an_interrupted_write_leaves_the_previous_result_intact(tmp_path, monkeypatch):
    from particle_replication import workflow

    path = tmp_path / "result.npz"
    workflow.save_results(path, x=np.arange(3.0))

    def interrupted(handle, **arrays):
        handle.write(b"PK\x03\x04 half a zip file")
        raise KeyboardInterrupt

    monkeypatch.setattr(workflow.np, "savez", interrupted)
    with pytest.raises(KeyboardInterrupt):
        workflow.save_results(path, x=np.arange(5.0))
    np.testing.assert_array_equal(workflow.load_results(path)["x"], np.arange(3.0))
    assert [p.name for p in tmp_path.iterdir()] == ["result.npz"]


def test_rate_tables_show_every_window_and_decide_on_the_finest():
    from particle_replication.rates import Recorder, order

    n = np.array([10.0, 100.0, 1000.0, 10000.0])
    errors = np.array([1.0, 0.3, 1e-3, 1e-4])  # pre-asymptotic, then order 1
    rate = order("x.a", "n", n, errors, window=2)
    assert rate.slope == pytest.approx(-1.0)
    np.testing.assert_allclose(rate.pairwise, np.diff(np.log(errors)) / np.diff(np.log(n)))
    assert rate.slopes[0][3] == pytest.approx(fit_order(n, errors))
    assert all(rate.slopes[i][j] is None for i in range(4) for j in range(i + 1))
    logged = []
    assert Recorder(logged.append).add(rate) == rate.slope and "*" in logged[0]
    with pytest.raises(ValueError, match="window must not exceed"):
        order("x.a", "n", n, errors, window=5)
    with pytest.raises(ValueError, match="window must be"):
        order("x.a", "n", n, errors, window=1)


def test_log_factor_measure_separates_log_n_over_n_from_one_over_n(tmp_path):
    from particle_replication.rates import fit, read_rates, write_rates

    n = 2.0 ** np.arange(10, 16)
    with_log = fit("x.a", "n error against log n", "n", n, np.log(n), n * (0.25 * np.log(n) + 2) / n, 3)
    without = fit("x.a", "n error against log n", "n", n, np.log(n), n * (3.0 / n), 3)
    assert with_log.slope == pytest.approx(0.25) and without.slope == pytest.approx(0.0, abs=1e-12)
    # a fitted order cannot tell them apart: both are close to -1 on this range
    assert abs(fit_order(n, (0.25 * np.log(n) + 2) / n) + 1) < 0.15
    write_rates(tmp_path / "r.json", [with_log])
    assert read_rates(tmp_path / "r.json") == [with_log]


def test_steadiness_criteria():
    from particle_replication.steady import first_steady_time, holds_from, run_until

    times = np.linspace(0.0, 10.0, 101)
    settling = np.exp(-times)[:, None] * np.ones((1, 3)) + 1.0
    moving = (times[:, None] * np.ones((1, 3))) + 1.0  # still moving at the end of the record
    assert first_steady_time(times, settling, window=1.0, tolerance=1e-3) == pytest.approx(7.6, abs=0.2)
    assert first_steady_time(times, moving, window=1.0, tolerance=1e-3) == np.inf
    assert holds_from(times, times >= 3.0) == 3.0
    assert holds_from(times, (times >= 3.0) & (times < 9.0)) == np.inf  # fails again before the end
    with pytest.raises(ValueError, match="increasing"):
        first_steady_time(times[::-1], settling, 1.0, 1e-3)

    def advance(state, chunk):  # decays to 0 at rate 1, ten records per unit time
        steps = round(chunk * 10)
        return state * np.exp(-0.1 * np.arange(steps + 1))[:, None]

    def done(t, states):
        return holds_from(t, np.abs(states).max(axis=1) < 1e-2)

    t, states, reached = run_until(advance, np.ones(2), chunk=2.0, t_min=2.0, t_max=20.0, done=done)
    assert reached == pytest.approx(4.7, abs=0.11) and t[-1] == pytest.approx(6.0) and states.shape == (61, 2)
    t, _, reached = run_until(advance, np.ones(2), chunk=2.0, t_min=2.0, t_max=3.0, done=lambda *a: np.inf)
    assert reached == np.inf and t[-1] == pytest.approx(3.0)


def test_catalogue_gives_every_claim_its_kind_and_source():
    catalogue = c.Catalogue("x", {"fig1.order": ("paper", "Figure 1"), "mass": ("check", "conservation")})
    row = catalogue.claim(c.at_most, "mass", "1", "mass defect", 1e-12, 0.0)
    assert (row.id, row.kind, row.source, row.status) == ("x.mass", "check", "conservation", "pass")
    with pytest.raises(ValueError, match="x.fig2.peaks has no kind and source"):
        catalogue.claim(c.at_most, "fig2.peaks", "2", "peaks", 1.0, 0.0)
    with pytest.raises(ValueError, match="must be one of"):
        c.Catalogue("x", {"a": ("theorem", "Theorem 1")})


def test_farthest_from_centre_picks_the_value_that_decides_a_band():
    from particle_replication.claims import farthest_from_centre

    assert farthest_from_centre([0.95, 1.02, 1.3], (0.9, 1.1)) == 1.3
    assert farthest_from_centre([0.5, 1.05], (0.9, 1.1)) == 0.5
    assert math.isnan(farthest_from_centre([], (0.9, 1.1)))


def test_no_claim_text_prints_a_non_finite_value_as_a_number():
    """A run that never settles or a fit on too few points leaves inf or NaN in a claim's text: the one constructor
    writes them as what they mean."""
    from particle_replication import claims as c

    made = c.claim("demo", c.at_most, "steady", "paper", "Figure 1", "1",
                   "steady from t = inf (steady time inf), ratio inf, slope nan, Linf error, so p = inf", 40.0,
                   float("inf"))
    assert made.claim == ("steady from t = never (steady time never), ratio not measured, slope not measured, Linf "
                          "error, so p = infinity")
    assert made.measured == "not measured" and made.status == "fail"


def test_every_comparison_takes_the_same_keywords():
    """published=, measured=, tolerance= (a bound, or a band for between) give the positional form's claim."""
    K = dict(kind="paper", source="Figure 1", figure="1", text="t")
    assert (c.claim("x", c.close_to, "a", **K, published=1.0, measured=1.05, tolerance=0.1)
            == c.claim("x", c.close_to, "a", "paper", "Figure 1", "1", "t", 1.0, 1.05, 0.1))
    assert (c.claim("x", c.at_most, "a", **K, measured=0.5, tolerance=1.0, published="small")
            == c.claim("x", c.at_most, "a", "paper", "Figure 1", "1", "t", 1.0, 0.5, published="small"))
    band = c.claim("x", c.between, "a", **K, measured=2.0, tolerance=(0.25, 1.0))
    assert band == c.claim("x", c.between, "a", "paper", "Figure 1", "1", "t", 0.25, 1.0, 2.0)
    assert band.status == "fail" and band.tolerance == "in [0.25, 1]"
    with pytest.raises(TypeError, match="tolerance of between must be a band"):
        c.claim("x", c.between, "a", **K, measured=0.5, tolerance=1.0)


def test_a_tolerance_no_claim_reads_stops_the_claims_job(tmp_path):
    """The schema types a new tolerance of a `claims` section without listing it; a misspelt one stops the job."""
    from types import SimpleNamespace

    def measure(results, cfg, recorder):
        return [c.claim("x", c.at_most, "a", kind="check", source="ours", figure="1", text="t", measured=0.5,
                        tolerance=cfg["claims"]["bound"])]

    output = SimpleNamespace(claims=tmp_path / "claims.csv", rates=tmp_path / "rates.json")
    c.measure_paper({}, {"claims": {"bound": 1.0}}, output, measure, log=print)
    assert c.read_claims(output.claims)[0].status == "pass"
    with pytest.raises(ValueError, match=r"tolerances no claim reads.*claims\.bund"):
        c.measure_paper({}, {"claims": {"bound": 1.0, "bund": 2.0}}, output, measure, log=print)
