"""Figure 5, one group of runs: the 2D L1_h errors at t = 0.5 for K = log|x|/(2 pi) of one case (the blob
method, m = 4, or the particle method, with regular data (1 - |x|^2)_+^2 or the indicator of the unit disk)
on the grid steps h = 1/inverse_h of the group."""

import time

import numpy as np

from particle_methods.blob.exact import newtonian_exact_2d
from particle_methods.blob.initial import data_2d
from particle_methods.blob.solver import run_2d
from particle_methods.norms import discrete_l1
from particle_replication.workflow import logged, progress, save_results

KEYS = ("trajectory", "density", "particles", "evaluations")


def one_run(p, case, inverse_h):
    data, h = data_2d(case["data"]), 1.0 / inverse_h
    start = time.perf_counter()
    sim = run_2d(data, p["kernel"], h, [0.0, p["t"]], method=case["method"], q=p["q"], rtol=p["rtol"],
                 atol=p["atol"])
    seconds = time.perf_counter() - start
    carried = None if sim.densities is None else sim.densities[0]  # the particles' own initial densities
    exact_x, exact_rho = newtonian_exact_2d(data, sim.positions[0], p["t"], rho0=carried)
    trajectory = discrete_l1(sim.positions[-1], exact_x, h, 2)
    density = discrete_l1(sim.densities[-1], exact_rho, h, 2) if sim.densities is not None else np.nan
    progress(f"{case['data']} {case['method']}: h = 1/{inverse_h}, {sim.masses.size} particles, {sim.evaluations} "
             f"right-hand sides in {seconds:.2f} s: trajectory error {trajectory:.4e}, density error {density:.4e}")
    return trajectory, density, sim.masses.size, sim.evaluations


def run(p, index, inverse_h, output):
    case = p["cases"][index]
    rows = [one_run(p, case, n) for n in inverse_h]
    save_results(output, label=f"{case['data']}, {case['method']}", inverse_h=np.array(inverse_h),
                 **{key: np.array(column) for key, column in zip(KEYS, zip(*rows))})


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.params.index, snakemake.params.inverse_h, snakemake.output[0])  # noqa: F821
