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
# # One equation, every method: K = |x|/2 in one dimension
#
# This notebook reads what the pipeline wrote; the cell marked **Try it** runs in seconds. Set
# `PARTICLE_METHODS_WORKDIR` to read another run.
#
# **The equation.** rho_t + (rho v)_x = 0 with v = -K' * rho and K = |x|/2 gives v = (M - 2F)/2,
# F the mass left of x. So F solves F_t + (M F/2 - F^2/2)_x = 0, a conservation law with a
# concave flux: the sticky paper's Figure 3 (with M = 1) and the blob paper's Figures 1-3 (data
# (4.3), (4.4)) are this equation. Its entropy solution is known exactly, before and after the
# blow-up at t = 1/max rho0, when a Dirac mass forms at 0
# (`particle_methods.cross.exact_mass_function`). Every method is measured by its W1 distance to
# it, computed exactly on the method's own output.

# %%
import matplotlib.pyplot as plt
import numpy as np
from IPython.display import Markdown, display

from particle_methods.cross import AggregationSolution, methods
from particle_replication.paths import RESULTS
from particle_replication.tour import show_figure, show_other_claims, show_remaining_figures, summary
from particle_replication.verdicts.cross import fastest_table
from particle_replication.workflow import load_results

print(summary("cross"))

# %% [markdown]
# ## Work-precision diagrams
#
# The SPD is the exact entropy solution for its discretised data (Remark 3.3 of the sticky paper),
# costs O(n) by the hull, and is first order in W1 like every method made of point masses. The
# particle method equals the weighted SPD up to its first collision. LTP and SP reconstruct a
# smooth density and are second order before the blow-up; after it SP smears the Dirac mass over
# eps = h. Godunov's scheme for F is first order.

# %%
show_figure("cross", "error_size")
show_figure("cross", "error_time")

# %% [markdown]
# Bump data whose aggregates move and merge, against the exact solution by the continuous hull
# (`particle_methods.cross.hull`). On `two_bumps` each bump is symmetric and collapses before the merger, so every
# aggregate sits at its bump's centre of mass and the merger is the meeting of two centres of mass: the positions
# are identities that any method with odd pair forces gets (checks). On the skewed data an aggregate forms off its
# bump's centre of mass and merges before its bump has collapsed; there the positions and the merger test the
# methods. Panel (b) shows what separates the methods: the mean distance of each exact aggregate's levels from it in
# the method's output, which is 0 only for the right mass at the right place.

# %%
show_figure("cross", "aggregates_two_bumps")
show_figure("cross", "aggregates_skewed")

# %% [markdown]
# Wall time to reach W1 = 1e-6 (interpolated between runs; * marks an extrapolation from the two
# largest runs):

# %%
study = load_results(RESULTS / "cross" / "study.npz")
table = fastest_table(study, 1e-6)
lines = ["| data | t | method | seconds to 1e-6 |", "|---|---|---|---|"]
for (data, t), times in table.items():
    for method, (seconds, extrapolated) in sorted(times.items(), key=lambda item: item[1][0]):
        lines.append(f"| {data} | {t:g} | {method} | {seconds:.3g}{' *' if extrapolated else ''} |")
display(Markdown("\n".join(lines)))

# %% [markdown]
# ## Claims

# %%
show_other_claims("cross")

# %% [markdown]
# **Try it:** the exact cumulative mass F(t, x) of (4.3) before and after the blow-up, and the
# weighted SPD with a coarse grid (steps). Change `t` (the Dirac mass appears after t = 1).

# %%
t = 1.1  # change me
solution = AggregationSolution("smooth20", t)
x = np.linspace(-0.8, 0.8, 2001)
positions, masses = methods.spd_grid("smooth20", 1 / 20, t)
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot(x, solution.cdf(x), "k", label="exact F(t, x)")
ax.step(np.sort(positions), np.cumsum(masses[np.argsort(positions)]), where="post", label="weighted SPD, h = 1/20")
ax.set(xlabel="x", ylabel="F(t, x)", title=f"t = {t:g}: Dirac mass {solution.dirac_mass:.4f} of {solution.mass:.4f}")
ax.legend()
plt.show()

# %% [markdown]
# ## Figures the tour does not discuss
#
# Every figure registered for this paper that the sections above do not show; a new figure appears here
# until the tour discusses it.

# %%
show_remaining_figures("cross")
