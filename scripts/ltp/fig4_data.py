"""Figure 4: W = x^2/2 from (6.1): exact, LTP and SP with the hat (left) and B3 (right) shapes."""

import numpy as np

from particle_methods.ltp import density_named, exact_density, potential, simulate
from particle_methods.norms import grid_errors
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("half_quadratic")
    grid = np.linspace(initial.lower, initial.upper, p["grid_points"])
    exact = exact_density(initial, w, p["t"], grid)
    results = {"grid": grid, "exact": exact, "shapes": np.array(["hat", "b3"])}
    for shape in ("hat", "b3"):
        progress(f"{shape}: LTP and SP (eps = {p['sp_eps']})")
        ltp = simulate(initial, w, p["h"], p["dt"], p["t"], shape=shape).at(-1).density(grid)
        sp_run = simulate(initial, w, p["h"], p["dt"], p["t"], shape=shape, method="sp", eps=p["sp_eps"])
        sp = sp_run.at(-1).density(grid)
        results[f"{shape}_ltp"], results[f"{shape}_sp"] = ltp, sp
        results[f"{shape}_ltp_errors"] = np.array(grid_errors(ltp, exact, grid))
        results[f"{shape}_sp_errors"] = np.array(grid_errors(sp, exact, grid))
    save_results(output, **results)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
