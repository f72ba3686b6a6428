"""The configuration's sizes, counts and times held to the work limits of the code they feed, before any job starts.

Every solver of :mod:`particle_methods` refuses work beyond module constants (``particle_methods.ltp.solver.MAX_STEPS``,
``particle_methods.blob.checks.MAX_PARTICLES``, ...), but only once a job runs, seconds to hours into a run, with a
message naming the solver's argument. :func:`check_work_limits` (called by
:func:`particle_replication.configuration.check_configuration`, so by the workflow at start and by ``snakemake -n``)
computes from the configuration what each job will ask of a solver and raises ValueError naming the key, its
value and the limit.

The limits are read from the source of the modules that define and enforce them (:func:`solver_limit`): the
value lives in one place, and the check does not import the solvers (numba, scipy: seconds at every start of the
workflow). :data:`LIMITS` pairs the configuration's keys with those constants; a test keeps every size, count and
time of ``config/config.yaml`` covered by it.
"""

from __future__ import annotations

import ast
import fnmatch
import functools
import importlib.util
import math
import operator
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from numbers import Real
from pathlib import Path

_OPERATORS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
              ast.Pow: operator.pow, ast.USub: operator.neg}


def walk(node, path=()):
    """(dotted path, value) of every leaf and every list of the configuration."""
    if isinstance(node, dict):
        for key, value in node.items():
            yield from walk(value, (*path, str(key)))
    elif isinstance(node, list):
        yield ".".join(path), node
        for index, value in enumerate(node):
            yield from walk(value, (*path, str(index)))
    else:
        yield ".".join(path), node


def _literal(node: ast.AST, names: Mapping[str, ast.expr] | None = None) -> float:
    """The value of a constant expression of numbers and + - * / ** (``2 * 10**9``, ``2.0**500``), and of the module's
    other constants by name (``8 * PRIMITIVE_CHUNK``), whose values ``names`` holds."""
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.BinOp) and type(node.op) in _OPERATORS:
        return _OPERATORS[type(node.op)](_literal(node.left, names), _literal(node.right, names))
    if isinstance(node, ast.UnaryOp) and type(node.op) in _OPERATORS:
        return _OPERATORS[type(node.op)](_literal(node.operand, names))
    if isinstance(node, ast.Name) and names and node.id in names:
        return _literal(names[node.id], {key: value for key, value in names.items() if key != node.id})
    raise ValueError(f"not a constant expression of numbers: {ast.unparse(node)}")


def _source(module: str) -> Path:
    """The file of ``module`` (a dotted name in a package of this repository), found without importing it."""
    if not isinstance(module, str) or not module:
        raise TypeError(f"module must be a dotted module name, got {module!r}")
    top, *rest = module.split(".")
    spec = importlib.util.find_spec(top)  # a top-level package: found without running its modules
    if spec is None or not spec.submodule_search_locations:
        raise ValueError(f"module {module!r}: no package {top!r}")
    path = Path(spec.submodule_search_locations[0]).joinpath(*rest)
    return path / "__init__.py" if path.is_dir() else path.with_suffix(".py")


@functools.cache
def solver_limit(constant: str) -> float:
    """The value of ``constant``, a module constant given as ``module.NAME``
    (``particle_methods.ltp.solver.MAX_STEPS``), read from the module's source: its top-level assignment
    ``NAME = <numbers and + - * / **>``."""
    if not isinstance(constant, str) or "." not in constant:
        raise ValueError(f"constant must be 'module.NAME', got {constant!r}")
    module, name = constant.rsplit(".", 1)
    path = _source(module)
    if not path.is_file():
        raise ValueError(f"constant {constant!r}: no module file {path}")
    assignments = _top_level_assignments(path)
    if name not in assignments:
        raise ValueError(f"constant {constant!r}: {path} assigns no {name} at its top level")
    return _literal(assignments[name], {key: value for key, value in assignments.items() if key != name})


@functools.cache
def _top_level_assignments(path: Path) -> dict[str, ast.expr]:
    """The values a module's source assigns to names at its top level, the first assignment of each (cached: a module
    holds several limits, and its parse took most of a check's time)."""
    found = {}
    for node in ast.parse(path.read_text()).body:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) \
            else []
        for target in targets:
            if isinstance(target, ast.Name) and node.value is not None:
                found.setdefault(target.id, node.value)
    return found


