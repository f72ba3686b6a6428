"""The census's calls (:mod:`census`) for ``particle_methods.ltp``: one good call of each public callable, by
keyword (:data:`ENTRIES`, built with :class:`census.Entry`), and the callables exempt from it with the reason
(:data:`EXEMPT`). Merged into :mod:`census_entries`. Tiny sizes and short times, so that the census stays cheap."""

from __future__ import annotations

import numpy as np
from census import Entry as E
from census import nan_function
from fuzzing import Later

from particle_methods.ltp import checks, exact, initial, kernels, measures, potentials, shapes, solver, theorems

PM = "particle_methods."
A = np.array

# Good values: a handful of particles, a few steps (a Later one is built on first use: fuzzing.Later).
X3 = A([-1.0, 0.0, 1.0])
W3 = A([0.2, 0.3, 0.5])
H3 = A([0.5, 0.5, 0.5])
RHO2 = initial.density_named("rho2")
QUADRATIC = potentials.potential("quadratic")
POWER = potentials.potential("power", a=1.5)
B3, HAT = shapes.B3, shapes.HAT
SIM = Later(lambda: solver.simulate("rho2", POWER, 0.5, 0.05, 0.1, record_every=1))
PARTICLES = SIM.at(0)
LATER = SIM.at(-1)
ATOMS, MASSES = initial.golden_atoms(3, -0.9, 0.9)
# the particle arrays of the kernels, and the shape and potential arrays they read
PARTICLE = {"centres": X3, "weights": W3, "widths": H3}
PIECES = {"breaks": B3.breaks, "pieces": B3.coefficients}
TERMS = dict(zip(("coefficients", "exponents"), POWER.as_arrays()))
# measures: a shrinking size over five records, two windows
TIMES5 = A([0.0, 0.1, 0.2, 0.3, 0.4])
SIZES5 = np.exp(-TIMES5)
# theorems: the config sections, shrunk to one or two coarse runs of two steps
THEOREM1 = {"initial": "rho2", "a": 3.0, "t": 0.1, "h_values": [0.5], "dt_values": [0.1, 0.05], "fit_points": 2}
THEOREM3_ATOMIC = {"atoms": 3, "a": 3.0, "dt": 0.05, "dt_factor": 2, "h_values": [0.5, 0.25], "times": [0.05, 0.1]}
THEOREM3 = {"initial": "rho2", "a": 3.0, "h_values": [0.5], "dt_over_h": 0.1, "reference_factor": 2,
            "times": [0.05, 0.1]}
THEOREM4 = {"initial": "rho2", "a": 1.5, "h_values": [0.5], "dt_over_h2": 0.2, "times": [0.05, 0.1]}
#: The name of a density, a potential or a shape is free text (it labels figures): "1" is a name too.
FREE_NAME = {"name": ["1"]}
#: The theorems' config sections are dicts, passed whole: an object to the census.
SECTION = {"q": "object"}


def SHRINK_ANSWER(result):
    """g(t) without its documented value inf where the size does not move (a shrink rate of zero)."""
    return np.where(np.isinf(result), 0.0, result)


def COLLAPSE_ANSWER(result):
    """(slopes, collapse times) without the documented collapse time inf where the slope is not negative."""
    slopes, collapse = result
    return slopes, np.where(np.isinf(collapse), 0.0, collapse)


