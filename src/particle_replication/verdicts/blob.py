"""Every checked claim of the blob paper (Figures 1-8), measured from the cached results.

The claims script (scripts/blob/claims.py) calls these functions on the cached result files with
the config's ``blob.claims`` (``rules``: every tolerance, threshold and cut-off of the measures);
tests/blob/test_blob_verdicts.py feeds them wrong outcomes.

Fitted orders use the finest ``fit_points`` grid steps; "close to" a published rate m q means
within ``rules["rate_tolerance"]``; the m = 6 rates lie between m = 4's and m q (section 4.3: not as
good as m q). The bounds 0 and 1 of a comparison (a rate difference, a ratio of errors) are the
statements themselves; identities exact by construction (straight 1D particle paths, the uniform
star density of the quadratic kernel) get the shared rounding tolerance
:data:`particle_replication.claims.ROUNDING` times the scale of the quantity compared.
"""

import numpy as np

from .. import claims as c
from .. import rates
from ..rates import Recorder
from ..steady import holds_from
from ..workflow import progress

PAPER = "blob"
RESOLUTION_TIME = 0.8  # Figures 1B and 3B: the densities are compared with the exact ones at t = 0.8

# Kind and source of every claim (see particle_replication.claims): "paper" for what the paper
# states (where), "derived" for what we derive from its theory, "check" for our own checks.
FIG4_RATE = ("paper", "Figure 4, section 4.3")
FIG4_M6_RATE = ("paper", "Figure 4, section 4.3: m = 6 rates not as good as m q (cannot fail in practice: see "
                "fig4.m6_rates_approach_mq)")
#: Our readings of section 4.3's "the m = 6 blob method shows even greater improvement" (K = (-Delta)^-1):
#: applied to each of the trajectory and density errors, and to their rates.
FIG4_M6_READING = ("derived", "our reading of section 4.3 ('even greater improvement' with m = 6)")
KINDS = {
    "fig1d.order_trajectory": ("paper", "Figure 1D, section 4.2"),
    "fig1d.order_density": ("paper", "Figure 1D, section 4.2"),
    "fig2.order": ("paper", "Figure 2, section 4.2"),
    "fig2.below_blob": ("paper", "Figure 2, section 4.2"),
    "fig3.slower_trajectory": ("paper", "Figure 3D, section 4.2"),
    "fig3.slower_density": ("paper", "Figure 3D, section 4.2"),
    "fig1c.no_collision": ("paper", "Figure 1C, section 4.2"),
    "fig1c.bends_away": ("paper", "Figure 1C, section 4.2"),
    "fig1b.loses_resolution": ("paper", "Figure 1B, section 4.2"),
    "fig3b.rounded": ("paper", "Figure 3B, section 4.2"),
    "fig3b.mollifier_oscillation": ("paper", "Figure 3B, section 4.2"),
    "fig2.no_bending": ("check", "Figure 2, section 4.2: straight in 1D by construction (constant velocities)"),
    "integrator": ("check", "ODE error far below the method error (section 4.1: VODE)"),
    "energy.decrease": ("paper", "section 2.2, energy (2.4)"),
    "mass": ("check", "conservation of mass (2.2), section 2.2"),
    "fig4.m4_newtonian_repulsive_trajectory": FIG4_RATE,
    "fig4.m4_newtonian_repulsive_density": FIG4_RATE,
    "fig4.m4_cubic_trajectory": FIG4_RATE,
    "fig4.m4_cubic_density": FIG4_RATE,
    "fig4.m6_newtonian_repulsive_trajectory": FIG4_M6_RATE,
    "fig4.m6_newtonian_repulsive_density": FIG4_M6_RATE,
    "fig4.m6_cubic_trajectory": FIG4_M6_RATE,
    "fig4.m6_cubic_density": FIG4_M6_RATE,
    "fig4.m6_better_newtonian_repulsive_trajectory": FIG4_M6_READING,
    "fig4.m6_better_newtonian_repulsive_density": FIG4_M6_READING,
    "fig4.m6_rate_above_m4_newtonian_repulsive_trajectory": FIG4_M6_READING,
    "fig4.m6_rate_above_m4_newtonian_repulsive_density": FIG4_M6_READING,
    "fig4.m6_rate_above_m4_cubic_trajectory": ("derived", "our reading of section 4.3 ('the m = 6 blob method is "
                                                          "best' for K = |x|^3/3)"),
    "fig4.m6_rate_above_m4_cubic_density": ("derived", "our reading of section 4.3 ('the m = 6 blob method is "
                                                       "best' for K = |x|^3/3)"),
    "fig4.m6_better_cubic_trajectory": FIG4_RATE,
    "fig4.m6_better_cubic_density": FIG4_RATE,
    "fig4.cubic_particle_beats_m4_trajectory": FIG4_RATE,
    "fig4.cubic_particle_loses_density": FIG4_RATE,
    "fig4.cubic_m6_best": FIG4_RATE,
    "fig4.newtonian_blob_improves": FIG4_RATE,
    "fig4.more_singular_more_gain": FIG4_RATE,
    "fig4.cubic_reference": ("check", "convergence of the reference solution for K = |x|^3/3 (no exact solution)"),
    "fig4.repulsive_density_q0.75_m4": ("check", "diagnostic rerun of Figure 4 with q = 0.75 (not in the paper)"),
    "fig4.repulsive_density_q0.75_m6": ("check", "diagnostic rerun of Figure 4 with q = 0.75 (not in the paper)"),
    "fig4log.caption_fits_density": ("check", "Figure 4: row label -log|x|/(2 pi) against caption (-Delta)^{-1}"),
    "fig4log.caption_fits_trajectory": ("check", "Figure 4: row label -log|x|/(2 pi) against caption (-Delta)^{-1}"),
    "fig4log.reference": ("check", "reference for the row label's reading (no exact solution)"),
    "fig5.m4_regular_trajectory": ("paper", "Figure 5, section 4.4"),
    "fig5.m4_regular_density": ("paper", "Figure 5, section 4.4"),
    "fig5.particle_slower": ("paper", "Figure 5, section 4.4"),
    "fig5.disk_slower": ("paper", "Figure 5, section 4.4"),
    "fig6.quadratic_point": ("paper", "Figure 6, section 4.4"),
    "fig6.cubic_ring": ("paper", "Figure 6, section 4.4"),
    "fig6.cubic_ring_radius": ("paper", "Figure 6, section 4.4"),
    "fig6.star_rounding_newtonian": ("paper", "Figure 6, section 4.4 (star patch)"),
    "fig6.star_no_rounding_quadratic": ("paper", "Figure 6, section 4.4 (star patch): m = 4 preserves quadratics"),
    "fig6.newtonian_blowup": ("derived", "Figure 6, section 4.4: blow-up at 1/rho0(0); exact density of section 4.1"),
    "energy.decrease_2d": ("paper", "section 2.2, energy (2.4)"),
    "mass_2d": ("check", "conservation of mass (2.2), section 2.2"),
    "mass_2d_tabulated": ("check", "conservation of mass (2.2), section 2.2, with a tabulated kernel"),
    "fig7.delta_ring_radius": ("derived", "Figure 7, section 4.4: delta ring; stationary radius of a uniform ring"),
    "fig7.delta_ring_thin": ("paper", "Figure 7, section 4.4: a delta ring"),
    "fig7.particle_log_disk": ("paper", "Figure 7, section 4.4: the particle method's compactly supported state"),
    "fig7.particle_power_ring": ("paper", "Figure 7, section 4.4: the particle method's delta ring"),
    "fig7.blob_ring_faster": ("derived", "Figure 7, section 4.4 (our reading: the blob state settles first)"),
    "fig7.blob_closer_at_8": ("paper", "Figure 7, section 4.4: the comparison at t = 8"),
    "fig7.log_ring_collapse": ("paper", "Figure 7, section 4.4"),
    "fig7.septic_three_points": ("paper", "Figure 7, section 4.4"),
    "fig7.no_origin.delta_ring_radius": ("derived", "Figure 7, section 4.4: delta ring; stationary radius of a "
                                         "uniform ring"),
    "fig7.no_origin.delta_ring_thin": ("paper", "Figure 7, section 4.4: a delta ring"),
    "fig7.no_origin.particle_power_ring": ("paper", "Figure 7, section 4.4: the particle method's delta ring"),
    "fig7.no_origin.blob_ring_faster": ("derived", "Figure 7, section 4.4 (our reading: the blob state settles "
                                        "first)"),
    "fig7.no_origin.blob_closer_at_8": ("paper", "Figure 7, section 4.4: the comparison at t = 8"),
    "fig7.no_origin.septic_three_points": ("paper", "Figure 7, section 4.4"),
    "fig7.origin_particle": ("check", "Figure 7 (our grid hZ^2: the particle at the origin)"),
    "fig8.regularisation_effect": ("paper", "Figure 8, section 4.4"),
    "fig8.regularisation_effect_paper_tables": ("check", "Figure 8 with the caption's radial tables (200 points)"),
    "fig8.paper_tables": ("check", "Figure 8's caption: radial tables of 200 points on radius 5"),
    "fig7.paper_tables": ("check", "Figure 7's caption: radial tables of 100 points on radius 2.5"),
    "fig4.repulsive_decomposition": ("check", "Figure 4, K = -|x|/2: our split of the density error"),
    "fig4.repulsive_quadrature_dominates": ("check", "Figure 4, K = -|x|/2: our split of the density error"),
    "fig4.repulsive_regularisation_m4": ("derived", "Corollary 3.10 for the regularisation part alone"),
    "fig4.repulsive_regularisation_m6": ("derived", "Corollary 3.10 for the regularisation part alone"),
    "fig4.repulsive_same_quadrature": ("derived", "(4.1): m = 4 and m = 6 share the narrowest Gaussian"),
    "fig4.repulsive_quadrature_prediction": ("derived", "(4.1), (4.5), section 4.1: Poisson summation of the narrowest "
                                             "Gaussian along the exact flow, no fitted parameter"),
    "fig4.repulsive_error_prediction": ("derived", "(4.1), (4.5), section 4.1: the predicted quadrature part plus "
                                        "the regularisation part, runs extended to finer h (not in the paper)"),
    "fig4.repulsive_m6_quadrature": ("derived", "(4.1): m = 6's narrowest Gaussian is 16/15 times m = 4's; its "
                                     "density error is its quadrature part"),
    "fig4.m6_rates_approach_mq": ("derived", "Corollary 3.10 with exact kernels (section 4.3: m = 6 rates not as "
                                  "good as m q, which we do not reproduce)"),
    "fig4.repulsive_coarse_window": ("check", "Figure 4: dependence on the unstated h range"),
}


