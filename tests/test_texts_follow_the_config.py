"""Every text a figure or a claim shows follows the configuration: with parameters changed in a scratch
overlay (the blob paper's q and m, the LTP rows' exponents, the cross study's times and target), no
registry label, caption or title, and no claim text built from results with the changed parameters, shows
an old value. Fast: no pipeline run, the claims on the synthetic results of tests/blob/test_blob_verdicts.py."""

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest
import yaml

from particle_replication import registry
from particle_replication.configuration import check_configuration, overlay
from particle_replication.rates import Recorder
from particle_replication.verdicts import blob as blob_verdicts

ROOT = Path(__file__).resolve().parents[1]
CONFIG = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())

#: The scratch overlay: for each paper, the changed parameters, and the old values no text may still show
#: (as regular expressions: a value not followed or preceded by a digit).
OVERLAY = {
    "blob": {**{f"fig{i}": {"q": 0.8} for i in range(1, 7)}, "fig1": {"q": 0.8, "order": 6},
             "fig3": {"q": 0.8, "order": 6}},
    "ltp": {"fig5": {"cases": [{"a": 1.7, "t": 2.0}, {"a": 2.7, "t": 4.0}]},
            "fig6": {"a": 3.5, "cases": [{"b": 1.2, "t": 20.0}, {"b": 1.6, "t": 20.0}, {"b": 2.6, "t": 20.0}]}},
    "cross": {"times": [0.6, 1.3], "target_error": 0.0123},
}
#: Old values per paper, and the figures in which they must not appear (all of the paper's by default).
OLD = {
    "blob": {"0.9": None, "m = 4": ("fig1", "fig3")},
    "ltp": {"1.5": ("fig5", "fig6"), "2.5": ("fig5", "fig6"), "1.1": ("fig6",), "^3/3": ("fig6",)},
    "cross": {},
}


def shown(value: str, text: str) -> bool:
    return re.search(rf"(?<![\d.]){re.escape(value)}(?![\d])", text) is not None


def texts(figure, section) -> list[str]:
    return [figure.describe(section), figure.caption(section)] + ([figure.title(section)] if figure.title else [])


def test_the_overlay_is_a_valid_configuration():
    config = overlay(CONFIG, OVERLAY)
    check_configuration(config)
    assert config["blob"]["fig1"]["q"] == 0.8 and config["blob"]["fig4"]["t"] == CONFIG["blob"]["fig4"]["t"]


@pytest.mark.parametrize("paper", sorted(OVERLAY))
def test_registry_texts_follow_the_config(paper):
    base, changed = CONFIG[paper], overlay(CONFIG, OVERLAY)[paper]
    old = dict(OLD[paper])
    if paper == "cross":  # the cross study's captions list its times and its target error
        old |= {f"{t:g}": ("error_size", "error_time") for t in base["times"] if t not in (1.0,)}
        old[f"{base['target_error']:g}"] = ("error_size",)
    for value, figures in old.items():
        names = figures or [figure.name for figure in registry.PAPERS[paper].figures]
        seen = [figure.name for figure in registry.PAPERS[paper].figures if figure.name in names
                and any(shown(value, text) for text in texts(figure, base))]
        assert seen, f"{value!r} is in no text of {paper}'s {names} with the full run's config: a stale test"
        stale = [(figure.name, text) for figure in registry.PAPERS[paper].figures if figure.name in names
                 for text in texts(figure, changed) if shown(value, text)]
        assert not stale, f"{paper}: typed {value!r} still shown after the overlay: {stale}"


def _blob_test_module():
    path = ROOT / "tests" / "blob" / "test_blob_verdicts.py"
    spec = importlib.util.spec_from_file_location("blob_verdict_builders", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_blob_claim_texts_follow_the_run(monkeypatch):
    """The claims of Figures 1-5 on synthetic results computed with q = 0.8 and, for Figure 1, m = 6: neither
    0.9, nor m = 4 for Figure 1, nor the old published rate m q = 3.6 remains; the published rates follow."""
    monkeypatch.setattr(blob_verdicts, "progress", lambda *_: None)
    build = _blob_test_module()
    recorder = Recorder(lambda *_: None)
    q = 0.8
    d1 = build.blob_run() | {"q": np.float64(q), "order": np.int64(6)}
    newtonian = blob_verdicts.newtonian_claims(d1, build.particle_run(), build.patch_run(), build.RULES, recorder)
    m4 = {f"{kernel}_blob4_{part}": (0.5, 4 * q) for kernel in build.KERNELS for part in build.PARTS}
    fig4 = blob_verdicts.fig4_claims(build.fig4(**m4) | {"q": np.float64(q)}, build.RULES, recorder)
    fig5 = blob_verdicts.fig5_claims(build.fig5(regular=(4 * q, 4 * q)) | {"q": np.float64(q)}, build.RULES, recorder)
    claims = {claim.id: claim for claim in newtonian + fig4 + fig5}
    for claim in claims.values():
        assert not shown("0.9", claim.claim) and not shown("3.6", claim.claim), (claim.id, claim.claim)
    for name in ("fig1d.order_trajectory", "fig1d.order_density"):
        assert "m = 6, q = 0.8" in claims[f"blob.{name}"].claim and claims[f"blob.{name}"].published == "4.8"
    for name in ("fig5.m4_regular_trajectory", "fig5.m4_regular_density"):
        assert claims[f"blob.{name}"].published == "3.2", claims[f"blob.{name}"]
    assert "instead of 0.8" in claims["blob.fig4.repulsive_density_q0.75_m4"].claim
    assert f"h = {d1['h']:g}" in claims["blob.mass"].claim


def test_notebook_markdown_types_no_parameter():
    """The notebooks' Markdown cells (jupytext percent files) type no value the config holds: a parameter is
    shown by a code cell that reads it."""
    for path in sorted((ROOT / "notebooks").glob("*.py")):
        cells = re.split(r"^# %%", path.read_text(), flags=re.MULTILINE)
        markdown = "\n".join(cell for cell in cells if cell.startswith(" [markdown]"))
        typed = re.findall(r"m q = \d[\d.]*|\bq = \d[\d.]*|h\^\d[\d.]*|\bt = \d\d+|\(\d+ and \d+ points\)", markdown)
        assert not typed, f"{path.name}: typed in Markdown: {typed}"