ENTRIES = {
    # checks
    PM + "ltp.checks.particle_arrays": E(checks.particle_arrays, dict(PARTICLE)),
    PM + "ltp.checks.piece_arrays": E(checks.piece_arrays, {"breaks": B3.breaks, "coefficients": B3.coefficients}),
    PM + "ltp.checks.power_arrays": E(checks.power_arrays, dict(TERMS)),
    PM + "ltp.checks.exponent_array": E(checks.exponent_array, {"exponents": A([1.5, 2.0])}),
    # exact
    PM + "ltp.exact.exact_density": E(exact.exact_density, {"initial": RHO2, "potential": QUADRATIC, "t": 0.1,
                                                            "x": X3}),
    PM + "ltp.exact.exact_support": E(exact.exact_support, {"initial": RHO2, "potential": QUADRATIC, "t": 0.1}),
    PM + "ltp.exact.quadratic_rate": E(exact.quadratic_rate, {"potential": QUADRATIC}),
    # initial
    PM + "ltp.initial.InitialDensity": E(initial.InitialDensity, {"name": "rho2", "pdf": RHO2.pdf, "cdf": RHO2.cdf,
                                                                  "lower": -1.0, "upper": 1.0},
                                         accepts=FREE_NAME),
    PM + "ltp.initial.atomic": E(initial.atomic, {"positions": ATOMS, "masses": MASSES}),
    PM + "ltp.initial.density_named": E(initial.density_named, {"name": "rho2"}, names={"name": ("density",)}),
    PM + "ltp.initial.golden_atoms": E(initial.golden_atoms, {"count": 3, "lower": -0.9, "upper": 0.9}),
    PM + "ltp.initial.grid_particles": E(initial.grid_particles, {"density": RHO2, "h": 0.5, "shape": B3,
                                                                  "weights": "cell", "offset": 0.0},
                                         kinds={"shape": "object"}),
    # kernels
    PM + "ltp.kernels.convolutions": E(kernels.convolutions, {"targets": X3, **PARTICLE, **TERMS, **PIECES}),
    PM + "ltp.kernels.density_at": E(kernels.density_at, {"points": X3, **PARTICLE, **PIECES}),
    PM + "ltp.kernels.cumulative_mass_at": E(kernels.cumulative_mass_at, {"points": X3, **PARTICLE, **PIECES}),
    PM + "ltp.kernels.far_series": E(kernels.far_series, {"exponents": A([1.5]), "moments": A([1.0, 0.0, 1 / 3])}),
    PM + "ltp.kernels.takes_pair_sums": E(kernels.takes_pair_sums, {"exponents": A([1.5, 2.0])}),
    # measures
    PM + "ltp.measures.shrink_rate_inverse": E(measures.shrink_rate_inverse, {"times": TIMES5, "sizes": SIZES5},
                                               documented=SHRINK_ANSWER),
    PM + "ltp.measures.collapse_times": E(measures.collapse_times, {"times": TIMES5, "sizes": SIZES5,
                                                                    "windows": A([[0.0, 1.0]])},
                                          documented=COLLAPSE_ANSWER),
    PM + "ltp.measures.side_concentration": E(measures.side_concentration, {
        "centres": X3, "weights": W3, "peak_values": A([1.0, 2.0, 1.0]), "fraction": 0.5, "radius": 0.5}),
    PM + "ltp.measures.peak_count": E(measures.peak_count, {"density": A([0.0, 1.0, 0.0, 2.0, 0.0]),
                                                            "prominence": 0.05}),
    PM + "ltp.measures.excess_variation": E(measures.excess_variation, {"x": A([-1.0, -0.5, 0.0, 0.5, 1.0]),
                                                                        "density": A([0.0, 1.0, 0.5, 1.0, 0.0])}),
    PM + "ltp.measures.shrink_rate_ratios": E(measures.shrink_rate_ratios, {
        "times": TIMES5, "sizes": SIZES5, "window": 0.1, "since": 0.0, "floor": 1e-3, "algebraic": False}),
    PM + "ltp.measures.concentration_series": E(measures.concentration_series, {"simulation": SIM,
                                                                                "fraction": 0.5, "radius": 0.5}),
    PM + "ltp.measures.l1_distance": E(measures.l1_distance, {"first": PARTICLES, "second": LATER}),
    PM + "ltp.measures.profile_changes": E(measures.profile_changes, {"simulation": SIM, "window": 0.05,
                                                                      "every": 1}),
    # potentials
    PM + "ltp.potentials.Potential": E(potentials.Potential, {"name": "p", "coefficients": A([1.0]),
                                                              "exponents": A([1.5])},
                                       accepts=FREE_NAME),
    PM + "ltp.potentials.Potential.__call__": E(POWER.__call__, {"x": X3}),
    PM + "ltp.potentials.Potential.derivative": E(POWER.derivative, {"x": X3}),
    PM + "ltp.potentials.Potential.second_derivative": E(POWER.second_derivative, {"x": A([-1.0, 0.5, 1.0])}),
    PM + "ltp.potentials.Potential.as_arrays": E(POWER.as_arrays, {}),
    PM + "ltp.potentials.potential": E(potentials.potential, {"kind": "attractive_repulsive", "a": 2.0, "b": 1.5}),
    # shapes
    PM + "ltp.shapes.Shape": E(shapes.Shape, {"name": "hat", "breaks": HAT.breaks,
                                              "coefficients": HAT.coefficients},
                                   accepts=FREE_NAME),
    PM + "ltp.shapes.Shape.__call__": E(B3.__call__, {"s": X3}),
    PM + "ltp.shapes.B3": E(B3, {"s": X3}),
    PM + "ltp.shapes.HAT": E(HAT, {"s": X3}),
    PM + "ltp.shapes.shape_named": E(shapes.shape_named, {"name": "b3"}, names={"name": ("shape",)}),
    # solver
    PM + "ltp.solver.Particles": E(solver.Particles, {**PARTICLE, "shape": B3}, kinds={"shape": "object"}),
    PM + "ltp.solver.Particles.density": E(PARTICLES.density, {"x": X3}),
    PM + "ltp.solver.Particles.cumulative_mass": E(PARTICLES.cumulative_mass, {"x": X3}),
    PM + "ltp.solver.Particles.convolutions": E(PARTICLES.convolutions, {"potential": POWER, "x": X3},
                                                accepts={"x": [None]}),
    PM + "ltp.solver.Simulation": E(solver.Simulation, {
        "method": "ltp", "shape": B3, "potential": POWER, "h": 0.5, "dt": 0.05, "steps": SIM.steps,
        "times": SIM.times, "weights": SIM.weights, "centres": SIM.centres, "widths": SIM.widths,
        "velocities": SIM.velocities}, kinds={"shape": "object"}),
    PM + "ltp.solver.Simulation.at": E(SIM.at, {"index": 1}),
    PM + "ltp.solver.Simulation.densities": E(SIM.densities, {"x": X3}),
    PM + "ltp.solver.Simulation.peak_densities": E(SIM.peak_densities, {}),
    PM + "ltp.solver.simulate": E(solver.simulate, {
        "initial": "rho2", "potential": POWER, "h": 0.5, "dt": 0.05, "t_final": 0.1, "shape": "b3",
        "weights": "cell", "offset": 0.0, "method": "ltp", "eps": None, "record_every": 1, "log": None},
        kinds={"log": "function"}, accepts={"log": [nan_function]}),  # what log returns is never read
    # theorems
    PM + "ltp.theorems.records": E(theorems.records, {"sim": SIM, "times": A([0.05, 0.1])}),
    PM + "ltp.theorems.atom_flow": E(theorems.atom_flow, {"positions": ATOMS, "masses": MASSES, "w": POWER,
                                                          "times": A([0.0, 0.1]), "rtol": 1e-8}),
    PM + "ltp.theorems.w1_to_atoms": E(theorems.w1_to_atoms, {"particles": PARTICLES, "positions": ATOMS,
                                                              "masses": MASSES}),
    PM + "ltp.theorems.theorem1_time_error": E(theorems.theorem1_time_error, {
        "q": THEOREM1, "grid_points": 11, "run": solver.simulate}, kinds=SECTION),
    PM + "ltp.theorems.theorem3_atomic": E(theorems.theorem3_atomic, {"q": THEOREM3_ATOMIC, "run": solver.simulate},
                                           kinds=SECTION),
    PM + "ltp.theorems.theorem3_rough": E(theorems.theorem3_rough, {
        "q": THEOREM3, "grid_points": 11, "run": solver.simulate}, kinds=SECTION),
    PM + "ltp.theorems.theorem4_differences": E(theorems.theorem4_differences, {
        "q": THEOREM4, "grid_points": 11, "run": solver.simulate}, kinds=SECTION),
}

EXEMPT: dict = {}