CATALOGUE = c.Catalogue(PAPER, KINDS)
claim = CATALOGUE.claim


def order(recorder: Recorder, d, key, name, prefix=""):
    """Fitted order of d[prefix + key] against h on the finest ``fit_points`` steps, recorded in ``recorder``
    under the claim ``name`` that it decides (the first one when it decides several)."""
    CATALOGUE.kind_and_source(name)
    h, errors = d["h_values"], d[f"{prefix}{key}"]
    progress(f"{PAPER}.{name}: {prefix}{key} at h = {', '.join(f'{v:.5g}' for v in h)}: "
             f"{', '.join(f'{e:.5e}' for e in errors)}")
    return recorder.add(rates.order(f"{PAPER}.{name}", "h", h, errors, int(d["fit_points"])))


def density_at(d, t):
    """(blob density sorted by position, exact density at the same particles) at output time ``t``."""
    i = int(np.argmin(np.abs(d["times"] - t)))
    j = int(np.argmin(np.abs(d["density_times"] - t)))
    order = np.argsort(d["positions"][i])
    return d["densities"][i][order], d["exact_densities"][j][order]


def newtonian_claims(d1, d2, d3, rules, recorder: Recorder):
    m, q, band = int(d1["order"]), float(d1["q"]), float(rules["rate_tolerance"])
    rate = m * q
    blob_x = order(recorder, d1, "trajectory_errors", "fig1d.order_trajectory")
    blob_rho = order(recorder, d1, "density_errors", "fig1d.order_density")
    particle_x = order(recorder, d2, "trajectory_errors", "fig2.order")
    patch_x = order(recorder, d3, "trajectory_errors", "fig3.slower_trajectory")
    patch_rho = order(recorder, d3, "density_errors", "fig3.slower_density")
    gaps = np.diff(d1["positions"], axis=1).min() / float(d1["h"])
    last = d1["exact_times"][-1]
    at = int(np.argmin(np.abs(d1["times"] - last)))
    turning = (np.diff(d1["positions"][at]).min() / np.diff(d1["exact_paths"][-1]).min())
    times = d2["times"]
    straight_until = float(rules["straight_until"])
    before = times < straight_until
    paths = d2["positions"][before]
    straight = paths[0] + times[before, None] * (paths[-1] - paths[0]) / times[before][-1]
    bend = np.abs(paths - straight).max()
    length = float(np.abs(paths).max())  # straight by construction (constant velocities): rounding of positions
    tight = np.abs(d1["tight_errors"] / np.array([d1["trajectory_errors"][-1], d1["density_errors"][-1]]) - 1).max()
    energy = d1["energies"]
    rise = np.diff(energy).max() / abs(energy[0])
    mass_defect = float(d1["mass_defect"])
    peak_blob, peak_exact = density_at(d1, RESOLUTION_TIME)
    patch_blob, patch_exact = density_at(d3, RESOLUTION_TIME)
    return [
        claim(
            c.close_to, "fig1d.order_trajectory", figure="1D",
            text=f"blob m = {m}, q = {q:g}, smooth data: trajectory "
                 f"error rate close to m q = {rate:g}",
            published=rate, measured=blob_x, tolerance=band),
        claim(
            c.close_to, "fig1d.order_density", figure="1D",
            text=f"blob m = {m}, q = {q:g}, smooth data: density error rate "
                 f"close to m q = {rate:g}",
            published=rate, measured=blob_rho, tolerance=band),
        claim(
            c.close_to, "fig2.order", figure="2",
            text="particle method (grad K(0) = 0): trajectory rate about 2, "
                 "O(h^(2 - eps))",
            published=2.0, measured=particle_x, tolerance=band),
        claim(
            c.at_most, "fig2.below_blob", figure="2",
            text="the particle method converges more slowly than the blob method: "
                 "particle rate minus blob rate (trajectories)",
            tolerance=0.0, measured=particle_x - blob_x, published="slower"),
        claim(
            c.at_most, "fig3.slower_trajectory", figure="3",
            text="discontinuous data converge more slowly than smooth data "
                 "(Figure 1): rate difference, trajectories",
            tolerance=0.0, measured=patch_x - blob_x, published="slower"),
        claim(
            c.at_most, "fig3.slower_density", figure="3",
            text="discontinuous data converge more slowly than smooth data "
                 "(Figure 1): rate difference, density",
            tolerance=0.0, measured=patch_rho - blob_rho, published="slower"),
        claim(
            c.at_least, "fig1c.no_collision", figure="1C",
            text="blob trajectories never collide: smallest gap between "
                 "neighbouring particles up to t = 1, in units of h (a clear gap, not a rounding one)",
            tolerance=float(rules["collision_gap"]), measured=float(gaps), published="> 0"),
        claim(
            c.at_most, "fig1b.loses_resolution", figure="1B",
            text=f"smooth data: the blob density loses resolution at t = "
                 f"{RESOLUTION_TIME:g}: largest blob density over the largest exact one",
            tolerance=float(rules["resolution_loss"]), measured=float(peak_blob.max() / peak_exact.max()),
            published="loses resolution"),
        claim(
            c.at_most, "fig3b.rounded", figure="3B",
            text="indicator data: the blob density is rounded at t = "
                 f"{RESOLUTION_TIME:g}: blob density at the outermost particle over the exact (uniform) density",
            tolerance=float(rules["rounded_edge"]),
            measured=float(patch_blob[[0, -1]].max() / patch_exact[[0, -1]].max()), published="rounded"),
        claim(
            c.at_least, "fig3b.mollifier_oscillation", figure="3B",
            text=f"indicator data, t = {RESOLUTION_TIME:g}: the rounded "
                 "profile oscillates like the mollifier (4.1), whose negative lobe makes it overshoot the exact "
                 "plateau near the edges (a monotone rounding does not): largest blob density over the exact plateau, "
                 "minus 1",
            tolerance=float(rules["oscillation_min"]), measured=float(patch_blob.max() / patch_exact.max() - 1.0),
            published="oscillating profile"),
        claim(
            c.at_least, "fig1c.bends_away", figure="1C",
            text=f"near the exact collision the blob trajectories turn away from "
                 f"the exact ones: smallest blob gap over smallest exact gap at t = {last:g}",
            tolerance=float(rules["bend_away"]), measured=float(turning), published="bend away"),
        claim(
            c.at_most, "fig2.no_bending", figure="2",
            text="particle trajectories do not bend: largest distance from the "
                 f"straight line through their end points, t < {straight_until:g}",
            tolerance=c.ROUNDING * length, measured=float(bend), published="straight"),
        claim(
            c.at_most, "integrator", figure="1D",
            text="the ODE error is far below the method's: relative change of the finest "
                 "errors when the tolerances are four times tighter",
            tolerance=float(rules["integrator_change"]), measured=float(tight), published="VODE"),
        claim(
            c.at_most, "energy.decrease", figure="section 2.2",
            text="the regularised energy E_delta decreases along the blob "
                 "particle system: largest increase between outputs, relative to E_delta(0)",
            tolerance=float(rules["energy_rise"]), measured=float(rise), published="decreasing"),
        claim(
            c.at_most, "mass", figure="section 2.2",
            text="mass is conserved along trajectories (2.2): rho~_i J_i = rho0_i "
                 "with J_i the Jacobian of the off-grid trajectory map (Definition 2.3, from massless tracers at "
                 f"alpha_i +- 1e-5); largest relative defect at t = 0.4, h = {float(d1['h']):g}",
            tolerance=float(rules["mass_defect"]), measured=mass_defect, published="conserved"),
    ]


