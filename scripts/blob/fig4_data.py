"""Figure 4: L1_h errors at t = 0.5 of the particle method and of the blob method with m = 4, 6.

For K = -|x|/2 the exact solution comes from mass coordinates. For the other kernels
(K = |x|^3/3, and K = -log|x|/(2 pi), the reading of the figure's row label) there is none:
the reference is the m = 6 blob method on a grid ``reference_factor`` times finer than the
finest one, read at the shared (nested) grid points; a second reference on a grid half as
fine estimates its own error. The same script builds Figure 4 and the row label's reading.
"""

import numpy as np

from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import data_1d
from particle_methods.blob.solver import run_1d
from particle_methods.norms import discrete_l1
from particle_replication.workflow import logged, progress, save_results

METHODS = (("particle", None), ("blob", 4), ("blob", 6))
EXACT = ("newtonian_attractive", "newtonian_repulsive")   # kernels with an exact solution


def final_state(p, kernel, method, order, n, rtol, atol):
    run = run_1d(p["data"], kernel, 1.0 / n, [0.0, p["t"]], method=method, order=order or 4, q=p["q"],
                 rtol=rtol, atol=atol)
    density = run.densities[-1] if run.densities is not None else None
    return run.positions[-1, :, 0], density


def reference(p, kernel, finest):
    """The m = 6 reference on h = 1/(reference_factor finest) and the self-estimate of its error at
    the nested points of h = 1/finest (trajectory, density)."""
    fine = p["reference_factor"] * finest
    progress(f"{kernel} reference: m = 6 with h = 1/{fine} and 1/{fine // 2}")
    states = final_state(p, kernel, "blob", 6, fine, p["rtol"], p["atol"])
    coarser = final_state(p, kernel, "blob", 6, fine // 2, p["rtol"], p["atol"])
    stride = p["reference_factor"]
    error = np.array([discrete_l1(states[i][::stride], coarser[i][:: stride // 2], 1.0 / finest) for i in (0, 1)])
    return fine, states, error


def run(p, output):
    data = data_1d(p["data"])
    inverse_h = np.asarray(p["inverse_h"], dtype=int)
    results = {"h_values": 1.0 / inverse_h, "kernels": np.array(p["kernels"]), "fit_points": p["fit_points"],
               "q": p["q"]}
    for kernel in p["kernels"]:
        if kernel not in EXACT:
            fine, states, results[f"{kernel}_reference_error"] = reference(p, kernel, inverse_h[-1])
        for method, order in METHODS:
            label = f"{kernel}_{method}{order or ''}"
            trajectory, density = [], []
            for n in inverse_h:
                progress(f"{label}: h = 1/{n}")
                x, rho = final_state(p, kernel, method, order, n, p["rtol"], p["atol"])
                if kernel in EXACT:
                    alpha = np.linspace(-1.0, 1.0, n * 2 + 1)
                    exact_x, exact_rho = newtonian_exact(data, kernel, alpha, p["t"])
                else:
                    stride = fine // n
                    exact_x, exact_rho = states[0][::stride], states[1][::stride]
                trajectory.append(discrete_l1(x, exact_x, 1.0 / n))
                density.append(discrete_l1(rho, exact_rho, 1.0 / n) if rho is not None else np.nan)
            results[f"{label}_trajectory"] = np.array(trajectory)
            results[f"{label}_density"] = np.array(density)
    if p["diagnostic_q"] is not None:
        # Diagnostic for the repulsive density: the same runs with a smaller q (larger delta / h).
        for order in (4, 6):
            errors = []
            for n in inverse_h:
                progress(f"diagnostic q = {p['diagnostic_q']}, m = {order}: h = 1/{n}")
                run = run_1d(p["data"], "newtonian_repulsive", 1.0 / n, [0.0, p["t"]], order=order,
                             q=p["diagnostic_q"], rtol=p["rtol"], atol=p["atol"])
                exact = newtonian_exact(data, "newtonian_repulsive", run.positions[0, :, 0], p["t"],
                                        rho0=run.densities[0])[1]
                errors.append(discrete_l1(run.densities[-1], exact, 1.0 / n))
            results[f"diagnostic_m{order}_density"] = np.array(errors)
        results["diagnostic_q"] = p["diagnostic_q"]
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
