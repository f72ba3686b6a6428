"""Outcome counts of a fuzz of the newest public entry points (issue 30): ``python tests/fuzz_counts.py``.

Each entry point of :data:`ENTRIES` is called with valid arguments, then with one argument at a time replaced by
each value of :data:`fuzzing.BAD_SCALARS` or :data:`fuzzing.BAD_ARRAYS` (by the kind of the argument) and by each
extreme number. Every call is classified:

- ``refused, named``: ValueError or TypeError naming the parameter (``ParameterTypeError`` for a value of the wrong
  kind: None, bytes, a string, a complex number, an object);
- ``refused, unclear``: ValueError or TypeError whose message does not name the parameter;
- ``refused, plain ValueError``: None or bytes refused by a ValueError that is not a ``ParameterTypeError``;
- ``answered``: a finite result;
- ``silent non-finite``: a result holding NaN or inf;
- ``other exception``: anything else (IndexError, ZeroDivisionError, MemoryError, ...);
- ``hang``: more than :data:`CALL_SECONDS` of CPU time (a profiling timer, which counts the process's CPU time
  and not the wall clock, so that a call slowed by a loaded machine is no hang, interrupts Python code; the
  compiled loops are bounded by the entry points' work limits).

The test suite's fuzz tests (tests/*/test_*_safety.py, :mod:`fuzzing`) assert the same properties; this script
counts them, for a closing note's before-and-after table.
"""

from __future__ import annotations

import collections
import signal
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from fuzzing import BAD_ARRAYS, BAD_SCALARS, all_finite

from particle_methods.cross import distances, exact, hull, methods
from particle_methods.finite_volume.psystem import hll_psystem, invariants_from_conservative, upwind_diagonal
from particle_methods.finite_volume.riemann import PSystemRiemann
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.systems import PSystem
from particle_methods.validation import ParameterTypeError

CALL_SECONDS = 30
EXTREMES = [0.0, -0.0, 5e-324, 1e-300, -1e-300, 1e300, -1e300, 1.7e308, -1.7e308, 1e-8, 1e8, -1.0]

SYSTEM = PSystem(nu=1.0, kappa=1.0)
EDGES = np.linspace(-1.0, 1.0, 11)
SOLUTION = exact.AggregationSolution("smooth20", 0.5)
X, MASSES = methods.spd_grid("smooth20", 1 / 16, 0.5)


def _riemann_cells(edges, t):
    return PSystemRiemann(SYSTEM, (0.6, 0.0), (0.7, 0.0)).cell_averages(edges, t)


