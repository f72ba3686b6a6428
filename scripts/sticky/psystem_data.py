"""Figures 4 to 7: iterated TSPD for the p-system (section 5.2.2), trajectories and fields.

Both runs of a case (few particles for the trajectories, many for the fields) go on in chunks of
``steps`` until the end state of section 5.2.2 holds up to the end of the run (w+ >= w- and no
cluster left), at most to ``max_steps``; the shorter one is then continued to the same time.
"""

import math

import numpy as np

from particle_methods.sticky.cases import empirical_cdf, psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_trajectory
from particle_methods.sticky.spd import cluster_sizes
from particle_methods.systems import MINUS, PLUS, PSystem
from particle_replication.steady import holds_from, run_until
from particle_replication.workflow import logged, progress, save_results


def end_state(times, states):
    """First time from which x+_k <= x-_k for every k and every particle is alone, to the end."""
    ordered = np.all(states[:, PLUS] <= states[:, MINUS], axis=1)
    free = [all(cluster_sizes(row).max() == 1 for row in state) for state in states]
    return holds_from(times, ordered & np.array(free))


def simulate(case, system, p, n):
    def advance(state, chunk):
        return mspd_trajectory(state, system, p["delta"], round(chunk / p["delta"]))

    shown = p["steps"] * p["delta"]
    return run_until(advance, psystem_initial_configuration(case, p["x0"], n), shown, shown,
                     max(p["max_steps"], p["steps"]) * p["delta"], end_state)


def run(case, system_params, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    runs = {}
    for name, n in (("trajectories", p["trajectory_particles"]), ("field_path", p["field_particles"])):
        times, path, reached = simulate(case, system, p, n)
        progress(f"{case}: {n} particles per type, {len(times) - 1} steps of {p['delta']}; end state at t = "
                 f"{reached:.4g}" + ("" if math.isfinite(reached) else " (not reached)"))
        runs[name] = (path, reached)
    steps = max(len(path) for path, _ in runs.values()) - 1
    for name, (path, reached) in runs.items():  # continue the shorter run to the common final time
        if len(path) - 1 < steps:
            path = np.concatenate([path, mspd_trajectory(path[-1], system, p["delta"], steps - len(path) + 1)[1:]])
        runs[name] = (path, reached)
    times = p["delta"] * np.arange(steps + 1)
    field_path = runs["field_path"][0]
    field_x = np.linspace(field_path.min() - 0.5, field_path.max() + 0.5, p["field_points"])
    w_minus = np.array([empirical_cdf(state[MINUS], field_x) for state in field_path])
    w_plus = np.array([empirical_cdf(state[PLUS], field_x) for state in field_path])
    u, v = system.physical_variables(w_minus, w_plus)
    save_results(output, times=times, trajectories=runs["trajectories"][0], field_path=field_path,
                 field_x=field_x, w_minus=w_minus, w_plus=w_plus, u=u, v=v,
                 trajectories_end=runs["trajectories"][1], field_end=runs["field_path"][1],
                 max_time=max(p["max_steps"], p["steps"]) * p["delta"])


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.case, snakemake.params.system, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
