"""Lemma 2.1 and the tail examples of section 2: W1 error of the discretisation (2.1)."""

import numpy as np
from scipy import integrate

from particle_methods.norms import w1_to_measure
from particle_methods.sticky.measures import (
    Atoms,
    Laplace,
    Pareto,
    TruncatedExponential,
    TruncatedPareto,
    Uniform,
    Weibull,
    median_quantiles,
)
from particle_replication.workflow import logged, progress, save_results


def measures(p):
    """Name -> measure; compactly supported ones first (their support length is recorded)."""
    chosen = {"uniform": Uniform(0.0, 1.0), "two_atoms": Atoms([-1.0, 1.0]), "laplace": Laplace(0.0)}
    chosen.update({f"exponential_{b:g}": TruncatedExponential(b) for b in p["positive_density_b"]})
    chosen.update({f"pareto_{alpha:g}": Pareto(alpha) for alpha in p["pareto_alpha"]})
    chosen.update({f"weibull_{alpha:g}": Weibull(alpha) for alpha in p["weibull_alpha"]})
    return chosen


def support_length(name, measure):
    """b - a for the compactly supported measures, None otherwise."""
    if name.startswith("exponential_"):
        return measure.b
    return {"uniform": 1.0, "two_atoms": 2.0}.get(name)


def sqrt_variance_integral(measure) -> float:
    """int sqrt(F (1 - F)) dx, the constant of Lemma 2.1 (ii), by adaptive quadrature.

    The integrand is continuous except at atoms, so the line is split at the
    quartiles and at 0 (all atoms used here are at -1, 0, 1 or quartiles).
    """
    cuts = sorted({float(measure.quantile(w)) for w in (0.25, 0.5, 0.75)} | {-1.0, 0.0, 1.0})
    integrand = lambda x: float(np.sqrt(max(measure.cdf(x) * (1.0 - measure.cdf(x)), 0.0)))  # noqa: E731
    edges = [-np.inf, *cuts, np.inf]
    return sum(integrate.quad(integrand, a, b, epsabs=1e-10, epsrel=1e-8, limit=400)[0]
               for a, b in zip(edges[:-1], edges[1:]))


def run(p, output):
    n_values = np.asarray(p["n_values"], dtype=np.int64)
    # Odd sizes as well: for the two-atom measure the bound (b - a)/(2n) is attained at odd n.
    odd_n = n_values + 1
    results = {"n_values": n_values, "odd_n": odd_n,
               "pareto_alpha": np.asarray(p["pareto_alpha"], float),
               "weibull_alpha": np.asarray(p["weibull_alpha"], float)}
    for name, measure in measures(p).items():
        progress(f"W1 discretisation error of {name}")
        results[name] = np.array([w1_to_measure(measure, median_quantiles(measure, int(n))) for n in n_values])
        results[f"{name}_odd"] = np.array([w1_to_measure(measure, median_quantiles(measure, int(n))) for n in odd_n])
        if not name.startswith("pareto") or measure.alpha > 2:
            results[f"{name}_sqrt_variance"] = np.float64(sqrt_variance_integral(measure))
        if support_length(name, measure) is not None:
            results[f"{name}_support"] = np.float64(support_length(name, measure))
    # Lemma 2.1 (i): no first moment. F = 1 - x^-alpha (alpha <= 1) truncated to [1, R], n fixed.
    heavy = p["heavy_tail"]
    upper = np.asarray(heavy["upper"], dtype=float)
    progress(f"heavy tail alpha = {heavy['alpha']:g}, n = {heavy['n']}, R = {upper.min():g}..{upper.max():g}")
    results["heavy_upper"] = upper
    results["heavy_errors"] = np.array([
        w1_to_measure(m, median_quantiles(m, heavy["n"])) for m in (TruncatedPareto(heavy["alpha"], r) for r in upper)])
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
