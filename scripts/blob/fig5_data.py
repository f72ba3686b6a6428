"""Figure 5: 2D L1_h errors at t = 0.5 for K = log|x|/(2 pi): blob m = 4 and particle method, regular
data (1 - |x|^2)_+^2, and blob m = 4 for the indicator of the unit disk."""

import numpy as np

from particle_methods.blob.exact import newtonian_exact_2d
from particle_methods.blob.initial import data_2d
from particle_methods.blob.solver import run_2d
from particle_methods.norms import discrete_l1
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    inverse_h = np.asarray(p["inverse_h"], dtype=int)
    results = {"h_values": 1.0 / inverse_h, "fit_points": p["fit_points"], "q": p["q"], "labels": []}
    for index, case in enumerate(p["cases"]):
        data = data_2d(case["data"])
        trajectory, density, counts = [], [], []
        for n in inverse_h:
            progress(f"{case['data']} {case['method']}: h = 1/{n}")
            sim = run_2d(data, p["kernel"], 1.0 / n, [0.0, p["t"]], method=case["method"], q=p["q"],
                         rtol=p["rtol"], atol=p["atol"])
            exact_x, exact_rho = newtonian_exact_2d(data, sim.positions[0], p["t"])
            trajectory.append(discrete_l1(sim.positions[-1], exact_x, 1.0 / n, 2))
            density.append(discrete_l1(sim.densities[-1], exact_rho, 1.0 / n, 2) if sim.densities is not None
                           else np.nan)
            counts.append(sim.masses.size)
        results["labels"].append(f"{case['data']}, {case['method']}")
        results[f"case{index}_trajectory"] = np.array(trajectory)
        results[f"case{index}_density"] = np.array(density)
        results[f"case{index}_particles"] = np.array(counts)
    results["labels"] = np.array(results["labels"])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
