"""Every checked claim of the sticky-particle paper, measured from the cached results.

Tolerances are fixed by what each statement means, not by what we measured:
identities that hold in exact arithmetic get 1e-9 (rounding only), fitted
orders get a band that the pre-asymptotic regime of the plotted range allows.
"""

import numpy as np

from particle_methods import claims as c
from particle_methods.convergence import fit_order, order_table
from particle_methods.sticky.hull_reference import hull_vertices
from particle_methods.sticky.psystem import MINUS, PLUS
from particle_methods.sticky.spd import cluster_sizes
from particle_methods.workflow import load_results, logged, progress

PAPER = "sticky"
ROUNDING = 1e-9


def claim(kind, name, figure, text, *args, **kwargs):
    return kind(f"{PAPER}.{name}", PAPER, figure, text, *args, **kwargs)


def burgers_claims(d):
    slopes = [np.polyfit(d["error_p"], np.log(row), 1)[0] for row in d["errors"]]
    for t, row in zip(d["error_times"], d["errors"]):
        progress(f"Burgers, t = {t:g}\n" + order_table(d["error_n"], row, "n"))
    worst = max(slopes, key=lambda s: abs(s + np.log(2)))
    ratios = d["errors"][1:] / d["errors"][:-1]
    even = d["error_n"] % 2 == 0
    return [
        claim(c.at_most, "fig2d.no_initial_error", "2d",
              "no initial discretisation error for even n: largest W1(m, mu_n) of (2.1) over even n", ROUNDING,
              float(np.abs(d["initial_errors"][even]).max()), published="0"),
        claim(c.close_to, "fig2d.order", "2d",
              "log L1 error against p (n = 2^p) has slope -log 2 for every t (order 1/n); worst line reported",
              -np.log(2), worst, 0.02),
        claim(c.at_least, "fig2d.ordering", "2d",
              "higher curves for larger t: smallest ratio error(t_next)/error(t) over all n", 1.0,
              float(ratios.min()), published="> 1"),
    ]


def concave_claims(d):
    errors, clusters, heaviside = d["errors"], d["clusters"], d["heaviside_errors"][:, None]
    in_shock = clusters == 1
    plateau_gap = np.abs(errors - heaviside) / heaviside
    decay_slopes = []
    for t, row, count in zip(d["error_times"], errors, clusters):
        progress(f"concave flux, t = {t:g}\n" + order_table(d["error_n"], row, "n"))
        tail = np.flatnonzero(count > 1)[-3:]
        if tail.size == 3 and tail[0] == count.size - 3:
            n = d["error_n"][tail].astype(float)
            decay_slopes.append(fit_order(n, row[tail] / np.log(n)))
    worst = max(decay_slopes, key=lambda s: abs(s + 1)) if decay_slopes else np.nan
    asymptotic = [fit_order(d["rate_n"], row / np.log(d["rate_n"])) for row in d["rate_errors"]]
    ratios = errors[1:] / errors[:-1]
    return [
        claim(c.at_most, "fig3d.plateau", "3d",
              f"while every particle is in the shock (n small) the error equals the distance to the Heaviside "
              f"function: largest relative gap over {int(in_shock.sum())} such runs",
              ROUNDING, float(plateau_gap[in_shock].max()) if in_shock.any() else np.nan, published="0"),
        claim(c.close_to, "fig3d.decay_plotted", "3d",
              f"past the plateau the error decays like log(n)/n, within the plotted range: slope of "
              f"log(error/log n) against log n on the three largest plotted n, worst of {len(decay_slopes)} "
              "times whose decay spans them", -1.0, worst, 0.1),
        claim(c.close_to, "fig3d.decay_asymptotic", "3d",
              f"the decay rate tends to that of the initial discretisation, log(n)/n: slope of log(error/log n) "
              f"against log n for n = {', '.join(str(n) for n in d['rate_n'])}, worst over all t",
              -1.0, max(asymptotic, key=lambda s: abs(s + 1)), 0.1),
        claim(c.at_most, "fig3d.ordering", "3d",
              "higher curves for smaller t: largest ratio error(t_next)/error(t) over all n", 1.0 + ROUNDING,
              float(ratios.max()), published="<= 1"),
    ]