def fig4_claims(d, rules, recorder: Recorder):
    rate4, rate6 = 4 * float(d["q"]), 6 * float(d["q"])
    band = float(rules["rate_tolerance"])
    out = []
    names = {"newtonian_repulsive": "-|x|/2", "cubic": "|x|^3/3"}
    for kernel in d["kernels"]:
        for part in ("trajectory", "density"):
            m4 = order(recorder, d, f"{kernel}_blob4_{part}", f"fig4.m4_{kernel}_{part}")
            m6 = order(recorder, d, f"{kernel}_blob6_{part}", f"fig4.m6_{kernel}_{part}")
            out.append(claim(
                c.close_to, f"fig4.m4_{kernel}_{part}", figure="4",
                text=f"K = {names[kernel]}, m = 4: {part} "
                     f"rate close to m q = {rate4:g}",
                published=rate4, measured=m4, tolerance=band))
            out.append(claim(
                c.at_most, f"fig4.m6_{kernel}_{part}", figure="4",
                text=f"K = {names[kernel]}, m = 6: {part} rate "
                     f"not as good as m q = {rate6:g} (the paper blames other error sources; our kernels are "
                     "exact). This cannot fail in practice: any rate fitted before the asymptotic range "
                     "passes. The shortfall is not reproduced, only not contradicted: our rates approach m q "
                     "(fig4.m6_rates_approach_mq)",
                tolerance=rate6, measured=m6, published=f"< {rate6:g}"))
            out.append(claim(
                c.at_least, f"fig4.m6_rate_above_m4_{kernel}_{part}", figure="4",
                text=f"K = {names[kernel]}: the "
                     f"m = 6 {part} rate at least m = 4's ({m4:.3g})",
                tolerance=m4, measured=m6, published="better"))
            ratio = d[f"{kernel}_blob6_{part}"][-1] / d[f"{kernel}_blob4_{part}"][-1]
            out.append(claim(
                c.at_most, f"fig4.m6_better_{kernel}_{part}", figure="4",
                text=f"K = {names[kernel]}: m = 6 "
                     f"beats m = 4 ({part}): ratio of the finest errors",
                tolerance=1.0, measured=float(ratio), published="better"))
    out.append(m6_approach_claim(d, band))
    particle_x, particle_rho = d["cubic_particle_trajectory"][-1], d["cubic_particle_density"][-1]
    m4_x, m4_rho = d["cubic_blob4_trajectory"][-1], d["cubic_blob4_density"][-1]
    # m = 6 error over the best other method's, worst of trajectory and density, at every h (the claim: the finest)
    best_by_h = np.maximum(
        d["cubic_blob6_trajectory"] / np.minimum(d["cubic_particle_trajectory"], d["cubic_blob4_trajectory"]),
        d["cubic_blob6_density"] / np.minimum(d["cubic_particle_density"], d["cubic_blob4_density"]))
    best = best_by_h[-1]
    by_h = ", ".join(f"1/{1 / h:.0f}: {value:.3g}" for h, value in zip(d["h_values"], best_by_h))
    gain = {kernel: d[f"{kernel}_particle_trajectory"][-1] / d[f"{kernel}_blob4_trajectory"][-1]
            for kernel in ("newtonian_repulsive", "cubic")}
    out += [
        claim(
            c.at_least, "fig4.newtonian_blob_improves", figure="4",
            text="K = -|x|/2: the m = 4 blob method improves on the "
                 "particle method: particle / m = 4 finest trajectory error",
            tolerance=1.0, measured=float(gain["newtonian_repulsive"]), published="improves"),
        claim(
            c.at_least, "fig4.more_singular_more_gain", figure="4",
            text="the more singular the kernel, the greater the gain of "
                 "the blob method: particle / m = 4 finest trajectory error for -|x|/2 over that for |x|^3/3",
            tolerance=1.0, measured=float(gain["newtonian_repulsive"] / gain["cubic"]),
            published="greater for more singular"),
        claim(
            c.at_most, "fig4.cubic_particle_beats_m4_trajectory", figure="4",
            text="K = |x|^3/3: the particle method beats "
                 "m = 4 on trajectories: particle / m = 4 finest error",
            tolerance=1.0, measured=float(particle_x / m4_x), published="beats"),
        claim(
            c.at_least, "fig4.cubic_particle_loses_density", figure="4",
            text="K = |x|^3/3: but not on density: particle / "
                 "m = 4 finest error", tolerance=1.0,
            measured=float(particle_rho / m4_rho), published="does not beat"),
        claim(
            c.at_most, "fig4.cubic_m6_best", figure="4",
            text="K = |x|^3/3: m = 6 is the best on both: its finest error over "
                 "the best other method's, worst of trajectory and density; the paper does not say at which h: at "
                 f"every h (h: ratio) {by_h}, best at {int((best_by_h <= 1).sum())} of {best_by_h.size}",
            tolerance=1.0, measured=float(best), published="best"),
        claim(
            c.at_most, "fig4.cubic_reference", figure="4",
            text="K = |x|^3/3 has no exact solution: the reference (m = 6 on a "
                 "finer nested grid) differs from its half-resolution twin by far less than the errors fitted: that "
                 "difference over the smallest error fitted, worst of trajectory and density",
            tolerance=float(rules["reference_share"]),
            measured=float(max(d["cubic_reference_error"][0] / d["cubic_blob6_trajectory"][-1],
                               d["cubic_reference_error"][1] / d["cubic_blob6_density"][-1])),
            published="n/a"),
    ]
    out += [diagnostic_claim(d, m, band, recorder) for m in (4, 6)]
    return out


def diagnostic_claim(d, m: int, band: float, recorder: Recorder):
    """Check: with q = ``diagnostic_q`` (a larger delta / h, the quadrature error negligible) the repulsive density
    error is the regularisation part and converges at m q. The h range is not stated, so the claim is stated on
    every window of ``fit_points`` successive h: the fit farthest from m q, within ``band``; the text gives every
    window's fit and the pairwise orders, and which windows would pass alone. (The aliasing prediction that
    decides the m = 6 error at q = 0.9 does not apply here: its expansion parameter, the saddle ratio, is not
    small at q = 0.75; config/config.yaml.)"""
    q, paper_q = float(d["diagnostic_q"]), float(d["q"])
    name, key = f"fig4.repulsive_density_q{q:g}_m{m}", f"diagnostic_m{m}_density"
    order(recorder, d, key, name)  # the table with its pairwise orders, in the claims' log
    h, errors, k = d["h_values"], d[key], int(d["fit_points"])
    fits = np.array([np.polyfit(np.log(h[i:i + k]), np.log(errors[i:i + k]), 1)[0] for i in range(h.size - k + 1)])
    held = np.abs(fits - m * q) <= band
    windows = ", ".join(f"{fit:.2f} (1/h = {1 / h[i]:.0f}-{1 / h[i + k - 1]:.0f})" for i, fit in enumerate(fits))
    flips = (f"{int(held.sum())} of {fits.size} windows would pass alone" if 0 < held.sum() < fits.size else
             f"{'every' if held.all() else 'no'} window would pass alone")
    # the regularisation error C delta^m (1 + a delta^2 + ...) (psi even): the gap m q - pairwise order shrinks by
    # 2^(2q) per halving of h once the first correction dominates
    pairwise = np.diff(np.log(errors)) / np.diff(np.log(h))
    gaps = m * q - pairwise
    shrink = ", ".join(f"{a / b:.2f}" for a, b in zip(gaps[:-1], gaps[1:])) if np.all(gaps > 0) else "not all positive"
    return claim(
        c.close_to, name, figure="4 (diagnostic)",
        text=f"K = -|x|/2, m = {m}, with q = {q:g} instead of {paper_q:g}: "
             "the density rate reaches m q on every window of the (unstated) h range, so the slow density rate at "
             f"q = {paper_q:g} is the quadrature error of the spreading particles, not the regularisation: the "
             f"{k}-point fit farthest from m q = {m * q:g} over every window ({windows}; {flips}); pairwise "
             f"orders {local_orders(np.rint(1.0 / h).astype(int), errors)}; their gaps to m q shrink by {shrink} "
             f"per halving of h (2^(2q) = {2 ** (2 * q):.2f} once the delta^2 correction of the regularisation "
             "error dominates)",
        published=m * q, measured=float(fits[np.argmax(np.abs(fits - m * q))]), tolerance=band)


