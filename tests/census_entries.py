"""The census's calls (:mod:`census`): one good call of every public callable of ``particle_methods``, by keyword,
and the callables exempt from it with the reason. Tiny sizes and short times, so that the whole census stays cheap.
"""

from __future__ import annotations

import census_blob
import census_cross
import census_finite_volume
import census_ltp
import numpy as np
from census import Entry as E
from census import nan_function

from particle_methods import convergence, norms, perturbation, systems, threads, validation
from particle_methods.finite_volume import fluxes
from particle_methods.finite_volume import grids as fv_grids
from particle_methods.finite_volume import scalar as fv_scalar
from particle_methods.sticky import (
    admissibility,
    cases,
    events,
    hopf,
    hull_reference,
    measures,
    mspd,
    multitype_events,
    spd,
    theory,
)
from particle_methods.sticky import exact as sticky_exact

PM = "particle_methods."
A = np.array


def restoring_threads(call):
    """``call`` (which sets the process's thread count) with the count it found restored after it, so that the
    census leaves its worker's later tests the threads they expect."""
    def restored(count):
        before = threads.numba.get_num_threads()
        try:
            return call(count)
        finally:
            threads.use_threads(before)
    return restored


# Shared good values (the census's parts keep their own: tests/census_blob.py and the others).
SYSTEM = systems.PSystem(nu=1.0, kappa=1.0)
EDGES = np.linspace(-1.0, 1.0, 11)
LAPLACE = measures.Laplace()
X3 = A([-1.0, 0.0, 1.0])
V3 = A([1.0, 0.0, -1.0])
CONFIG = cases.psystem_initial_configuration("rarefaction", 0.0, 4)
BURGERS = fluxes.BURGERS
SCALAR_CASE = cases.SCALAR_CASES["burgers_two_atoms"]
TIMES = A([0.0, 0.05])


def method(factory, name):
    """The bound method ``name`` of a fresh good instance (a function of the census's keyword arguments)."""
    return getattr(factory(), name)


def V(function, **good):
    """A check of :mod:`particle_methods.validation`: the name (and the limits) are the caller's constants, and the
    message names the value by the name given (``x``)."""
    fixed = {"name", "ndim", "minimum", "maximum", "low", "high", "what", "cause", "kind", "table", "limit",
             "limit_name", "why"}
    return E(function, good, kinds={key: "fixed" for key in good if key in fixed},
             names={key: ("x",) for key in good})


def NO_COLLISION(record):
    """The record without its documented sentinel: largest_collision_gap is -inf when no pair collided."""
    return record._replace(largest_collision_gap=0.0) if record.collisions.sum() == 0 else record


COUNTS = ("merges", "crossings", "splits", "member_updates")

