"""Figure 6: 2D blob runs (m = 4, delta = h^0.9) for K = log|x|/(2 pi), |x|^2/2, |x|^3/3.

Top: data exp(1/(|x|^2 - 1)) with unit mass, trajectories up to t_max and the density at
t_density. Bottom: the star patch (4.6), density at t_star. Also the energy E_delta along
the top runs (where K_delta is known in closed form) and mass conservation along trajectories.
"""

import numpy as np

from particle_methods.blob.solver import mass_defect, run_2d, setup_2d
from particle_replication.workflow import logged, progress, save_results


def run(p, output):
    top, bottom = p["top"], p["bottom"]
    times = np.linspace(0.0, top["t_max"], top["times"])
    density_index = int(np.argmin(np.abs(times - top["t_density"])))
    results = {"kernels": np.array(p["kernels"]), "times": times, "density_index": density_index,
               "star_t": bottom["t"]}
    for kernel in p["kernels"]:
        progress(f"{kernel}: bump data, h = {top['h']:.4g}, up to t = {top['t_max']}")
        sim = run_2d(top["data"], kernel, top["h"], times, q=p["q"], rtol=p["rtol"], atol=p["atol"])
        results[f"{kernel}_positions"] = sim.positions
        results[f"{kernel}_densities"] = sim.densities
        results[f"{kernel}_energies"] = sim.energies() if sim.kernel.has_potential else np.full(times.size, np.nan)
        points, rho0, masses, k, _ = setup_2d(top["data"], kernel, top["h"], q=p["q"])
        results[f"{kernel}_mass_defect"] = mass_defect(points, rho0, masses, k, top["t_density"], rtol=p["rtol"],
                                                       atol=p["atol"])
        progress(f"{kernel}: star patch, h = {bottom['h']:.4g}, t = {bottom['t']}")
        star = run_2d(bottom["data"], kernel, bottom["h"], [0.0, bottom["t"]], q=p["q"], rtol=p["rtol"],
                      atol=p["atol"])
        results[f"{kernel}_star_positions"] = star.positions[-1]
        results[f"{kernel}_star_densities"] = star.densities[-1]
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