#: The m = 6 errors whose rate the regularisation sets (Corollary 3.10): every error of Figure 4 but the repulsive
#: density, which its quadrature part limits over the paper's range (repulsive_claims).
M6_REGULARISED = (("newtonian_repulsive", "trajectory"), ("cubic", "trajectory"), ("cubic", "density"))


def m6_approach_claim(d, band: float):
    """Derived: with exact kernels the m = 6 errors set by the regularisation approach the order m q. Its error is
    C delta^m (1 + O(delta^2)), so the pairwise order of the two finest h tends to m q and is the measure nearest
    to it; the claim takes the one farthest from m q over :data:`M6_REGULARISED`, within ``band`` (the
    repository's "close to"). A shortfall like the paper's (rates visibly below m q) fails it."""
    h, rate6 = d["h_values"], 6 * float(d["q"])
    orders = {f"{kernel} {part}": float(np.log(d[f"{kernel}_blob6_{part}"][-1] / d[f"{kernel}_blob6_{part}"][-2])
                                        / np.log(h[-1] / h[-2])) for kernel, part in M6_REGULARISED}
    farthest = max(orders.values(), key=lambda value: abs(value - rate6))
    return claim(
        c.close_to, "fig4.m6_rates_approach_mq", figure="4",
        text=f"with exact kernels our m = 6 rates approach m q = "
             f"{rate6:g}, so the paper's shortfall is not reproduced: pairwise order between h = 1/{1 / h[-2]:.0f} "
             f"and 1/{1 / h[-1]:.0f} of the errors the regularisation sets "
             f"({', '.join(f'{name}: {value:.3f}' for name, value in orders.items())}), the one farthest from "
             f"{rate6:g}",
        published=rate6, measured=farthest, tolerance=band)


def fig4log_claims(d_log, d, rules, recorder: Recorder):
    """Figure 4's row label reads K = -log|x|/(2 pi); its caption and text say (-Delta)^{-1}, -|x|/2 in
    1D. Which reading do the published m = 4 rates (m q = 3.6) fit? For trajectory and density: the
    distance of the label's m = 4 order from 3.6 minus that of the caption's (Figure 4's first row);
    positive when the caption's reading fits better."""
    rate4 = 4 * float(d["q"])
    out = []
    for part in ("trajectory", "density"):
        label = order(recorder, d_log, f"log_repulsive_blob4_{part}", f"fig4log.caption_fits_{part}")
        key = f"newtonian_repulsive_blob4_{part}"  # recorded by fig4_claims
        caption = rates.order(f"{PAPER}.fig4.m4_{key}", "h", d["h_values"], d[key], int(d["fit_points"])).slope
        out.append(claim(
            c.at_least, f"fig4log.caption_fits_{part}", figure="4",
            text=f"the published m = 4 {part} rate "
                 f"m q = {rate4:g} fits the caption's K = -|x|/2 (order {caption:.3g}) better than the row "
                 f"label's -log|x|/(2 pi) (order {label:.3g}): |label - {rate4:g}| - |caption - {rate4:g}|",
            tolerance=0.0, measured=abs(label - rate4) - abs(caption - rate4), published="caption's reading"))
    error = d_log["log_repulsive_reference_error"]
    out.append(claim(
        c.at_most, "fig4log.reference", figure="4",
        text="K = -log|x|/(2 pi) has no exact solution: the reference "
             "(m = 6 on a finer nested grid) differs from its half-resolution twin by well under the errors "
             "fitted (orders near 1 need a margin the cubic kernel's orders do not): that difference over the "
             "smallest m = 6 error fitted, worst of trajectory and density",
        tolerance=float(rules["log_reference_share"]),
        measured=float(max(error[0] / d_log["log_repulsive_blob6_trajectory"][-1],
                           error[1] / d_log["log_repulsive_blob6_density"][-1])),
        published="n/a"))
    return out


def repulsive_claims(d, p, rules, recorder: Recorder):
    """Figure 4, K = -|x|/2: where the slow density rate comes from, whether the quadrature part is the
    aliasing predicted without fitted parameters (particle_methods.blob.aliasing), and whether that prediction,
    added to the regularisation part, gives the runs' error beyond the paper's range of h."""
    n, base = d["inverse_h"], int(d["base_count"])
    h, q, k = 1.0 / n, float(d["q"]), int(p["fit_points"])
    band = float(rules["rate_tolerance"])
    out = []
    # the decomposition's sizes: where the quadrature part is most of the error (h <= 1/decomposition_from)
    counted = n >= int(rules["decomposition_from"])
    gaps = {m: np.abs(d[f"m{m}_combined"] / d[f"m{m}_total"] - 1) for m in (4, 6)}
    mismatch = max(float(gaps[m][counted].max()) for m in (4, 6)) if counted.any() else np.nan  # nan: unmeasured
    share = min(float(d[f"m{m}_quadrature"][base - 1] / d[f"m{m}_combined"][base - 1]) for m in (4, 6))
    out += [
        claim(
            c.at_most, "fig4.repulsive_decomposition", figure="4",
            text="K = -|x|/2: the quadrature and regularisation parts, "
                 "integrated along the exact trajectories, account for the measured density error: largest relative "
                 f"gap between their sum and the blob runs' error, m = 4 and 6, 1/h from "
                 f"{int(rules['decomposition_from'])} to {n[-1]} (coarser: "
                 f"{', '.join(f'1/{v}: {max(gaps[4][i], gaps[6][i]):.3g}' for i, v in enumerate(n) if not counted[i])}"
                 ", where the regularisation part, and with it the neglected displacement of the particles by their "
                 "trajectory error, dominates)",
            tolerance=float(rules["decomposition_gap"]), measured=mismatch),
        claim(
            c.at_least, "fig4.repulsive_quadrature_dominates", figure="4",
            text=f"K = -|x|/2 at h = 1/{n[base - 1]}: the "
                 "quadrature part (particle sum against the exact mollified convolution) is most of the density error: "
                 "its share, smallest of m = 4 and 6",
            tolerance=float(rules["quadrature_share_min"]), measured=share),
    ]
    for m in (4, 6):
        slope = recorder.add(rates.order(f"{PAPER}.fig4.repulsive_regularisation_m{m}", "h", h[:base],
                                      d[f"m{m}_regularisation"][:base], k))
        out.append(claim(
            c.close_to, f"fig4.repulsive_regularisation_m{m}", figure="4",
            text=f"K = -|x|/2, m = {m}: the "
                 f"regularisation part alone converges at m q = {m * q:g}: order on the {k} finest h of the "
                 "paper's range",
            published=m * q, measured=slope, tolerance=band))
    ratios = d["m6_quadrature"][:base] / d["m4_quadrature"][:base]
    farthest = float(ratios[np.argmax(np.abs(ratios / SAME_QUADRATURE - 1))])
    out.append(claim(
        c.relatively_close_to, "fig4.repulsive_same_quadrature", figure="4",
        text="(4.1) gives m = 6 the narrowest "
             "Gaussian of m = 4 with 16/15 its weight, and that Gaussian sets the quadrature error (the next "
             "one aliases exp(-3c/J^2) times less): m = 6 over m = 4 quadrature part, the one farthest from "
             f"16/15 over the paper's range (h = 1/{n[0]} to 1/{n[base - 1]})",
        published=SAME_QUADRATURE, measured=farthest, tolerance=float(rules["same_quadrature_tolerance"])))
    out.append(quadrature_prediction_claim(d, p, rules))
    out.append(error_prediction_claim(d, rules))
    out.append(m6_quadrature_claim(d, p, rules))
    coarse = float(np.polyfit(np.log(h[:k]), np.log(d["m4_total"][:k]), 1)[0])
    out.append(claim(
        c.close_to, "fig4.repulsive_coarse_window", figure="4",
        text=f"K = -|x|/2, m = 4: density order on the {k} "
             f"coarsest h of the paper's range (h = 1/{n[0]} to 1/{n[k - 1]}): the verdict depends on the "
             "unstated h range",
        published=4 * q, measured=coarse, tolerance=band))
    return out


#: m = 6 over m = 4 weight of the narrowest Gaussian of (4.1): psi6 = (16/15) psi4(x) - (1/30) psi4(x/2), and
#: psi4(x/2) holds only wider Gaussians (particle_methods.blob.aliasing.quadrature_prediction).
SAME_QUADRATURE = 16.0 / 15.0


def local_orders(n, errors) -> str:
    """Pairwise orders of ``errors`` between successive 1/h in ``n``, as text."""
    orders = np.diff(np.log(errors)) / np.diff(np.log(1.0 / n))
    return ", ".join(f"{order:.2f} ({a}-{b})" for order, a, b in zip(orders, n[:-1], n[1:]))


