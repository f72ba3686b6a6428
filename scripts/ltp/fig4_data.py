"""Figure 4: W = x^2/2 from (6.1): exact, LTP and SP with the hat (left) and B3 (right) shapes.

The SP width is not stated in the paper: the figure uses ``sp_eps``, and a scan of eps around h
gives the best SP error of each shape, so the report shows how the verdicts depend on eps."""

import numpy as np

from particle_methods.ltp import density_named, exact_density, potential, simulate
from particle_methods.norms import grid_errors
from particle_replication.workflow import logged, progress, save_results


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("half_quadratic")
    grid = np.linspace(initial.lower, initial.upper, p["grid_points"])
    exact = exact_density(initial, w, p["t"], grid)
    scan = p["eps_scan"]
    eps_values = p["h"] * np.geomspace(scan["min_ratio"], scan["max_ratio"], scan["count"])
    results = {"grid": grid, "exact": exact, "shapes": np.array(["hat", "b3"]), "eps_values": eps_values,
               "h": p["h"], "sp_eps": p["sp_eps"]}
    for shape in ("hat", "b3"):
        progress(f"{shape}: LTP and SP (eps = {p['sp_eps']}), and SP over {eps_values.size} widths")
        ltp = simulate(initial, w, p["h"], p["dt"], p["t"], shape=shape).at(-1).density(grid)
        sp = simulate(initial, w, p["h"], p["dt"], p["t"], shape=shape, method="sp",
                      eps=p["sp_eps"]).at(-1).density(grid)
        results[f"{shape}_ltp"], results[f"{shape}_sp"] = ltp, sp
        results[f"{shape}_ltp_errors"] = np.array(grid_errors(ltp, exact, grid))
        results[f"{shape}_sp_errors"] = np.array(grid_errors(sp, exact, grid))
        results[f"{shape}_scan_errors"] = np.array([
            grid_errors(simulate(initial, w, p["h"], p["dt"], p["t"], shape=shape, method="sp", eps=eps)
                        .at(-1).density(grid), exact, grid) for eps in eps_values])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
