"""Figure 4, K = -|x|/2: where the density error of the blob method comes from.

For the repulsive Newtonian kernel Delta K = -delta_0, so the blob density obeys
d log rho_i/dt = -D_i with D_i = sum_j m_j psi_delta(X_i - X_j), against d log rho/dt = -rho for
the exact solution. Along the exact trajectories X(alpha, t) (mass coordinates, section 4.1),
D_i - rho splits into
  a quadrature part  Q_i = sum_j m_j psi_delta(X_i - X_j) - int psi_delta(X_i - X(alpha)) rho0(alpha) dalpha
  a regularisation part R_i = int psi_delta(X_i - X(alpha)) rho0(alpha) dalpha - rho(X_i),
and the density error is about -rho(T) int_0^T (Q_i + R_i) dt. The integral over alpha is a
trapezoid rule on a grid ``fine_factor`` times finer than the particles' (its own aliasing error
is negligible), the time integral a Gauss-Legendre rule. The same runs are extended to finer h
(blob method, m = 4 and 6), beyond the paper's range; the claims compare the quadrature part with its
prediction (particle_methods.blob.aliasing), and the runs' error with the L1_h norm of that prediction
added particle by particle to the regularisation part (``m*_predicted``: P + R, with R the regularisation
part computed along the exact trajectories above, from the exact solution and the mollifier alone, no run
and nothing fitted)."""

import numpy as np

from particle_methods.blob.aliasing import quadrature_prediction_terms
from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import data_1d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.solver import run_1d
from particle_methods.norms import discrete_l1
from particle_replication.workflow import load_results, logged, progress, save_results

KERNEL = "newtonian_repulsive"


def parts(data, n, order, q, t_final, nodes, fine_factor):
    """L1_h norms of the quadrature part, the regularisation part and their sum, the density error
    they predict at t_final, and of the predicted quadrature part (no fitted parameter) plus the
    regularisation part, particle by particle."""
    h = 1.0 / n
    delta = h**q
    psi = mollifier(order, 1)
    alpha = np.linspace(-1.0, 1.0, 2 * n + 1)
    fine = np.linspace(-1.0, 1.0, 2 * n * fine_factor + 1)
    masses, fine_masses = data(alpha) * h, data(fine) * (h / fine_factor)
    fine_masses[[0, -1]] *= 0.5
    points, weights = np.polynomial.legendre.leggauss(nodes)
    times, weights = 0.5 * t_final * (points + 1.0), 0.5 * t_final * weights
    quadrature, regularisation = np.zeros(alpha.size), np.zeros(alpha.size)
    for t, w in zip(times, weights):
        x, rho = newtonian_exact(data, KERNEL, alpha, t)
        x_fine = newtonian_exact(data, KERNEL, fine, t)[0]
        particle_sum = psi.sums_1d(x, x, masses, delta)
        convolution = psi.sums_1d(x, x_fine, fine_masses, delta)
        quadrature += w * (particle_sum - convolution)
        regularisation += w * (convolution - rho)
    rho_final = newtonian_exact(data, KERNEL, alpha, t_final)[1]
    zero = np.zeros_like(alpha)
    predicted = quadrature_prediction_terms(data, h, q, t_final, order)
    return (discrete_l1(rho_final * quadrature, zero, h), discrete_l1(rho_final * regularisation, zero, h),
            discrete_l1(rho_final * (quadrature + regularisation), zero, h),
            discrete_l1(rho_final * (predicted + regularisation), zero, h))


def run(p, fig4_path, output):
    base = load_results(fig4_path)
    data = data_1d(p["data"])
    base_n = np.rint(1.0 / base["h_values"]).astype(int)
    extra_n = np.asarray(p["extra_inverse_h"], dtype=int)
    all_n = np.concatenate([base_n, extra_n])
    results = {"inverse_h": all_n, "base_count": base_n.size, "q": p["q"], "t": p["t"]}
    for order in (4, 6):
        totals = list(base[f"{KERNEL}_blob{order}_density"])
        for n in extra_n:
            progress(f"m = {order}: blob run with h = 1/{n}")
            run_ = run_1d(p["data"], KERNEL, 1.0 / n, [0.0, p["t"]], order=order, q=p["q"], rtol=p["rtol"],
                          atol=p["atol"])
            exact = newtonian_exact(data, KERNEL, run_.positions[0, :, 0], p["t"], rho0=run_.densities[0])[1]
            totals.append(discrete_l1(run_.densities[-1], exact, 1.0 / n))
        decomposition = []
        for n in all_n:
            progress(f"m = {order}: decomposition at h = 1/{n}")
            decomposition.append(parts(data, n, order, p["q"], p["t"], p["time_nodes"], p["fine_factor"]))
        results[f"m{order}_total"] = np.array(totals)
        results[f"m{order}_quadrature"] = np.array(decomposition)[:, 0]
        results[f"m{order}_regularisation"] = np.array(decomposition)[:, 1]
        results[f"m{order}_combined"] = np.array(decomposition)[:, 2]
        results[f"m{order}_predicted"] = np.array(decomposition)[:, 3]
        progress(f"m = {order}: total {np.array(totals)}, quadrature {results[f'm{order}_quadrature']}, "
                 f"regularisation {results[f'm{order}_regularisation']}")
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.input.fig4, snakemake.output[0])  # noqa: F821