def error_prediction_claim(d, rules):
    """Derived: beyond the paper's range (the extended runs, out of sample), the m = 4 run's density error is the
    L1_h norm of P + R, particle by particle: P the quadrature part predicted with no fitted parameter, R the
    regularisation part computed along the exact trajectories (from the exact solution and the mollifier, no run,
    nothing fitted). The crossover from P to R is where the order of the error moves towards m q."""
    n, base = d["inverse_h"], int(d["base_count"])
    extended = slice(base, None)
    gaps = d["m4_total"][extended] / d["m4_predicted"][extended] - 1.0
    crossing = np.flatnonzero(d["m4_regularisation"] > d["m4_quadrature"])
    crossing = crossing[crossing >= base - 1]
    crossover = f"the regularisation part exceeds the quadrature part from 1/h = {n[crossing[0]]}" if crossing.size \
        else "the quadrature part dominates at every h"
    shares = ", ".join(f"{a / b:.3g} (1/{v})" for a, b, v in zip(d["m4_quadrature"][base - 1:],
                                                              d["m4_regularisation"][base - 1:], n[base - 1:]))
    windows = ", ".join(f"{np.polyfit(np.log(1.0 / n[i:i + 3]), np.log(d['m4_total'][i:i + 3]), 1)[0]:.2f} "
                        f"({n[i]}-{n[i + 2]})" for i in range(n.size - 2))
    return claim(
        c.at_most, "fig4.repulsive_error_prediction", figure="4",
        text="K = -|x|/2, m = 4, runs extended beyond the "
             f"paper's range (1/h = {', '.join(str(v) for v in n[extended])}): the density error equals P + R "
             "(L1_h norm of their sum particle by particle; P the aliasing prediction with no fitted parameter, R "
             "the regularisation part along the exact trajectories): largest |error / (P + R) - 1|, "
             f"{', '.join(f'{g:+.3g} (1/{v})' for g, v in zip(gaps, n[extended]))}; quadrature over "
             f"regularisation part {shares}: {crossover}; pairwise orders of the error "
             f"{local_orders(n, d['m4_total'])}; three-point fits {windows}",
        tolerance=float(rules["error_prediction_gap"]), measured=float(np.abs(gaps).max()),
        published="(our derivation)")


def m6_quadrature_claim(d, p, rules):
    """Derived: the m = 6 run's density error is its quadrature part, 16/15 times the m = 4 prediction P (its
    regularisation part falls at h^5.4), at the h where P's neglected terms, of order the square of the saddle
    ratio (:func:`~particle_methods.blob.aliasing.saddle_ratio`), are below the tolerance, and where the predicted
    error stays above the integrator's floor, rtol times the mass, by the tolerance's inverse."""
    from particle_methods.blob.aliasing import quadrature_prediction, saddle_ratio
    from particle_methods.blob.initial import data_1d, grid_1d

    n, q, t, data = d["inverse_h"], float(d["q"]), float(d["t"]), data_1d(p["data"])
    tolerance = float(rules["m6_quadrature_gap"])
    predicted = SAME_QUADRATURE * np.array([quadrature_prediction(data, 1.0 / v, q, t) for v in n])
    expansion = np.array([saddle_ratio(data, 1.0 / v, q) for v in n]) ** 2
    finest = 1.0 / n.max()
    mass = float(finest * data(grid_1d(finest)[:, 0]).sum())
    floor = float(p["rtol"]) * mass
    held = (expansion <= tolerance) & (predicted * tolerance >= floor)
    ratios = d["m6_total"] / predicted
    text = ", ".join(f"{r:.5g} (1/{v})" for r, v in zip(ratios, n))
    return claim(
        c.relatively_close_to, "fig4.repulsive_m6_quadrature", figure="4",
        text="K = -|x|/2, m = 6: the density error "
             "is the quadrature part of the narrowest Gaussian, 16/15 times the m = 4 prediction P (no fitted "
             f"parameter): error / ((16/15) P) at every h, {text}; the one farthest from 1 where P's neglected "
             f"terms (saddle ratio squared) are at most the tolerance and (16/15) P is at least the integrator's "
             f"floor (rtol {float(p['rtol']):g} times the mass {mass:.4g}) over the tolerance (h = "
             f"{', '.join(f'1/{v}' for v in n[held])})",
        published=1.0, measured=float(ratios[held][np.argmax(np.abs(ratios[held] - 1))]) if held.any() else np.nan,
        tolerance=tolerance)


def quadrature_prediction_claim(d, p, rules):
    """The m = 4 quadrature part against its prediction without fitted parameters, at every h of the study where
    the prediction's expansion parameter (:func:`~particle_methods.blob.aliasing.saddle_ratio`) is below 1."""
    from particle_methods.blob.aliasing import quadrature_prediction, saddle_ratio
    from particle_methods.blob.initial import data_1d

    n, q, t, data = d["inverse_h"], float(d["q"]), float(d["t"]), data_1d(p["data"])
    predicted = np.array([quadrature_prediction(data, 1.0 / v, q, t) for v in n])
    expansion = np.array([saddle_ratio(data, 1.0 / v, q) for v in n])
    measured = d["m4_quadrature"]
    gaps = np.maximum(predicted / measured, measured / predicted) - 1.0
    held = expansion < 1.0
    progress(f"{PAPER}.fig4.repulsive_quadrature_prediction: h = 1/({', '.join(str(v) for v in n)}), predicted "
             f"{', '.join(f'{v:.4e}' for v in predicted)}, measured {', '.join(f'{v:.4e}' for v in measured)}, "
             f"saddle ratio {', '.join(f'{v:.3f}' for v in expansion)}")
    return claim(
        c.at_most, "fig4.repulsive_quadrature_prediction", figure="4",
        text="K = -|x|/2, m = 4: the quadrature part "
             "predicted with no fitted parameter, the first alias of the narrowest Gaussian of (4.1) by Poisson "
             "summation along the exact flow, h sum_i rho(X_i, t) (4/3) [E1(c/J_i^2) - E1(c)], c = (pi delta/h)^2, "
             "J_i = 1 + t rho0(ih), against the measured one: factor - 1 at every h, "
             f"{', '.join(f'{g:.3g} (1/{v})' for g, v in zip(gaps, n))}; largest where the saddle displacement "
             f"pi delta^2/h is below the width 1/sqrt(2p) of the data, p = {data.power} (h = "
             f"{', '.join(f'1/{v}' for v in n[held])})",
        tolerance=float(rules["quadrature_prediction_gap"]), measured=float(gaps[held].max()) if held.any() else np.nan,
        published="(our derivation)")


def ring_radii(points, centre: float):
    """Distances to the origin of the particles off the centre, farther than ``centre`` from it (a centre
    particle stays there by symmetry, up to rounding that the dynamics may amplify)."""
    r = np.linalg.norm(points, axis=-1)
    return r[r > centre]


def variation(values):
    return float(values.std() / values.mean())


def cluster_count(points, threshold: float):
    """Number of groups of particles closer than ``threshold`` (single linkage)."""
    from scipy.cluster.hierarchy import fcluster, linkage

    return int(fcluster(linkage(points, "single"), threshold, criterion="distance").max())


def fig5_claims(d, rules, recorder: Recorder):
    labels = list(d["labels"])
    band, rate = float(rules["rate_tolerance"]), 4 * float(d["q"])  # m = 4 in every blob case of Figure 5
    # the claim each case's fits are recorded under: the one its trajectory rate decides (the
    # density rates of the particle and disk cases decide none)
    names = {"regular, blob": ("fig5.m4_regular_trajectory", "fig5.m4_regular_density"),
             "regular, particle": ("fig5.particle_slower",) * 2, "disk, blob": ("fig5.disk_slower",) * 2}
    slopes = {label: (order(recorder, d, "_trajectory", names[label][0], f"case{i}"),
                      order(recorder, d, "_density", names[label][1], f"case{i}")
                      if np.isfinite(d[f"case{i}_density"]).all() else np.nan)
              for i, label in enumerate(labels)}
    regular, particle, disk = slopes["regular, blob"], slopes["regular, particle"], slopes["disk, blob"]
    return [
        claim(
            c.close_to, "fig5.m4_regular_trajectory", figure="5",
            text="2D, K = log|x|/(2 pi), m = 4, regular data: trajectory "
                 f"rate close to m q = {rate:g}",
            published=rate, measured=regular[0], tolerance=band),
        claim(
            c.close_to, "fig5.m4_regular_density", figure="5",
            text=f"2D, m = 4, regular data: density rate close to m q = "
                 f"{rate:g}", published=rate,
            measured=regular[1], tolerance=band),
        claim(
            c.at_most, "fig5.particle_slower", figure="5",
            text="2D: the particle method converges more slowly: particle "
                 "minus blob trajectory rate",
            tolerance=0.0, measured=particle[0] - regular[0], published="slower"),
        claim(
            c.at_most, "fig5.disk_slower", figure="5",
            text="2D: discontinuous data converge more slowly: disk minus regular "
                 "trajectory rate (blob)",
            tolerance=0.0, measured=disk[0] - regular[0], published="slower"),
    ]


