"""The census's calls (:mod:`census`): one good call of every public callable of ``particle_methods``, by keyword,
and the callables exempt from it with the reason. Tiny sizes and short times, so that the whole census stays cheap.
"""

from __future__ import annotations

import numpy as np
from census import Entry as E

from particle_methods import convergence, jit, norms, perturbation, systems, threads, validation
from particle_methods.blob import aliasing, checks, exact, initial, kernels, mollifiers, newtonian_fmm, pair_sums
from particle_methods.blob import radial, rings, solver, sums_1d, vector_erfc, vector_exp
from particle_methods.cross import aggregates, distances, hull, methods, profiles
from particle_methods.cross import exact as cross_exact
from particle_methods.finite_volume import fluxes, grids, psystem, riemann, scalar
from particle_methods.ltp import checks as ltp_checks
from particle_methods.ltp import exact as ltp_exact
from particle_methods.ltp import initial as ltp_initial
from particle_methods.ltp import kernels as ltp_kernels
from particle_methods.ltp import measures as ltp_measures
from particle_methods.ltp import potentials, shapes, theorems
from particle_methods.ltp import solver as ltp_solver
from particle_methods.sticky import admissibility, cases, events, hopf, hull_reference, measures, mspd
from particle_methods.sticky import exact as sticky_exact
from particle_methods.sticky import multitype_events, spd, theory

PM = "particle_methods."
A = np.array

# Shared good values.
PSI1, PSI2 = mollifiers.mollifier(4, 1), mollifiers.mollifier(4, 2)
CUBIC = kernels.kernel_1d("cubic", PSI1, 0.3)
LINE = np.linspace(-1.0, 1.0, 5)[:, None]
SMALL_RUN = solver.run_1d("smooth20", "cubic", 0.5, [0.0, 0.05])
DATA1 = initial.data_1d("smooth20")
DATA2 = initial.data_2d("regular")
SYSTEM = systems.PSystem(nu=1.0, kappa=1.0)
EDGES = np.linspace(-1.0, 1.0, 11)
CROSS = cross_exact.AggregationSolution("smooth20", 0.5)
HULL = hull.HullSolution("two_bumps", 1.2)
BUMP = hull.Bump(1.0, 0.0, 1.0, 2)
BUMPS = hull.bump_data("two_bumps")
SPD_X, SPD_M = methods.spd_grid("smooth20", 1 / 8, 0.5)
RANGES = aggregates.level_ranges(HULL)
LAPLACE = measures.Laplace()
X3 = A([-1.0, 0.0, 1.0])
V3 = A([1.0, 0.0, -1.0])
CONFIG = cases.psystem_initial_configuration("rarefaction", 0.0, 4)
RHO2 = ltp_initial.density_named("rho2")
QUADRATIC = potentials.potential("quadratic")
POWER = potentials.potential("power", a=1.5)
SIM = ltp_solver.simulate("rho2", POWER, 0.25, 0.05, 0.1, record_every=1)
PARTICLES = SIM.at(0)
B3 = shapes.B3
BURGERS = fluxes.BURGERS
SCALAR_CASE = cases.SCALAR_CASES["burgers_two_atoms"]
TIMES = A([0.0, 0.05])
KINDS_1D, COEFFICIENTS_1D, PARAMETERS_1D, TABLES_1D, STEPS_1D = CUBIC.arrays()
KINDS_2D = kernels.kernel_2d("newtonian", PSI2, 0.5).arrays()


def method(factory, name):
    """The bound method ``name`` of a fresh good instance (a function of the census's keyword arguments)."""
    return getattr(factory(), name)


def V(function, **good):
    """A check of :mod:`particle_methods.validation`: the name (and the limits) are the caller's constants, and the
    message names the value by the name given (``x``)."""
    fixed = {"name", "ndim", "minimum", "maximum", "low", "high", "what", "cause", "kind", "table"}
    return E(function, good, kinds={key: "fixed" for key in good if key in fixed},
             names={key: ("x",) for key in good})


ENTRIES = {
    # validation
    PM + "validation.finite_values": V(validation.finite_values, name="x", values=X3),
    PM + "validation.finite_array": V(validation.finite_array, name="x", values=X3, ndim=1),
    PM + "validation.sorted_array": V(validation.sorted_array, name="x", values=X3, ndim=1),
    PM + "validation.finite_number": V(validation.finite_number, name="x", value=1.0),
    PM + "validation.positive": V(validation.positive, name="x", value=1.0),
    PM + "validation.nonnegative": V(validation.nonnegative, name="x", value=1.0),
    PM + "validation.integer_at_least": V(validation.integer_at_least, name="x", value=3, minimum=1, maximum=10),
    PM + "validation.in_interval": V(validation.in_interval, name="x", values=X3, low=-1.0, high=1.0),
    PM + "validation.one_of": V(validation.one_of, what="x", name="a", table={"a": 1}),
    # shared
    PM + "norms.w1_to_measure": E(norms.w1_to_measure, {"measure": LAPLACE, "points": X3}),
    PM + "norms.w1_between_samples": E(norms.w1_between_samples, {"x": X3, "y": V3}),
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
    PM + "threads.use_threads": E(lambda count: threads.use_threads(count) and threads.use_threads(1), {"count": 1},
                                   accepts={"count": [10**400]}),  # clamped to the available threads
    PM + "threads.numba_threads": E(lambda count: threads.numba_threads(count).__enter__(), {"count": 1},
                                      accepts={"count": [10**400]}),
    PM + "threads.threads_for": E(threads.threads_for, {"size": 10, "threshold": 100},
                                    accepts={"size": [10**400], "threshold": [10**400]}),
    PM + "threads.available": E(threads.available, {}),
}

EXEMPT = {
    PM + "validation.real_array": "a type check only (finiteness is finite_values' check): NaN passes by design",
    PM + "validation.instance": "a type check only: any value of the type passes by design",
    PM + "validation.same_length": "takes arrays its caller has checked (every caller passes checked arrays)",
    PM + "validation.finite_result": "checks a result the caller computed from checked inputs",
    PM + "validation.ParameterTypeError": "an exception type",
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
