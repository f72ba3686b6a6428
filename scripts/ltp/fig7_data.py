"""Figure 7: density snapshots of the LTP method for |x|^3/3 - |x|^2.5/2.5 from (6.3).

The run continues past the figure's final time to ``t_long`` with the same time step, for the
concentration measures (see particle_methods.ltp.measures)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.ltp.measures import concentration_series
from particle_replication.workflow import logged, progress, save_results


def run(p, concentration, output):
    w = potential("attractive_repulsive", a=p["a"], b=p["b"])
    dt = p["t"] / p["steps"]
    steps = int(round(max(p["t"], p["t_long"]) / dt))
    progress(f"{w.name}: {steps} steps of {dt:g} up to t = {steps * dt:g} (figure: t <= {p['t']:g})")
    sim = simulate(density_named(p["initial"]), w, p["h"], dt, steps * dt, record_every=1)
    shown = np.linspace(0, p["steps"], p["snapshots"]).round().astype(int)
    grid = np.linspace(-1.1, 1.1, 4401)
    widths, masses = concentration_series(sim, concentration["fraction"], concentration["radius"])
    progress(f"t = {sim.times[-1]:g}: widths {widths[-1]}, mass near the peaks {masses[-1].sum():.4g}")
    save_results(output, grid=grid, times=sim.times[shown], densities=sim.densities(grid)[shown],
                 record_times=sim.times, concentration_widths=widths, concentration_masses=masses,
                 weights=sim.weights, label=np.array(w.name), h=p["h"], dt=dt, steps=p["steps"])


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.params.concentration, snakemake.output[0])  # noqa: F821
