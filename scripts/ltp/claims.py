"""Every checked claim of the LTP paper, measured from the cached results.

Thresholds that turn the paper's qualitative words into numbers are fixed here
once, with their meaning: "clearly below" is a factor 2, "close to the best SP
error" is within a factor 2, a blow-up is a log-growth of the peak density that
accelerates at least five-fold over the run, "no blow-up" is growth that does not
accelerate, a peak is a local maximum standing out by 5 % of its height.
"""

import numpy as np
from scipy.signal import find_peaks

from particle_methods import claims as c
from particle_methods import rates
from particle_methods.rates import Recorder
from particle_methods.workflow import load_results, logged, progress

PAPER = "ltp"
ROUNDING = 1e-10
RATES = Recorder(progress)

# Kind and source of every claim (see particle_methods.claims): "paper" for what the paper
# states (where), "derived" for what we derive from its theory, "check" for our own checks.
KINDS = {
    "fig2.order_l1": ("paper", "Figure 2, Theorem 1"),
    "fig2.order_linf": ("paper", "Figure 2, Theorem 2"),
    "fig3.best_sp_l1": ("paper", "Figure 3 (left), section 6.1"),
    "fig3.best_sp_linf": ("paper", "Figure 3 (left), section 6.1"),
    "mass.quadrature": ("check", "conservation of mass at the discrete level, section 2.2 after (2.27)"),
    "centre_of_mass.quadratic": ("check", "conservation of the centre of mass for W = x^2, section 6.1 before (6.4)"),
    "fig4.hat": ("paper", "Figure 4, section 6.1"),
    "fig4.hat_gain_larger": ("paper", "Figure 4, section 6.1"),
    "fig5.blowup_a1.5": ("paper", "Figure 5, section 6.2"),
    "fig5.no_blowup_a2.5": ("paper", "Figure 5, section 6.2"),
    "fig5.dirac": ("paper", "Figure 5, section 6.2"),
    "fig6.b2.5_two_diracs": ("paper", "Figure 6, section 6.2"),
    "fig6.b2.5_equal_split": ("paper", "Figure 6, section 6.2"),
    "fig6.b1.5_steady": ("paper", "Figure 6, section 6.2"),
    "fig6.b1.5_edges": ("paper", "Figure 6, section 6.2"),
    "fig7.finitely_many_diracs": ("paper", "Figure 7, section 6.2"),
    "fig8.sp_oscillates": ("paper", "Figure 8, section 6.2"),
    "fig8.ltp_smooth": ("paper", "Figure 8, section 6.2"),
    "mass.weights": ("check", "weights constant in time by construction, section 2.2 (2.27)"),
    "centre_of_mass.even_w": ("check", "centre of mass of symmetric data under even W: 0 by symmetry"),
}


CATALOGUE = c.Catalogue(PAPER, KINDS)
claim = CATALOGUE.claim


def order(name, h, errors, points):
    """Fitted order of ``errors`` against ``h`` (coarse to fine) on the ``points`` finest steps,
    recorded under the claim ``name`` that it decides."""
    CATALOGUE.kind_and_source(name)
    progress(f"{PAPER}.{name}: errors at h = {', '.join(f'{v:.5g}' for v in h)}: "
             f"{', '.join(f'{e:.5e}' for e in errors)}")
    return RATES.add(rates.order(f"{PAPER}.{name}", "h", h, errors, points))


def peak_count(density) -> int:
    """Local maxima whose prominence is at least 5 % of their height."""
    peaks, properties = find_peaks(density, prominence=0.0)
    return int(np.sum(properties["prominences"] >= 0.05 * density[peaks]))