@dataclass(frozen=True, eq=False)
class Limit:
    """Keys of the configuration (``fnmatch`` patterns of dotted keys, ``*`` matching dots too; a list's key
    stands for each of its values) and the work limit of the code they feed: ``work(value, section)`` is what
    one value asks of the solver, at most the module constant ``constant`` (:func:`solver_limit`); ``section``
    is the mapping ``up`` levels above the key (1: the one that holds it); ``what`` names the work."""

    keys: tuple[str, ...]
    constant: str
    work: Callable[[float, Mapping], float]
    what: str
    up: int = 1

    def matches(self, key: str) -> bool:
        return _patterns(self.keys).fullmatch(key) is not None


@functools.cache
def _patterns(keys: tuple[str, ...]) -> re.Pattern:
    """One regular expression for ``fnmatch`` patterns (matched as ``fnmatchcase`` matches them, ``*`` matching dots
    too): a configuration's check matches each of its keys against every limit."""
    return re.compile("|".join(f"(?:{fnmatch.translate(pattern)})" for pattern in keys))


@functools.cache
def _holding(key: str, limits: tuple[Limit, ...]) -> tuple[Limit, ...]:
    """The limits of ``limits`` whose patterns match a dotted key (cached: every check of a configuration, at every
    job's start, asks it of every key)."""
    if _any_of(limits).fullmatch(key) is None:
        return ()  # most keys: held to no limit, found by one match
    return tuple(limit for limit in limits if limit.matches(key))


@functools.cache
def _any_of(limits: tuple[Limit, ...]) -> re.Pattern:
    """One regular expression for the patterns of every limit of ``limits``."""
    return _patterns(tuple(pattern for limit in limits for pattern in limit.keys))


def _largest(values) -> float:
    """The largest number of a value or a list of them (0 for none)."""
    values = values if isinstance(values, list) else [values]
    return max((v for v in values if _is_number(v)), default=0)


def _smallest(values) -> float:
    values = values if isinstance(values, list) else [values]
    return min((v for v in values if _is_number(v)), default=math.inf)


def _is_number(value) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def _power_of_two(p: float) -> float:
    return 2.0 ** min(p, 1000.0)


# Modules of the limits.
SPD = "particle_methods.sticky.spd"
MSPD = "particle_methods.sticky.mspd"
EVENTS = "particle_methods.sticky.multitype_events"
ADMISSIBILITY = "particle_methods.sticky.admissibility"
THEORY = "particle_methods.sticky.theory"
GRIDS = "particle_methods.finite_volume.grids"
GODUNOV = "particle_methods.finite_volume.scalar"
PSYSTEM_FV = "particle_methods.finite_volume.psystem"
LTP = "particle_methods.ltp.solver"
LTP_CHECKS = "particle_methods.ltp.checks"
LTP_THEOREMS = "particle_methods.ltp.theorems"
BLOB = "particle_methods.blob.checks"
CROSS = "particle_methods.cross.methods"
HULL = "particle_methods.cross.hull"
WORKFLOW = "particle_replication.workflow"


def _ltp_particles(h: float, s=None) -> float:
    """Particles of an LTP or SP run at step h: every initial density of the paper lies on [-1, 1]
    (:func:`particle_methods.ltp.initial.density_named`)."""
    return 2.0 / h


def _row_steps(section: Mapping) -> float:
    """Steps of a row of LTP runs (Figures 5-8: dt = t / steps of each case) up to the longest of t and t_long."""
    cases = section.get("cases") or [section]
    return max(max(case["t"], case.get("t_long", section.get("t_long", case["t"]))) * section["steps"] / case["t"]
               for case in cases)

#: Largest |f'| over the states [0, 1] of the scalar fluxes, Burgers (5.1) u^2/2 and the concave (5.3) u(1 - u)/2 (the
#: speeds ``ScalarFlux.max_speed(0, 1)`` of ``particle_methods.finite_volume.fluxes``, which a test compares): the
#: Godunov runs' time step is cfl dx / speed.
SCALAR_SPEEDS = {"burgers": 1.0, "concave": 0.5}
#: The flux of each scalar case of ``sticky.beyond.scalar`` (``particle_methods.sticky.cases.SCALAR_CASES``).
CASE_FLUXES = {"burgers_two_atoms": "burgers", "concave_laplace": "concave"}


