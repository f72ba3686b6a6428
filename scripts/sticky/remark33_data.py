"""Remark 3.3: exact error t/(4n) from one Dirac mass (Burgers); for the concave flux the SPD is the
entropy solution of the discretised data, tested exactly against Hopf's formula for that solution
(at every n and t of the study; Burgers from two atoms as the contrast), by construction (the
Rankine-Hugoniot speed and Oleinik's condition at every jump, a check) and against an independent
Godunov solver."""

import math

import numpy as np

from particle_methods.finite_volume.fluxes import BURGERS, CONCAVE, burgers_flux
from particle_methods.finite_volume.grids import cell_averages_of_step_cdf, l1_distance_to_step_cdf
from particle_methods.finite_volume.scalar import godunov
from particle_methods.norms import w1_to_measure
from particle_methods.sticky.admissibility import admissibility_violation, spd_state
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.exact import BurgersSolution
from particle_methods.sticky.hopf import hopf_gap
from particle_methods.sticky.measures import Atoms
from particle_methods.sticky.spd import spd_positions, velocities_from_flux
from particle_replication.workflow import logged, progress, save_results


def godunov_distance(flux, x, positions, t, cells_per_unit, cfl):
    """L1 distance between the Godunov solution at time t, started from the empirical CDF of x,
    and the empirical CDF of the SPD positions at t (both exact on the grid, no quadrature)."""
    # A cell edge at x = 0, where the clusters of the concave case end in one stationary shock: a
    # first-order scheme's error on a stationary shock depends on where it sits inside a cell.
    left = math.ceil((1.0 - min(x[0], positions[0])) * cells_per_unit)
    right = math.ceil((max(x[-1], positions[-1]) + 1.0) * cells_per_unit)
    edges = np.arange(-left, right + 1) / cells_per_unit
    values = godunov(flux, cell_averages_of_step_cdf(x, edges), edges, t, cfl=cfl, left=0.0, right=1.0)
    return l1_distance_to_step_cdf(values, edges, positions)


def exact_tests(case, n_values, times, points):
    """The SPD of ``case`` started from (2.1), for every n of ``n_values`` and t of ``times``, against
    Hopf's formula (:func:`hopf_gap`, the remark) and against (RH) and (E) (:func:`admissibility_violation`,
    which hold by construction for a concave flux): an array of gaps and rows of Admissibility results,
    one per n."""
    gaps, table = np.empty((len(n_values), len(times))), []
    for a, n in enumerate(n_values):
        progress(f"the SPD against Hopf's formula, (RH) and (E): n = {n}, t = {times.tolist()}")
        x, v = case.initial_state(int(n))
        states = [spd_state(x, v, t) for t in times]
        gaps[a] = [hopf_gap(x, positions, t, case.flux, points=points) for (positions, _), t in zip(states, times)]
        table.append([admissibility_violation(*state, case.flux, points=points) for state in states])
    return gaps, table


def run(p, output):
    dirac_n = np.asarray(p["dirac_n"], dtype=np.int64)
    dirac_times = np.asarray(p["dirac_times"], dtype=float)
    dirac_errors = np.empty((dirac_times.size, dirac_n.size))
    for i, t in enumerate(dirac_times):
        solution = BurgersSolution(Atoms([0.0]), t)
        for j, n in enumerate(dirac_n):
            positions = spd_positions(np.zeros(n), velocities_from_flux(burgers_flux, int(n)), t)
            dirac_errors[i, j] = w1_to_measure(solution, positions)

    # The exact tests: the SPD state at each n and t against Hopf's formula and against (RH) and (E), for
    # the concave flux with the Laplace data (2.1) and, as the contrast where the remark does not apply,
    # Burgers from two atoms.
    check = p["admissibility"]
    check_n = np.asarray(check["n"], dtype=np.int64)
    check_times = np.asarray(check["times"], dtype=float)
    hopf, concave = exact_tests(SCALAR_CASES["concave_laplace"], check_n, check_times, check["points"])
    convex_hopf, convex_check = exact_tests(SCALAR_CASES["burgers_two_atoms"], check_n, check_times, check["points"])

    # Concave flux, Laplace data (2.1): SPD of the discretised data against Godunov from the same data.
    case = SCALAR_CASES["concave_laplace"]
    n_values = np.asarray(p["godunov_n"], dtype=np.int64)
    times = np.asarray(p["godunov_times"], dtype=float)
    cells = np.asarray(p["cells_per_unit"], dtype=np.int64)
    distances = np.empty((n_values.size, times.size, cells.size))
    total_errors = np.empty((n_values.size, times.size))
    initial_errors = np.empty(n_values.size)
    for a, n in enumerate(n_values):
        x, v = case.initial_state(int(n))
        initial_errors[a] = w1_to_measure(case.initial, x)
        for b, t in enumerate(times):
            progress(f"Godunov against the SPD: n = {n}, t = {t:g}, {cells.tolist()} cells per unit")
            positions = spd_positions(x, v, t)
            total_errors[a, b] = w1_to_measure(case.solution(t), positions)
            distances[a, b] = [godunov_distance(CONCAVE, x, positions, t, int(c), p["cfl"]) for c in cells]

    # The same measure where the SPD is not entropic: Burgers from delta_0, distance -> t/(4n).
    convex = p["convex"]
    x = np.zeros(convex["n"])
    positions = spd_positions(x, velocities_from_flux(burgers_flux, convex["n"]), convex["t"])
    progress(f"Godunov against the SPD for Burgers from delta_0, n = {convex['n']}")
    convex_distances = np.array([godunov_distance(BURGERS, x, positions, convex["t"], int(c), p["cfl"])
                                 for c in cells])
    # Diagnostic: one case with many particles on finer grids, to see whether its order rises.
    refinement = p["refinement"]
    x, v = case.initial_state(refinement["n"])
    positions = spd_positions(x, v, refinement["t"])
    progress(f"refined grids for n = {refinement['n']}, t = {refinement['t']:g}: {refinement['cells_per_unit']}")
    refined = np.array([godunov_distance(CONCAVE, x, positions, refinement["t"], int(c), p["cfl"])
                        for c in refinement["cells_per_unit"]])
    save_results(output, admissibility_n=check_n, admissibility_times=check_times, hopf_gaps=hopf,
                 convex_hopf_gaps=convex_hopf,
                 admissibility_rankine_hugoniot=[[r.rankine_hugoniot for r in row] for row in concave],
                 admissibility_entropy=[[r.entropy for r in row] for row in concave],
                 admissibility_clusters=[[r.clusters for r in row] for row in concave],
                 convex_admissibility=[[r.largest for r in row] for row in convex_check],
                 refined_cells=np.asarray(refinement["cells_per_unit"]), refined_distances=refined,
                 refined_n=refinement["n"], refined_t=refinement["t"], dirac_n=dirac_n, dirac_times=dirac_times,
                 dirac_errors=dirac_errors,
                 godunov_n=n_values, godunov_times=times, cells_per_unit=cells, distances=distances,
                 total_errors=total_errors, initial_errors=initial_errors, convex_distances=convex_distances,
                 convex_n=convex["n"], convex_t=convex["t"])


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
