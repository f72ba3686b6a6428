"""Checks of the pipeline configuration that a JSON schema cannot state.

``config/schema.yaml`` fixes the keys, types and simple bounds; :func:`check_configuration`,
called by the Snakefile right after the schema, rejects at start what would otherwise produce a
meaningless number hours later, with a ValueError naming the dotted key:

- NaN or infinite numbers (YAML's ``.nan`` and ``.inf`` pass the schema's ``type: number``);
- lists of resolutions, sizes or times that repeat a value or are not monotone (an order fitted
  on repeated resolutions is meaningless), and ranges given backwards: every value the schema
  declares a range (``$defs`` :data:`RANGE_DEFINITIONS`: bands, domains, windows, zoom boxes),
  whatever its key is called, and ``x_min`` above ``x_max``;
- fit windows longer than the list they are fitted on;
- times beyond the ``t_max`` of their run, and time steps that do not divide the final time of
  their runs into a whole number of steps (:data:`WHOLE_STEPS`; the solver refuses them, but only once
  the job runs);
- sizes beyond what one run can compute (:data:`MAX_COUNT` particles, steps or cells;
  :data:`MAX_INVERSE_H` for 1/h), and every size, count and time beyond the work limit of the solver it feeds
  (:func:`particle_replication.work_limits.check_work_limits`).
"""

from __future__ import annotations

import copy
import functools
import math
from numbers import Real
from pathlib import Path

from .paths import REPOSITORY, read_yaml
from .work_limits import check_work_limits, held, walk

MAX_COUNT = 10**8
"""Largest integer parameter (particles, cells, steps): 1e8 doubles are 0.8 GB per array."""

MAX_INVERSE_H = 10**5
"""Largest 1/h: the 1D methods then hold 1e5 particles per unit length, the 2D ones 1e10."""

# Fit windows (integer keys) and the lists they are fitted on (a tuple: lists fitted together).
FIT_WINDOWS = {
    "sticky.fig2.order_window": ["sticky.fig2.error_p"],
    "sticky.fig3.decay_window": [("sticky.fig3.error_p", "sticky.fig3.rate_p")],
    "sticky.lemma21.rate_window": ["sticky.lemma21.n_values"],
    "sticky.tspd_convergence.window": ["sticky.tspd_convergence.deltas", "sticky.tspd_convergence.n_values"],
    "sticky.cost.window": ["sticky.cost.hull_n", "sticky.cost.rank_n", "sticky.cost.tspd_n",
                           "sticky.cost.steps_values"],
    "ltp.quadratic.dt_study.fit_points": ["ltp.quadratic.dt_study.dt_values"],
    "blob.fig1.fit_points": ["blob.fig1.inverse_h"],
    "cross.fit_points": ["cross.spd_n", "cross.grid_inverse_h", "cross.blob.inverse_h", "cross.blob.after_inverse_h",
                         "cross.ltp.inverse_h", "cross.ltp.sp_after_inverse_h", "cross.godunov.cells"],
    "blob.fig2.fit_points": ["blob.fig2.inverse_h"],
    "blob.fig3.fit_points": ["blob.fig3.inverse_h"],
    "blob.fig4.fit_points": ["blob.fig4.inverse_h"],
    "blob.fig5.fit_points": ["blob.fig5.inverse_h"],
}

# Times plotted or measured within a run, and the run's final time.
TIMES_WITHIN = {
    "sticky.fig2.profile_times": "sticky.fig2.t_max",
    "sticky.fig3.profile_times": "sticky.fig3.t_max",
    "blob.fig1.density_times": "blob.fig1.t_max",
    "blob.fig2.density_times": "blob.fig2.t_max",
    "blob.fig3.density_times": "blob.fig3.t_max",
}

# Time steps (a number or a list of them) and the final time every run with them must reach in whole steps.
WHOLE_STEPS = {
    "ltp.quadratic.dt": "ltp.quadratic.t",
    "ltp.quadratic.eps_scan.dt": "ltp.quadratic.t",
    "ltp.quadratic.eps_scan.fine_dt": "ltp.quadratic.t",
    "ltp.quadratic.dt_study.dt_values": "ltp.quadratic.t",
    "ltp.nonaffine.dt": "ltp.nonaffine.t",
    "ltp.nonaffine.centre_of_mass.dt": "ltp.nonaffine.t",
}

#: Relative tolerance of a whole number of steps, as the solver's (:func:`particle_methods.ltp.solver.simulate`).
STEPS_TOLERANCE = 1e-9


def _is_number(value) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def _get(config, dotted):
    node = config
    for key in dotted.split("."):
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    return node


