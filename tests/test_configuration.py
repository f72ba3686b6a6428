"""The configuration checks beyond the schema (particle_replication.configuration)."""

import copy
import re
from pathlib import Path

import pytest

from particle_replication.configuration import check_configuration, overlay
from particle_replication.paths import read_yaml

ROOT = Path(__file__).resolve().parents[1]
FULL = read_yaml(ROOT / "config" / "config.yaml")


def test_the_full_configuration_passes():
    check_configuration(FULL)


@pytest.mark.parametrize("name", ["quick.yaml", "fig5-extended.yaml"])
def test_the_committed_overlays_pass_over_the_full_configuration(name):
    check_configuration(overlay(FULL, read_yaml(ROOT / "config" / name)))


def leaves(node, path=()):
    if isinstance(node, dict):
        for key, value in node.items():
            yield from leaves(value, (*path, key))
    else:
        yield path, node


def test_the_quick_overlay_holds_only_what_differs():
    """At most 10 of its values repeat the full configuration's (issue 26)."""
    quick = read_yaml(ROOT / "config" / "quick.yaml")
    full = dict(leaves(FULL))
    repeated = [".".join(path) for path, value in leaves(quick) if full.get(path, object()) == value]
    assert len(repeated) <= 10, repeated


def test_an_overlay_merges_mappings_and_replaces_lists():
    base = {"a": {"x": 1, "y": [1, 2, 3], "z": {"p": 1, "q": 2}}, "b": 5}
    merged = overlay(base, {"a": {"y": [9], "z": {"q": 7}}})
    assert merged == {"a": {"x": 1, "y": [9], "z": {"p": 1, "q": 7}}, "b": 5}
    assert base["a"]["y"] == [1, 2, 3]  # not modified
    with pytest.raises(TypeError, match="overlay must be a mapping"):
        overlay(base, [1])


def edited(path, value):
    config = copy.deepcopy(FULL)
    *parents, last = path.split(".")
    node = config
    for key in parents:
        node = node[int(key)] if isinstance(node, list) else node[key]
    node[last] = value
    return config


@pytest.mark.parametrize(
    "path, value, message",
    [
        ("sticky.fig2.t_max", float("nan"), "must be finite"),
        ("blob.fig4.q", float("inf"), "must be finite"),
        ("blob.fig5.inverse_h", [5, 10, 10, 40], "distinct and ordered"),
        ("ltp.quadratic.h_values", [0.1, 0.05, 0.1], "distinct and ordered"),
        ("blob.fig5.fit_points", 6, "longer than blob.fig5.inverse_h"),
        ("sticky.fig3.decay_window", 16, "longer than sticky.fig3.error_p + sticky.fig3.rate_p"),
        ("blob.fig1.zoom", [-0.06, 0.06, 1.0, 0.8], "low < high"),
        ("sticky.cost.band", [1.2, 0.8], "low < high"),
        ("sticky.beyond.events_band", [2.0, 0.5], "low < high"),
        ("ltp.claims.dt_order_band", [1.2, 0.8], "low < high"),
        ("ltp.quadratic.eps_scan.eps_min", 0.2, "must be below ltp.quadratic.eps_scan.eps_max"),
        ("blob.fig2.density_times", [0.0, 0.4, 1.5], "beyond blob.fig2.t_max"),
        ("sticky.cost.hull_n", [100000, 1000000, 10**12], "beyond"),
        ("blob.fig4.inverse_h", [20, 40, 10**6], "beyond the limit MAX_PARTICLES"),
        ("ltp.quadratic.h_values", [0.1, 0.05, 1e-9], "beyond the limit MAX_PARTICLES"),
        # ranges by the schema's meaning, whatever their key (issue 30: these three passed the dry run)
        ("sticky.beyond.domain", [30.0, -30.0], "low < high"),
        ("sticky.beyond.scalar.concave_laplace.domain", [40.0, -40.0], "low < high"),
        ("cross.claims.spd_order", [1.1, 0.9], "low < high"),
        ("ltp.fig5.collapse.windows", [[0.5, 0.25], [0.5, 0.75]], "low < high"),
        ("ltp.quadratic.dt", 0.3, "not a whole number of steps"),
        ("ltp.quadratic.dt_study.dt_values", [0.02, 0.01, 0.003], "not a whole number of steps"),
    ],
)
def test_a_meaningless_value_is_refused_naming_its_key(path, value, message):
    with pytest.raises(ValueError, match=re.escape(message)) as error:
        check_configuration(edited(path, value))
    assert path.rsplit(".", 1)[0] in str(error.value)


def test_ranges_are_found_by_the_schema_not_by_the_key_name():
    """Every [low, high] the schema declares (bands, domains, windows, zoom boxes) and no other list."""
    from particle_replication.configuration import range_paths

    ranges = {".".join(path) for path in range_paths()}
    assert {"sticky.beyond.domain", "sticky.beyond.scalar.*.domain", "cross.claims.spd_order", "blob.fig1.zoom",
            "ltp.fig5.collapse.windows.*", "sticky.cost.band"} <= ranges
    assert not {"blob.fig5.inverse_h", "sticky.beyond.limit_n", "ltp.nonaffine.theorem3.h_values"} & ranges