ENTRIES = {
    # validation
    PM + "validation.finite_values": V(validation.finite_values, name="x", values=X3),
    PM + "validation.finite_array": V(validation.finite_array, name="x", values=X3, ndim=1),
    PM + "validation.sorted_array": V(validation.sorted_array, name="x", values=X3, ndim=1),
    PM + "validation.finite_number": V(validation.finite_number, name="x", value=1.0),
    PM + "validation.positive": V(validation.positive, name="x", value=1.0),
    PM + "validation.nonnegative": V(validation.nonnegative, name="x", value=1.0),
    PM + "validation.integer_at_least": V(validation.integer_at_least, name="x", value=3, minimum=1, maximum=10),
    PM + "validation.time_within": V(validation.time_within, name="x", value=1.0, limit=2.0, limit_name="MAX_TIME",
                                      why="a limit"),
    PM + "validation.in_interval": V(validation.in_interval, name="x", values=X3, low=-1.0, high=1.0),
    PM + "validation.one_of": V(validation.one_of, what="x", name="a", table={"a": 1}),
    # shared
    PM + "norms.w1_to_measure": E(norms.w1_to_measure, {"measure": LAPLACE, "points": X3}),
    PM + "norms.w1_between_samples": E(norms.w1_between_samples, {"x": X3, "y": X3 + 0.5}),
    PM + "norms.grid_errors": E(norms.grid_errors, {"values": X3, "reference": V3, "x": X3}),
    PM + "norms.discrete_l1": E(norms.discrete_l1, {"values": X3, "reference": V3, "h": 0.1, "dimension": 1}),
    PM + "norms.check_within_range": E(norms.check_within_range, {"name": "x", "x": X3, "mass": 1.0},
                                       kinds={"name": "fixed"}),
    PM + "norms.cdf_antiderivative": E(norms.cdf_antiderivative, {"measure": LAPLACE, "x": X3, "mass": 1.0},
                                       accepts={"mass": [None]}),
    PM + "norms.l1_to_step_function": E(norms.l1_to_step_function, {"measure": LAPLACE, "breaks": X3,
                                                                     "values": A([0.5, 0.7, 1.0])}),
    PM + "norms.tail_integrals": E(norms.tail_integrals, {"measure": LAPLACE, "left": -1.0, "right": 1.0}),
    PM + "convergence.fit_order": E(convergence.fit_order, {"steps": A([0.1, 0.05, 0.025]),
                                                            "errors": A([1e-2, 2.5e-3, 6e-4])}),
    PM + "convergence.pairwise_orders": E(convergence.pairwise_orders, {"steps": A([0.1, 0.05, 0.025]),
                                                                        "errors": A([1e-2, 2.5e-3, 6e-4])}),
    PM + "convergence.order_table": E(convergence.order_table, {"steps": A([0.1, 0.05]), "errors": A([1e-2, 2e-3]),
                                                                "step_name": "h"},
                                           kinds={"step_name": "fixed"}),
    PM + "perturbation.set_nudge": E(lambda ulps, seed: perturbation.set_nudge(ulps, seed) or
                                     perturbation.set_nudge(0), {"ulps": 2, "seed": 0},
                                     accepts={"seed": [10**400]}),
    PM + "perturbation.nudge": E(lambda ulps, seed: perturbation.nudge(ulps, seed).__enter__() or
                                 perturbation.set_nudge(0), {"ulps": 2, "seed": 0}, accepts={"seed": [10**400]}),
    PM + "perturbation.nudged": E(perturbation.nudged, {"values": X3}),
    PM + "threads.use_threads": E(restoring_threads(threads.use_threads), {"count": 1},
                                   names={"count": ("threads",)}, accepts={"count": [10**400]}),  # clamped
    PM + "threads.numba_threads": E(restoring_threads(lambda count: threads.numba_threads(count).__enter__()),
                                      {"count": 1}, accepts={"count": [10**400]}),
    PM + "threads.threads_for": E(threads.threads_for, {"size": 10, "threshold": 100},
                                    accepts={"size": [10**400], "threshold": [10**400]}),
    PM + "threads.available": E(threads.available, {}),
    PM + "threads.pool": E(threads.pool, {"workers": 1}, accepts={"workers": [10**400]}),
    # sticky
    PM + "sticky.admissibility.Admissibility": E(admissibility.Admissibility, {"rankine_hugoniot": 0.1, "entropy": 0.0,
                                                                                "speed_scale": 1.0, "clusters": 2},
                                                 accepts={"clusters": [10**400]}),
    PM + "sticky.admissibility.flux_values": E(admissibility.flux_values, {"flux": fluxes.burgers_flux,
                                                                          "states": A([0.0, 0.5])}),
    PM + "sticky.admissibility.checked_sampling": E(admissibility.checked_sampling, {
        "n": 4, "flux": fluxes.burgers_flux, "points": 4, "fewest_points": 1},
        # it checks that the flux is callable and never calls it: flux_values checks the values where it is called
        accepts={"flux": [nan_function]}),
    PM + "sticky.admissibility.mass_levels": E(admissibility.mass_levels, {"masses": A([0.5, 0.5]),
                                                                          "particles": A([0.0, 1.0]),
                                                                          "order": A([0, 1])}),
    PM + "sticky.admissibility.admissibility_violation": E(admissibility.admissibility_violation, {
        "positions": A([0.0, 0.0, 1.0]), "velocities": A([0.5, 0.5, -1.0]), "flux": fluxes.burgers_flux,
        "masses": A([0.25, 0.25, 0.5]), "points": 4}),
    PM + "sticky.admissibility.spd_state": E(admissibility.spd_state, {"x": X3, "v": V3, "t": 0.5, "masses": None}),
    PM + "sticky.multitype_events.EventCounts": E(multitype_events.EventCounts, {"merges": 1, "crossings": 2,
                                                                                "splits": 0, "member_updates": 3},
                                                     accepts={key: [10**400] for key in COUNTS}),
    PM + "sticky.events.sticky_collisions": E(events.sticky_collisions, {"x": X3, "v": V3, "t": 0.5,
                                                                        "masses": A([1.0, 1.0, 1.0])}),
    PM + "sticky.hopf.hopf_gap": E(hopf.hopf_gap, {"initial": X3, "positions": spd.spd_positions(X3, V3, 0.5),
                                                  "t": 0.5, "flux": fluxes.burgers_flux, "masses": None, "points": 4}),
    PM + "sticky.hull_reference.HullIteration": E(hull_reference.HullIteration, {"k": 1, "before": (0,), "removed": (),
                                                                                "after": (0, 1)}),
    PM + "sticky.hull_reference.cumulative_free_positions": E(hull_reference.cumulative_free_positions,
                                                              {"x": X3, "v": V3, "t": 0.5}),
    PM + "sticky.hull_reference.hull_vertices": E(hull_reference.hull_vertices, {"q": A([0.0, 1.0, 1.5, 3.0])}),
    PM + "sticky.hull_reference.spd_positions_python": E(hull_reference.spd_positions_python, {"x": X3, "v": V3,
                                                                                              "t": 0.5}),
    PM + "sticky.measures.QuantileMeasure.quantile": E(LAPLACE.quantile, {"w": A([0.1, 0.5, 0.9])}),
    PM + "sticky.measures.QuantileMeasure.quantile_integral": E(LAPLACE.quantile_integral, {"w": A([0.0, 0.5, 1.0])}),
    PM + "sticky.measures.QuantileMeasure.cdf": E(LAPLACE.cdf, {"x": X3}),
    PM + "sticky.measures.checked_measure": E(measures.checked_measure, {"name": "measure", "measure": LAPLACE},
                                              kinds={"name": "fixed"}),
    PM + "sticky.measures.Atoms": E(measures.Atoms, {"positions": X3, "weights": A([0.2, 0.3, 0.5])}),
    PM + "sticky.measures.Laplace": E(measures.Laplace, {"loc": 0.0}),
    PM + "sticky.measures.Uniform": E(measures.Uniform, {"a": 0.0, "b": 1.0}),
    PM + "sticky.measures.TruncatedExponential": E(measures.TruncatedExponential, {"b": 1.0}),
    PM + "sticky.measures.Pareto": E(measures.Pareto, {"alpha": 2.0}),
    PM + "sticky.measures.TruncatedPareto": E(measures.TruncatedPareto, {"alpha": 2.0, "upper": 3.0}),
    PM + "sticky.measures.Weibull": E(measures.Weibull, {"alpha": 2.0}),
    PM + "sticky.measures.median_quantiles": E(measures.median_quantiles, {"measure": LAPLACE, "n": 4}),
    PM + "sticky.measures.averaged_quantiles": E(measures.averaged_quantiles, {"measure": LAPLACE, "n": 4}),
    PM + "sticky.mspd.ScalarLaw": E(mspd.ScalarLaw, {"flux": fluxes.burgers_flux}),
    PM + "sticky.mspd.ScalarLaw.speed_primitive": E(mspd.ScalarLaw(fluxes.burgers_flux).speed_primitive,
                                                    {"gamma": 0, "levels": A([[0.0], [0.5]])}),
    PM + "sticky.mspd.checked_configuration": E(mspd.checked_configuration, {"name": "x", "x": CONFIG,
                                                                            "system": SYSTEM}, kinds={"name": "fixed"}),
    PM + "sticky.mspd.rank_velocities": E(mspd.rank_velocities, {"x": CONFIG, "system": SYSTEM}),
    PM + "sticky.mspd.mspd_trajectory": E(mspd.mspd_trajectory, {"x0": CONFIG, "system": SYSTEM, "delta": 0.05,
                                                                "steps": 2}),
    PM + "sticky.mspd.mspd_positions": E(mspd.mspd_positions, {"x0": CONFIG, "system": SYSTEM, "delta": 0.05,
                                                              "steps": 2}),
    PM + "sticky.spd.checked_state": E(spd.checked_state, {"x": X3, "v": V3}),
    PM + "sticky.spd.checked_masses": E(spd.checked_masses, {"masses": A([1.0, 2.0, 1.0]), "x": X3}),
    PM + "sticky.spd.check_reach": E(spd.check_reach, {"x": X3, "speed": 1.0, "t": 0.5}),
    PM + "sticky.spd.spd_trajectories": E(spd.spd_trajectories, {"x": X3, "v": V3, "times": TIMES, "masses": None}),
    PM + "sticky.spd.cluster_sizes": E(spd.cluster_sizes, {"positions": A([0.0, 0.0, 1.0])}),
    PM + "sticky.spd.velocities_from_flux": E(spd.velocities_from_flux, {"flux": fluxes.burgers_flux, "n": 4}),
    PM + "sticky.spd.velocities_from_levels": E(spd.velocities_from_levels, {"flux": fluxes.burgers_flux,
                                                                            "levels": A([0.0, 0.5, 1.0])}),
    PM + "sticky.theory.cubic_flux": E(theory.cubic_flux, {"u": A([0.0, 0.5, 1.0])}),
    PM + "sticky.theory.CubicDiracSolution": E(theory.CubicDiracSolution, {"position": 0.0, "t": 0.5}),
    PM + "sticky.theory.empirical_atoms": E(theory.empirical_atoms, {"x": X3}),
    PM + "sticky.theory.duplicated": E(theory.duplicated, {"x": X3}),
    PM + "sticky.theory.sampled_configuration": E(theory.sampled_configuration, {
        "measures": [LAPLACE, LAPLACE], "n": 3, "rng": np.random.default_rng(1)}, kinds={"measures": "object"}),
    PM + "sticky.theory.SystemConstants": E(theory.SystemConstants, {"d": 2, "speed_bound": 1.0, "hyperbolicity": 0.5,
                                                                    "lipschitz": 1.0, "crossings_bound": 1}),
    PM + "sticky.theory.psystem_constants": E(theory.psystem_constants, {"system": SYSTEM}),
    PM + "sticky.theory.CollisionRecord": E(theory.CollisionRecord, {
        "collisions": A([1.0]), "step_distances": A([0.1]), "pair_counts": A([1.0]), "smallest_shrink": 0.5,
        "largest_collision_gap": 0.1, "mspd_distances": A([0.1]), "extent": 1.0}),
    PM + "sticky.theory.collision_record": E(theory.collision_record, {"x0": CONFIG, "system": SYSTEM, "delta": 0.05,
                                                                      "steps": 2}, documented=NO_COLLISION),
    PM + "sticky.theory.doubling_distance": E(theory.doubling_distance, {"flux": fluxes.burgers_flux, "x": X3,
                                                                        "t": 0.5}),
    PM + "sticky.exact.lambert_w0": E(sticky_exact.lambert_w0, {"z": A([-0.3, -0.1, 0.0])}),
    PM + "sticky.exact.BurgersSolution": E(sticky_exact.BurgersSolution, {"initial": LAPLACE, "t": 0.5}),
    PM + "sticky.exact.ConcaveLaplaceSolution": E(sticky_exact.ConcaveLaplaceSolution, {"t": 0.5}),
    PM + "sticky.cases.ScalarCase": E(cases.ScalarCase, {"initial": LAPLACE, "flux": fluxes.burgers_flux,
                                                         "solution": SCALAR_CASE.solution, "flux_lipschitz": 1.0}),
    PM + "sticky.cases.ScalarCase.initial_state": E(SCALAR_CASE.initial_state, {"n": 4}),
    PM + "sticky.cases.ScalarCase.positions": E(SCALAR_CASE.positions, {"n": 4, "t": 0.5}),
    PM + "sticky.cases.ScalarCase.error": E(SCALAR_CASE.error, {"n": 4, "t": 0.5}),
    PM + "sticky.cases.psystem_initial_measures": E(cases.psystem_initial_measures, {"case": "rarefaction", "x0": 0.1}),
    PM + "sticky.cases.psystem_initial_configuration": E(cases.psystem_initial_configuration, {
        "case": "rarefaction", "x0": 0.1, "n": 4}),
    PM + "sticky.cases.psystem_initial_cells": E(cases.psystem_initial_cells, {"case": "rarefaction", "x0": 0.1,
                                                                              "x_edges": EDGES}),
    PM + "sticky.cases.distance_to_cells": E(cases.distance_to_cells, {
        "configuration": CONFIG, "w": cases.psystem_initial_cells("rarefaction", 0.0, EDGES), "x_edges": EDGES}),
    PM + "sticky.cases.cells_distance": E(cases.cells_distance, {
        "w_a": cases.psystem_initial_cells("rarefaction", 0.0, EDGES), "edges_a": EDGES,
        "w_b": cases.psystem_initial_cells("rarefaction", 0.1, EDGES), "edges_b": EDGES}),
    PM + "sticky.cases.cells_quantile": E(cases.cells_quantile, {"w": np.linspace(0.1, 1.0, 10), "x_edges": EDGES,
                                                                 "level": 0.5}),
    PM + "sticky.cases.configuration_distance": E(cases.configuration_distance, {"a": CONFIG, "b": CONFIG + 0.1}),
    PM + "sticky.cases.empirical_cdf": E(cases.empirical_cdf, {"points": X3, "x": A([0.5, 2.0])}),
    # systems
    PM + "systems.PSystem": E(systems.PSystem, {"nu": 1.0, "kappa": 1.0}),
    PM + "systems.PSystem.g": E(SYSTEM.g, {"u": A([0.5, 1.0])}),
    PM + "systems.PSystem.pressure": E(SYSTEM.pressure, {"u": A([0.5, 1.0])}),
    PM + "systems.PSystem.sound_speed": E(SYSTEM.sound_speed, {"u": A([0.5, 1.0])}),
    PM + "systems.PSystem.riemann_invariants": E(SYSTEM.riemann_invariants, {"u": A([0.5, 1.0]), "v": A([0.0, 0.1])}),
    PM + "systems.PSystem.physical_variables": E(SYSTEM.physical_variables, {"w_minus": A([0.0, 0.1]),
                                                                           "w_plus": A([0.2, 0.3])}),
    PM + "systems.PSystem.speeds": E(SYSTEM.speeds, {"w_minus": A([0.0, 0.1]), "w_plus": A([0.2, 0.3])}),
    PM + "systems.PSystem.speed_primitive": E(SYSTEM.speed_primitive, {"gamma": 0, "levels": A([[0.2, 0.5]])}),
    PM + "systems.checked_primitive": E(systems.checked_primitive, {"system": SYSTEM, "gamma": 0,
                                                                    "levels": A([[0.2, 0.5]])}),
    PM + "systems.checked_system": E(systems.checked_system, {"system": SYSTEM}),
    # finite volumes
    PM + "finite_volume.fluxes.burgers_flux": E(fluxes.burgers_flux, {"u": A([0.0, 0.5, 1.0])}),
    PM + "finite_volume.fluxes.concave_flux": E(fluxes.concave_flux, {"u": A([0.0, 0.5, 1.0])}),
    PM + "finite_volume.fluxes.checked_flux": E(fluxes.checked_flux, {"flux": BURGERS}),
    PM + "finite_volume.fluxes.ScalarFlux.max_speed": E(BURGERS.max_speed, {"lo": 0.0, "hi": 1.0}),
    PM + "finite_volume.fluxes.godunov_flux": E(fluxes.godunov_flux, {"flux": BURGERS, "left": A([0.0, 1.0]),
                                                                     "right": A([1.0, 0.0])}),
    PM + "finite_volume.grids.checked_edges": E(fv_grids.checked_edges, {"x_edges": EDGES, "name": "x_edges"},
                                                kinds={"name": "fixed"}),
    PM + "finite_volume.grids.uniform_width": E(fv_grids.uniform_width, {"edges": EDGES}),
    PM + "finite_volume.grids.l1_between_cell_functions": E(fv_grids.l1_between_cell_functions, {
        "values_a": np.linspace(0.0, 1.0, 10), "edges_a": EDGES, "values_b": np.linspace(0.1, 1.0, 10),
        "edges_b": EDGES}),
    PM + "finite_volume.scalar.cfl_time_step": E(fv_scalar.cfl_time_step, {"flux": BURGERS, "low": 0.0, "high": 1.0,
                                                                         "dx": 0.1, "cfl": 0.9}),
    PM + "finite_volume.scalar.godunov": E(fv_scalar.godunov, {"flux": BURGERS, "u0": np.linspace(0.0, 1.0, 10),
                                                               "x_edges": EDGES, "t": 0.1, "cfl": 0.9,
                                                               "left": None, "right": None},
                                           kinds={"left": "number", "right": "number"}),  # None: the default
    # issue46-b's
    PM + "sticky.spd.spd_positions": E(spd.spd_positions, {"x": X3, "v": V3, "t": 0.5, "masses": None}),
    PM + "sticky.multitype_events.mspd_exact": E(multitype_events.mspd_exact, {"x0": CONFIG, "system": SYSTEM,
                                                                              "times": TIMES}),
    PM + "sticky.multitype_events.mspd_exact_at": E(multitype_events.mspd_exact_at, {"x0": CONFIG, "system": SYSTEM,
                                                                                "t": 0.05, "return_method": False}),
}

