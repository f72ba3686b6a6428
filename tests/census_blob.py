"""The census's calls (:mod:`census`) for ``particle_methods.blob``: one good call of each public callable, by
keyword (:data:`ENTRIES`, built with :class:`census.Entry`), and the callables exempt from it with the reason
(:data:`EXEMPT`). Merged into :mod:`census_entries`. Tiny sizes and short times, so that the census stays cheap."""

from __future__ import annotations

import numpy as np
from census import Entry as E
from fuzzing import Later

from particle_methods.blob import (
    aliasing,
    checks,
    exact,
    initial,
    kernels,
    mollifiers,
    newtonian_fmm,
    pair_sums,
    radial,
    rings,
    solver,
    vector_erfc,
    vector_exp,
)

PM = "particle_methods."
B = PM + "blob."
A = np.array

# Good values: a few particles, one short time step (a Later one is built on first use: fuzzing.Later).
PSI1, PSI2 = mollifiers.mollifier(4, 1), mollifiers.mollifier(4, 2)
CUBIC = kernels.kernel_1d("cubic", PSI1, 0.3)
DATA1 = initial.data_1d("smooth20")
DATA2 = initial.data_2d("regular")
TIMES = A([0.0, 0.05])
X3 = A([-0.5, 0.0, 0.5])
LINE = A([[-0.5], [0.0], [0.5]])
MASSES3 = A([0.25, 0.5, 0.25])
PLANE = A([[0.0, 0.0], [0.5, 0.0], [0.0, 0.5]])
SMALL_RUN = Later(lambda: solver.run_1d("smooth20", "cubic", 0.5, TIMES))
CUBIC_ARRAYS = dict(zip(("kinds", "coefficients", "parameters", "tables", "steps"), CUBIC.arrays()))


def QUARTIC_LAPLACIAN(r):
    """Delta of |x|^4/4 in 2D, 4 r^2: a radial Laplacian for the tables."""
    return 4.0 * np.asarray(r) ** 2


#: The parameter ``name`` of the data and kernel catalogues is the name of a datum or kernel, which their
#: refusals call by what it names ("unknown 2D data 'x'", "kernel must be one of ...").
DATA_NAME = {"name": ("data",)}
KERNEL_NAME = {"name": ("kernel",)}