def psystem_peak_speed(nu: float, kappa: float) -> float:
    """The largest sound speed c(nu/2) = kappa / (2 nu asinh(kappa/2)) of the p-system of section 5.2.2, the largest
    |lambda| of (5.7) (``particle_methods.systems.PSystem.speed_scale``, which a test compares; computed here without
    importing the solvers). Both data of section 5.2.2 reach it, so the finite volumes' time step is cfl dx / it."""
    return kappa / (2.0 * nu * math.asinh(0.5 * kappa))


def _steps(t: float, speed: float, width: float, cells: float, cfl: float = 1.0) -> float:
    """Time steps ceil(t / dt) of a finite-volume run at dt = cfl dx / speed, dx = width / cells (cfl <= 1: at least
    the steps of cfl = 1)."""
    return math.ceil(t * speed * cells / (cfl * width))


def _remark33_cell_steps(s: Mapping) -> float:
    """Cell updates of the largest Godunov run of Remark 3.3's check: its grid spans [min - 1, max + 1] of the data and
    the SPD positions, at least [-1, 1], at cells_per_unit (the refinement's own list for its run)."""
    cfl = s["cfl"]
    runs = [(t, SCALAR_SPEEDS["concave"], c) for t in s["godunov_times"] for c in s["cells_per_unit"]]
    runs += [(s["convex"]["t"], SCALAR_SPEEDS["burgers"], c) for c in s["cells_per_unit"]]
    runs += [(s["refinement"]["t"], SCALAR_SPEEDS["concave"], c) for c in s["refinement"]["cells_per_unit"]]
    return max(2 * c * _steps(t, speed, 1.0, c, cfl) for t, speed, c in runs)


def _scalar_cell_steps(s: Mapping) -> float:
    """Cell updates (cells x steps) of the finest Godunov run of the cases of ``sticky.beyond.scalar``, each on its
    ``cells`` over its ``domain`` up to its ``t``."""
    return max(_largest(case["cells"]) * _steps(case["t"], SCALAR_SPEEDS[CASE_FLUXES[name]],
                                                case["domain"][1] - case["domain"][0], _largest(case["cells"]))
               for name, case in s.items())


def psystem_type_cell_steps(s: Mapping, cells: float) -> float:
    """Type-cell updates (2 x cells x steps) of a run on ``cells`` cells of ``sticky.beyond.domain`` up to
    ``sticky.beyond.t``: the upwind scheme updates both invariants of every cell at each step."""
    beyond, system = s["beyond"], s["psystem"]
    width = beyond["domain"][1] - beyond["domain"][0]
    return 2 * cells * _steps(beyond["t"], psystem_peak_speed(system["nu"], system["kappa"]), width, cells,
                              beyond["cfl"])


_PSYSTEM_KEYS = ("sticky.beyond.t", "sticky.beyond.cfl", "sticky.psystem.nu", "sticky.psystem.kappa")

