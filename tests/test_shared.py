"""Shared helpers: order fitting, claims table, validation."""

import numpy as np
import pytest

from particle_methods import claims as c
from particle_methods.convergence import fit_order, order_table, pairwise_orders
from particle_methods.validation import in_interval, integer_at_least, positive, sorted_array


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


def test_claim_verdicts():
    assert c.close_to("x.a", "x", "1", "t", 1.0, 1.05, 0.1).status == "pass"
    assert c.close_to("x.a", "x", "1", "t", 1.0, 1.2, 0.1).status == "fail"
    assert c.close_to("x.a", "x", "1", "t", 1.0, float("nan"), 0.1).status == "fail"
    assert c.relatively_close_to("x.a", "x", "1", "t", 2.0, 2.1, 0.1).status == "pass"
    assert c.at_most("x.a", "x", "1", "t", 1.0, 1.01).status == "fail"
    assert c.at_least("x.a", "x", "1", "t", 1.0, 1.01).status == "pass"
    with pytest.raises(ValueError, match="must start with the paper id"):
        c.close_to("y.a", "x", "1", "t", 1.0, 1.0, 0.1)


def test_claims_round_trip_merge_and_verify(tmp_path, capsys):
    good = [c.close_to("x.a", "x", "1", "slope, with a | pipe", -1.0, -0.98, 0.05)]
    bad = [c.at_most("y.b", "y", "2", "bound", 1.0, 2.0)]
    c.write_claims(tmp_path / "x.csv", good)
    c.write_claims(tmp_path / "y.csv", bad)
    assert c.read_claims(tmp_path / "x.csv") == good
    merged = c.merge([tmp_path / "x.csv", tmp_path / "y.csv"], tmp_path / "all.csv", tmp_path / "all.md")
    assert [claim.id for claim in merged] == ["x.a", "y.b"]
    markdown = (tmp_path / "all.md").read_text()
    assert "2 claims checked: 1 pass, 1 fail" in markdown and "\\|" in markdown
    assert c.main(["verify", str(tmp_path / "x.csv")]) == 0
    assert c.main(["verify", str(tmp_path / "all.csv")]) == 1
    assert "FAIL y.b" in capsys.readouterr().out
    with pytest.raises(ValueError, match="duplicate"):
        c.write_claims(tmp_path / "z.csv", good + good)


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

    from particle_methods.workflow import module_dependencies

    root = Path(__file__).resolve().parents[1]
    package = root / "src" / "particle_methods"
    found = {Path(p).relative_to(package).as_posix() for p in
             module_dependencies(root / "scripts" / "sticky" / "scalar_data.py", package)}
    # Direct imports, relative imports inside the package (spd -> validation -> jit), nothing unused.
    assert {"norms.py", "sticky/cases.py", "sticky/spd.py", "sticky/exact.py", "validation.py", "jit.py"} <= found
    assert not {"sticky/mspd.py", "sticky/psystem.py", "plotting.py", "sticky/__init__.py"} & found


def test_an_interrupted_write_leaves_the_previous_result_intact(tmp_path, monkeypatch):
    from particle_methods import workflow

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
