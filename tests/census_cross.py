"""The census's calls (:mod:`census`) for ``particle_methods.cross``: one good call of each public callable, by
keyword (:data:`ENTRIES`, built with :class:`census.Entry`), and the callables exempt from it with the reason
(:data:`EXEMPT`). Merged into :mod:`census_entries`. Tiny sizes and short times, so that the census stays cheap."""

from __future__ import annotations

import numpy as np
from census import Entry as E
from fuzzing import Later

from particle_methods.cross import aggregates, distances, exact, hull, methods, profiles

PM = "particle_methods."
A = np.array

# Good values: the cheapest data and the coarsest grids (h = 1/4: 7 to 9 particles, 8 to 16 cells); a Later one is
# built on first use (fuzzing.Later).
SMOOTH = Later(lambda: exact.AggregationSolution("smooth20", 0.5))
BUMP = hull.Bump(2.0, -0.4, 0.3, 2)
#: Two indicator bumps: a hull solution of these costs a few ms (two_bumps: about 50 ms), and they merge at t = 1.25.
PAIR = hull.BumpData("pair", (hull.Bump(2.0, -0.5, 0.2, 0), hull.Bump(2.0, 0.5, 0.2, 0)))
HULL = Later(lambda: hull.HullSolution(PAIR, 1.0))
ATOMS = A([-0.5, -0.1, 0.1, 0.5])
ATOM_MASSES = A([0.3, 0.5, 0.5, 0.3])
SPD = Later(lambda: methods.spd_equal("smooth20", 4, 0.5))
SPD_X, SPD_M = SPD[0], SPD[1]
EDGES = np.linspace(-1.0, 1.0, 9)
F_VALUES = np.linspace(0.02, 0.37, 8)
PARTICLES = Later(lambda: methods.ltp_method("smooth20", 0.25, 0.125, 0.25))
LEVELS = A([0.0, 0.1, 0.2])
POLYNOMIAL = profiles.PROFILES["smooth20"]
# The two-particle pair of spd_merger: heavy clusters at -0.5 and 0.5 that meet at t = 1.
MERGING = {"x0": A([-0.5, 0.5]), "velocities": A([0.5, -0.5]), "masses": A([1.0, 1.0])}


