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
# # The blob method (Craig and Bertozzi)
#
# Reads the cached results of the pipeline; set `PARTICLE_METHODS_WORKDIR` to read another run.
#
# **The method.** Point particles on the grid hZ^d move with the velocity of the mollified
# kernel K * psi_delta, delta = h^q, and carry a density along their trajectories. Our
# mollifiers are mixtures of Gaussians, so every mollified kernel here is in closed form or
# tabulated by an exact radial convolution.

# %%
import matplotlib.pyplot as plt
import numpy as np

from particle_methods.blob import data_1d, newtonian_exact, run_1d
from particle_methods.claims import read_claims
from particle_methods.convergence import fit_order
from particle_methods.paths import RESULTS
from particle_methods.workflow import load_results

# %% [markdown]
# ## Figure 4: errors at t = 0.5, the m = 6 rates approach m q = 5.4

# %%
fig4 = load_results(RESULTS / "blob" / "fig4.npz")
h = fig4["h_values"]
for label in ("cubic_blob4_trajectory", "cubic_blob6_trajectory", "cubic_particle_trajectory"):
    plt.loglog(h, fig4[label], "o-", label=f"{label}: order {fit_order(h[-3:], fig4[label][-3:]):.2f}")
plt.xlabel("h")
plt.ylabel("L1_h error")
plt.legend(fontsize=7)
plt.show()

# %% [markdown]
# ## Try it: blob trajectories bend away near the blow-up time t = 1; change delta through q

# %%
q = 0.9  # change me, in (1/2, 1)
times = np.linspace(0.0, 1.0, 101)
run = run_1d("smooth20", "newtonian_attractive", 0.04, times, q=q)
exact = np.array([newtonian_exact(data_1d("smooth20"), "newtonian_attractive", run.positions[0, :, 0], t)[0]
                  for t in times[:-1]])
plt.plot(run.positions[:, ::2, 0], times, "r--", lw=0.7)
plt.plot(exact[:, ::2], times[:-1], "k-", lw=0.7)
plt.xlim(-0.1, 0.1)
plt.ylim(0.7, 1.0)
plt.xlabel("x")
plt.ylabel("t")
plt.show()

# %% [markdown]
# ## The checked claims of this paper

# %%
for claim in read_claims(RESULTS / "blob" / "claims.csv"):
    print(f"{claim.status:4}  {claim.id:44} measured {claim.measured:>12} ({claim.tolerance})")
