"""Figures 2 and 3: SPD trajectories, space-time field, profiles and L1 errors (section 5.1)."""

import numpy as np

from particle_methods.norms import w1_to_measure
from particle_methods.sticky.cases import SCALAR_CASES, empirical_cdf
from particle_methods.sticky.spd import cluster_sizes, spd_trajectories
from particle_replication.workflow import logged, progress, save_results


def run(p, output):
    case = SCALAR_CASES[p["case"]]
    trajectory_times = np.linspace(0.0, p["t_max"], p["trajectory_times"])
    trajectories = spd_trajectories(*case.initial_state(p["trajectory_particles"]), trajectory_times)

    field_times = np.linspace(0.0, p["t_max"], p["field_times"])
    field_positions = spd_trajectories(*case.initial_state(p["field_particles"]), field_times)
    margin = 0.05 * (field_positions.max() - field_positions.min()) + 0.5
    field_x = np.linspace(field_positions.min() - margin, field_positions.max() + margin, p["field_points"])
    field = np.array([empirical_cdf(row, field_x) for row in field_positions])

    profile_times = np.asarray(p["profile_times"], dtype=float)
    profile_positions = spd_trajectories(*case.initial_state(p["profile_particles"]), profile_times)
    profile_particle_cdf = np.array([empirical_cdf(row, field_x) for row in profile_positions])
    profile_exact_cdf = np.array([case.solution(t).cdf(field_x) for t in profile_times])

    error_n = 2 ** np.asarray(p["error_p"])
    error_times = np.asarray(p["error_times"], dtype=float)
    errors = np.empty((error_times.size, error_n.size))
    clusters = np.empty(errors.shape, dtype=np.int64)
    for i, t in enumerate(error_times):
        progress(f"errors at t = {t:g} for n = {error_n.min()}..{error_n.max()}")
        solution = case.solution(t)
        for j, n in enumerate(error_n):
            positions = case.positions(int(n), t)
            errors[i, j] = w1_to_measure(solution, positions)
            clusters[i, j] = cluster_sizes(positions).size
    # Larger n than plotted, where the asymptotic rate of the decay is measured (Figure 3 (d)).
    rate_n = 2 ** np.asarray(p.get("rate_p", []), dtype=np.int64)
    rate_errors = np.empty((error_times.size, rate_n.size))
    for i, t in enumerate(error_times):
        progress(f"asymptotic errors at t = {t:g} for n = {rate_n.tolist()}")
        rate_errors[i] = [case.error(int(n), t) for n in rate_n]
    initial_errors = np.array([w1_to_measure(case.initial, case.initial_state(int(n))[0]) for n in error_n])
    # Distance from u(t, .) to the Heaviside function (all mass at 0): the plateau of Figure 3 (d).
    heaviside_errors = np.array([w1_to_measure(case.solution(t), np.zeros(1)) for t in error_times])

    save_results(
        output,
        trajectory_times=trajectory_times, trajectories=trajectories,
        field_times=field_times, field_x=field_x, field=field,
        profile_times=profile_times, profile_particle_cdf=profile_particle_cdf,
        profile_exact_cdf=profile_exact_cdf,
        error_p=np.asarray(p["error_p"]), error_n=error_n, error_times=error_times, errors=errors,
        rate_n=rate_n, rate_errors=rate_errors, initial_errors=initial_errors,
        heaviside_errors=heaviside_errors, clusters=clusters,
        flux_lipschitz=case.flux_lipschitz,
    )


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