ENTRIES = {
    # aggregates
    PM + "cross.aggregates.cell_atoms": E(aggregates.cell_atoms, {"edges": EDGES, "values": F_VALUES,
                                                                  "mass": 0.389}),
    PM + "cross.aggregates.first_within": E(aggregates.first_within, {"times": A([0.0, 1.0, 2.0]),
                                                                      "gaps": A([2.0, 1.0, 0.0]), "threshold": 0.5}),
    PM + "cross.aggregates.gap_path": E(aggregates.gap_path, {"positions": ATOMS, "masses": ATOM_MASSES,
                                                              "ranges": A([[0.0, 0.8], [0.8, 1.6]])}),
    PM + "cross.aggregates.godunov_merger": E(aggregates.godunov_merger, {"data": PAIR, "cells": 16, "low": 0.75,
                                                                          "high": 1.5, "cfl": 0.9, "chunk": 16},
                                              kinds={"data": "object"}),
    PM + "cross.aggregates.heavy_clusters": E(aggregates.heavy_clusters, {"positions": ATOMS, "masses": ATOM_MASSES,
                                                                          "share": 0.2}),
    PM + "cross.aggregates.level_centres": E(aggregates.level_centres, {"positions": ATOMS, "masses": ATOM_MASSES,
                                                                        "ranges": A([[0.0, 0.8], [0.8, 1.6]])}),
    PM + "cross.aggregates.level_ranges": E(aggregates.level_ranges, {"solution": HULL}),
    PM + "cross.aggregates.level_spreads": E(aggregates.level_spreads, {
        "positions": ATOMS, "masses": ATOM_MASSES, "ranges": A([[0.0, 0.8], [0.8, 1.6]]), "targets": A([-0.3, 0.3])}),
    PM + "cross.aggregates.spd_merger": E(aggregates.spd_merger, {**MERGING, "low": 0.5, "high": 1.5, "share": 0.4}),
    PM + "cross.aggregates.two_body_gap": E(aggregates.two_body_gap, {"order": 4}),
    # distances
    PM + "cross.distances.w1_atoms": E(distances.w1_atoms, {"solution": SMOOTH, "positions": SPD_X,
                                                            "masses": SPD_M}),
    PM + "cross.distances.w1_cells": E(distances.w1_cells, {"solution": SMOOTH, "edges": EDGES, "values": F_VALUES}),
    PM + "cross.distances.w1_particles": E(distances.w1_particles, {"solution": SMOOTH, "particles": PARTICLES}),
    PM + "cross.distances.w1_smooth": E(distances.w1_smooth, {
        "solution": SMOOTH, "cumulative": PARTICLES.cumulative_mass, "breaks": A([-1.5, 0.0, 1.5]), "largest": 0.5}),
    # exact
    PM + "cross.exact.AggregationSolution": E(exact.AggregationSolution, {"data": "smooth20", "t": 0.5}),
    PM + "cross.exact.AggregationSolution.antiderivative": E(SMOOTH.antiderivative, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.exact.AggregationSolution.cdf": E(SMOOTH.cdf, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.exact.AggregationSolution.quantile": E(SMOOTH.quantile, {"w": LEVELS}),
    PM + "cross.exact.AggregationSolution.quantile_integral": E(SMOOTH.quantile_integral, {"w": LEVELS}),
    PM + "cross.exact.exact_mass_function": E(exact.exact_mass_function, {"data": "smooth20", "t": 0.5,
                                                                          "x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.exact.solution": E(exact.solution, {"data": "smooth20", "t": 0.5}),
    # hull
    PM + "cross.hull.Bump": E(hull.Bump, {"height": 2.0, "centre": -0.4, "radius": 0.3, "power": 2,
                                          "right_radius": 0.2}, accepts={"right_radius": [None]}),
    PM + "cross.hull.Bump.dense_interval": E(BUMP.dense_interval, {"t": 1.0}),
    PM + "cross.hull.Bump.density": E(BUMP.density, {"a": A([-0.5, -0.4, 0.0])}),
    PM + "cross.hull.Bump.left_integrals": E(BUMP.left_integrals, {"a": A([-0.5, -0.4, 0.0])}),
    PM + "cross.hull.Bump.scaled": E(BUMP.scaled, {"a": A([-0.5, -0.4, 0.0])}),
    PM + "cross.hull.BumpData": E(hull.BumpData, {"name": "pair", "bumps": PAIR.bumps},
                                  accepts={"name": ["1"]}),  # a label: any text
    PM + "cross.hull.BumpData.cdf": E(PAIR.cdf, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.hull.BumpData.density": E(PAIR.density, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.hull.BumpData.in_bump": E(PAIR.in_bump, {"index": 1, "a": A([0.4, 0.5])}),
    PM + "cross.hull.HullSolution": E(hull.HullSolution, {"data": PAIR, "t": 1.0}, kinds={"data": "object"}),
    PM + "cross.hull.HullSolution.antiderivative": E(HULL.antiderivative, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.hull.HullSolution.cdf": E(HULL.cdf, {"x": A([-0.5, 0.0, 0.5])}),
    PM + "cross.hull.HullSolution.quantile": E(HULL.quantile, {"w": LEVELS}),
    PM + "cross.hull.HullSolution.quantile_integral": E(HULL.quantile_integral, {"w": LEVELS}),
    PM + "cross.hull.aggregate_paths": E(hull.aggregate_paths, {"data": PAIR, "times": A([0.5, 1.0])},
                                         kinds={"data": "object"}),
    PM + "cross.hull.bump_data": E(hull.bump_data, {"data": "two_bumps"}),
    PM + "cross.hull.check_hull_work": E(hull.check_hull_work, {"data": PAIR, "solutions": 2, "name": "times"},
                                         kinds={"data": "object", "name": "fixed"},
                                         names={"solutions": ("times",)}),  # the errors name the caller's parameter
    PM + "cross.hull.merger_time": E(hull.merger_time, {"data": PAIR, "low": 1.0, "high": 1.5},
                                     kinds={"data": "object"}),
    # methods
    PM + "cross.methods.aggregation_flux": E(methods.aggregation_flux, {"mass": 1.0}),
    PM + "cross.methods.blob_method": E(methods.blob_method, {"data": "smooth20", "h": 0.25, "t": 0.25, "order": 4,
                                                              "q": 0.9, "rtol": 1e-6, "atol": 1e-8}),
    PM + "cross.methods.blob_paths": E(methods.blob_paths, {"data": "smooth20", "h": 0.25, "times": A([0.0, 0.25]),
                                                            "order": 4, "q": 0.9, "rtol": 1e-6, "atol": 1e-8}),
    PM + "cross.methods.godunov_advance": E(methods.godunov_advance, {"edges": EDGES, "values": F_VALUES,
                                                                      "mass": 0.389, "t": 0.1, "cfl": 0.9}),
    PM + "cross.methods.godunov_mass": E(methods.godunov_mass, {"data": "smooth20", "cells": 8, "t": 0.1,
                                                                "cfl": 0.9}),
    PM + "cross.methods.godunov_paths": E(methods.godunov_paths, {"data": "smooth20", "cells": 8,
                                                                  "times": A([0.05, 0.1]), "cfl": 0.9}),
    PM + "cross.methods.godunov_time_step": E(methods.godunov_time_step, {"edges": EDGES, "mass": 0.389,
                                                                          "cfl": 0.9}),
    PM + "cross.methods.grid_particles": E(methods.grid_particles, {"data": "smooth20", "h": 0.25}),
    PM + "cross.methods.initial_density": E(methods.initial_density, {"data": "smooth20"}),
    PM + "cross.methods.ltp_method": E(methods.ltp_method, {"data": "smooth20", "h": 0.25, "dt": 0.125, "t": 0.25,
                                                            "method": "ltp", "eps": None},
                                       kinds={"eps": "number"}, accepts={"eps": [None]}),
    PM + "cross.methods.ltp_paths": E(methods.ltp_paths, {"data": "smooth20", "h": 0.25, "dt": 0.125,
                                                          "times": A([0.0, 0.25]), "method": "ltp", "eps": None},
                                      kinds={"eps": "number"}, accepts={"eps": [None]}),
    PM + "cross.methods.particle_method": E(methods.particle_method, {"data": "smooth20", "h": 0.25, "t": 0.25,
                                                                      "rtol": 1e-6, "atol": 1e-8}),
    PM + "cross.methods.particle_velocities": E(methods.particle_velocities, {"x": SPD_X, "masses": SPD_M}),
    PM + "cross.methods.spd_equal": E(methods.spd_equal, {"data": "smooth20", "n": 4, "t": 0.5}),
    PM + "cross.methods.spd_grid": E(methods.spd_grid, {"data": "smooth20", "h": 0.25, "t": 0.5}),
    PM + "cross.methods.weighted_velocities": E(methods.weighted_velocities, {"masses": SPD_M}),
    # profiles
    PM + "cross.profiles.Profile": E(profiles.Profile, {
        "name": "p", "mass": POLYNOMIAL.mass, "peak": POLYNOMIAL.peak, "radius": 1.0, "density": POLYNOMIAL.density,
        "mass_from_origin": POLYNOMIAL.mass_from_origin, "moment_from_left": POLYNOMIAL.moment_from_left,
        "level_position": POLYNOMIAL.level_position}, accepts={"name": ["1"], "radius": [np.inf]},
        documented=lambda shape: (shape.mass, shape.peak)),  # a label: any text; radius inf: an unbounded support
    PM + "cross.profiles.monotone_root": E(profiles.monotone_root, {
        "function": np.tanh, "derivative": lambda s: 1.0 - np.tanh(s) ** 2, "target": A([0.0, 0.5]),
        "low": A([-1.0, -1.0]), "high": A([1.0, 1.0])}),
    PM + "cross.profiles.profile": E(profiles.profile, {"data": "smooth20"}),
}

EXEMPT = {
    PM + "cross.profiles.limited": "takes an array its caller has checked (its docstring: 'the checked array')",
}
