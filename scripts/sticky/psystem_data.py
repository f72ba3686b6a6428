"""Figures 4 to 7: iterated TSPD for the p-system (section 5.2.2), trajectories and fields."""

import numpy as np

from particle_methods.sticky.cases import empirical_cdf, psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_trajectory
from particle_methods.sticky.psystem import MINUS, PLUS, PSystem
from particle_methods.workflow import logged, progress, save_results


def run(case, system_params, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    times = p["delta"] * np.arange(p["steps"] + 1)
    progress(f"{case}: {p['trajectory_particles']} particles per type, {p['steps']} steps of {p['delta']}")
    trajectories = mspd_trajectory(
        psystem_initial_configuration(case, p["x0"], p["trajectory_particles"]), system, p["delta"], p["steps"])
    progress(f"{case}: {p['field_particles']} particles per type for the fields")
    field_path = mspd_trajectory(
        psystem_initial_configuration(case, p["x0"], p["field_particles"]), system, p["delta"], p["steps"])
    field_x = np.linspace(field_path.min() - 0.5, field_path.max() + 0.5, p["field_points"])
    w_minus = np.array([empirical_cdf(state[MINUS], field_x) for state in field_path])
    w_plus = np.array([empirical_cdf(state[PLUS], field_x) for state in field_path])
    u, v = system.physical_variables(w_minus, w_plus)
    save_results(output, times=times, trajectories=trajectories, field_path=field_path, field_x=field_x,
                 w_minus=w_minus, w_plus=w_plus, u=u, v=v)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.wildcards.case, snakemake.params.system, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
