"""Remark 3.3: exact error t/(4n) from one Dirac mass (Burgers); SPD = entropy solution (concave flux)."""

import numpy as np

from particle_methods.norms import w1_between_samples, w1_to_measure
from particle_methods.sticky.cases import SCALAR_CASES
from particle_methods.sticky.events import sticky_collisions
from particle_methods.sticky.exact import BurgersSolution, burgers_flux
from particle_methods.sticky.measures import Atoms
from particle_methods.sticky.spd import spd_positions, velocities_from_flux
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    dirac_n = np.asarray(p["dirac_n"], dtype=np.int64)
    dirac_times = np.asarray(p["dirac_times"], dtype=float)
    dirac_errors = np.empty((dirac_times.size, dirac_n.size))
    for i, t in enumerate(dirac_times):
        solution = BurgersSolution(Atoms([0.0]), t)
        for j, n in enumerate(dirac_n):
            positions = spd_positions(np.zeros(n), velocities_from_flux(burgers_flux, int(n)), t)
            dirac_errors[i, j] = w1_to_measure(solution, positions)

    # Concave flux: front tracking of the entropy solution with the discretised data
    # (event-driven collisions at Rankine-Hugoniot speeds) against the hull SPD.
    case = SCALAR_CASES["concave_laplace"]
    tracking_n = np.asarray(p["tracking_n"], dtype=np.int64)
    tracking_times = np.asarray(p["tracking_times"], dtype=float)
    shape = (tracking_times.size, tracking_n.size)
    position_gap, tracking_w1, total_errors = np.empty(shape), np.empty(shape), np.empty(shape)
    initial_errors = np.empty(tracking_n.size)
    for j, n in enumerate(tracking_n):
        progress(f"front tracking with n = {n}")
        x, v = case.initial_state(int(n))
        initial_errors[j] = w1_to_measure(case.initial, x)
        for i, t in enumerate(tracking_times):
            hull = spd_positions(x, v, t)
            fronts = sticky_collisions(x, v, t)
            position_gap[i, j] = np.max(np.abs(hull - fronts))
            tracking_w1[i, j] = w1_between_samples(hull, fronts)
            total_errors[i, j] = w1_to_measure(case.solution(t), hull)
    save_results(output, dirac_n=dirac_n, dirac_times=dirac_times, dirac_errors=dirac_errors,
                 tracking_n=tracking_n, tracking_times=tracking_times, position_gap=position_gap,
                 tracking_w1=tracking_w1, total_errors=total_errors, initial_errors=initial_errors)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
