"""The census of the whole public API (issue 46, :mod:`census`): every public callable of ``particle_methods`` is
called with each argument replaced by bad and extreme values, and none may hang, return NaN or inf silently, raise
another exception than ValueError/TypeError, refuse without naming the parameter, or answer a bad value."""

import pytest
from census import FAILURES, HUGE, census, public_callables
from census_entries import ENTRIES, EXEMPT
from fuzzing import Later, built


def test_every_public_callable_is_in_the_census():
    listed = set(ENTRIES) | set(EXEMPT)
    kernels = {name for name in public_callables() if name.rsplit(".", 1)[-1].endswith("_kernel")}
    missing = sorted(set(public_callables()) - listed - kernels)
    assert not missing, f"public callables neither in the census nor exempt (tests/census_entries.py): {missing}"
    stale = sorted(listed - set(public_callables()))
    assert not stale, f"census entries of no public callable: {stale}"


def test_an_exemption_for_trust_is_one_its_docstring_states():
    """A callable exempt because it trusts its caller's checks says so in its docstring (CONTRIBUTING, "Names")."""
    import importlib

    trusting = [name for name, reason in EXEMPT.items() if "docstring says so" in reason]
    silent = [name for name in trusting if "trusts its caller" not in " ".join(
        (getattr(importlib.import_module(name.rpartition(".")[0]), name.rpartition(".")[2]).__doc__ or "").split())]
    assert trusting and not silent, silent


def test_the_census_refuses_a_new_function(monkeypatch):
    import particle_methods.norms as norms

    monkeypatch.setattr(norms, "brand_new", lambda x: x, raising=False)
    norms.brand_new.__module__ = "particle_methods.norms"
    assert "particle_methods.norms.brand_new" in public_callables()


@pytest.mark.parametrize("name", sorted(ENTRIES))
def test_census(name):
    failures = [f"{outcome}: {parameter} = {value!r:.60}: {detail}"
                for parameter, value, outcome, detail in census(name, ENTRIES[name]) if outcome in FAILURES]
    header = f"{name}: {len(failures)} failing calls (zero-stride arrays of {HUGE} entries included)"
    assert not failures, "\n".join([header, *failures])


def test_a_later_good_value_is_built_once_on_first_use():
    """The census's costly good values (fuzzing.Later): nothing is built at import, and once for every use."""
    builds = []
    value = Later(lambda: builds.append(1) or {"x": [1.0, 2.0], "f": lambda y: 2 * y})
    item, doubled = value["x"][1], value["f"](value["x"][0])
    assert builds == []  # an item and a call of a Later value are Later too
    assert built({"a": item, "b": doubled, "c": 3}) == {"a": 2.0, "b": 2.0, "c": 3}
    assert built(value.keys)() == {"x": None, "f": None}.keys() and builds == [1]
