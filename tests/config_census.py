"""Census of the configuration (issue 46, item 5): every value of ``config/config.yaml`` replaced in turn by bad
values, each checked as the workflow checks a configuration before any job (the schema, then
:func:`particle_replication.configuration.check_configuration`, as ``rules/common.smk`` does).

The leaves are generated from the configuration itself (every number, string and flag, and every entry of a list),
so that a new key cannot escape the census. A bad value must be refused before any work, and the refusal must
name the key (its dotted path, or the schema's path to it). The bad values of a leaf, by its type:

- every leaf: None, a list, a mapping (a value of the wrong shape);
- a number: a string, NaN, +-inf, a flag (``true``);
- a string: a number, and a name no code knows (``no-such-name``): a case, kernel or flux name that would fail in
  its job, hours into a run, unless the check refuses it;
- a size, count or time held to a work limit (:data:`particle_replication.work_limits.LIMITS`): the value times
  and divided by 10**9, of which the one that asks its limits for more work must be refused naming the key
  (the other, less work, may pass: ``less work``).

Free text (:data:`FREE_TEXT`: where a run writes, the robustness variants' environment values) takes any string.
A value refused without naming its key is ``unclear``; one accepted is ``accepted``. The test
(``tests/test_config_census.py``) tries a fixed sample of the leaves; ``python tests/config_census.py`` tries them
all and prints the counts (``-v``: every failing value).
"""

from __future__ import annotations

import copy
import functools
import math
import sys
import zlib
from fnmatch import fnmatchcase
from pathlib import Path

import jsonschema

from particle_replication.configuration import SCHEMA, check_configuration, repository_configuration
from particle_replication.paths import read_yaml
from particle_replication.work_limits import LIMITS, held, walk

#: The outcomes: the first is what every bad value must get.
OUTCOMES = ("refused, named", "less work", "refused, unclear", "accepted")
#: The outcomes that fail the census.
FAILURES = OUTCOMES[2:]
#: Keys whose strings are free text, with the reason.
FREE_TEXT = {
    "output_root": "a directory the run creates: any name is one",
    "robustness.variants.*.env.*": "an environment variable's value, read by the library it configures",
}
#: The factor a size held to a work limit is multiplied by.
HUGE = 10**9
NAME = "no-such-name"


@functools.cache
def validator() -> jsonschema.protocols.Validator:
    """The schema's validator, built once (``snakemake.utils.validate`` builds it at every call)."""
    schema = read_yaml(Path(SCHEMA))
    return jsonschema.validators.validator_for(schema)(schema)


def leaves(config: dict) -> list[tuple[str, object]]:
    """(dotted key, value) of every number, string and flag of ``config``, list entries included (``key.3``)."""
    return [(key, value) for key, value in walk(config) if key and not isinstance(value, (dict, list))]


def bad_values(key: str, value) -> list:
    """The bad values of one leaf (module docstring)."""
    values: list = [None, [], {}]
    if isinstance(value, bool):
        values += ["x", 1.5]
    elif isinstance(value, (int, float)):
        values += ["x", math.nan, math.inf, -math.inf, True]
        if held(key):
            values += [value * HUGE, value / HUGE] if value else [HUGE]
    elif isinstance(value, str):
        values += [1.0] if any(fnmatchcase(key, pattern) for pattern in FREE_TEXT) else [1.0, NAME]
    return values


def replaced(config: dict, key: str, value) -> dict:
    """A deep copy of ``config`` with the leaf at the dotted ``key`` replaced by ``value``."""
    changed = copy.deepcopy(config)
    parts = key.split(".")
    node = changed
    for part in parts[:-1]:
        node = node[int(part)] if isinstance(node, list) else node[part]
    last = parts[-1]
    if isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value
    return changed


def names_the_key(message: str, key: str, schema_path=None) -> bool:
    """Whether a refusal names the key: its dotted path (or that of its list), or the schema's path to it."""
    parts = key.split(".")
    listed = ".".join(parts[:-1]) if parts[-1].isdigit() else key
    if listed in message:
        return True
    return schema_path is not None and [str(p) for p in schema_path][: len(listed.split("."))] == listed.split(".")


def classify(config: dict, key: str, value) -> tuple[str, str]:
    """(outcome, message) of the configuration with one leaf replaced, through the schema and the check."""
    changed = replaced(config, key, value)
    error = jsonschema.exceptions.best_match(validator().iter_errors(changed))
    if error is not None:
        named = names_the_key(error.message, key, error.absolute_path)
        return ("refused, named" if named else "refused, unclear"), f"schema: {error.message}"[:200]
    try:
        check_configuration(changed)
    except (ValueError, TypeError) as error:
        return ("refused, named" if names_the_key(str(error), key) else "refused, unclear"), str(error)[:200]
    if _is_number(value) and held(key) and less_work(config, changed, key):
        return "less work", ""
    return "accepted", ""


def less_work(config: dict, changed: dict, key: str) -> bool:
    """Whether every limit holding ``key`` asks no more work of ``changed`` than of ``config``."""
    parts = key.split(".")
    listed = ".".join(parts[:-1]) if parts[-1].isdigit() else key
    for limit in LIMITS:
        if limit.matches(listed):
            before, after = (_work(limit, c, listed) for c in (config, changed))
            if before is not None and after is not None and after > before:
                return False
    return True


def _work(limit, config: dict, key: str):
    """The largest work a limit asks of the values of ``key`` in ``config`` (None where it does not apply)."""
    parts = key.split(".")
    section = _get(config, ".".join(parts[: -limit.up]))
    values = _get(config, key)
    works = []
    for value in values if isinstance(values, list) else [values]:
        try:
            works.append(limit.work(value, section))
        except (KeyError, TypeError, ZeroDivisionError, IndexError):
            pass
    return max(works, default=None)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _get(config, dotted: str):
    node = config
    for part in dotted.split(".") if dotted else []:
        node = node[int(part)] if isinstance(node, list) else node.get(part) if isinstance(node, dict) else None
    return node


def sampled(pairs: list, every: int | None) -> list:
    """A fixed subset of (key, value) pairs: those whose hash falls in 1 of ``every`` (all if None)."""
    if every is None:
        return pairs
    return [pair for pair in pairs if zlib.crc32(f"{pair[0]}={pair[1]!r}".encode()) % every == 0]


def census(config: dict | None = None, every: int | None = None) -> list[tuple[str, object, str, str]]:
    """(key, bad value, outcome, message) of every (or every ``every``-th, by hash) bad value of every leaf."""
    config = repository_configuration("full") if config is None else config
    pairs = [(key, bad) for key, value in leaves(config) for bad in bad_values(key, value)]
    return [(key, bad, *classify(config, key, bad)) for key, bad in sampled(pairs, every)]


def main(argv: list[str]) -> int:
    results = census()
    counts = {outcome: sum(1 for *_, found, _ in results if found == outcome) for outcome in OUTCOMES}
    print(f"{len(results)} bad values of {len(leaves(repository_configuration('full')))} leaves: {counts}")
    if "-v" in argv:
        for key, bad, outcome, message in results:
            if outcome in FAILURES:
                print(f"{outcome:18} {key} = {bad!r}  {message}")
    return int(any(outcome in FAILURES for *_, outcome, _ in results))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
