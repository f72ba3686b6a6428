"""The configuration checks beyond the schema (particle_methods.configuration)."""

import copy
import re
from pathlib import Path

import pytest
import yaml

from particle_methods.configuration import check_configuration

ROOT = Path(__file__).resolve().parents[1]
FULL = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())


@pytest.mark.parametrize("name", ["config.yaml", "quick.yaml"])
def test_the_committed_configurations_pass(name):
    check_configuration(yaml.safe_load((ROOT / "config" / name).read_text()))


def test_the_extended_figure_5_overlay_passes():
    merged = copy.deepcopy(FULL)
    overlay = yaml.safe_load((ROOT / "config" / "fig5-extended.yaml").read_text())
    merged["blob"]["fig5"].update(overlay["blob"]["fig5"])
    check_configuration(merged)


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
        ("ltp.quadratic.eps_scan.eps_min", 0.2, "must be below ltp.quadratic.eps_scan.eps_max"),
        ("blob.fig2.density_times", [0.0, 0.4, 1.5], "beyond blob.fig2.t_max"),
        ("sticky.cost.hull_n", [100000, 1000000, 10**12], "beyond"),
        ("blob.fig4.inverse_h", [20, 40, 10**6], "1/h beyond"),
        ("ltp.quadratic.h_values", [0.1, 0.05, 1e-9], "h below"),
    ],
)
def test_a_meaningless_value_is_refused_naming_its_key(path, value, message):
    with pytest.raises(ValueError, match=re.escape(message)) as error:
        check_configuration(edited(path, value))
    assert path.rsplit(".", 1)[0] in str(error.value)
