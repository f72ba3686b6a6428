"""Figures 5 and 6: potential, density, velocity and particle sizes of LTP runs from (6.2).

Every step is recorded, for the collapse measure of Figure 5 (the smallest particle width and the
spread of the centres at every step). Figure 6 runs continue past the figure's final time to
``t_long`` with the same time step, for the concentration measures (width holding a fraction of
each side's mass, mass near each side's peak, density at the edge over the centre, and the L1 change of the
density over one concentration window, for the steadiness of a profile). Figure 6's case
``edge_refinement["b"]`` runs again at the coarser ``edge_refinement["h_values"]`` (same dt and final time):
the largest density at the centres at every record, with the widths of the concentration measure that
date its steady state, at every h (the figure's included)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.ltp.measures import concentration_series, profile_changes
from particle_replication.workflow import logged, progress, save_results


def case_potential(p, case):
    if "b" in case:
        return potential("attractive_repulsive", a=p["a"], b=case["b"])
    return potential("power", a=case["a"])


def largest_densities(sim):
    """Largest density at the centres, at every record of ``sim``."""
    return np.array([sim.at(i).density(sim.at(i).centres).max() for i in range(sim.steps.size)])


def run(p, concentration, output):
    initial = density_named(p["initial"])
    results = {"labels": []}
    grid = np.linspace(-1.1, 1.1, 2201)
    x_potential = np.linspace(-2.0, 2.0, 401)
    for index, case in enumerate(p["cases"]):
        w = case_potential(p, case)
        dt = case["t"] / p["steps"]
        t_end = max(case["t"], case.get("t_long", p.get("t_long", case["t"])))
        steps = int(round(t_end / dt))
        progress(f"{w.name}: {steps} steps of {dt:g} up to t = {t_end:g} (figure: t <= {case['t']:g})")
        sim = simulate(initial, w, p["h"], dt, steps * dt, record_every=1, log=None)
        shown = np.linspace(0, p["steps"], p["snapshots"]).round().astype(int)
        prefix = f"case{index}"
        densities = sim.densities(grid)
        results["labels"].append(w.name)
        results.update({
            f"{prefix}_times": sim.times, f"{prefix}_figure_t": case["t"],
            f"{prefix}_centres": sim.centres, f"{prefix}_widths": sim.widths,
            f"{prefix}_velocities": sim.velocities, f"{prefix}_weights": sim.weights,
            f"{prefix}_shown": shown, f"{prefix}_densities": densities[shown],
            f"{prefix}_potential": w(x_potential),
        })
        if "b" in case:
            widths, masses = concentration_series(sim, concentration["fraction"], concentration["radius"])
            centre = np.argmin(np.abs(grid))
            edge_ratio = densities.max(axis=1) / densities[:, centre]
            # at every tenth of a window: the steady time to that resolution
            every = max(1, round(0.1 * concentration["window"] / dt))
            profile_times, changes = profile_changes(sim, concentration["window"], every)
            results.update({f"{prefix}_concentration_widths": widths, f"{prefix}_concentration_masses": masses,
                            f"{prefix}_edge_ratio": edge_ratio, f"{prefix}_profile_times": profile_times,
                            f"{prefix}_profile_changes": changes})
            progress(f"  t = {t_end:g}: widths holding {concentration['fraction']:g} of each side "
                     f"{widths[-1]}, mass within {concentration['radius']:g} of the peaks {masses[-1].sum():.4g}")
        refinement = p.get("edge_refinement")
        if refinement is not None and case.get("b") == refinement["b"]:
            series = {p["h"]: (largest_densities(sim), widths)}  # the figure's run, its widths measured above
            for h in refinement["h_values"]:
                progress(f"{w.name}: edge refinement, h = {h:g}, {steps} steps of {dt:g}")
                refined = simulate(initial, w, h, dt, steps * dt, record_every=1, log=None)
                series[h] = (largest_densities(refined),
                             concentration_series(refined, concentration["fraction"], concentration["radius"])[0])
            edge_h = np.array(sorted(series, reverse=True))
            results.update({"edge_h": edge_h, "edge_peaks": np.array([series[h][0] for h in edge_h]),
                            "edge_widths": np.array([series[h][1] for h in edge_h]), "edge_case": index})
    results["labels"] = np.array(results["labels"])
    save_results(output, grid=grid, x_potential=x_potential, h=p["h"], steps=p["steps"], **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.params.concentration, snakemake.output[0])  # noqa: F821
