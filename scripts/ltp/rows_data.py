"""Figures 5 and 6: potential, density, velocity and particle sizes of LTP runs from (6.2)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.workflow import logged, progress, save_results


def case_potential(p, case):
    if "b" in case:
        return potential("attractive_repulsive", a=p["a"], b=case["b"])
    return potential("power", a=case["a"])


def run(p, output):
    initial = density_named(p["initial"])
    results = {"labels": []}
    grid = np.linspace(-1.1, 1.1, 2201)
    x_potential = np.linspace(-2.0, 2.0, 401)
    for index, case in enumerate(p["cases"]):
        w = case_potential(p, case)
        label = w.name
        progress(f"{label}: {p['steps']} steps up to t = {case['t']}")
        every = p["steps"] // 20
        sim = simulate(initial, w, p["h"], case["t"] / p["steps"], case["t"], record_every=every,
                       log=progress)
        shown = np.linspace(0, sim.steps.size - 1, p["snapshots"]).round().astype(int)
        results["labels"].append(label)
        prefix = f"case{index}"
        results.update({
            f"{prefix}_times": sim.times, f"{prefix}_centres": sim.centres, f"{prefix}_widths": sim.widths,
            f"{prefix}_velocities": sim.velocities, f"{prefix}_weights": sim.weights,
            f"{prefix}_shown": shown, f"{prefix}_densities": sim.densities(grid)[shown],
            f"{prefix}_peaks": sim.peak_densities(), f"{prefix}_potential": w(x_potential),
        })
    results["labels"] = np.array(results["labels"])
    save_results(output, grid=grid, x_potential=x_potential, h=p["h"], **results)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