def growth_acceleration(peaks) -> float:
    """Log-growth of the peak density over the last tenth of the run over that of the first tenth."""
    tenth = max(len(peaks) // 10, 1)
    return float((np.log(peaks[-1]) - np.log(peaks[-1 - tenth])) / (np.log(peaks[tenth]) - np.log(peaks[0])))


def quadratic_claims(d):
    k = int(d["order_points"])
    h = d["h_values"]
    out = []
    for column, norm in ((0, "l1"), (1, "linf")):
        errors = d["ltp_errors"][:, column]
        out.append(claim(c.at_least, f"fig2.order_{norm}", "2",
                         f"LTP {norm.upper()} error decreases at least at first order in h (Theorem 1, dt <= C h); "
                         f"slope on the {k} finest h", 1.0, order(f"fig2.order_{norm}", h, errors, k),
                         published=">= 1"))
    for column, norm in ((0, "l1"), (1, "linf")):
        ratio = d["scan_sp"][:, column].min() / d["scan_ltp"][column]
        out.append(claim(c.close_to, f"fig3.best_sp_{norm}", "3 (left)",
                         f"the LTP error is close to the best SP error over eps ({norm.upper()}): "
                         "log10(min_eps SP error / LTP error), 0 when equal", 0.0, float(np.log10(ratio)),
                         np.log10(2.0)))
    out.append(claim(c.at_most, "mass.quadrature", "2",
                     "mass is conserved: |int rho_h^n - 1| by quadrature at t = 0.5, largest over h", 1e-6,
                     float(d["mass_error"].max()), published="exact"))
    out.append(claim(c.at_most, "centre_of_mass.quadratic", "2",
                     "centre of mass conserved for W = x^2: largest drift of sum omega_k x_k over h", ROUNDING,
                     float(d["centre_drift"].max()), published="conserved"))
    return out


def fig4_claims(d):
    ratio = {shape: d[f"{shape}_ltp_errors"][0] / d[f"{shape}_sp_errors"][0] for shape in ("hat", "b3")}
    return [
        claim(c.at_most, "fig4.hat", "4", "with hat shapes the LTP L1 error is clearly below the SP one: "
              "LTP / SP ratio", 0.5, float(ratio["hat"]), published="clearly below"),
        claim(c.at_most, "fig4.hat_gain_larger", "4", "the gain of LTP over SP is larger with hat than with B3 "
              "shapes: (LTP/SP with hat) / (LTP/SP with B3)", 1.0, float(ratio["hat"] / ratio["b3"]),
              published="< 1"),
    ]


def fig5_claims(d):
    labels = list(d["labels"])
    acceleration = [growth_acceleration(d[f"case{i}_peaks"]) for i in range(len(labels))]
    spread = [np.ptp(d[f"case{i}_centres"][-1]) / np.ptp(d[f"case{i}_centres"][0]) for i in range(len(labels))]
    return [
        claim(c.at_least, "fig5.blowup_a1.5", "5", f"W = {labels[0]}: finite-time concentration, the peak density "
              "grows ever faster: acceleration of its log-growth (last tenth / first tenth)", 5.0, acceleration[0],
              published="finite-time blow-up"),
        claim(c.at_most, "fig5.no_blowup_a2.5", "5", f"W = {labels[1]}: no finite-time blow-up in Linf, the "
              "log-growth of the peak density does not accelerate", 1.0, acceleration[1],
              published="no blow-up"),
        claim(c.at_most, "fig5.dirac", "5", "both tend to a single Dirac mass: final over initial spread of the "
              "particle centres, largest of the two runs", 0.25, float(max(spread)), published="single Dirac"),
    ]


def fig6_claims(d):
    labels = list(d["labels"])
    index = {label: i for i, label in enumerate(labels)}
    b25 = index[next(label for label in labels if label.endswith("2.5/2.5"))]
    b15 = index[next(label for label in labels if label.endswith("1.5/1.5"))]
    centres, weights = d[f"case{b25}_centres"][-1], d[f"case{b25}_weights"]
    near_edges = weights[np.abs(centres) > np.abs(centres).max() - 0.1].sum() / weights.sum()
    middle = 1e-9 * np.abs(centres).max()  # a particle on the axis of symmetry belongs to neither side
    left, right = weights[centres < -middle].sum(), weights[centres > middle].sum()
    densities, grid = d[f"case{b15}_densities"], d["grid"]
    change = np.trapezoid(np.abs(densities[-1] - densities[-2]), grid)
    edge_ratio = densities[-1].max() / densities[-1][np.argmin(np.abs(grid))]
    return [
        claim(c.at_least, "fig6.b2.5_two_diracs", "6", f"W = {labels[b25]}: mass concentrates on two points: "
              "fraction within 0.1 of the two outermost particles at the final time", 0.5, float(near_edges),
              published="two Dirac masses"),
        claim(c.at_most, "fig6.b2.5_equal_split", "6", f"W = {labels[b25]}: the two masses are equal: "
              "|left mass - right mass| (a particle at 0 counted on neither side)", 0.01,
              float(abs(left - right)), published="equal"),
        claim(c.at_most, "fig6.b1.5_steady", "6", f"W = {labels[b15]}: a steady L1 profile: L1 change of rho_h "
              "over the last recorded interval", 0.05, float(change), published="steady"),
        claim(c.at_least, "fig6.b1.5_edges", "6", f"W = {labels[b15]}: the profile grows at the edges of its "
              "support: max density over density at the centre", 2.0, float(edge_ratio), published="edge growth"),
    ]


def fig7_claims(d):
    return [claim(c.close_to, "fig7.finitely_many_diracs", "7", "the solution tends to finitely many Dirac masses: "
                  "number of peaks of rho_h at the final time (two, at the edges)", 2.0,
                  float(peak_count(d["densities"][-1])), 0.0)]


def fig8_claims(d):
    return [
        claim(c.at_least, "fig8.sp_oscillates", "8", "the SP steady state oscillates: number of peaks of its density",
              3.0, float(peak_count(d["sp_density"])), published="oscillations"),
        claim(c.at_most, "fig8.ltp_smooth", "8", "the LTP steady state does not: number of peaks of its density "
              "(the two edge concentrations)", 2.0, float(peak_count(d["ltp_density"])), published="no oscillation"),
    ]


def conservation_claims(runs):
    masses, centres = [], []
    for d, prefixes in runs:
        for prefix in prefixes:
            weights = d[f"{prefix}weights"]
            masses.append(abs(weights.sum() - 1.0))
            centres.append(abs(weights @ d[f"{prefix}centres"][-1]))
    return [
        claim(c.at_most, "mass.weights", "5-8", "mass is conserved exactly: |sum_k omega_k - 1| (constant in time "
              "by construction), largest over the runs of Figures 5-8", ROUNDING, float(max(masses)),
              published="exact"),
        claim(c.at_most, "centre_of_mass.even_w", "5-8", "centre of mass conserved for even W (symmetric data: it "
              "stays at 0): largest |sum omega_k x_k| at the final time", ROUNDING, float(max(centres)),
              published="conserved"),
    ]


def run(inputs, output):
    d5, d6, d7 = load_results(inputs.fig5), load_results(inputs.fig6), load_results(inputs.fig7)
    rows = [
        *quadratic_claims(load_results(inputs.quadratic)),
        *fig4_claims(load_results(inputs.fig4)),
        *fig5_claims(d5),
        *fig6_claims(d6),
        *fig7_claims(d7),
        *fig8_claims(load_results(inputs.fig8)),
        *conservation_claims([
            (d5, [f"case{i}_" for i in range(len(d5["labels"]))]),
            (d6, [f"case{i}_" for i in range(len(d6["labels"]))]),
            (d7, [""]),
        ]),
    ]
    for row in rows:
        progress(f"{row.status:4} {row.id}: measured {row.measured} ({row.tolerance})")
    c.write_claims(output.claims, rows)
    RATES.write(output.rates)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.input, snakemake.output)  # noqa: F821
