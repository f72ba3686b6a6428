"""Figures 7 and 8: particle against blob trajectories in 2D for repulsive-attractive kernels."""

import numpy as np

from particle_methods.blob.solver import run_2d
from particle_methods.workflow import logged, progress, save_results


def run(p, output):
    results = {"labels": []}
    for index, case in enumerate(p["cases"]):
        times = np.linspace(0.0, case["t_max"], p["times"])
        for method in ("particle", "blob"):
            progress(f"{case['kernel']} from {case['data']}: {method}, h = {p['h']:.4g}, delta = {p['delta']}, "
                     f"t = {case['t_max']}")
            sim = run_2d(case["data"], case["kernel"], p["h"], times, method=method, delta=p["delta"],
                         rtol=p["rtol"], atol=p["atol"])
            if np.abs(sim.positions).max() > 2.4:  # pair distances must stay inside the radial tables
                raise ValueError(f"particles left the tabulated range in {case['kernel']}")
            results[f"case{index}_{method}"] = sim.positions
        results[f"case{index}_times"] = times
        results["labels"].append(f"{case['kernel']}|{case['data']}")
    results["labels"] = np.array(results["labels"])
    save_results(output, h=p["h"], delta=p["delta"], **results)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