#: Definitions of ``config/schema.yaml`` whose values are [low, high] ranges (or pairs of them).
RANGE_DEFINITIONS = ("#/$defs/band", "#/$defs/interval", "#/$defs/unit_interval", "#/$defs/boxes")

SCHEMA = REPOSITORY / "config" / "schema.yaml"


@functools.cache
def range_paths(schema_path: Path = SCHEMA) -> frozenset[tuple[str, ...]]:
    """The configuration paths (tuples of keys, ``*`` for any list index or free key) whose schema is one of
    :data:`RANGE_DEFINITIONS`: found by walking the schema and the definitions it refers to."""
    schema = read_yaml(schema_path)
    definitions = schema.get("$defs", {})
    found = set()

    def walk(node, path, seen):
        if not isinstance(node, dict):
            return
        reference = node.get("$ref")
        if reference in RANGE_DEFINITIONS:
            found.add(path)
            return
        if isinstance(reference, str) and reference.startswith("#/$defs/") and reference not in seen:
            walk(definitions.get(reference.removeprefix("#/$defs/")), path, seen | {reference})
        for key, child in node.get("properties", {}).items():
            walk(child, (*path, key), seen)
        for key in ("items", "additionalProperties"):
            walk(node.get(key), (*path, "*"), seen)
        for child in node.get("patternProperties", {}).values():
            walk(child, (*path, "*"), seen)
        for key in ("allOf", "anyOf", "oneOf"):
            for child in node.get(key, ()):
                walk(child, path, seen)

    walk(schema, (), frozenset())
    return frozenset(found)


def _is_range(path: str, ranges) -> bool:
    """Whether the schema declares the list at ``path`` a range (:func:`range_paths`)."""
    keys = tuple(path.split("."))
    return any(len(pattern) == len(keys) and all(p in ("*", k) for p, k in zip(pattern, keys)) for pattern in ranges)


def _check_list(path: str, values: list, ranges) -> None:
    if len(values) < 2 or not all(_is_number(value) for value in values):
        return
    steps = [b - a for a, b in zip(values, values[1:])]
    if _is_range(path, ranges):
        pairs = [values[i:i + 2] for i in range(0, len(values), 2)]
        if any(len(pair) == 2 and pair[0] >= pair[1] for pair in pairs):
            raise ValueError(f"{path} = {values}: a range must be given as [low, high] with low < high")
    elif not (all(step > 0 for step in steps) or all(step < 0 for step in steps)):
        raise ValueError(f"{path} = {values}: the values must be distinct and ordered (increasing or decreasing)")


def overlay(base: dict, *overlays: dict) -> dict:
    """``base`` with each of ``overlays`` laid over it in turn, as Snakemake merges a ``--configfile``
    into the workflow's configuration: mappings are merged key by key, any other value (a list
    included) replaces the base's. The inputs are not modified."""
    merged = copy.deepcopy(base)
    for layer in overlays:
        if not isinstance(layer, dict):
            raise TypeError(f"an overlay must be a mapping, got {type(layer).__name__}")
        for key, value in layer.items():
            if isinstance(value, dict) and isinstance(merged.get(key), dict):
                merged[key] = overlay(merged[key], value)
            else:
                merged[key] = copy.deepcopy(value)
    return merged


def check_configuration(config: dict, schema_path: Path = SCHEMA) -> None:
    """Raise ValueError naming the first key whose value no run can use meaningfully (ranges: those
    ``schema_path`` declares)."""
    ranges = range_paths(Path(schema_path))
    for path, value in walk(config):
        if isinstance(value, list):
            _check_list(path, value, ranges)
        elif isinstance(value, float) and not math.isfinite(value):
            raise ValueError(f"{path} = {value}: every number must be finite")
        elif isinstance(value, int) and not held(path) and not isinstance(value, bool) and abs(value) > MAX_COUNT:
            raise ValueError(f"{path} = {value}: beyond {MAX_COUNT:.0e}, more than one run can compute")
        last = path.split(".")[-1]
        if last in ("inverse_h", "extra_inverse_h") and isinstance(value, list) and not held(path):
            if any(_is_number(v) and v > MAX_INVERSE_H for v in value):
                raise ValueError(f"{path} = {value}: 1/h beyond {MAX_INVERSE_H:.0e}")
        is_h = last == "h" or path.split(".")[-2:-1] == ["h_values"]
        if is_h and _is_number(value) and 0 < value < 1 / MAX_INVERSE_H and not held(path):
            raise ValueError(f"{path} = {value}: h below {1 / MAX_INVERSE_H:g}")
        if last.endswith("_min") and _is_number(value):
            upper = _get(config, path[: -len("_min")] + "_max")
            if _is_number(upper) and value >= upper:
                raise ValueError(f"{path} = {value} must be below {path[: -len('_min')]}_max = {upper}")
    _check_times_within(config)
    _check_whole_steps(config)
    _check_files(config)
    check_work_limits(config)
    for window_path, lists in FIT_WINDOWS.items():
        window = _get(config, window_path)
        for paths in lists:
            paths = (paths,) if isinstance(paths, str) else paths
            length = sum(len(_get(config, path) or ()) for path in paths)
            if _is_number(window) and window > length:
                raise ValueError(f"{window_path} = {window}: longer than {' + '.join(paths)}, {length} values")