def theorem31_claims(burgers, concave):
    ratios = []
    for d in (burgers, concave):
        bound = d["initial_errors"][None, :] + d["error_times"][:, None] * d["flux_lipschitz"] / d["error_n"][None, :]
        ratios.append((d["errors"] / bound).max())
    return [claim(c.at_most, "thm31.bound", "2d, 3d",
                  "Theorem 3.1: error <= W1(m, mu_0) + t L_LC / n; largest ratio error/bound over Figures 2d and 3d",
                  1.0 + ROUNDING, float(max(ratios)), published="<= 1")]


def remark33_claims(d):
    t, n = d["dirac_times"][:, None], d["dirac_n"][None, :]
    dirac_gap = np.abs(d["dirac_errors"] / (t / (4 * n)) - 1.0).max()
    contraction = (d["total_errors"] / d["initial_errors"][None, :]).max()
    return [
        claim(c.at_most, "remark33.dirac", "Remark 3.3",
              "Burgers from delta_0: error exactly t/(4n); largest relative gap", ROUNDING, float(dirac_gap),
              published="t/(4n)"),
        claim(c.at_most, "remark33.concave", "Remark 3.3",
              "concave flux: SPD equals the entropy solution of the discretised data (front tracking); "
              "largest position gap", ROUNDING, float(d["position_gap"].max()), published="0"),
        claim(c.at_most, "remark33.contraction", "Remark 3.3",
              "concave flux: the SPD error never exceeds the initial discretisation error (L1 contraction of "
              "entropy solutions); largest ratio", 1.0 + ROUNDING, float(contraction), published="<= 1"),
    ]


def lemma21_claims(d):
    n_all = np.concatenate([d["n_values"], d["odd_n"]]).astype(float)
    out = []
    compact = [name for name in ("uniform", "truncated_exponential", "two_atoms")]
    bound_ratio = max((2 * n_all * np.concatenate([d[m], d[f"{m}_odd"]]) / d[f"{m}_support"]).max() for m in compact)
    out.append(claim(c.at_most, "lemma21.iii", "Lemma 2.1",
                     "(iii) W1(m, mu_n) <= (b - a)/(2n) for m on [a, b]; largest ratio over uniform, truncated "
                     "exponential and two atoms, even and odd n", 1.0 + ROUNDING, float(bound_ratio)))
    sqrt_names = [key[: -len("_sqrt_variance")] for key in d if key.endswith("_sqrt_variance")]
    ratio_ii = max((d[m] * np.sqrt(d["n_values"]) / d[f"{m}_sqrt_variance"]).max() for m in sqrt_names)
    out.append(claim(c.at_most, "lemma21.ii", "Lemma 2.1",
                     "(ii) W1(m, mu_n) <= n^{-1/2} int sqrt(F(1 - F)); largest ratio over "
                     f"{len(sqrt_names)} measures", 1.0 + 1e-6, float(ratio_ii)))
    for name in ("uniform", "truncated_exponential"):
        limit = d[f"{name}_support"] / 4
        out.append(claim(c.relatively_close_to, f"lemma21.iv.{name}", "Lemma 2.1",
                         f"(iv) n W1(m, mu_n) -> (b - a)/4 for a positive density ({name.replace('_', ' ')}), "
                         f"at n = {d['n_values'][-1]}", float(limit),
                         float(d["n_values"][-1] * d[name][-1]), 1e-3))
    n = d["n_values"][-4:].astype(float)
    for alpha in d["pareto_alpha"]:
        slope = fit_order(n, d[f"pareto_{alpha:g}"][-4:])
        out.append(claim(c.close_to, f"lemma21.pareto_{alpha:g}", "section 2",
                         f"F = 1 - x^-alpha, alpha = {alpha:g}: W1 = O(n^(-1 + 1/alpha)); slope on the four largest n",
                         -1 + 1 / alpha, slope, 0.05))
    for alpha in d["weibull_alpha"]:
        slope = fit_order(n, d[f"weibull_{alpha:g}"][-4:] / np.log(n) ** (1 / alpha))
        out.append(claim(c.close_to, f"lemma21.weibull_{alpha:g}", "section 2",
                         f"F = 1 - exp(-x^alpha), alpha = {alpha:g}: W1 = O((log n)^(1/alpha)/n); slope of "
                         "log(W1/(log n)^(1/alpha)) on the four largest n", -1.0, slope, 0.1))
    return out


