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
# # Linearly transformed particles (Campos Pinto, Carrillo, Charles, Choi)
#
# Reads the cached results of the pipeline; set `PARTICLE_METHODS_WORKDIR` to read another run.
#
# **The method.** Particles carry a weight, a centre and a width. Centres move by explicit
# Euler with the velocity -W' * rho_h; each width is multiplied by exp(-dt W'' * rho_h) at its
# centre (2.31)-(2.32), so particles shrink where the flow compresses. The smooth-particle (SP)
# method keeps one fixed width eps instead.

# %%
import matplotlib.pyplot as plt
import numpy as np

from particle_methods.claims import read_claims
from particle_methods.ltp import density_named, exact_density, potential, simulate
from particle_methods.paths import RESULTS
from particle_methods.workflow import load_results

# %% [markdown]
# ## Figure 3 (left): the LTP error sits at the best SP error over eps

# %%
quadratic = load_results(RESULTS / "ltp" / "quadratic.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
ax.loglog(quadratic["eps_values"], quadratic["scan_sp"][:, 0], "o-", label="SP, L1")
ax.axhline(quadratic["scan_ltp"][0], ls="--", color="k", label="LTP, L1")
ax.set(xlabel="eps", ylabel="L1 error at t = 0.5")
ax.legend()
plt.show()

# %% [markdown]
# ## Try it: an LTP run against the exact solution (6.4); change h or the shape

# %%
h, shape = 0.05, "hat"  # change me ("hat" or "b3")
w = potential("quadratic")
run = simulate("rho1", w, h, 1e-3, 0.5, shape=shape)
x = np.linspace(-0.6, 0.4, 2001)
plt.plot(x, exact_density(density_named("rho1"), w, 0.5, x), "k", label="exact")
plt.plot(x, run.at(-1).density(x), "--", label=f"LTP, h = {h}, {shape}")
plt.legend()
plt.show()

# %% [markdown]
# ## The checked claims of this paper

# %%
for claim in read_claims(RESULTS / "ltp" / "claims.csv"):
    print(f"{claim.status:4}  {claim.id:38} measured {claim.measured:>12} ({claim.tolerance})")