def spread(values) -> float:
    """(max - min) / max."""
    return float((values.max() - values.min()) / values.max())


def blowup_claim(d, p, rules):
    """Derived: the blob density at the peak blows up at the exact time 1/rho0(0) while the peak is resolved.

    Along the exact trajectories of section 4.1 the density at the origin is 1/(1/rho0(0) - t), so the extrapolated
    blow-up time T(t) = t + 1/rho(0, t) is 1/rho0(0) at every t before it. The blob density of the particle at the
    origin obeys d log rho/dt = S(t) = sum_j m_j psi_delta(X_j) (the mollified density there) instead of rho(0, t),
    so dT/dt = 1 - S / rho~ (rho~ the blob density there), to first order 1 - S / rho: T drifts by the integral of
    the relative rate error 1 - S / rho, which for m = 4 is O((delta / w)^4), w = 1 - t rho0(0) the width of the
    narrowing peak. Computed along the exact trajectories (the data, h and delta; no run), its integral of absolute
    values up to the last record where it is at most ``blowup_rate_error`` (the first-order expansion holds) gives
    the band, ``blowup_allowance`` times it: the particles' displacement by their own O(delta^4) trajectory error,
    not computed, changes S by a term of the same order. T is read at the records themselves (no interpolation): the
    time grid only places the last record. Measured: T at the record farthest from
    1/rho0(0) up to that one; NaN (a failure) when no record after t = 0 qualifies."""
    from scipy import integrate

    from particle_methods.blob.initial import data_2d
    from particle_methods.blob.mollifiers import mollifier

    top, times = p["top"], d["times"]
    h, delta, data = float(top["h"]), float(top["h"]) ** float(p["q"]), data_2d(top["data"])
    # the grid from the run, the initial density from the data (the run's first record is a state it computed)
    points, blob = d["newtonian_positions"][0], d["newtonian_densities"]
    rho0 = data(points)
    peak = int(np.argmax(rho0))
    rho00 = float(rho0[peak])
    if np.linalg.norm(points[peak]) > 1e-9 * h:
        raise ValueError("the Newtonian bump run of Figure 6 has no particle at the origin, where the peak stays")
    blowup = 1.0 / rho00
    before = times < blowup
    r0 = np.linalg.norm(points, axis=1)
    # exact trajectories (section 4.1, d = 2): |X|^2 = r0^2 - 2 t m(r0), m(r) = int_0^r s rho0(s) ds
    mass = np.array([integrate.quad(lambda s: s * float(data(np.array([s, 0.0]))), 0.0, r, epsabs=1e-14)[0]
                     for r in r0])
    psi = mollifier(4, 2)
    masses = rho0 * h * h
    mollified = np.array([(masses * psi(np.sqrt(np.maximum(r0**2 - 2.0 * t * mass, 0.0)), delta)).sum()
                          for t in times[before]])
    rate_error = np.abs(1.0 - mollified * (blowup - times[before]))
    beyond = np.flatnonzero(rate_error > float(rules["blowup_rate_error"]))
    last = (int(beyond[0]) if beyond.size else int(before.sum())) - 1
    drift = integrate.cumulative_trapezoid(rate_error, times[before], initial=0.0)
    band = float(rules["blowup_allowance"]) * float(drift[max(last, 0)])
    extrapolated = times[: last + 1] + 1.0 / blob[: last + 1, peak]
    # the regularisation part alone: the origin particle's density grown at the mollified exact density
    growth = integrate.cumulative_trapezoid(mollified, times[before], initial=0.0)
    predicted = times[before] + np.exp(-growth) / rho00 - blowup
    farthest = int(np.argmax(np.abs(extrapolated - blowup))) if last > 0 else -1
    shown = np.unique(np.linspace(0, max(last, 0), 5).round().astype(int))
    text = ", ".join(f"{extrapolated[i] - blowup:+.2e} (t = {times[i]:g})" for i in shown) if last > 0 else "none"
    return claim(
        c.close_to, "fig6.newtonian_blowup", figure="6",
        text=f"K = log|x|/(2 pi), delta = {delta:.4g}: the blob density "
             f"at the peak blows up at the exact time 1/rho0(0) = {blowup:.4f} while the peak is resolved: "
             "extrapolated blow-up time t + 1/rho(0, t) (1/rho0(0) at every t for the exact density of section "
             "4.1), the record farthest from 1/rho0(0) up to the last one where the relative rate error of the "
             f"mollified exact density at the peak is at most {float(rules['blowup_rate_error']):g} (t = "
             f"{times[max(last, 0)]:g}, peak {blob[max(last, 0), peak] / rho00:.3g} times rho0(0); beyond it the "
             "peak narrows to delta and the drift becomes O(delta)); minus 1/rho0(0) there: " + text +
             f"; tolerance {float(rules['blowup_allowance']):g} times that rate error's integral "
             f"({float(drift[max(last, 0)]):.2e}, computed along the exact trajectories; the regularisation "
             f"part alone predicts {float(predicted[max(last, 0)]):+.2e} at the last record)",
        published=blowup, measured=float(extrapolated[farthest]) if last > 0 else np.nan, tolerance=band)


def fig6_claims(d, p, rules):
    times = d["times"]
    quadratic = np.linalg.norm(d["quadratic_positions"], axis=-1)
    centre = float(rules["centre_radius"])
    cubic_start, cubic_end = (ring_radii(d["cubic_positions"][0], centre),
                              ring_radii(d["cubic_positions"][-1], centre))
    rises = [np.diff(d[f"{k}_energies"]).max() / abs(d[f"{k}_energies"][0]) for k in ("newtonian", "quadratic")]
    return [
        claim(
            c.at_most, "fig6.quadratic_point", figure="6",
            text="K = |x|^2/2: particles converge to a point: final over initial "
                 f"largest radius at t = {times[-1]:g}",
            tolerance=float(rules["point_ratio"]), measured=float(quadratic[-1].max() / quadratic[0].max()),
            published="a point"),
        claim(
            c.at_most, "fig6.cubic_ring", figure="6",
            text="K = |x|^3/3: particles approach a ring: coefficient of variation "
                 "of the radii (centre particle excluded), final over initial; a pure contraction keeps it (1), a ring "
                 "forming lowers it",
            tolerance=float(rules["ring_variation"]), measured=variation(cubic_end) / variation(cubic_start),
            published="a ring"),
        claim(
            c.at_least, "fig6.cubic_ring_radius", figure="6",
            text="K = |x|^3/3: a ring, not a point: mean radius (centre "
                 f"particle excluded) at t = {times[-1]:g} over the initial one (the quadratic kernel's collapse to a "
                 f"point gives {float(quadratic[-1].mean() / quadratic[0].mean()):.3g})",
            tolerance=float(rules["ring_radius_min"]), measured=float(cubic_end.mean() / cubic_start.mean()),
            published="a ring"),
        claim(
            c.at_least, "fig6.star_rounding_newtonian", figure="6",
            text="star patch (4.6), K = log|x|/(2 pi): the density is "
                 f"rounded by the regularisation at t = {float(d['star_t']):g} (the exact one stays uniform): "
                 "(max - min) / max over the particles",
            tolerance=float(rules["star_rounding_min"]), measured=spread(d["newtonian_star_densities"]),
            published="rounded"),
        claim(
            c.at_most, "fig6.star_no_rounding_quadratic", figure="6",
            text="star patch (4.6), K = |x|^2/2: no rounding, since "
                 "psi of order m = 4 reproduces polynomials of degree < 4 (grad K, Delta K): (max - min) / max of the "
                 f"density at t = {float(d['star_t']):g}",
            tolerance=c.ROUNDING, measured=spread(d["quadratic_star_densities"]),
            published="no rounding"),  # an identity; the spread is relative (scale 1)
        blowup_claim(d, p, rules),
        claim(
            c.at_most, "energy.decrease_2d", figure="section 2.2",
            text="2D: E_delta decreases along the blob particle system "
                 "(log and quadratic kernels): largest relative increase",
            tolerance=float(rules["energy_rise_2d"]), measured=float(max(rises)), published="decreasing"),
        claim(
            c.at_most, "mass_2d", figure="section 2.2",
            text="2D: rho~ det(J) = rho0 along trajectories (closed-form log and "
                 "quadratic kernels), largest relative defect",
            tolerance=float(rules["mass_defect"]),
            measured=float(max(d["newtonian_mass_defect"], d["quadratic_mass_defect"])), published="conserved"),
        claim(
            c.at_most, "mass_2d_tabulated", figure="section 2.2",
            text="2D, tabulated cubic kernel: the same defect, limited "
                 "by the linear interpolation of the radial tables",
            tolerance=float(rules["mass_defect_tabulated"]), measured=float(d["cubic_mass_defect"]),
            published="conserved"),
    ]


