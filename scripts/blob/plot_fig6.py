"""Figure 6: trajectories of 20 particles and density at t = 1.4 (top); star patch density from the side
and from above at t = 0.8 (bottom), for K = log|x|/(2 pi), |x|^2/2, |x|^3/3."""

import numpy as np
from matplotlib.tri import Triangulation

from particle_methods.plotting import save_figure
from particle_methods.workflow import load_results, logged

TITLES = {"newtonian": "K = log|x|/(2 pi)", "quadratic": "K = |x|^2/2", "cubic": "K = |x|^3/3"}


def run(d, shown, output):
    import matplotlib.pyplot as plt

    from particle_methods.plotting import STYLE

    plt.rcParams.update(STYLE)
    kernels = list(d["kernels"])
    fig = plt.figure(figsize=(4.6 * len(kernels), 15), constrained_layout=True)
    times, index = d["times"], int(d["density_index"])
    for column, kernel in enumerate(kernels):
        positions = d[f"{kernel}_positions"]
        pick = np.linspace(0, positions.shape[1] - 1, shown).round().astype(int)
        ax = fig.add_subplot(4, len(kernels), column + 1, projection="3d")
        for p in pick:
            ax.plot(positions[:, p, 0], positions[:, p, 1], times, lw=0.8)
        ax.set(xlabel="x", ylabel="y", zlabel="t", title=f"{TITLES[kernel]}: {shown} trajectories")
        ax = fig.add_subplot(4, len(kernels), len(kernels) + column + 1)
        points = positions[index]
        scatter = ax.scatter(points[:, 0], points[:, 1], c=d[f"{kernel}_densities"][index], s=12, cmap="viridis")
        fig.colorbar(scatter, ax=ax, label="density along trajectories")
        ax.set(xlabel="x", ylabel="y", aspect="equal", title=f"density at t = {times[index]:g}")
        star, density = d[f"{kernel}_star_positions"], d[f"{kernel}_star_densities"]
        triangles = Triangulation(star[:, 0], star[:, 1])
        ax = fig.add_subplot(4, len(kernels), 2 * len(kernels) + column + 1, projection="3d")
        ax.plot_trisurf(triangles, density, cmap="viridis", linewidth=0.1)
        ax.view_init(elev=5, azim=-60)
        ax.set(xlabel="x", ylabel="y", zlabel="density", title=f"star patch, t = {float(d['star_t']):g}, side")
        ax = fig.add_subplot(4, len(kernels), 3 * len(kernels) + column + 1)
        image = ax.tripcolor(triangles, density, shading="gouraud", cmap="viridis")
        fig.colorbar(image, ax=ax, label="density")
        ax.set(xlabel="x", ylabel="y", aspect="equal", title="star patch, from above")
    fig.suptitle("2D blob method, m = 4, delta = h^0.9: bump data (h = 2/15) and star patch (4.6) (h = 1/14)")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0]):  # noqa: F821
    run(load_results(snakemake.input.data), snakemake.params.shown, snakemake.output)  # noqa: F821
