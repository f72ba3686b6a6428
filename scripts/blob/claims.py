"""Every checked claim of the blob paper's 1D part (Figures 1-4), measured from the cached results.

Fitted orders use the finest ``fit_points`` grid steps; "close to" a published
rate means within 0.3 (0.4 for m = 6, whose finest errors approach the integrator's
floor); identities exact by construction get rounding tolerances.
"""

import numpy as np

from particle_methods import claims as c
from particle_methods.convergence import fit_order, order_table
from particle_methods.workflow import load_results, logged, progress

PAPER = "blob"


def claim(kind, name, figure, text, *args, **kwargs):
    return kind(f"{PAPER}.{name}", PAPER, figure, text, *args, **kwargs)


def order(d, key, prefix=""):
    k = int(d["fit_points"])
    errors = d[f"{prefix}{key}"]
    progress(f"{prefix}{key}\n" + order_table(d["h_values"], errors))
    return fit_order(d["h_values"][-k:], errors[-k:])


def newtonian_claims(d1, d2, d3):
    rate = 4 * float(d1["q"])
    blob_x, blob_rho = order(d1, "trajectory_errors"), order(d1, "density_errors")
    particle_x = order(d2, "trajectory_errors")
    patch_x, patch_rho = order(d3, "trajectory_errors"), order(d3, "density_errors")
    gaps = np.diff(d1["positions"], axis=1).min() / float(d1["h"])
    times = d2["times"]
    before = times < 0.99
    paths = d2["positions"][before]
    straight = paths[0] + times[before, None] * (paths[-1] - paths[0]) / times[before][-1]
    bend = np.abs(paths - straight).max()
    tight = np.abs(d1["tight_errors"] / np.array([d1["trajectory_errors"][-1], d1["density_errors"][-1]]) - 1).max()
    energy = d1["energies"]
    rise = np.diff(energy).max() / abs(energy[0])
    mass_defect = float(d1["mass_defect"])
    return [
        claim(c.close_to, "fig1d.order_trajectory", "1D", f"blob m = 4, q = 0.9, smooth data: trajectory "
              f"error rate close to m q = {rate:g}", rate, blob_x, 0.3),
        claim(c.close_to, "fig1d.order_density", "1D", f"blob m = 4, q = 0.9, smooth data: density error rate "
              f"close to m q = {rate:g}", rate, blob_rho, 0.3),
        claim(c.close_to, "fig2.order", "2", "particle method (grad K(0) = 0): trajectory rate about 2, "
              "O(h^(2 - eps))", 2.0, particle_x, 0.3),
        claim(c.at_most, "fig2.below_blob", "2", "the particle method converges more slowly than the blob method: "
              "particle rate minus blob rate (trajectories)", 0.0, particle_x - blob_x, published="slower"),
        claim(c.at_most, "fig3.slower_trajectory", "3", "discontinuous data converge more slowly than smooth data "
              "(Figure 1): rate difference, trajectories", 0.0, patch_x - blob_x, published="slower"),
        claim(c.at_most, "fig3.slower_density", "3", "discontinuous data converge more slowly than smooth data "
              "(Figure 1): rate difference, density", 0.0, patch_rho - blob_rho, published="slower"),
        claim(c.at_least, "fig1c.no_collision", "1C", "blob trajectories never collide (they bend away near t = 1): "
              "smallest gap between neighbouring particles up to t = 1, in units of h", 1e-6, float(gaps),
              published="> 0"),
        claim(c.at_most, "fig2.no_bending", "2", "particle trajectories do not bend: largest distance from the "
              "straight line through their end points, t < 0.99", 1e-9, float(bend), published="straight"),
        claim(c.at_most, "integrator", "1D", "the ODE error is far below the method's: relative change of the finest "
              "errors when the tolerances are four times tighter", 0.01, float(tight), published="VODE"),
        claim(c.at_most, "energy.decrease", "section 2.2", "the regularised energy E_delta decreases along the blob "
              "particle system: largest increase between outputs, relative to E_delta(0)", 1e-12, float(rise),
              published="decreasing"),
        claim(c.at_most, "mass", "section 2.2", "mass is conserved along trajectories (2.2): rho~_i J_i = rho0_i "
              "with J_i the Jacobian of the off-grid trajectory map (Definition 2.3, from massless tracers at "
              "alpha_i +- 1e-5); largest relative defect at t = 0.4, h = 0.04", 1e-6, mass_defect,
              published="conserved"),
    ]