def tspd_claims(d):
    n = d["n_values"].astype(float)
    progress("iterated TSPD\n" + order_table(n, d["errors"], "n"))
    slope = fit_order(n, d["errors"] / np.log(n))
    return [claim(c.close_to, "thm44.order", "Theorem 4.4",
                  f"iterated TSPD with Delta ~ 1/n at t = {float(d['t']):g}: error O(t/n + Delta) plus the "
                  "O(log n / n) initial error of Laplace data; slope of log(error/log n) against log n",
                  -1.0, slope, 0.2)]


def max_cluster(path):
    return max(cluster_sizes(row).max() for state in path for row in state)


def psystem_claims(rarefaction, shocks):
    order_gap = max((r[:, PLUS] - r[:, MINUS]).max() for r in (rarefaction["trajectories"], rarefaction["field_path"]))
    same_type = max(max_cluster(r[1:]) for r in (rarefaction["trajectories"], rarefaction["field_path"]))
    path = shocks["trajectories"]
    n = path.shape[-1]
    biggest = max(cluster_sizes(state[PLUS]).max() for state in path)
    final_cluster = max(cluster_sizes(row).max() for row in path[-1])
    ordered = np.all(path[:, PLUS] <= path[:, MINUS], axis=1)
    disordered_steps = np.flatnonzero(~ordered)
    recovery = shocks["times"][disordered_steps[-1] + 1] if disordered_steps.size else 0.0
    if disordered_steps.size and disordered_steps[-1] + 1 == len(ordered):
        recovery = np.inf
    return [
        claim(c.at_most, "fig4.order_preserved", "4",
              "w0+ >= w0- case: w+ >= w- at all times, i.e. x+_k <= x-_k; largest x+_k - x-_k over both runs",
              0.0, float(order_gap), published="w+ >= w-"),
        claim(c.at_most, "fig4.no_same_type_collision", "4",
              "particles of the same type never collide: largest cluster over all steps and types", 1.0,
              float(same_type), published="no collision"),
        claim(c.at_least, "fig6.cluster_forms", "6",
              f"the + particles first move as one cluster: largest + cluster (of {n})", float(n),
              float(biggest), published="single cluster"),
        claim(c.at_most, "fig6.clusters_break_up", "6",
              "clusters break up after crossing: largest cluster at the final time", 1.0, float(final_cluster),
              published="break-up"),
        claim(c.at_most, "fig6.order_recovered", "6",
              "after a finite time w+ >= w- again: time from which x+_k <= x-_k for every k (final time "
              f"{shocks['times'][-1]:g})", float(shocks["times"][-1]), float(recovery), published="finite"),
    ]


def cost_claims(seed=0, n=20000):
    rng = np.random.default_rng(seed)
    q = np.concatenate(([0.0], np.cumsum(np.sort(rng.normal(size=n)) + rng.normal(size=n))))
    history = []
    hull_vertices(q, trace=history)
    tests = sum(len(step.removed) + (1 if len(step.before) - len(step.removed) > 1 else 0) for step in history)
    return [claim(c.at_most, "cost.hull", "section 5.1.1",
                  f"the hull pass is O(n): slope comparisons per particle, random data, n = {n}", 2.0, tests / n,
                  published="O(n)")]


def run(inputs, output):
    burgers = load_results(inputs.burgers)
    concave = load_results(inputs.concave)
    rows = [
        *burgers_claims(burgers),
        *concave_claims(concave),
        *theorem31_claims(burgers, concave),
        *remark33_claims(load_results(inputs.remark33)),
        *lemma21_claims(load_results(inputs.lemma21)),
        *tspd_claims(load_results(inputs.tspd)),
        *psystem_claims(load_results(inputs.rarefaction), load_results(inputs.shocks)),
        *cost_claims(),
    ]
    for row in rows:
        progress(f"{row.status:4} {row.id}: measured {row.measured} ({row.tolerance})")
    c.write_claims(output, rows)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.input, snakemake.output[0])  # noqa: F821
