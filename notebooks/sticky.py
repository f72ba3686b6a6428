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
# This notebook reads the cached results of the pipeline (`snakemake --cores 2`); it never
# re-runs the expensive studies. Set `PARTICLE_METHODS_WORKDIR` to read another run.
#
# **The method.** n particles of mass 1/n start at the quantiles (2.1) of the initial measure
# with velocities n (Lambda(k/n) - Lambda((k-1)/n)), move freely and stick on collision. The
# positions at time t are the slopes of the lower convex hull of the cumulative free-transport
# positions (section 5.1.1): one O(n) pass, no time stepping.

# %%
import matplotlib.pyplot as plt
import numpy as np

from particle_methods.claims import read_claims
from particle_methods.norms import w1_to_measure
from particle_methods.paths import RESULTS
from particle_methods.sticky import (
    Atoms,
    BurgersSolution,
    burgers_flux,
    median_quantiles,
    spd_positions,
    velocities_from_flux,
)
from particle_methods.workflow import load_results

# %% [markdown]
# ## Figure 2 (d): the error is exactly t/(4n) for Burgers from two atoms
#
# Every curve has slope -log 2 per unit of p (n = 2^p): order 1/n.

# %%
burgers = load_results(RESULTS / "sticky" / "fig2.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
for t, errors in zip(burgers["error_times"], burgers["errors"]):
    ax.plot(burgers["error_p"], np.log(errors), "o-", label=f"t = {t:g}")
ax.set(xlabel="p (n = 2^p)", ylabel="log L1 error")
ax.legend()
plt.show()

# %% [markdown]
# ## Try it: change n or t and recompute one point of Figure 2 (d) in a few microseconds

# %%
n, t = 64, 10.0  # change me
initial = Atoms([-1.0, 1.0])
positions = spd_positions(median_quantiles(initial, n), velocities_from_flux(burgers_flux, n), t)
print(f"error {w1_to_measure(BurgersSolution(initial, t), positions):.6g}, t/(4n) = {t / (4 * n):.6g}")

# %% [markdown]
# ## Figure 3 (d): plateau, then log(n)/n decay

# %%
concave = load_results(RESULTS / "sticky" / "fig3.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
for t, errors in zip(concave["error_times"], concave["errors"]):
    ax.plot(concave["error_p"], np.log(errors), "-", color=plt.cm.plasma(t / concave["error_times"].max() * 0.9))
ax.set(xlabel="p (n = 2^p)", ylabel="log L1 error", title="higher curves: smaller t")
plt.show()

# %% [markdown]
# ## The checked claims of this paper

# %%
for claim in read_claims(RESULTS / "sticky" / "claims.csv"):
    print(f"{claim.status:4}  {claim.id:38} measured {claim.measured:>12} ({claim.tolerance})")