def fig7_claims(d, p, rules):
    """Figure 7: end states of the power-law kernels, each measured once steady (``inf``, unmeasured, otherwise),
    on the grid hZ^2 and again without its particle at the origin (``fig7.no_origin.*``)."""
    centre, distance = float(rules["centre_radius"]), float(rules["cluster_distance"])
    delta = float(d["delta"])
    window, tolerance = float(p["steady"]["window"]), float(p["steady"]["tolerance"]) * delta
    hold = float(p["steady"]["hold"])
    labels = [label.split("|")[0] for label in d["labels"]]
    case = {label: i for i, label in enumerate(labels)}

    def state(kernel, method, to_the_end=True, suffix="", until=np.inf):
        i = case[kernel]
        times = d[f"case{i}_times{suffix}"]
        last = int(np.searchsorted(times, until, side="right"))
        positions = d[f"case{i}_{method}{suffix}"][:last]
        radii = np.sort(np.linalg.norm(positions, axis=-1), axis=1)
        steady, at = settled_from(times[:last], radii, window, tolerance, hold, to_the_end=to_the_end)
        return positions[at], steady

    log_blob, log_blob_t = state("quartic_log", "blob")
    log_particle, log_particle_t = state("quartic_log", "particle")
    criterion = (f"steady: sorted radii moving at most {p['steady']['tolerance']:g} delta per {window:g} time units "
                 f"from then to the end of the run (at least {hold:g} time units), measured at the end")

    def spacing(suffix):
        """Largest spacing of the quartic power kernel's record times: the resolution of its settling times."""
        return float(np.diff(d[f"case{case['quartic_power']}_times{suffix}"]).max())

    def time_8(suffix):
        """The record time of the quartic power kernel's runs nearest t = 8, where the paper compares the methods."""
        times = d[f"case{case['quartic_power']}_times{suffix}"]
        return float(times[np.argmin(np.abs(times - 8.0))])

    def at_time(method, suffix, when=8.0):
        """The quartic power kernel's state at the record nearest ``when`` (t = 8: :func:`time_8`), all particles."""
        times = d[f"case{case['quartic_power']}_times{suffix}"]
        return d[f"case{case['quartic_power']}_{method}{suffix}"][int(np.argmin(np.abs(times - when)))]

    def septic_by_end(suffix):
        """Clusters of the septic blob end state for runs ending at every 20 time units from 40 ('-': not steady)."""
        times = d[f"case{case['septic_power']}_times{suffix}"]
        ends = [*np.arange(40.0, times[-1], 20.0), times[-1]]
        counts = []
        for end in ends:
            points, steady = state("septic_power", "blob", suffix=suffix, until=end)
            counts.append(f"{cluster_count(points, distance)}" if np.isfinite(steady) else "-")
        return ", ".join(f"{end:g}: {count}" for end, count in zip(ends, counts))

    return [
        *_ring_claims(state, "", rules, criterion, hold, septic_by_end(""), spacing(""), at_time, time_8("")),
        claim(
            c.at_least, "fig7.particle_log_disk", figure="7",
            text="K = |x|^4/4 - log|x|/(2 pi), particle method: a radial, "
                 "compactly supported two-dimensional state, not a ring: coefficient of variation of the radii, once "
                 f"{criterion} (from t = {log_particle_t:g}; a ring gives about 0)",
            tolerance=float(rules["disk_variation_min"]),
            measured=_when_steady(variation(ring_radii(log_particle, centre)), log_particle_t),
            published="compact support"),
        claim(
            c.at_most, "fig7.log_ring_collapse", figure="7",
            text="K = |x|^4/4 - log|x|/(2 pi): the particle method keeps a "
                 "radial compactly supported state, the large-delta blob collapses towards a ring: spread of radii, "
                 f"blob over particle, once both are {criterion} (from t = {log_blob_t:g} and {log_particle_t:g})",
            tolerance=float(rules["log_collapse"]),
            measured=_when_steady(variation(ring_radii(log_blob, centre)) / variation(ring_radii(log_particle, centre)),
                                  log_blob_t, log_particle_t),
            published="ring for large delta"),
        *_ring_claims(state, "_no_origin", rules, criterion, hold, septic_by_end("_no_origin"), spacing("_no_origin"),
                      at_time, time_8("_no_origin")),
        origin_particle_claim(d, case["quartic_power"], case["septic_power"], float(rules["origin_departure"])),
        paper_tables_claim(d, p, "fig7", float(rules["paper_tables_gap"])),
    ]


def _when_steady(value, *steady_times):
    return float(value) if all(np.isfinite(steady_times)) else float("inf")  # unmeasured: never steady


def _ring_claims(state, suffix, rules, criterion, hold, septic_ends, resolution, at_time, time_8):
    """The claims of Figure 7 on its rings and points (quartic and septic power kernels) on the runs ``suffix``:
    '' on the grid hZ^2, '_no_origin' without its particle at the origin (ids ``fig7.no_origin.*``);
    ``resolution`` the spacing of their record times, below which two settling times cannot be ordered;
    ``at_time(method, suffix)`` the quartic power kernel's state at the record ``time_8`` nearest t = 8."""
    from particle_methods.blob.rings import uniform_ring_radius

    centre, thin, distance = float(rules["centre_radius"]), float(rules["thin_ring"]), float(rules["cluster_distance"])
    prefix, grid = ("fig7.no_origin.", "; without the grid particle at the origin") if suffix else ("fig7.", "")
    power_blob, power_blob_t = state("quartic_power", "blob", suffix=suffix)
    reached_blob = state("quartic_power", "blob", to_the_end=False, suffix=suffix)[1]
    reached_particle = state("quartic_power", "particle", to_the_end=False, suffix=suffix)[1]
    power_particle, power_particle_t = state("quartic_power", "particle", suffix=suffix)
    septic, septic_t = state("septic_power", "blob", suffix=suffix)
    ring = ring_radii(power_blob, centre)
    radius = uniform_ring_radius(4.0, 1.5)

    def way_left(method):
        """How far the quartic power kernel's state of ``method`` still is from its own end state at t = 8: mean
        |difference| of the sorted radii from those of its end state (measured once steady), over the same at
        t = 0 (both methods start from the same data; each converges to its own ring)."""
        end = np.sort(np.linalg.norm(state("quartic_power", method, suffix=suffix)[0], axis=-1))
        start = np.sort(np.linalg.norm(at_time(method, suffix, 0.0), axis=-1))
        now = np.sort(np.linalg.norm(at_time(method, suffix), axis=-1))
        return float(np.abs(now - end).mean() / np.abs(start - end).mean())

    steady_both = np.isfinite([power_blob_t, power_particle_t]).all()
    left = {method: way_left(method) for method in ("blob", "particle")} if steady_both else {}
    return [
        claim(
            c.relatively_close_to, f"{prefix}delta_ring_radius", figure="7",
            text="K = |x|^4/4 - |x|^1.5/1.5: the blob end "
                 "state is a delta ring of the stationary radius (B_1.5/B_4)^(1/2.5)/2 derived for a uniform ring: "
                 f"mean radius once {criterion} (from t = {power_blob_t:g}){grid}",
            published=radius, measured=_when_steady(ring.mean(), power_blob_t),
            tolerance=float(rules["ring_radius_tolerance"])),
        claim(
            c.at_most, f"{prefix}delta_ring_thin", figure="7",
            text="K = |x|^4/4 - |x|^1.5/1.5: the blob end state is a delta "
                 "ring, not an annulus: coefficient of variation of the radii (centre particle excluded), once "
                 f"steady{grid}",
            tolerance=thin, measured=_when_steady(variation(ring), power_blob_t), published="a delta ring"),
        claim(
            c.at_most, f"{prefix}particle_power_ring", figure="7",
            text="K = |x|^4/4 - |x|^1.5/1.5, particle method: the "
                 f"stable delta ring: coefficient of variation of the radii, once {criterion} (from t = "
                 f"{power_particle_t:g}){grid}",
            tolerance=thin, measured=_when_steady(variation(ring_radii(power_particle, centre)), power_particle_t),
            published="a delta ring"),
        claim(
            c.at_most, f"{prefix}blob_closer_at_8", figure="7",
            text="at t = 8 the blob solution has come nearer its ring than "
                 "the particle solution has to its own (the paper's comparison): each state's mean |difference| of the "
                 "sorted radii from those of its own end state (once steady), over the same at t = 0 (blob "
                 f"{left.get('blob', np.inf):.3g}, particle {left.get('particle', np.inf):.3g}), blob over particle, "
                 f"at t = {time_8:g}{grid}",
            tolerance=1.0, measured=left["blob"] / left["particle"] if steady_both else float("inf"),
            published="converges more quickly"),
        claim(
            c.at_least, f"{prefix}blob_ring_faster", figure="7",
            text="the blob method reaches the ring faster than the "
                 f"particle method: first time the particle state is steady for {hold:g} time units minus that of the "
                 f"blob state ({reached_particle:g} - {reached_blob:g}), at least one record interval (both times lie "
                 f"on the record times: strictly later){grid}",
            tolerance=resolution,
            measured=(
                reached_particle - reached_blob if np.isfinite([reached_blob, reached_particle]).all() else -np.inf),
            published="faster"),
        claim(
            c.close_to, f"{prefix}septic_three_points", figure="7",
            text="K = |x|^7/7 - |x|^1.5/1.5 with large delta: the end "
                 f"state is three point masses: number of clusters of the blob end state (distance {distance:g}), once "
                 f"{criterion} (from t = {septic_t:g}){grid}; for runs ending at other times (end: clusters) "
                 f"{septic_ends}",
            published=3.0, measured=_when_steady(cluster_count(septic, distance), septic_t), tolerance=0.0),
    ]