LIMITS: tuple[Limit, ...] = (
    # --- sticky: the SPD (hull), the MSPD and iterated TSPD, the exact MSPD's events, finite volumes
    Limit(("sticky.fig1.particles", "sticky.lemma21.n_values", "sticky.lemma21.heavy_tail.n", "sticky.remark33.dirac_n",
           "sticky.remark33.godunov_n", "sticky.remark33.convex.n", "sticky.remark33.refinement.n",
           "sticky.cost.hull_n", "sticky.cost.rank_n", "sticky.theory.scalar.n_values", "sticky.beyond.scalar.*.spd_n"),
          f"{SPD}.MAX_POSITIONS", lambda v, s: v, "particles"),
    Limit(("sticky.fig[23].trajectory_particles", "sticky.fig[23].trajectory_times"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: s["trajectory_particles"] * s["trajectory_times"],
          "trajectory_particles x trajectory_times positions"),
    Limit(("sticky.fig[23].field_particles", "sticky.fig[23].field_times"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: s["field_particles"] * s["field_times"], "field_particles x field_times positions"),
    Limit(("sticky.fig[23].field_points",), f"{SPD}.MAX_POSITIONS",
          lambda v, s: v * s["field_times"], "field_points x field_times values"),
    Limit(("sticky.fig[23].profile_particles", "sticky.fig[23].profile_times"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: s["profile_particles"] * len(s["profile_times"]), "profile_particles x profile times positions"),
    Limit(("sticky.fig[23].error_p", "sticky.fig[23].rate_p", "sticky.fig[23].error_times"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: _power_of_two(_largest(s["error_p"] + s.get("rate_p", []))) * len(s["error_times"]),
          "2^p particles x error_times positions"),
    Limit(("sticky.psystem.*.steps", "sticky.psystem.*.max_steps"), f"{MSPD}.MAX_STEPS",
          lambda v, s: max(s["steps"], s["max_steps"]), "steps of delta"),
    Limit(("sticky.psystem.*.trajectory_particles", "sticky.psystem.*.field_particles", "sticky.psystem.*.steps",
           "sticky.psystem.*.max_steps"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: (max(s["steps"], s["max_steps"]) + 1) * 2 * max(s["trajectory_particles"], s["field_particles"]),
          "(steps + 1) x 2 types x particles positions"),
    Limit(("sticky.psystem.*.field_points",), f"{SPD}.MAX_POSITIONS",
          lambda v, s: v * (max(s["steps"], s["max_steps"]) + 1), "field_points x (steps + 1) values"),
    Limit(("sticky.remark33.admissibility.points",), f"{ADMISSIBILITY}.MAX_POINTS", lambda v, s: v, "points"),
    Limit(("sticky.remark33.admissibility.n", "sticky.remark33.admissibility.points"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: _largest(s["n"]) * (s["points"] + 1),
          "n x (points + 1) positions"),
    Limit(("sticky.remark33.cells_per_unit", "sticky.remark33.refinement.cells_per_unit"), f"{GRIDS}.MAX_CELLS",
          lambda v, s: 2 * v, "cells on [-1, 1] at least"),
    Limit(("sticky.tspd_convergence.deltas", "sticky.tspd_convergence.reference_delta",
           "sticky.tspd_convergence.n_delta", "sticky.tspd_convergence.times"), f"{MSPD}.MAX_STEPS",
          lambda v, s: _largest(s["times"]) / min(_smallest(s["deltas"]), s["reference_delta"], s["n_delta"]),
          "steps: largest time / smallest delta"),
    Limit(("sticky.tspd_convergence.delta_n", "sticky.tspd_convergence.reference_delta",
           "sticky.tspd_convergence.times"),
          f"{MSPD}.MAX_WORK", lambda v, s: _largest(s["times"]) / s["reference_delta"] * 4 * _largest(s["delta_n"]),
          "steps x d^2 x n rank entries (times, reference_delta, delta_n)"),
    Limit(("sticky.tspd_convergence.n_values", "sticky.tspd_convergence.reference_n",
           "sticky.tspd_convergence.n_delta"),
          f"{MSPD}.MAX_WORK",
          lambda v, s: _largest(s["times"]) / s["n_delta"] * 4 * max(_largest(s["n_values"]), s["reference_n"]),
          "steps x d^2 x n rank entries (times, n_delta, n_values, reference_n)"),
    Limit(("sticky.cost.tspd_steps", "sticky.cost.steps_values"), f"{MSPD}.MAX_STEPS", lambda v, s: v, "steps"),
    Limit(("sticky.cost.tspd_steps", "sticky.cost.tspd_n"), f"{MSPD}.MAX_WORK",
          lambda v, s: s["tspd_steps"] * 4 * _largest(s["tspd_n"]), "tspd_steps x d^2 x tspd_n rank entries"),
    Limit(("sticky.cost.tspd_n",), f"{SPD}.MAX_POSITIONS", lambda v, s: (s["tspd_steps"] + 1) * 2 * v,
          "(tspd_steps + 1) x 2 types x n positions"),
    Limit(("sticky.cost.steps_values", "sticky.cost.steps_n"), f"{MSPD}.MAX_WORK",
          lambda v, s: _largest(s["steps_values"]) * 4 * s["steps_n"], "steps_values x d^2 x steps_n rank entries"),
    Limit(("sticky.cost.repeats", "sticky.beyond.repeats", "cross.repeats"), f"{WORKFLOW}.MAX_REPEATS",
          lambda v, s: v, "timing rounds"),
    Limit(("sticky.theory.steps.deltas", "sticky.theory.steps.t"), f"{MSPD}.MAX_STEPS",
          lambda v, s: s["t"] / _smallest(s["deltas"]), "steps t / delta"),
    Limit(("sticky.theory.steps.n_values",), f"{THEORY}.MAX_PAIRS", lambda v, s: v * v, "n^2 pair counters"),
    Limit(("sticky.theory.steps.n_values", "sticky.theory.steps.deltas", "sticky.theory.steps.t"),
          f"{SPD}.MAX_POSITIONS",
          lambda v, s: (s["t"] / _smallest(s["deltas"]) + 1) * 2 * _largest(s["n_values"]),
          "(t / delta + 1) x 2 types x n positions"),
    Limit(("sticky.theory.random.n_values", "sticky.theory.random.reference_n", "sticky.beyond.limit_n",
           "sticky.beyond.exact_n", "sticky.beyond.reference_n"), f"{EVENTS}.MAX_EVENTS",
          lambda v, s: v * v + 2 * v, "events of the exact MSPD, n^2 + 2 n for two types"),
    Limit(("sticky.theory.random.n_values", "sticky.beyond.tspd_n"), f"{MSPD}.MAX_WORK", lambda v, s: 4 * v * v,
          "n steps x d^2 x n rank entries"),
    Limit(("sticky.beyond.reference_cells", "sticky.beyond.upwind_reference_cells", "sticky.beyond.upwind_cells",
           "sticky.beyond.scalar.*.cells"), f"{GRIDS}.MAX_CELLS", lambda v, s: v, "cells"),
    # finite volumes: steps grow with the time, at the largest speed of the flux
    # (the nested keys named by the refusal; the check itself is reached at the section's own keys)
    Limit(("sticky.remark33.godunov_times", "sticky.remark33.cells_per_unit", "sticky.remark33.cfl",
           "sticky.remark33.convex.t", "sticky.remark33.refinement.t", "sticky.remark33.refinement.cells_per_unit"),
          f"{GODUNOV}.MAX_CELL_STEPS", lambda v, s: _remark33_cell_steps(s),
          "cell updates of the largest Godunov run, at least (2 cells_per_unit) x steps over [-1, 1]"),
    Limit(("sticky.beyond.scalar.*.t", "sticky.beyond.scalar.*.cells"),
          f"{GODUNOV}.MAX_CELL_STEPS", lambda v, s: _scalar_cell_steps(s),
          "cell updates of the finest Godunov run of a case, cells x steps over its domain (at least those of cfl = 1)",
          up=2),
    Limit((*_PSYSTEM_KEYS, "sticky.beyond.reference_cells"), f"{PSYSTEM_FV}.MAX_CELL_STEPS",
          lambda v, s: psystem_type_cell_steps(s, s["beyond"]["reference_cells"]) / 2,
          "cell updates of the HLL reference, reference_cells x steps over sticky.beyond.domain at the peak sound "
          "speed",
          up=2),
    Limit((*_PSYSTEM_KEYS, "sticky.beyond.upwind_reference_cells", "sticky.beyond.upwind_cells"),
          f"{PSYSTEM_FV}.MAX_UPWIND_WORK",
          lambda v, s: psystem_type_cell_steps(s, max(s["beyond"]["upwind_reference_cells"],
                                                   _largest(s["beyond"]["upwind_cells"]))),
          "type-cell updates of the finest upwind run, 2 x cells x steps over sticky.beyond.domain at the peak speed",
          up=2),
    # --- LTP and SP (particle_methods.ltp): particles on [-1, 1] at step h, steps of dt
    Limit(("ltp.*.h", "ltp.*h_values", "ltp.*.sp_h", "ltp.*.plot_h", "ltp.*.reference_h"),
          f"{LTP_CHECKS}.MAX_PARTICLES",
          _ltp_particles, "particles 2 / h"),
    Limit(("ltp.nonaffine.theorem4.h_values",), f"{LTP_CHECKS}.MAX_PARTICLES", lambda v, s: 4.0 / v,
          "particles 2 / (h / 2) of the half step"),
    Limit(("ltp.nonaffine.theorem3.h_values", "ltp.nonaffine.theorem3.reference_factor"), f"{LTP_CHECKS}.MAX_PARTICLES",
          lambda v, s: 2.0 * s["reference_factor"] / _smallest(s["h_values"]), "particles of the reference run"),
    Limit(("cross.ltp.inverse_h", "cross.ltp.sp_after_inverse_h", "cross.aggregates.ltp.inverse_h",
           "cross.aggregates.ltp.sp_inverse_h", "cross.behaviour.ltp_inverse_h"), f"{LTP_CHECKS}.MAX_PARTICLES",
          lambda v, s: 2 * v + 1, "particles 2 / h + 1"),
    Limit(("ltp.quadratic.t", "ltp.quadratic.dt"), f"{LTP}.MAX_STEPS", lambda v, s: s["t"] / s["dt"], "steps t / dt"),
    Limit(("ltp.quadratic.eps_scan.dt", "ltp.quadratic.eps_scan.fine_dt", "ltp.quadratic.dt_study.dt_values"),
          f"{LTP}.MAX_STEPS", lambda v, s: s["t"] / v, "steps ltp.quadratic.t / dt", up=2),
    Limit(("ltp.fig4.t", "ltp.fig4.dt", "ltp.nonaffine.t", "ltp.nonaffine.dt"), f"{LTP}.MAX_STEPS",
          lambda v, s: s["t"] / s["dt"], "steps t / dt"),
    Limit(("ltp.nonaffine.centre_of_mass.dt",), f"{LTP}.MAX_STEPS", lambda v, s: s["t"] / v,
          "steps ltp.nonaffine.t / dt", up=2),
    Limit(("ltp.nonaffine.theorem1.dt_values", "ltp.nonaffine.theorem1.t"), f"{LTP}.MAX_STEPS",
          lambda v, s: s["t"] / _smallest(s["dt_values"]), "steps t / dt"),
    Limit(("ltp.nonaffine.theorem4.*",), f"{LTP}.MAX_STEPS",
          lambda v, s: _largest(s["times"]) / (s["dt_over_h2"] * (_smallest(s["h_values"]) / 2) ** 2),
          "steps: largest time / (dt_over_h2 (h / 2)^2)"),
    Limit(("ltp.nonaffine.theorem3_atomic.*",), f"{LTP}.MAX_STEPS",
          lambda v, s: _largest(s["times"]) * s["dt_factor"] / s["dt"], "steps: largest time x dt_factor / dt"),
    Limit(("ltp.nonaffine.theorem3_atomic.atoms",), f"{LTP_CHECKS}.MAX_PARTICLES", lambda v, s: v, "atoms"),
    Limit(("ltp.nonaffine.theorem3.*",), f"{LTP}.MAX_STEPS",
          lambda v, s: _largest(s["times"]) * s["reference_factor"] / (s["dt_over_h"] * _smallest(s["h_values"])),
          "steps of the reference: largest time / (dt_over_h x smallest h / reference_factor)"),
    # (the cases' times listed again, so that a refusal reached at steps names them too; their section is below)
    Limit(("ltp.fig[5678].steps", "ltp.fig[5678].t", "ltp.fig[5678].t_long", "ltp.fig[5678].cases.*.t"),
          f"{LTP}.MAX_STEPS",
          lambda v, s: _row_steps(s), "steps up to t_long at dt = t / steps"),
    Limit(("ltp.fig[5678].cases.*.t",), f"{LTP}.MAX_STEPS", lambda v, s: _row_steps(s),
          "steps up to t_long at dt = t / steps", up=3),
    Limit(("ltp.fig[5678].snapshots",), f"{LTP}.MAX_STEPS", lambda v, s: v, "snapshots"),
    Limit(("ltp.nonaffine.grid_points",), f"{LTP_THEOREMS}.MAX_GRID_POINTS", lambda v, s: v,
          "evaluation points of the theorems' studies"),
    Limit(("ltp.nonaffine.theorem3_atomic.times",), f"{LTP_THEOREMS}.MAX_FLOW_TIME", lambda v, s: v,
          "time of the atoms' flow"),
    Limit(("cross.ltp.dt_over_h", "cross.ltp.inverse_h", "cross.ltp.sp_after_inverse_h", "cross.ltp.times",
           "cross.ltp.sp_times"), f"{LTP}.MAX_STEPS",
          lambda v, s: _largest(s["times"] + s["sp_times"]) * _largest(s["inverse_h"] + s["sp_after_inverse_h"])
          / s["dt_over_h"], "steps: largest time / (dt_over_h h)"),
    Limit(("cross.aggregates.ltp.*",), f"{LTP}.MAX_STEPS",
          lambda v, s: s["t_end"] * _largest(s["ltp"]["inverse_h"] + s["ltp"]["sp_inverse_h"]) / s["ltp"]["dt_over_h"],
          "steps: t_end / (dt_over_h h)", up=2),
    # (the LTP keys listed again, so that a refusal reached at t_end names them too; their section is the one above)
    Limit(("cross.aggregates.t_end", "cross.aggregates.ltp.inverse_h", "cross.aggregates.ltp.sp_inverse_h",
           "cross.aggregates.ltp.dt_over_h"), f"{LTP}.MAX_STEPS",
          lambda v, s: s["t_end"] * _largest(s["ltp"]["inverse_h"] + s["ltp"]["sp_inverse_h"]) / s["ltp"]["dt_over_h"],
          "steps: t_end / (dt_over_h h)"),
    # --- blob and particle methods (particle_methods.blob): 1D grids on [-1, 1], 2D grids around the data
    Limit(("blob.fig[1234].inverse_h", "blob.fig4.repulsive.extra_inverse_h", "blob.fig4.log_reading.inverse_h",
           "cross.particle_inverse_h", "cross.blob.inverse_h", "cross.blob.after_inverse_h",
           "cross.aggregates.particle_inverse_h", "cross.aggregates.blob.inverse_h",
           "cross.behaviour.collision_inverse_h"),
          f"{BLOB}.MAX_PARTICLES", lambda v, s: 2 * v + 1, "particles 2 / h + 1"),
    Limit(("blob.fig[123].h",), f"{BLOB}.MAX_PARTICLES", lambda v, s: 2 / v + 1, "particles 2 / h + 1"),
    Limit(("blob.fig4.reference_factor", "blob.fig4.log_reading.reference_factor"), f"{BLOB}.MAX_PARTICLES",
          lambda v, s: 2 * v * _largest(s["inverse_h"]) + 1, "particles of the reference, 2 reference_factor / h + 1"),
    Limit(("blob.fig5.inverse_h",), f"{BLOB}.MAX_FMM_PARTICLES", lambda v, s: (2 * math.ceil(v) + 3) ** 2 / 4,
          "grid nodes (2 / h + 3)^2 / 4 around the data of radius 1"),
    Limit(("blob.fig6.*.h", "blob.fig[78].h"), f"{BLOB}.MAX_FMM_PARTICLES",
          lambda v, s: (2 * math.ceil(1 / v) + 3) ** 2 / 4, "grid nodes (2 / h + 3)^2 / 4 around data of radius 1"),
    Limit(("blob.fig[123].t_max", "blob.fig[123].error_t", "blob.fig4.t", "blob.fig5.t", "blob.fig6.top.t_max",
           "blob.fig6.top.t_density", "blob.fig6.bottom.t", "blob.fig[78].cases.*.t_max", "blob.fig7.without_origin.*",
           "cross.behaviour.stall_window"), f"{BLOB}.MAX_TIME", lambda v, s: v, "time"),
    Limit(("blob.fig[123].times", "blob.fig[123].inverse_h"), f"{BLOB}.MAX_STORED",
          lambda v, s: s["times"] * (2 * _largest(s["inverse_h"]) + 1) * 2, "times x particles x 2 stored values"),
    Limit(("blob.fig6.top.times",), f"{BLOB}.MAX_STORED", lambda v, s: v * (2 / s["h"] + 3) ** 2 * 3,
          "times x particles x 3 stored values"),
    Limit(("blob.fig[78].times",), f"{BLOB}.MAX_STORED", lambda v, s: v * (2 / s["h"] + 3) ** 2 * 3,
          "times x particles x 3 stored values"),
    Limit(("blob.fig[78].paper_tables.points", "blob.fig[78].paper_tables.radius"), f"{BLOB}.MAX_TABLE_WORK",
          lambda v, s: s["paper_tables"]["points"] * s["paper_tables"]["radius"] / s["delta"],
          "points x radius / delta", up=2),
    Limit(("cross.behaviour.stall_evaluations",), f"{BLOB}.MAX_EVALUATIONS", lambda v, s: v, "right-hand sides"),
    # --- cross: equal masses, grids, cells and times
    Limit(("cross.spd_n", "cross.aggregates.spd_n"), f"{CROSS}.MAX_EQUAL_MASSES", lambda v, s: v, "particles"),
    Limit(("cross.grid_inverse_h", "cross.aggregates.grid_inverse_h"), f"{SPD}.MAX_POSITIONS", lambda v, s: 2 * v + 1,
          "grid points 2 / h + 1"),
    Limit(("cross.godunov.cells", "cross.aggregates.godunov_cells"), f"{GRIDS}.MAX_CELLS", lambda v, s: v, "cells"),
    Limit(("cross.times", "cross.particle_times", "cross.ltp.times", "cross.ltp.sp_times",
           "cross.behaviour.ltp_t_final"),
          f"{CROSS}.MAX_TIME", lambda v, s: v, "time"),
    Limit(("cross.aggregates.t_end", "cross.aggregates.cases.*.fixed_times", "cross.aggregates.cases.*.merger_bracket"),
          f"{HULL}.MAX_TIME", lambda v, s: v, "time"),
    Limit(("cross.aggregates.steps", "cross.aggregates.path_steps", "cross.aggregates.spd_n"), f"{SPD}.MAX_POSITIONS",
          lambda v, s: (max(s["steps"], s["path_steps"]) + 1 + 8) * _largest(s["spd_n"]),
          "times x spd_n positions"),
)


def _section(config: Mapping, keys: list[str]):
    node = config
    for key in keys:
        if isinstance(node, list) and key.isdigit() and int(key) < len(node):
            node = node[int(key)]
        elif isinstance(node, Mapping) and key in node:
            node = node[key]
        else:
            return None
    return node


def held(key: str, limits: tuple[Limit, ...] = LIMITS) -> bool:
    """Whether a dotted key (or a value of a list key: ``key.3``) is held to a work limit of :data:`LIMITS`."""
    parts = key.split(".")
    key = ".".join(parts[:-1]) if parts[-1].isdigit() else key
    return bool(_holding(key, limits))


def check_work_limits(config: Mapping, limits: tuple[Limit, ...] = LIMITS) -> None:
    """Raise ValueError naming the first key of ``config`` whose value asks a solver for more than its work limit
    (:data:`LIMITS`): the key, its value, the work and the limit, with the module that sets it."""

    if not isinstance(config, Mapping):
        raise TypeError(f"config must be a mapping, got {type(config).__name__}")
    for key, value in walk(config):
        parts = key.split(".")
        if not key or parts[-1].isdigit():
            continue  # a list's values are checked with its key
        values = value if isinstance(value, list) else [value]
        for limit in _holding(key, limits):
            section = _section(config, parts[:-limit.up])
            limit_value = solver_limit(limit.constant)
            for v in values:
                if not _is_number(v) or not isinstance(section, Mapping):
                    continue
                try:
                    work = limit.work(v, section)
                except (KeyError, TypeError, ZeroDivisionError, IndexError):
                    continue  # a value the schema or the other checks refuse, or a key this run does not use
                if not work <= limit_value:
                    module, name = limit.constant.rsplit(".", 1)
                    prefix = ".".join(parts[:-limit.up]) + "."
                    named = ", ".join(f"{other} = {given}" for other, given in walk(config)
                                      if other.startswith(prefix) and limit.matches(other))
                    raise ValueError(f"{named}: {limit.what} = {work:.3g}, beyond the limit {name} = "
                                     f"{limit_value:.3g} of the code it feeds ({module})")