# name -> (function, valid arguments as (parameter name, value, kind)), kind "scalar" or "array".
ENTRIES = {
    "spd_equal": (methods.spd_equal, [("data", "smooth20", "scalar"), ("n", 64, "scalar"), ("t", 0.5, "scalar")]),
    "spd_grid": (methods.spd_grid, [("data", "smooth20", "scalar"), ("h", 1 / 16, "scalar"), ("t", 0.5, "scalar")]),
    "particle_method": (methods.particle_method, [("data", "smooth20", "scalar"), ("h", 0.1, "scalar"),
                                                  ("t", 0.5, "scalar")]),
    "blob_method": (lambda data, h, t, order, q: methods.blob_method(data, h, t, order=order, q=q),
                    [("data", "smooth20", "scalar"), ("h", 0.1, "scalar"), ("t", 0.5, "scalar"),
                     ("order", 4, "scalar"), ("q", 0.9, "scalar")]),
    "ltp_method": (methods.ltp_method, [("data", "smooth20", "scalar"), ("h", 0.1, "scalar"), ("dt", 0.05, "scalar"),
                                        ("t", 0.5, "scalar")]),
    "godunov_mass": (methods.godunov_mass, [("data", "smooth20", "scalar"), ("cells", 64, "scalar"),
                                            ("t", 0.5, "scalar")]),
    "grid_particles": (methods.grid_particles, [("data", "smooth20", "scalar"), ("h", 0.1, "scalar")]),
    "weighted_velocities": (methods.weighted_velocities, [("masses", MASSES, "array")]),
    "particle_velocities": (methods.particle_velocities, [("x", X, "array"), ("masses", MASSES, "array")]),
    "aggregation_flux": (lambda mass: methods.aggregation_flux(mass)(0.1), [("mass", 1.0, "scalar")]),
    "exact_mass_function": (exact.exact_mass_function, [("data", "smooth20", "scalar"), ("t", 1.1, "scalar"),
                                                        ("x", np.linspace(-1, 1, 5), "array")]),
    "HullSolution.cdf": (lambda data, t, x: hull.HullSolution(data, t).cdf(x),
                         [("data", "two_bumps", "scalar"), ("t", 1.2, "scalar"),
                          ("x", np.linspace(-1, 1, 5), "array")]),
    "merger_time": (hull.merger_time, [("data", "two_bumps", "scalar"), ("low", 1.5, "scalar"),
                                       ("high", 2.5, "scalar")]),
    "w1_atoms": (lambda positions, masses: distances.w1_atoms(SOLUTION, positions, masses),
                 [("positions", X, "array"), ("masses", MASSES, "array")]),
    "w1_cells": (lambda edges, values: distances.w1_cells(SOLUTION, edges, values),
                 [("edges", EDGES, "array"), ("values", np.linspace(0.0, SOLUTION.mass, 10), "array")]),
    "w1_smooth": (lambda breaks, largest: distances.w1_smooth(SOLUTION, lambda x: np.clip((x + 1) / 2, 0, 1) *
                                                              SOLUTION.mass, breaks, largest),
                  [("breaks", np.array([-1.0, 1.0]), "array"), ("largest", 0.1, "scalar")]),
    "hll_psystem": (lambda u0, v0, t, cfl: hll_psystem(SYSTEM, u0, v0, EDGES, t, cfl),
                    [("u0", np.full(10, 0.3), "array"), ("v0", np.linspace(-0.1, 0.1, 10), "array"),
                     ("t", 0.1, "scalar"), ("cfl", 0.9, "scalar")]),
    "invariants_from_conservative": (lambda u, v: invariants_from_conservative(SYSTEM, u, v),
                                     [("u", np.full(10, 0.3), "array"), ("v", np.zeros(10), "array")]),
    "upwind_diagonal": (lambda w0, t, cfl: upwind_diagonal(SYSTEM, w0, EDGES, t, cfl),
                        [("w0", np.vstack([np.linspace(0.1, 0.2, 10), np.linspace(0.3, 0.4, 10)]), "array"),
                         ("t", 0.1, "scalar"), ("cfl", 0.9, "scalar")]),
    "PSystemRiemann.cell_averages": (_riemann_cells, [("x_edges", EDGES, "array"), ("t", 0.5, "scalar")]),
    "mspd_exact": (lambda times: mspd_exact(psystem_initial_configuration("rarefaction", 0.0, 8), SYSTEM, times),
                   [("times", np.array([0.0, 0.5]), "array")]),
}

CLASSES = ("refused, named", "refused, unclear", "refused, plain ValueError", "answered", "silent non-finite",
           "other exception", "hang")


class _Hang(Exception):
    pass


def _alarm(signum, frame):
    raise _Hang


def classify(function, arguments, parameter, value) -> str:
    signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, CALL_SECONDS)
    try:
        result = function(*arguments)
    except _Hang:
        return "hang"
    except (ValueError, TypeError) as error:
        wrong_kind = value is None or isinstance(value, bytes)
        if wrong_kind and not isinstance(error, ParameterTypeError):
            return "refused, plain ValueError"
        return "refused, named" if parameter in str(error) else "refused, unclear"
    except BaseException:
        return "other exception"
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
    return "answered" if all_finite(result) else "silent non-finite"


def run(verbose: bool = False) -> collections.Counter:
    counts = collections.Counter()
    for name, (function, spec) in ENTRIES.items():
        valid = [value for _, value, _ in spec]
        for index, (parameter, _, kind) in enumerate(spec):
            for value in (BAD_SCALARS if kind == "scalar" else BAD_ARRAYS) + EXTREMES:
                arguments = list(valid)
                arguments[index] = value
                outcome = classify(function, arguments, parameter, value)
                counts[outcome] += 1
                if verbose and outcome not in ("refused, named", "answered"):
                    print(f"{outcome:26} {name}({parameter} = {value!r:.40})")
    return counts


if __name__ == "__main__":
    totals = run(verbose="-v" in sys.argv)
    print(f"{sum(totals.values())} calls over {len(ENTRIES)} entry points")
    for outcome in CLASSES:
        print(f"  {outcome:26} {totals[outcome]}")