def origin_particle_claim(d, power: int, septic: int, departure: float):
    """The grid particle at the origin leaves it: its largest distance from 0 in the blob runs of the power
    kernels on hZ^2, over the radius of that run's end state (its farthest particle), smaller of the two (0 if
    it stays: the explanation fails)."""
    moves, text = [], []
    for i, name in ((power, "quartic"), (septic, "septic")):
        positions = d[f"case{i}_blob"]
        origin = int(np.argmin(np.linalg.norm(positions[0], axis=-1)))
        if np.linalg.norm(positions[0, origin]) != 0.0:
            raise ValueError("the grid of Figure 7 has no particle at the origin")
        distance = np.linalg.norm(positions[:, origin], axis=-1)
        radius = float(np.linalg.norm(positions[-1], axis=-1).max())
        times = d[f"case{i}_times"]
        left = times[np.argmax(distance > 0.1 * radius)] if np.any(distance > 0.1 * radius) else np.inf
        moves.append(float(distance.max() / radius))
        text.append(f"{name}: from {distance[1]:.1e} at t = {times[1]:g} to {distance.max():.3g} (a tenth of the "
                    f"radius at t = {left:g})")
    return claim(
        c.at_least, "fig7.origin_particle", figure="7",
        text="the grid particle at the origin sits at an unstable "
             "balance: rounding moves it until it reaches the ring, which breaks up (the runs without it, "
             "fig7.no_origin.*, test that this is what decides the end times): its largest distance from 0 over "
             f"the radius of the run's end state, smaller of the blob runs of the power kernels "
             f"({'; '.join(text)})",
        tolerance=departure, measured=min(moves), published="n/a")


def settled_from(times, radii, window: float, tolerance: float, hold: float, *, to_the_end: bool = True
                 ) -> tuple[float, int]:
    """When the sorted radii are steady: they change by at most ``tolerance`` (absolute) over every
    ``window``. With ``to_the_end`` (end states): the first time from which that holds up to the end
    of the run, provided it holds for at least ``hold``; the state is measured at the last record.
    Without it (the time to reach a steady state): the first time from which it holds for ``hold``,
    measured at its end; a steady state may later break up (an instability seeded by rounding), as
    the rings of Figure 7 do before settling again. (inf, -1) when there is no such time."""
    earlier = np.searchsorted(times, times - window + c.ROUNDING * window, side="right") - 1  # times to rounding
    usable = earlier >= 0
    change = np.full(times.size, np.inf)
    change[usable] = np.abs(radii[usable] - radii[earlier[usable]]).max(axis=1)
    ok = change <= tolerance
    if to_the_end:
        start = holds_from(times, ok)
        lasts = times[-1] - start >= hold - c.ROUNDING * max(hold, 1.0)
        return (start, times.size - 1) if lasts else (float("inf"), -1)
    for first in np.flatnonzero(ok):
        end = int(np.searchsorted(times, times[first] + hold - c.ROUNDING * max(hold, 1.0)))
        if end < times.size and ok[first:end + 1].all():
            return float(times[first]), end
    return float("inf"), -1


def end_state_gaps(d, p, first, second):
    """For every case of Figure 7 or 8: (mean |difference| of the sorted end-state radii of the runs
    ``first`` and ``second`` over delta, the time from which both are steady); the difference is
    measured at the last record once both runs are steady to the end, inf when either is not."""
    delta = float(d["delta"])
    window, tolerance = float(p["steady"]["window"]), float(p["steady"]["tolerance"]) * delta
    hold = float(p["steady"]["hold"])
    gaps = []
    for i in range(len(d["labels"])):
        times = d[f"case{i}_times"]
        radii = {m: np.sort(np.linalg.norm(d[f"case{i}_{m}"], axis=-1), axis=1) for m in (first, second)}
        steady = max(settled_from(times, radii[m], window, tolerance, hold)[0] for m in radii)
        gap = float(np.abs(radii[first][-1] - radii[second][-1]).mean() / delta)
        gaps.append((gap if np.isfinite(steady) else float("inf"), steady))
    return gaps


def paper_tables_claim(d, p, figure, bound: float):
    """Check: the end states of the blob method do not depend on the radial tables (ours against the
    paper's coarse ones): the largest gap at most ``bound``."""
    gaps = end_state_gaps(d, p, "blob", "blob_paper_tables")
    radius, points = d["paper_tables"]
    text = ", ".join(f"{label}: {gap:.3g}" for label, (gap, _) in zip(d["labels"], gaps))
    return claim(
        c.at_most, f"{figure}.paper_tables", figure=figure[3:],
        text=f"the blob end states do not depend on the radial "
             f"tables: ours (8001 nodes on radius 5) against the paper's ({points:g} on radius {radius:g}): mean "
             f"|difference| of the sorted end-state radii over delta, largest over the cases ({text}), each "
             "measured once both runs are steady",
        tolerance=bound, measured=max(gap for gap, _ in gaps), published="n/a")


def fig8_claims(d, p, rules):
    """Figure 8: the large delta changes the Morse end state only for 2e^-|x| - 2e^-|x|/2 with
    regular data. The effect is compared with delta itself, a fixed length (not with the size of the
    initial data, which differs threefold between the cases), once every state is steady; the same
    comparison on the paper's coarse tables is a check."""
    labels = list(d["labels"])
    target = labels.index("morse_2|quartic")
    window, hold = float(p["steady"]["window"]), float(p["steady"]["hold"])
    out = []
    for name, blob, kind in (("fig8.regularisation_effect", "blob", "paper"),
                             ("fig8.regularisation_effect_paper_tables", "blob_paper_tables", "check")):
        gaps = end_state_gaps(d, p, "particle", blob)
        others = max(gap for i, (gap, _) in enumerate(gaps) if i != target)
        # max(others, 1e-12): a guard against dividing by zero when no other case changes at all
        ratio = gaps[target][0] / max(others, 1e-12) if np.isfinite(others + gaps[target][0]) else float("inf")
        text = ", ".join(f"{label}: {gap:.3g} (steady from t = {t:g})" for label, (gap, t) in zip(labels, gaps))
        tables = "our radial tables" if kind == "paper" else "the paper's coarse radial tables"
        out.append(claim(
            c.at_least, name, figure="8",
            text=f"the large delta changes the end state only for K = 2e^-|x| - "
                 f"2e^-|x|/2 with regular data ({tables}): mean |particle - blob| difference of the sorted "
                 f"end-state radii over delta ({text}), the named case over the largest other, measured once "
                 f"every state is steady (sorted radii moving at most {p['steady']['tolerance']:g} delta per "
                 f"{window:g} time units from then to the end, at least {hold:g} time units)",
            tolerance=1.0, measured=ratio, published="only that case"))
    return [*out, paper_tables_claim(d, p, "fig8", float(rules["paper_tables_gap"]))]


def claims(results, p, recorder: Recorder) -> list:
    """Every claim of the blob paper from its result files (``results``: file stem -> arrays), with the
    tolerances, thresholds and cut-offs of ``p["claims"]`` and the figures' sections of ``p``."""
    rules = p["claims"]
    return [
        *newtonian_claims(results["fig1"], results["fig2"], results["fig3"], rules, recorder),
        *fig4_claims(results["fig4"], rules, recorder),
        *fig4log_claims(results["fig4log"], results["fig4"], rules, recorder),
        *repulsive_claims(results["repulsive"], p["fig4"], rules, recorder),
        *fig5_claims(results["fig5"], rules, recorder),
        *fig6_claims(results["fig6"], p["fig6"], rules),
        *fig7_claims(results["fig7"], p["fig7"], rules),
        *fig8_claims(results["fig8"], p["fig8"], rules),
    ]
