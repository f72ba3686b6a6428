"""Figures 1-3: 1D Newtonian kernel, exact solutions by mass coordinates against blob or particle runs."""

import numpy as np

from particle_methods.blob.exact import blowup_time, newtonian_exact
from particle_methods.blob.initial import data_1d
from particle_methods.blob.solver import mass_defect, run_1d, setup_1d
from particle_methods.norms import discrete_l1
from particle_replication.workflow import logged, progress, save_results


def errors(p, h, t, rtol, atol):
    run = run_1d(p["data"], p["kernel"], h, [0.0, t], method=p["method"], order=p["order"], q=p["q"],
                 rtol=rtol, atol=atol)
    alpha = run.positions[0, :, 0]
    carried = None if run.densities is None else run.densities[0]  # the particles' own initial densities
    exact_x, exact_rho = newtonian_exact(data_1d(p["data"]), p["kernel"], alpha, t, rho0=carried)
    trajectory = discrete_l1(run.positions[-1, :, 0], exact_x, h)
    density = discrete_l1(run.densities[-1], exact_rho, h) if run.densities is not None else np.nan
    return trajectory, density, run.evaluations


def lagrangian_mass_defect(p, data, t):
    """Mass conservation along trajectories at time t, on the grid of panels A-C."""
    points, rho0, masses, kernel, _ = setup_1d(data, p["kernel"], p["h"], order=p["order"], q=p["q"])
    return mass_defect(points, rho0, masses, kernel, t, rtol=p["rtol"], atol=p["atol"])


def run(p, output):
    data = data_1d(p["data"])
    times = np.linspace(0.0, p["t_max"], p["times"])
    progress(f"{p['method']} run, h = {p['h']}, up to t = {p['t_max']}")
    shown = run_1d(data, p["kernel"], p["h"], times, method=p["method"], order=p["order"], q=p["q"],
                   rtol=p["rtol"], atol=p["atol"])
    alpha = shown.positions[0, :, 0]
    exact_times = times[times < blowup_time(data, p["kernel"])]
    exact_paths = np.array([newtonian_exact(data, p["kernel"], alpha, t)[0] for t in exact_times])
    density_times = np.asarray(p["density_times"], dtype=float)
    density_index = [int(np.argmin(np.abs(times - t))) for t in density_times]
    carried = None if shown.densities is None else shown.densities[0]
    exact_densities = np.array([newtonian_exact(data, p["kernel"], alpha, t, rho0=carried)[1] for t in density_times])
    energies = shown.energies() if p["method"] == "blob" else np.full(times.size, np.nan)

    mass_defect = lagrangian_mass_defect(p, data, 0.4) if p["method"] == "blob" else np.nan

    inverse_h = np.asarray(p["inverse_h"], dtype=int)
    table = []
    for n in inverse_h:
        progress(f"errors at t = {p['error_t']} with h = 1/{n}")
        table.append(errors(p, 1.0 / n, p["error_t"], p["rtol"], p["atol"]))
    table = np.array(table)
    # The same finest run with tolerances four times tighter: the integrator must not move the errors.
    tight = np.array(errors(p, 1.0 / inverse_h[-1], p["error_t"], p["rtol"] / 4, p["atol"] / 4))
    save_results(
        output, times=times, positions=shown.positions[:, :, 0],
        densities=shown.densities if shown.densities is not None else np.full(shown.positions.shape[:2], np.nan),
        exact_times=exact_times, exact_paths=exact_paths, density_times=density_times,
        density_index=np.array(density_index), exact_densities=exact_densities, masses=shown.masses,
        energies=energies, h_values=1.0 / inverse_h, trajectory_errors=table[:, 0], density_errors=table[:, 1],
        evaluations=table[:, 2], mass_defect=mass_defect, tight_errors=tight[:2], method=np.array(p["method"]),
        order=p["order"],
        q=p["q"], fit_points=p["fit_points"], zoom=np.asarray(p["zoom"], float), h=p["h"],
    )


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
