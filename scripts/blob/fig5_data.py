"""Figure 5, one case: 2D L1_h errors at t = 0.5 for K = log|x|/(2 pi), at every h of the config, for
the blob method (m = 4) or the particle method, with regular data (1 - |x|^2)_+^2 or the indicator of
the unit disk."""

import numpy as np

from particle_methods.blob.exact import newtonian_exact_2d
from particle_methods.blob.initial import data_2d
from particle_methods.blob.solver import run_2d
from particle_methods.norms import discrete_l1
from particle_methods.workflow import logged, progress, save_results


def run(p, index, output):
    case = p["cases"][index]
    inverse_h = np.asarray(p["inverse_h"], dtype=int)
    data = data_2d(case["data"])
    trajectory, density, counts, evaluations = [], [], [], []
    for n in inverse_h:
        sim = run_2d(data, p["kernel"], 1.0 / n, [0.0, p["t"]], method=case["method"], q=p["q"],
                     rtol=p["rtol"], atol=p["atol"])
        exact_x, exact_rho = newtonian_exact_2d(data, sim.positions[0], p["t"])
        trajectory.append(discrete_l1(sim.positions[-1], exact_x, 1.0 / n, 2))
        density.append(discrete_l1(sim.densities[-1], exact_rho, 1.0 / n, 2) if sim.densities is not None
                       else np.nan)
        counts.append(sim.masses.size)
        evaluations.append(sim.evaluations)
        progress(f"{case['data']} {case['method']}: h = 1/{n}, {counts[-1]} particles, {sim.evaluations} "
                 f"right-hand sides: trajectory error {trajectory[-1]:.4e}, density error {density[-1]:.4e}")
    save_results(output, label=f"{case['data']}, {case['method']}", trajectory=np.array(trajectory),
                 density=np.array(density), particles=np.array(counts), evaluations=np.array(evaluations))


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.params.index, snakemake.output[0])  # noqa: F821