ENTRIES = {
    # aliasing
    B + "aliasing.quadrature_prediction": E(aliasing.quadrature_prediction, {"data": "smooth20", "h": 0.25, "q": 0.9,
                                                                            "t": 0.5, "order": 4}),
    B + "aliasing.quadrature_prediction_terms": E(aliasing.quadrature_prediction_terms, {
        "data": "smooth20", "h": 0.25, "q": 0.9, "t": 0.5, "order": 4}),
    B + "aliasing.saddle_ratio": E(aliasing.saddle_ratio, {"data": "smooth20", "h": 0.25, "q": 0.9, "order": 4}),
    # checks, exact solutions
    B + "checks.output_times": E(checks.output_times, {"times": TIMES}),
    B + "exact.blowup_time": E(exact.blowup_time, {"data": "smooth20", "kernel": "newtonian_attractive"}),
    B + "exact.newtonian_exact": E(exact.newtonian_exact, {"data": "smooth20", "kernel": "newtonian_attractive",
                                                          "alpha": X3, "t": 0.5, "rho0": A([0.5, 1.0, 0.5])}),
    B + "exact.newtonian_exact_2d": E(exact.newtonian_exact_2d, {"data": "regular", "points": PLANE, "t": 0.5,
                                                                "rho0": A([1.0, 0.5, 0.5])}),
    # initial data
    B + "initial.Data1D": E(initial.Data1D, {"name": "x", "power": 2}, accepts={"name": ["1"]}),  # a label
    B + "initial.Data1D.__call__": E(DATA1.__call__, {"x": X3}),
    B + "initial.Data1D.mass_from_origin": E(DATA1.mass_from_origin, {"x": X3}),
    B + "initial.Data1D.moment_from_left": E(DATA1.moment_from_left, {"x": X3}),
    B + "initial.Data2D": E(initial.Data2D, {"name": "regular", "radius": 1.0}, names=DATA_NAME),
    B + "initial.Data2D.__call__": E(DATA2.__call__, {"points": PLANE}),
    B + "initial.Data2D.mass_from_origin": E(DATA2.mass_from_origin, {"r": X3}),
    B + "initial.as_data_1d": E(initial.as_data_1d, {"data": "smooth20"}),
    B + "initial.as_data_2d": E(initial.as_data_2d, {"data": "regular"}),
    B + "initial.data_1d": E(initial.data_1d, {"name": "smooth20"}, names=DATA_NAME),
    B + "initial.data_2d": E(initial.data_2d, {"name": "regular"}, names=DATA_NAME),
    B + "initial.grid_1d": E(initial.grid_1d, {"h": 0.25}),
    B + "initial.grid_2d": E(initial.grid_2d, {"h": 0.5, "data": "regular"}),
    # kernels
    B + "kernels.Kernel": E(kernels.Kernel, {"name": "k", "dimension": 1, "kinds": [kernels.POWER],
                                             "coefficients": [1.0], "parameters": [3.0], "tables": ()},
                            accepts={"name": ["1"]}),  # a label
    B + "kernels.Kernel.arrays": E(CUBIC.arrays, {}),
    B + "kernels.Kernel.profile": E(CUBIC.profile, {"r": A([0.0, 0.5, 1.0])}),
    B + "kernels.kernel_1d": E(kernels.kernel_1d, {"name": "cubic", "mollifier": PSI1, "delta": 0.3},
                              names=KERNEL_NAME),
    B + "kernels.kernel_2d": E(kernels.kernel_2d, {"name": "quartic_power", "mollifier": PSI2, "delta": 0.5,
                                                   "table_radius": 2.0, "table_points": 21}, names=KERNEL_NAME),
    # mollifiers
    B + "mollifiers.Mollifier": E(mollifiers.Mollifier, {"order": 4, "dimension": 1, "weights": [4 / 3, -1 / 3],
                                                         "widths": [1.0, 2.0]}),
    B + "mollifiers.Mollifier.__call__": E(PSI1.__call__, {"r": X3, "delta": 0.3}),
    B + "mollifiers.Mollifier.scaled_widths": E(PSI1.scaled_widths, {"delta": 0.3}),
    B + "mollifiers.Mollifier.sums_1d": E(PSI1.sums_1d, {"targets": X3, "sources": X3, "weights": MASSES3,
                                                        "delta": 0.3}),
    B + "mollifiers.mollifier": E(mollifiers.mollifier, {"order": 4, "dimension": 1}),
    # pair sums
    B + "newtonian_fmm.far_field": E(newtonian_fmm.far_field, {"positions": PLANE, "masses": MASSES3}),
    B + "newtonian_fmm.newtonian_sums": E(newtonian_fmm.newtonian_sums, {
        "positions": PLANE, "masses": MASSES3, "coefficients": A([2.0, -1.0]), "widths": A([0.5, 0.7])}),
    B + "pair_sums.pair_sums": E(pair_sums.pair_sums, {"positions": LINE, "masses": MASSES3, **CUBIC_ARRAYS,
                                                       "newtonian_2d": "auto"}),
    B + "pair_sums.checked_terms": E(pair_sums.checked_terms, {"dimension": 1, **CUBIC_ARRAYS}),
    # radial tables, rings
    B + "radial.RadialTable": E(radial.RadialTable, {"radius": 1.0, "gradient": A([1.0, 0.5, 0.2]),
                                                     "laplacian": A([2.0, 0.5, 0.1])}),
    B + "radial.mollified_laplacian": E(radial.mollified_laplacian, {"laplacian": QUARTIC_LAPLACIAN, "mollifier": PSI2,
                                                                     "delta": 0.5, "r": A([0.0, 0.5, 1.0])}),
    B + "radial.tabulate": E(radial.tabulate, {"laplacian": QUARTIC_LAPLACIAN, "mollifier": PSI2, "delta": 0.5,
                                               "radius": 2.0, "points": 21}),
    B + "rings.sine_power_integral": E(rings.sine_power_integral, {"a": 2.0, "name": "a"}, kinds={"name": "fixed"}),
    B + "rings.uniform_ring_radius": E(rings.uniform_ring_radius, {"a": 4.0, "b": 1.5}),
    # solver
    B + "solver.BlobRun": E(solver.BlobRun, {"kernel": CUBIC, "h": 0.5, "times": TIMES,
                                             "positions": SMALL_RUN.positions, "densities": SMALL_RUN.densities,
                                             "masses": SMALL_RUN.masses, "evaluations": 3},
                            accepts={"h": [None], "densities": [None]}),
    B + "solver.BlobRun.energies": E(SMALL_RUN.energies, {}),
    B + "solver.integrate_particles": E(solver.integrate_particles, {
        "points": LINE, "densities0": A([0.5, 1.0, 0.5]), "masses": MASSES3, "kernel": CUBIC, "times": TIMES,
        "with_density": True, "rtol": 1e-8, "atol": 1e-10, "h": 0.5, "newtonian_2d": "auto"}),
    B + "solver.mass_defect": E(solver.mass_defect, {
        "points": LINE, "rho0": A([0.5, 1.0, 0.5]), "masses": MASSES3, "kernel": CUBIC, "t": 0.05,
        "offset": 1e-5, "rtol": 1e-8, "atol": 1e-10, "threshold": 1e-3}),
    B + "solver.run_1d": E(solver.run_1d, {"data": "smooth20", "kernel": "cubic", "h": 0.5, "times": TIMES,
                                           "method": "blob", "order": 4, "q": 0.9, "rtol": 1e-8, "atol": 1e-10}),
    B + "solver.run_2d": E(solver.run_2d, {"data": "regular", "kernel": "newtonian", "h": 0.5, "times": TIMES,
                                           "method": "blob", "q": 0.9, "delta": 0.5, "rtol": 1e-8, "atol": 1e-10,
                                           "table_radius": 2.0, "table_points": 21}),
    B + "solver.setup_1d": E(solver.setup_1d, {"data": "smooth20", "kernel": "cubic", "h": 0.5, "method": "blob",
                                               "order": 4, "q": 0.9}),
    B + "solver.setup_2d": E(solver.setup_2d, {"data": "regular", "kernel": "newtonian", "h": 0.5,
                                               "method": "blob", "q": 0.9, "delta": 0.5, "table_radius": 2.0,
                                               "table_points": 21}),
    # the array wrappers of the vectorised special functions
    B + "vector_erfc.erfc_and_gauss_array": E(vector_erfc.erfc_and_gauss_array, {"z": A([0.0, 0.5, 3.0])}),
    B + "vector_exp.checked_argument": E(vector_exp.checked_argument, {"z": A([0.0, 0.5, 3.0]), "limit": 10.0},
                                                 kinds={"limit": "fixed"}),  # the wrapper's constant Z_LIMIT
    B + "vector_exp.exp_minus_and_complement_array": E(vector_exp.exp_minus_and_complement_array,
                                                       {"z": A([0.0, 0.5, 3.0])}),
}

#: Compiled helpers and predicates of the pair sums that trust their caller's checks (their docstrings say so:
#: CONTRIBUTING, "Names"); their callers (pair_sums, the array wrappers, BlobRun.energies) are in the census.
TRUSTING = ("kernels.is_newtonian_2d", "kernels.radial_power", "pair_sums.checked_pair_sums", "pair_sums.pair_energy",
            "pair_sums.tiled_2d_supported", "pair_sums.newtonian_2d_forces", "newtonian_fmm.near_field",
            "newtonian_fmm.near_sums", "newtonian_fmm.squarings", "pair_sums.newtonian_2d_constants",
            "special.dawson", "special.dawson_and_slope", "special.exp1", "sums_1d.far_coefficients",
            "sums_1d.log_series", "sums_1d.log_supported", "sums_1d.sorted_log_sums", "sums_1d.sorted_sums",
            "sums_1d.supported", "tile_sums.row_share", "vector_erfc.erfc_and_gauss",
            "vector_exp.exp_minus_and_complement")
EXEMPT = {B + name: "trusts its caller's checks (its docstring says so)" for name in TRUSTING}
