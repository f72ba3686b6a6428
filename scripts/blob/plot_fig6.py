"""Figure 6: trajectories of 20 particles and density at t = 1.4 (top); star patch density from the side
and from above at t = 0.8 (bottom), for K = log|x|/(2 pi), |x|^2/2, |x|^3/3.

The star patch is drawn on the particles' Lagrangian mesh: the squares of the initial grid hZ^2 whose
corners are particles (split in two triangles, or one triangle when a corner is missing), carried by the
flow. A triangulation of the convex hull of the particles would fill the gaps between the star's arms.
Particles of no square (the thin fifth arm's tip at this h) are drawn as points coloured by density.
"""

from fractions import Fraction

import numpy as np
from matplotlib.colors import Normalize
from matplotlib.ticker import MaxNLocator
from matplotlib.tri import Triangulation

from particle_methods.blob.initial import data_2d, grid_2d
from particle_replication.plotting import save_figure, suptitle
from particle_replication.workflow import load_results, logged

TITLES = {"newtonian": r"$K = \log|x|/(2\pi)$", "quadratic": r"$K = |x|^2/2$", "cubic": r"$K = |x|^3/3$"}
SQUARE = ((0, 0), (1, 0), (1, 1), (0, 1))


def fraction(h):
    """h as a short fraction (2/15, 1/14) when it is one, else in decimals."""
    ratio = Fraction(float(h)).limit_denominator(100)
    return f"{ratio.numerator}/{ratio.denominator}" if abs(float(ratio) - h) < 1e-9 * h else f"{h:.3g}"


def lattice_triangulation(final, h, data="star"):
    """Triangles of the initial grid hZ^2 restricted to the particles, on the particles' final positions;
    None when the particles are not the grid points of ``data`` (then the caller falls back)."""
    initial = grid_2d(h, data_2d(data))
    if initial.shape != final.shape:
        return None
    cells = np.rint(initial / h).astype(int)
    index = {(int(i), int(j)): n for n, (i, j) in enumerate(cells)}
    corners = {(i - a, j - b) for i, j in index for a, b in SQUARE}
    triangles = []
    for i, j in sorted(corners):
        present = [index.get((i + a, j + b)) for a, b in SQUARE]
        if None not in present:
            triangles += [present[:3], [present[0], present[2], present[3]]]
        elif sum(p is not None for p in present) == 3:
            triangles.append([p for p in present if p is not None])
    return Triangulation(final[:, 0], final[:, 1], np.array(triangles))


def support_triangulation(points, spacings=1.8):
    """Fallback: Delaunay triangulation without the triangles having an edge longer than ``spacings``
    median nearest-neighbour distances (those bridge the gaps between the arms)."""
    triangulation = Triangulation(points[:, 0], points[:, 1])
    gaps = np.linalg.norm(points[:, None] - points[None], axis=-1)
    np.fill_diagonal(gaps, np.inf)
    corners = points[triangulation.triangles]
    edges = np.linalg.norm(corners - np.roll(corners, 1, axis=1), axis=-1).max(axis=1)
    triangulation.set_mask(edges > spacings * np.median(gaps.min(axis=1)))
    return triangulation


def colour_norm(values):
    """Colour scale of the values; a constant field gets a +-5% range so it shows as one mid colour."""
    low, high = float(np.min(values)), float(np.max(values))
    if high - low <= 1e-9 * max(abs(high), 1.0):
        return Normalize(0.95 * low, 1.05 * high)
    return Normalize(low, high)


def tidy_3d(ax, zlabel, y_ticks=True, aspect=None, zoom=1.15):
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(3))
    ax.tick_params(labelsize="small", pad=-1)
    ax.set_xlabel("$x$", labelpad=-5)
    ax.set_ylabel("$y$" if y_ticks else "", labelpad=-7)
    ax.set_zlabel(zlabel, labelpad=-6)
    if not y_ticks:
        ax.set_yticklabels([])
    ax.set_box_aspect(aspect, zoom=zoom)


