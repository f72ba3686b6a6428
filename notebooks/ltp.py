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
# This notebook reads what the pipeline wrote (figures, cached results, claims); the cells
# marked **Try it** run small examples in seconds. Set `PARTICLE_METHODS_WORKDIR` to read
# another run.
#
# **The method.** The density is a sum of particles, each a weight times a shape (the hat (2.12)
# or the cubic B-spline (2.13)) with its own centre and width. Centres move by explicit Euler
# steps with the velocity -W' * rho_h; each width is multiplied by exp(-dt W'' * rho_h) at its
# centre, (2.31)-(2.32), so particles shrink where the flow compresses and widen where it
# expands. The smooth-particle (SP) method keeps one fixed width eps instead. Theorem 1 proves
# first-order convergence of LTP when dt <= C h.

# %%
import matplotlib.pyplot as plt
import numpy as np

from particle_methods.convergence import fit_order
from particle_methods.ltp import density_named, exact_density, potential, simulate
from particle_methods.ltp.measures import shrink_rate_inverse
from particle_replication.paths import RESULTS
from particle_replication.tour import show_figure, show_other_claims, show_remaining_figures, summary
from particle_replication.workflow import load_results

print(summary("ltp"))

# %% [markdown]
# ## Figure 1: the hat shape and its integration kernel

# %%
show_figure("ltp", 1)

# %% [markdown]
# ## Figures 2 and 3: W = x^2, where the exact solution (6.4) is known
#
# The velocity -W' * rho = -2 (x - centre of mass) is affine, so the exact flow is an affine
# contraction towards the centre of mass. LTP converges at about second order here, more than
# Theorem 1 guarantees; the SP method needs its width tuned to the particle spacing to do as well.

# %%
show_figure("ltp", 2)
show_figure("ltp", 3)

# %%
quadratic = load_results(RESULTS / "ltp" / "quadratic.npz")
h = quadratic["h_values"]
points = int(quadratic["order_points"])
fig, ax = plt.subplots(figsize=(5, 3.5))
for column, norm in enumerate(("L1", "Linf")):
    errors = quadratic["ltp_errors"][:, column]
    ax.loglog(h, errors, "o-", label=f"LTP, {norm}: order {fit_order(h[-points:], errors[-points:]):.2f}")
ax.set(xlabel="h", ylabel="error at t = 0.5")
ax.legend()
plt.show()

# %% [markdown]
# **Try it:** an LTP run against the exact solution (6.4); change h or the shape.

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
# ## Figure 4: hat against cubic B-spline shapes
#
# With the hat, the SP density is visibly rough; LTP much less so, because each particle's
# width follows the compression of the flow.

# %%
show_figure("ltp", 4)

# %% [markdown]
# ## Figures 5 and 6: power and attractive-repulsive potentials
#
# For |x|^a/a the solution collapses to a point in finite time when a < 2 and only
# asymptotically when a > 2. The claims do not depend on where the run stops: with h_min the
# smallest particle width, g = -1/(d log h_min/dt) falls linearly to 0 at a collapse time and grows
# when the shrinking is algebraic. For |x|^3/3 - |x|^b/b the mass gathers on two Dirac masses in
# infinite time when b = 2.5 (the width holding 90 % of each side's mass keeps shrinking) and
# settles on an L1 profile that peaks at the edges of its support when b = 1.5.

# %%
show_figure("ltp", 5)

# %%
fig5 = load_results(RESULTS / "ltp" / "fig5.npz")
fig, ax = plt.subplots(figsize=(5, 3.5))
for case, label in enumerate(fig5["labels"]):
    times = fig5[f"case{case}_times"]
    ax.plot(times, shrink_rate_inverse(times, fig5[f"case{case}_widths"].min(axis=1)), label=str(label))
ax.axhline(0, color="0.5", lw=0.8)
ax.set(xlabel="t", ylabel="g = -1 / (d log h_min / dt)", title="g reaches 0 at a collapse (a = 1.5 only)")
ax.legend()
plt.show()

# %%
show_figure("ltp", 6)

# %% [markdown]
# ## Figures 7 and 8, and the long-time measures
#
# Figure 8 is called a stationary state. Followed in time, SP settles and its oscillations are
# gone by then; LTP never oscillates but does not settle: the particle at x = 0 widens and pulls
# the two concentrations together (panel (d) below).

# %%
show_figure("ltp", 7)
show_figure("ltp", 8)
show_figure("ltp", "long_time")

# %% [markdown]
# ## Beyond the affine test case: a singular power potential, and the centre of mass

# %%
show_figure("ltp", "nonaffine")

# %% [markdown]
# ## Claims on several figures at once: exact mass and centre of mass

# %%
show_other_claims("ltp")

# %% [markdown]
# ## Figures the tour does not discuss
#
# Every figure registered for this paper that the sections above do not show; a new figure appears here
# until the tour discusses it.

# %%
show_remaining_figures("ltp")
