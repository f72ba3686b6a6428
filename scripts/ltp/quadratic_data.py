"""Figures 2 and 3: W = x^2 from (6.1), LTP against the exact solution (6.4) and the SP method."""

import numpy as np

from particle_methods.ltp import density_named, exact_density, exact_support, potential, simulate
from particle_methods.norms import grid_errors
from particle_replication.workflow import logged, progress, save_results


def errors(run, initial, w, t, grid):
    return grid_errors(run.at(-1).density(grid), exact_density(initial, w, t, grid), grid)


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("quadratic")
    t, dt = p["t"], p["dt"]
    grid = np.linspace(initial.lower, initial.upper, p["grid_points"])
    h_values = np.asarray(p["h_values"], dtype=float)
    ltp_errors, sp_errors, mass_error, centre_drift = [], [], [], []
    plot_density = {}
    for h in h_values:
        progress(f"h = {h:g}: LTP and SP with eps = h, {round(t / dt)} steps")
        ltp = simulate(initial, w, h, dt, t)
        sp = simulate(initial, w, h, dt, t, method="sp", eps=h)
        ltp_errors.append(errors(ltp, initial, w, t, grid))
        sp_errors.append(errors(sp, initial, w, t, grid))
        mass_error.append(abs(np.trapezoid(ltp.at(-1).density(grid), grid) - 1.0))
        centre_drift.append(abs(ltp.at(-1).centre_of_mass - ltp.at(0).centre_of_mass))
        if h in p["plot_h"]:
            plot_density[h] = ltp.at(-1).density(grid)

    progress(f"SP with h = {p['sp_h']} and eps = {p['sp_eps']}")
    sp_densities = np.array([simulate(initial, w, p["sp_h"], dt, t, method="sp", eps=eps).at(-1).density(grid)
                             for eps in p["sp_eps"]])

    scan = p["eps_scan"]
    eps_values = np.geomspace(scan["eps_min"], scan["eps_max"], scan["count"])
    progress(f"eps scan: h = {scan['h']}, dt = {scan['dt']}, {eps_values.size} values")
    scan_ltp = errors(simulate(initial, w, scan["h"], scan["dt"], t), initial, w, t, grid)
    scan_sp = np.array([errors(simulate(initial, w, scan["h"], scan["dt"], t, method="sp", eps=eps),
                               initial, w, t, grid) for eps in eps_values])
    fine = scan["fine_dt"]
    progress(f"eps scan again at dt = {fine:g}, where the time error is negligible")
    scan_ltp_fine = errors(simulate(initial, w, scan["h"], fine, t), initial, w, t, grid)
    scan_sp_fine = np.array([errors(simulate(initial, w, scan["h"], fine, t, method="sp", eps=eps),
                                    initial, w, t, grid) for eps in eps_values])

    study = p["dt_study"]
    progress(f"dt study: h = {study['h_values']}, dt = {study['dt_values']}")
    dt_errors, dt_gaps = [], []
    for h in study["h_values"]:
        runs = [simulate(initial, w, h, step, t).at(-1).density(grid) for step in study["dt_values"]]
        dt_errors.append([grid_errors(run, exact_density(initial, w, t, grid), grid) for run in runs])
        dt_gaps.append([grid_errors(run, runs[-1], grid) for run in runs[:-1]])
    dt_errors, dt_gaps = np.array(dt_errors), np.array(dt_gaps)
    # The cut-off of the data at their support's ends: the exact density's jump there at t (no continuous rho_h
    # comes closer than half of it in Linf).
    lower, upper = exact_support(initial, w, t)
    inside = 1e-12 * (upper - lower)
    edge_jump = float(exact_density(initial, w, t, np.array([lower + inside, upper - inside])).max())
    save_results(
        output, grid=grid, exact=exact_density(initial, w, t, grid), h_values=h_values,
        ltp_errors=np.array(ltp_errors), sp_errors=np.array(sp_errors), mass_error=np.array(mass_error),
        centre_drift=np.array(centre_drift), plot_h=np.array(sorted(plot_density, reverse=True)),
        plot_density=np.array([plot_density[h] for h in sorted(plot_density, reverse=True)]),
        sp_eps=np.asarray(p["sp_eps"], float), sp_densities=sp_densities, eps_values=eps_values,
        scan_ltp=np.array(scan_ltp), scan_sp=scan_sp, order_points=p["order_points"], t=t, dt=dt, sp_h=p["sp_h"],
        scan_dt=scan["dt"], scan_h=scan["h"], fine_dt=fine, scan_ltp_fine=np.array(scan_ltp_fine),
        scan_sp_fine=scan_sp_fine, dt_h=np.asarray(study["h_values"], float),
        dt_values=np.asarray(study["dt_values"], float), dt_errors=dt_errors, dt_gaps=dt_gaps,
        dt_fit_points=study["fit_points"], edge_jump=edge_jump,
    )


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