EXEMPT = {
    PM + "validation.real_array": "a type check only (finiteness is finite_values' check): NaN passes by design",
    PM + "validation.instance": "a type check only: any value of the type passes by design",
    PM + "validation.same_length": "takes arrays its caller has checked (every caller passes checked arrays)",
    PM + "validation.finite_result": "checks a result the caller computed from checked inputs",
    PM + "validation.ParameterTypeError": "an exception type",
    PM + "sticky.measures.QuantileMeasure": "an abstract base class (its methods are called on Laplace)",
    PM + "blob.solver.CollisionError": "an exception type",
    PM + "ltp.solver.StabilityError": "an exception type",
    PM + "jit.njit": "a decorator of the package's own kernels (its argument is a function of the package)",
    PM + "jit.njit_threaded": "a decorator of the package's own kernels (its argument is a function of the package)",
    PM + "jit.sources_digest": "build tooling run at import on the package's own source directory",
    PM + "jit.clear_stale_caches": "build tooling run at import on the package's own cache directory",
}
#: Compiled or plain helpers that trust their caller's checks, by their name (``*_kernel``) or by their docstring
#: (CONTRIBUTING, "Names"): not entry points.
TRUSTING = {
    "finite_volume.fluxes.burgers_formula", "finite_volume.fluxes.concave_formula", "systems.pressure_formula",
    "systems.sound_speed_formula", "systems.speed_primitive_formula", "systems.speed_primitives_into",
    "sticky.theory.cubic_speed", "ltp.kernels.convolution_sums", "ltp.kernels.shape_moments",
    "blob.sums_1d.pair_sums_1d", "blob.sums_1d.log_pair_sums_1d",
}
EXEMPT.update({PM + name: "trusts its caller's checks (its docstring says so)" for name in TRUSTING})

# The parts of the census kept in files of their own (one per subpackage).
for part in (census_blob, census_ltp, census_cross, census_finite_volume):
    ENTRIES.update(part.ENTRIES)
    EXEMPT.update(part.EXEMPT)
