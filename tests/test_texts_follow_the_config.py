"""Every text a figure or a claim shows follows the configuration: with parameters changed in a scratch
overlay (the blob paper's q and m, the sticky p-system's Delta and x0 and the rate windows, the LTP rows' and the
non-affine study's exponents, the cross study's times, q and target), no registry label, caption or title, and no
claim text or source built from results with the changed parameters, shows an old value. Fast: no pipeline run,
the claims on the synthetic results of each paper's verdict tests (tests/<paper>/test_*verdicts.py), built for the
changed parameters."""

import importlib.util
import re
from pathlib import Path
from unittest import mock

import numpy as np
import pytest

from particle_methods.ltp import potential
from particle_replication import paths, registry
from particle_replication.configuration import check_configuration, overlay
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import blob as blob_verdicts
from particle_replication.verdicts import cross as cross_verdicts
from particle_replication.verdicts import ltp as ltp_verdicts
from particle_replication.verdicts import sticky as sticky_verdicts

ROOT = Path(__file__).resolve().parents[1]
CONFIG = read_yaml(ROOT / "config" / "config.yaml")

#: The scratch overlay: for each paper, the changed parameters, and the old values no text may still show
#: (as regular expressions: a value not followed or preceded by a digit).
OVERLAY = {
    "blob": {**{f"fig{i}": {"q": 0.8} for i in range(1, 7)}, "fig1": {"q": 0.8, "order": 6},
             "fig3": {"q": 0.8, "order": 6}},
    "sticky": {"psystem": {"rarefaction": {"x0": 0.15, "delta": 0.04}, "shocks": {"delta": 0.025}},
               "fig2": {"order_window": 7}, "lemma21": {"rate_window": 3}},
    "ltp": {"fig5": {"cases": [{"a": 1.7, "t": 2.0}, {"a": 2.7, "t": 4.0}]},
            "fig6": {"a": 3.5, "cases": [{"b": 1.2, "t": 20.0}, {"b": 1.6, "t": 20.0}, {"b": 2.6, "t": 20.0}],
                     "edge_refinement": {"b": 1.6}},
            "fig7": {"b": 2.6}, "nonaffine": {"a": 1.3, "theorem4": {"a": 1.3}}},
    "cross": {"times": [0.6, 1.3], "particle_times": [0.6], "ltp": {"times": [0.6], "sp_times": [0.6, 1.3]},
              "blob": {"q": 0.8}, "target_error": 0.0123},
}
#: Old values per paper, and the figures in which they must not appear (all of the paper's by default).
OLD = {
    "blob": {"0.9": None, "m = 4": ("fig1", "fig3")},
    "sticky": {"0.03": ("fig4", "fig5"), "0.02": ("fig6", "fig7"), "x0 = 0.1": ("fig4",)},
    "ltp": {"1.5": ("fig5", "fig6", "nonaffine"), "2.5": ("fig5", "fig6"), "1.1": ("fig6",), "^3/3": ("fig6",)},
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


def _test_module(path: str, config: dict | None = None):
    """A paper's verdict-test module (its builders of synthetic results), reading ``config`` instead of
    config/config.yaml when given, so that its results are built for the overlay's parameters."""
    spec = importlib.util.spec_from_file_location(Path(path).stem + "_builders", ROOT / path)
    module = importlib.util.module_from_spec(spec)
    if config is None:
        spec.loader.exec_module(module)
    else:
        with mock.patch.object(paths, "read_yaml", lambda *_: config):  # the module reads its config through it
            spec.loader.exec_module(module)
    return module


def stale(claims, values, fields=("claim", "source")):
    """(id, value, text) of every claim whose text or source still shows one of ``values``."""
    return [(claim.id, value, getattr(claim, field)) for claim in claims for value in values for field in fields
            if shown(value, getattr(claim, field))]


def test_sticky_claim_texts_follow_the_run():
    """The rate windows of Figure 2 (d) and Lemma 2.1, changed in the overlay, are those the texts state."""
    build = _test_module("tests/sticky/test_verdicts.py")
    changed, base = overlay(CONFIG, OVERLAY)["sticky"], CONFIG["sticky"]
    rules, l21 = changed["claims"], changed["lemma21"]
    burgers = sticky_verdicts.burgers_claims(build.burgers(build.N[:, None].T ** -1.0 * np.ones((2, 1))), Recorder(
        lambda *_: None), changed["fig2"]["order_window"], rules["order_tolerance"])
    assert f"the {changed['fig2']['order_window']} largest n" in burgers[0].claim
    assert not stale(burgers, [f"the {base['fig2']['order_window']} largest"])
    lemma = sticky_verdicts.lemma21_claims(build.lemma21(), Recorder(lambda *_: None), l21["rate_window"],
                                           l21["weibull_band"], l21["heavy_tail"]["growth_ratio"],
                                           rules["quadrature_margin"], rules["positive_density_tolerance"],
                                           rules["pareto_tolerance"])
    windowed = [claim for claim in lemma if "largest n" in claim.claim]
    assert windowed and all(f"the {l21['rate_window']} largest n" in claim.claim for claim in windowed)
    assert not stale(lemma, [f"the {base['lemma21']['rate_window']} largest"])


def test_ltp_claim_texts_follow_the_run():
    """Figures 5-7 and the non-affine study on results computed with the overlay's exponents: the cases are
    found by their roles (smallest and largest exponent, the edge refinement's case) and named by the run's
    potentials; no text shows the full run's a = 1.5, 2.5 or b = 1.5, 2.5, nor alpha = -1/2."""
    build = _test_module("tests/ltp/test_ltp_verdicts.py")
    changed = overlay(CONFIG, OVERLAY)["ltp"]
    rules, quiet = changed["claims"], Recorder(lambda *_: None)
    fig5 = build.fig5() | {"labels": np.array([potential("power", a=case["a"]).name
                                               for case in changed["fig5"]["cases"]])}
    fig6 = build.fig6() | {"labels": np.array([potential("attractive_repulsive", a=changed["fig6"]["a"], b=case["b"])
                                               .name for case in changed["fig6"]["cases"]])}
    assert changed["fig6"]["cases"][int(fig6["edge_case"])]["b"] == changed["fig6"]["edge_refinement"]["b"]
    fig7 = build.fig7() | {"label": potential("attractive_repulsive", a=changed["fig7"]["a"],
                                              b=changed["fig7"]["b"]).name}
    nonaffine = build.nonaffine() | {"label": potential("power", a=changed["nonaffine"]["a"]).name,
                                     "theorem4_label": potential("power", a=changed["nonaffine"]["theorem4"]["a"]).name}
    claims = [*ltp_verdicts.fig5_claims(fig5, changed["fig5"], rules),
              *ltp_verdicts.fig6_claims(fig6, quiet, changed["concentration"], rules),
              *ltp_verdicts.fig7_claims(fig7, changed["concentration"])]
    assert not stale(claims, ["1.5", "2.5"])
    texts = {claim.id: claim.claim for claim in claims}
    assert texts["ltp.fig5.blowup_a1.5"].startswith("W = |x|^1.7/1.7:")
    assert texts["ltp.fig6.b1.5_steady"].startswith("b = 1.6:") and texts["ltp.fig6.b2.5_dirac_mass"].startswith(
        "b = 2.6:") and "|x|^2.6/2.6" in texts["ltp.fig7.dirac_mass"]
    studied = [claim for claim in ltp_verdicts.nonaffine_claims(nonaffine, quiet, changed["nonaffine"], rules)
               if claim.id.startswith(("ltp.nonaffine.order", "ltp.thm4."))]
    assert studied and not stale(studied, ["1.5", "-1/2", "-0.5"])
    assert all("alpha = 1 - a = -0.3" in claim.claim + claim.source for claim in studied)


def test_cross_claim_texts_follow_the_run():
    """The study's claims on results built for the overlay's times and blob q (the cross verdict tests' builder,
    reading the overlay): no text shows the full run's times or q. Issue 15's figure for (4.3) at t = 1.1, which the
    Dirac-mass share is checked against, is a citation and stays."""
    config = overlay(CONFIG, OVERLAY)
    build = _test_module("tests/cross/test_cross_verdicts.py", config)
    claims = cross_verdicts.study_claims(build.study(), Recorder(lambda *_: None), config["cross"])
    base = CONFIG["cross"]
    times = [f"{t:g}" for t in base["times"]]
    old = [f"t {relation} {t}" for t in times for relation in "=<>"] + [", ".join(times), f"q = {base['blob']['q']:g}"]
    citation = "(issue 15: about 57 % for (4.3) at t = 1.1)"
    found = [(i, v, text.replace(citation, "")) for i, v, text in stale(claims, old)]
    assert not [entry for entry in found if shown(entry[1], entry[2])], found
    assert any("t = 1.3" in claim.claim for claim in claims) and any("q = 0.8" in claim.claim for claim in claims)


def _reasons(entry):
    if isinstance(entry, dict):
        for key, value in entry.items():
            yield from [value] if key == "reason" else _reasons(value)
    elif isinstance(entry, list):
        for value in entry:
            yield from _reasons(value)


def test_expected_verdict_reasons_type_no_run_value():
    """The reasons of config/verdicts.yaml (the README shows the full run's) name no parameter's or measure's value:
    a value that follows the run is in the claim's text. The blow-up time t = 1 of the blob paper's data (4.3),
    the mathematics of the data, stays."""
    verdicts = read_yaml(ROOT / "config" / "verdicts.yaml")
    typed = re.compile(r"(?<![\w.])(t|h|n|1/h|t_max|x0|dt|eps|m q|a|b|q) ?(=|<=|>=|<|>) ?\d|about \d"
                       r"|\d+ (cells|particles|ms|s|widths|runs)\b|\d+\.\d+(?!\))")
    found = [(match.group(0), reason) for reason in _reasons(verdicts)
             for match in typed.finditer(reason.replace("t = 1 - dt", "the blow-up time minus dt"))]
    assert not found, found