#: Keys that name a file of the repository (a path relative to its root).
FILE_KEYS = ("verdicts", "robustness.spreads")


def _check_files(config: dict) -> None:
    """The files the configuration names exist, and the expected verdicts have a section for its run."""
    for key in FILE_KEYS:
        value = _get(config, key)
        if isinstance(value, str) and not (REPOSITORY / value).is_file():
            raise ValueError(f"{key} = {value!r}: no such file in the repository {REPOSITORY}")
    verdicts, run = _get(config, "verdicts"), config.get("verdicts_run")
    if isinstance(verdicts, str) and isinstance(run, str) and run != "full":
        sections = sorted(set(read_yaml(REPOSITORY / verdicts) or {}) - {"pass", "fail"})
        if run not in sections:
            raise ValueError(f"verdicts_run = {run!r}: {verdicts} has no section for this run (full, {sections})")


def _check_whole_steps(config: dict) -> None:
    for dt_path, t_path in WHOLE_STEPS.items():
        steps, t = _get(config, dt_path), _get(config, t_path)
        for dt in steps if isinstance(steps, list) else [steps]:
            if _is_number(dt) and _is_number(t) and dt > 0:
                count = t / dt
                if abs(count - round(count)) > STEPS_TOLERANCE * max(count, 1.0):
                    raise ValueError(f"{dt_path} = {steps}: {t_path} = {t} is not a whole number of steps {dt}")


def _check_times_within(config: dict) -> None:
    for times_path, t_max_path in TIMES_WITHIN.items():
        times, t_max = _get(config, times_path), _get(config, t_max_path)
        if isinstance(times, list) and _is_number(t_max):
            late = [t for t in times if _is_number(t) and t > t_max]
            if late:
                raise ValueError(f"{times_path}: times {late} beyond {t_max_path} = {t_max}")


#: Keys that do not change what a claim measures: where the run writes, which expected verdicts it reads, the
#: robustness run's settings and its nudge of the initial data (whose verdicts must be those of the run nudged).
NOT_MEASURED = frozenset({"output_root", "verdicts", "verdicts_run", "nudge", "robustness"})


def differing_keys(config: dict, other: dict, prefix: str = "") -> list[str]:
    """Dotted keys whose values differ between two configurations (a key present in one only included), but
    for the top-level keys of :data:`NOT_MEASURED`."""
    keys = sorted(set(config) | set(other))
    out = []
    for key in keys:
        if not prefix and key in NOT_MEASURED:
            continue
        dotted = f"{prefix}{key}"
        a, b = config.get(key), other.get(key)
        if isinstance(a, dict) and isinstance(b, dict):
            out += differing_keys(a, b, f"{dotted}.")
        elif a != b or (key in config) != (key in other):
            out.append(dotted)
    return out


def repository_configuration(run: str, root: Path = REPOSITORY) -> dict:
    """The configuration of one of the repository's own runs: ``config/config.yaml`` for ``full``, with
    ``config/<run>.yaml`` laid over it for another (``quick``)."""
    base = read_yaml(root / "config" / "config.yaml")
    if run == "full":
        return base
    path = root / "config" / f"{run}.yaml"
    if not path.is_file():
        raise ValueError(f"verdicts_run {run!r} names no configuration of the repository ({path} does not exist)")
    return overlay(base, read_yaml(path) or {})


def compared_run(config: dict, root: Path = REPOSITORY) -> tuple[str | None, list[str]]:
    """(run, differing keys): the run whose expected verdicts apply to ``config`` (its ``verdicts_run``, when
    the configuration measures what that run of the repository measures, :data:`NOT_MEASURED` aside), or None
    with the keys in which it differs (a user's own overlay: no verdicts are expected of it)."""
    run = config["verdicts_run"]
    differing = differing_keys(config, repository_configuration(run, root))
    return (None, differing) if differing else (run, [])