def fig4_claims(d):
    rate4, rate6 = 4 * float(d["q"]), 6 * float(d["q"])
    out = []
    names = {"newtonian_repulsive": "-|x|/2", "cubic": "|x|^3/3"}
    for kernel in d["kernels"]:
        for part in ("trajectory", "density"):
            m4, m6 = order(d, f"{kernel}_blob4_{part}"), order(d, f"{kernel}_blob6_{part}")
            out.append(claim(c.close_to, f"fig4.m4_{kernel}_{part}", "4", f"K = {names[kernel]}, m = 4: {part} "
                             f"rate close to m q = {rate4:g}", rate4, m4, 0.3))
            out.append(claim(c.close_to, f"fig4.m6_{kernel}_{part}", "4", f"K = {names[kernel]}, m = 6: {part} rate; "
                             "the paper's stayed below m q = 5.4, which it blamed on numerical kernel convolutions, "
                             "and ours uses exact ones", rate6, m6, 0.4))
            ratio = d[f"{kernel}_blob6_{part}"][-1] / d[f"{kernel}_blob4_{part}"][-1]
            out.append(claim(c.at_most, f"fig4.m6_better_{kernel}_{part}", "4", f"K = {names[kernel]}: m = 6 "
                             f"beats m = 4 ({part}): ratio of the finest errors", 1.0, float(ratio),
                             published="better"))
    particle_x, particle_rho = d["cubic_particle_trajectory"][-1], d["cubic_particle_density"][-1]
    m4_x, m4_rho = d["cubic_blob4_trajectory"][-1], d["cubic_blob4_density"][-1]
    best = max(d["cubic_blob6_trajectory"][-1] / min(particle_x, m4_x),
               d["cubic_blob6_density"][-1] / min(particle_rho, m4_rho))
    out += [
        claim(c.at_most, "fig4.cubic_particle_beats_m4_trajectory", "4", "K = |x|^3/3: the particle method beats "
              "m = 4 on trajectories: particle / m = 4 finest error", 1.0, float(particle_x / m4_x),
              published="beats"),
        claim(c.at_least, "fig4.cubic_particle_loses_density", "4", "K = |x|^3/3: but not on density: particle / "
              "m = 4 finest error", 1.0, float(particle_rho / m4_rho), published="does not beat"),
        claim(c.at_most, "fig4.cubic_m6_best", "4", "K = |x|^3/3: m = 6 is the best on both: its finest error over "
              "the best other method's, worst of trajectory and density", 1.0, float(best), published="best"),
        claim(c.at_most, "fig4.cubic_reference", "4", "K = |x|^3/3 has no exact solution: the reference (m = 6 on a "
              "finer nested grid) differs from its half-resolution twin by far less than the errors fitted: that "
              "difference over the smallest error fitted, worst of trajectory and density", 0.1,
              float(max(d["cubic_reference_error"][0] / d["cubic_blob6_trajectory"][-1],
                        d["cubic_reference_error"][1] / d["cubic_blob6_density"][-1])),
              published="n/a"),
    ]
    q = float(d["diagnostic_q"])
    for m in (4, 6):
        rate = order(d, f"diagnostic_m{m}_density")
        out.append(claim(c.close_to, f"fig4.repulsive_density_q{q:g}_m{m}", "4 (diagnostic)",
                         f"K = -|x|/2, m = {m}, with q = {q:g} instead of 0.9: the density rate reaches m q, so the "
                         "slow density rate at q = 0.9 is the quadrature error of the spreading particles, not the "
                         "regularisation", m * q, rate, 0.3))
    return out


def run(inputs, output):
    rows = [*newtonian_claims(load_results(inputs.fig1), load_results(inputs.fig2), load_results(inputs.fig3)),
            *fig4_claims(load_results(inputs.fig4))]
    for row in rows:
        progress(f"{row.status:4} {row.id}: measured {row.measured} ({row.tolerance})")
    c.write_claims(output, rows)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.input, snakemake.output[0])  # noqa: F821
