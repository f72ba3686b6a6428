"""Figure 7: density snapshots of the LTP method for |x|^3/3 - |x|^2.5/2.5 from (6.3)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    w = potential("attractive_repulsive", a=p["a"], b=p["b"])
    every = max(p["steps"] // (p["snapshots"] - 1), 1)
    progress(f"{w.name}: {p['steps']} steps up to t = {p['t']}")
    sim = simulate(density_named(p["initial"]), w, p["h"], p["t"] / p["steps"], p["t"], record_every=every,
                   log=progress)
    grid = np.linspace(-1.1, 1.1, 4401)
    save_results(output, grid=grid, times=sim.times, densities=sim.densities(grid), centres=sim.centres,
                 widths=sim.widths, weights=sim.weights, label=np.array(w.name))


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
