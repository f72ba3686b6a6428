"""Figure 4: L1_h errors at t = 0.5 of the particle method and of the blob method with m = 4, 6.

For K = -|x|/2 the exact solution comes from mass coordinates. For K = |x|^3/3 there is
none: the reference is the m = 6 blob method on a grid ``reference_factor`` times finer
than the finest one, read at the shared (nested) grid points; a second reference on a
grid half as fine estimates its own error.
"""

import numpy as np

from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import data_1d
from particle_methods.blob.solver import run_1d
from particle_methods.norms import discrete_l1
from particle_methods.workflow import logged, progress, save_results

METHODS = (("particle", None), ("blob", 4), ("blob", 6))


def final_state(p, kernel, method, order, n, rtol, atol):
    run = run_1d(p["data"], kernel, 1.0 / n, [0.0, p["t"]], method=method, order=order or 4, q=p["q"],
                 rtol=rtol, atol=atol)
    density = run.densities[-1] if run.densities is not None else None
    return run.positions[-1, :, 0], density


def run(p, output):
    data = data_1d(p["data"])
    inverse_h = np.asarray(p["inverse_h"], dtype=int)
    results = {"h_values": 1.0 / inverse_h, "kernels": np.array(p["kernels"]), "fit_points": p["fit_points"],
               "q": p["q"]}
    for kernel in p["kernels"]:
        if kernel == "cubic":
            fine = p["reference_factor"] * inverse_h[-1]
            progress(f"cubic reference: m = 6 with h = 1/{fine} and 1/{fine // 2}")
            reference = final_state(p, kernel, "blob", 6, fine, p["rtol"], p["atol"])
            coarser = final_state(p, kernel, "blob", 6, fine // 2, p["rtol"], p["atol"])
            stride = p["reference_factor"]
            # Self-estimate of the reference's error at the nested points, per quantity.
            results["cubic_reference_error"] = np.array([
                discrete_l1(reference[0][::stride], coarser[0][:: stride // 2], 1.0 / inverse_h[-1]),
                discrete_l1(reference[1][::stride], coarser[1][:: stride // 2], 1.0 / inverse_h[-1]),
            ])
        for method, order in METHODS:
            label = f"{kernel}_{method}{order or ''}"
            trajectory, density = [], []
            for n in inverse_h:
                progress(f"{label}: h = 1/{n}")
                x, rho = final_state(p, kernel, method, order, n, p["rtol"], p["atol"])
                if kernel == "cubic":
                    stride = fine // n
                    exact_x, exact_rho = reference[0][::stride], reference[1][::stride]
                else:
                    alpha = np.linspace(-1.0, 1.0, n * 2 + 1)
                    exact_x, exact_rho = newtonian_exact(data, kernel, alpha, p["t"])
                trajectory.append(discrete_l1(x, exact_x, 1.0 / n))
                density.append(discrete_l1(rho, exact_rho, 1.0 / n) if rho is not None else np.nan)
            results[f"{label}_trajectory"] = np.array(trajectory)
            results[f"{label}_density"] = np.array(density)
    # Diagnostic for the repulsive density: the same runs with a smaller q (larger delta / h).
    for order in (4, 6):
        errors = []
        for n in inverse_h:
            progress(f"diagnostic q = {p['diagnostic_q']}, m = {order}: h = 1/{n}")
            run = run_1d(p["data"], "newtonian_repulsive", 1.0 / n, [0.0, p["t"]], order=order,
                         q=p["diagnostic_q"], rtol=p["rtol"], atol=p["atol"])
            exact = newtonian_exact(data, "newtonian_repulsive", run.positions[0, :, 0], p["t"])[1]
            errors.append(discrete_l1(run.densities[-1], exact, 1.0 / n))
        results[f"diagnostic_m{order}_density"] = np.array(errors)
    results["diagnostic_q"] = p["diagnostic_q"]
    save_results(output, **results)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