def colour_bar(fig, mappable, ax):
    """Colour bar as tall as the (equal-aspect) axes, right of it."""
    bar = fig.colorbar(mappable, cax=ax.inset_axes([1.04, 0.0, 0.06, 1.0]))
    bar.ax.tick_params(labelsize="small")
    bar.locator = MaxNLocator(4)
    bar.update_ticks()


def run(d, shown, cfg, output):
    import matplotlib.pyplot as plt

    from particle_replication.plotting import apply_style

    kernels = list(d["kernels"])
    columns = len(kernels)
    apply_style(2.5 * columns)
    fig = plt.figure(figsize=(2.5 * columns, 8.8), constrained_layout=True)
    fig.get_layout_engine().set(h_pad=0.02, w_pad=0.06)
    grid = fig.add_gridspec(4, columns)
    times, index = d["times"], int(d["density_index"])
    star_h = float(cfg["bottom"]["h"])
    for column, kernel in enumerate(kernels):
        positions = d[f"{kernel}_positions"]
        pick = np.linspace(0, positions.shape[1] - 1, shown).round().astype(int)
        ax = fig.add_subplot(grid[0, column], projection="3d")
        for p in pick:
            ax.plot(positions[:, p, 0], positions[:, p, 1], times, lw=0.7)
        tidy_3d(ax, "$t$")
        ax.set_title(f"{TITLES.get(kernel, kernel)}\n{shown} trajectories", fontsize="medium")

        ax = fig.add_subplot(grid[1, column])
        points, density = positions[index], d[f"{kernel}_densities"][index]
        scatter = ax.scatter(points[:, 0], points[:, 1], c=density, s=5, norm=colour_norm(density))
        colour_bar(fig, scatter, ax)
        ax.set(xlabel="$x$", ylabel="$y$", aspect="equal")
        ax.set_title(f"density at $t = {times[index]:g}$", fontsize="medium")

        star, density = d[f"{kernel}_star_positions"], d[f"{kernel}_star_densities"]
        mesh = lattice_triangulation(star, star_h)
        if mesh is None:
            mesh = support_triangulation(star)
        norm = colour_norm(density)
        # Particles in no triangle (the tip of the thin arm along -x, one grid point wide at this h) are
        # drawn as points coloured by their density, in both views.
        lone = np.setdiff1d(np.arange(len(star)), mesh.triangles.ravel())
        ax = fig.add_subplot(grid[2, column], projection="3d")
        ax.plot_trisurf(mesh, density, cmap="viridis", norm=norm, linewidth=0.1, edgecolor="0.3")
        ax.scatter(star[lone, 0], star[lone, 1], density[lone], c=density[lone], norm=norm, s=10,
                   edgecolors="0.2", linewidths=0.3, depthshade=False)
        ax.view_init(elev=8, azim=-60)
        tidy_3d(ax, "", y_ticks=False, aspect=(1, 1, 0.7), zoom=1.35)
        ax.set_title(f"star patch, $t = {float(d['star_t']):g}$, side", fontsize="medium")

        ax = fig.add_subplot(grid[3, column])
        image = ax.tripcolor(mesh, density, shading="gouraud", norm=norm)
        ax.plot(star[:, 0], star[:, 1], ".", ms=1.5, color="0.2")
        ax.scatter(star[lone, 0], star[lone, 1], c=density[lone], norm=norm, s=14, edgecolors="0.2",
                   linewidths=0.3, zorder=3)
        colour_bar(fig, image, ax)
        ax.set(xlabel="$x$", ylabel="$y$", aspect="equal")
        ax.set_title("star patch, from above", fontsize="medium")
        ax.xaxis.set_major_locator(MaxNLocator(3))
        ax.yaxis.set_major_locator(MaxNLocator(5))
    suptitle(fig, rf"2D blob method, $m = 4$, $\delta = h^{{{float(cfg['q']):g}}}$: bump data "
                 rf"($h = {fraction(float(cfg['top']['h']))}$), star patch (4.6) ($h = {fraction(star_h)}$); "
                 "colour: density")
    save_figure(fig, output.pdf, output.png)


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    cfg = snakemake.params.cfg  # noqa: F821
    run(load_results(snakemake.input.data), cfg["top"]["trajectories"], cfg, snakemake.output)  # noqa: F821
