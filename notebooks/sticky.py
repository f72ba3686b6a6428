# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Sticky particles (Jourdain and Reygner): a guided tour of the reproduction
#
# This notebook reads what the pipeline (`snakemake --cores 2`) wrote: figures, cached results
# and the claims table. It never reruns a study; the cells marked **Try it** run small
# examples in a few milliseconds. Set `PARTICLE_METHODS_WORKDIR` to read another run.
#
# **The method.** n particles of mass 1/n start at the quantiles (2.1) of the initial measure,
# the k-th with velocity n (Lambda(k/n) - Lambda((k-1)/n)); they fly freely and stick together
# when they meet, conserving momentum. Their empirical distribution function converges to the
# entropy solution of the conservation law (1.1), with the error bound of Theorem 3.1:
# W1(m, mu_0) + t L / n. Positions at time t need no time stepping: they are the slopes of the
# lower convex hull of the cumulative free-flight positions (section 5.1.1), one O(n) pass.

# %%
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import Markdown, display

from particle_methods.norms import w1_between_samples, w1_to_measure
from particle_methods.sticky import (
    Atoms,
    BurgersSolution,
    PSystem,
    burgers_flux,
    median_quantiles,
    mspd_exact,
    mspd_positions,
    spd_positions,
    velocities_from_flux,
)
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_replication.claims import markdown_table
from particle_replication.paths import RESULTS
from particle_replication.tour import paper_claims, show_figure, show_other_claims, show_remaining_figures, summary
from particle_replication.workflow import load_results

print(summary("sticky"))

# %% [markdown]
# ## Figure 1: one step of the hull algorithm
#
# The list L holds the vertices of the lower hull built so far; a new point that makes a concave
# corner removes vertices until the corner is convex. Each removal is a collision of clusters.

# %%
show_figure("sticky", 1)

# %% [markdown]
# ## Figure 2: Burgers' equation from two atoms
#
# Each atom opens a rarefaction fan. For even n the initial discretisation (2.1) is exact and
# the error of the particles is exactly t/(4n): every curve of panel (d) has slope -log 2 per
# unit of p, n = 2^p.

# %%
show_figure("sticky", 2)

# %%
burgers = load_results(RESULTS / "sticky" / "fig2.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
for t, errors in zip(burgers["error_times"], burgers["errors"]):
    ax.plot(burgers["error_p"], np.log(errors * 4 * 2.0 ** burgers["error_p"] / t), "o-", label=f"t = {t:g}")
ax.set(xlabel="p (n = 2^p)", ylabel="log(error / (t / 4n))", title="the error divided by t/(4n) is 1")
ax.legend()
plt.show()

# %% [markdown]
# **Try it:** change n or t and recompute one point of panel (d). Odd n adds the error of
# discretising the atoms, so the identity holds for even n only.

# %%
n, t = 64, 10.0  # change me
initial = Atoms([-1.0, 1.0])
positions = spd_positions(median_quantiles(initial, n), velocities_from_flux(burgers_flux, n), t)
print(f"error {w1_to_measure(BurgersSolution(initial, t), positions):.6g}, t/(4n) = {t / (4 * n):.6g}")

# %% [markdown]
# ## Figure 3: a concave flux and the Laplace law
#
# With flux u(1-u)/2 the characteristics run into a stationary shock. While n is small every
# particle is already in the shock and the error is the distance of the data to a step: the
# plateau of panel (d). Past it the error decays like the initial discretisation error, log(n)/n.
# A fitted order cannot tell log(n)/n from 1/n over a few octaves (both give about -1), so the
# claims fit n times the error against log n: a constant for 1/n, a slope near 1/2 here (each
# exponential tail of the Laplace law contributes 1/4).

# %%
show_figure("sticky", 3)

# %%
concave = load_results(RESULTS / "sticky" / "fig3.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
n_values = 2.0 ** concave["error_p"]
for t, errors in zip(concave["error_times"], concave["errors"]):
    ax.plot(np.log(n_values), n_values * errors, "-", color=plt.cm.plasma(t / concave["error_times"].max() * 0.9))
ax.plot(np.log(n_values), 0.5 * np.log(n_values), "k--", label="slope 1/2")
ax.set(xlabel="log n", ylabel="n * error", title="past the plateau n * error grows like (log n)/2; colour: t")
ax.legend()
plt.show()

# %% [markdown]
# ## Figures 4 to 7: the p-system by the multitype dynamics
#
# Two types of particles carry the Riemann invariants w- and w+ of the p-system; each type moves
# with velocities that depend on its ranks among the other type (1.8). The iterated typewise
# dynamics restarts every Delta. In the first case (Figures 4-5) the order w+ >= w- persists and
# particles of one type never collide; in the second (Figures 6-7) the + particles first move as
# one cluster, which breaks up as the - particles cross it. The caption of Figure 6 ties the
# break-up to the median - particle; with 20 particles the median crosses inside a - cluster
# together with the 7th, whose crossing already breaks the + cluster by the velocities (1.8).
# With 200 particles the break-up comes at rank 65, before the median (`sticky.fig6.breakup_threshold`).
# The dashed line marks the time from which w+ >= w- holds again and no cluster is left.

# %%
for number in (4, 5, 6, 7):
    show_figure("sticky", number)

# %% [markdown]
# ## Claims that belong to no figure
#
# Lemma 2.1 and the end of section 2 (discretisation errors of (2.1) for compact support, Pareto
# and Weibull tails), Remark 3.3 (exact identities), Theorem 4.4 (the iterated typewise
# dynamics at rate 1/n + Delta) and the O(n) cost of the hull algorithm.

# %%
show_other_claims("sticky")

# %% [markdown]
# ## Beyond the paper: the exact multitype dynamics and the cost argument
#
# Section 5.2 computes the multitype dynamics only through the iterated typewise SPD and argues,
# without measuring, that an exact event-driven algorithm costs O(n^2) and that both it and a
# first-order upwind scheme need O(eps^-2) operations for an error eps. `mspd_exact` moves clusters
# at constant velocities from one event to the next (same-type meetings stick, different types
# cross and get new velocities (1.8), a cluster splits as the SPD of its members decides). Below: a
# small run of both algorithms on the shock case, then the study's figures and claims.

# %%
system, start = PSystem(), psystem_initial_configuration("shocks", -4.0, 40)
exact, events = mspd_exact(start, system, [2.0], return_events=True)
print(events)
for delta in (0.04, 0.02, 0.01, 0.005):
    approx = mspd_positions(start, system, delta, round(2.0 / delta))
    print(f"Delta = {delta}: W1 to the exact MSPD {sum(map(w1_between_samples, approx, exact[0])):.2e}")

# %%
show_figure("sticky", "beyond_limits")
show_figure("sticky", "beyond_cost")
display(Markdown(markdown_table([claim for claim in paper_claims("sticky") if ".beyond." in claim.id],
                                heading=False)))

# %% [markdown]
# ## Figures the tour does not discuss
#
# Every figure registered for this paper that the sections above do not show; a new figure appears here
# until the tour discusses it.

# %%
show_remaining_figures("sticky")
