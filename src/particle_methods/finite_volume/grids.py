"""Cell edges, time steps and Courant numbers checked once for every scheme, and exact L1 distances.

Particle configurations enter through the empirical distribution function
H(x) = (1/n) #{k : x_k <= x} (the solution u = H * m_t of section 1.1 of the sticky paper):
:func:`cell_averages_of_step_cdf` discretises it exactly and :func:`l1_distance_to_step_cdf` measures a
finite-volume solution against it with exact piecewise integration, as :mod:`particle_methods.norms`
does for quantile functions; :func:`l1_between_cell_functions` compares two finite-volume solutions on
different grids.
"""

from __future__ import annotations

import numpy as np

from ..validation import (
    finite_array,
    finite_number,
    finite_result,
    integer_at_least,
    nonnegative,
    positive,
    real_array,
    sorted_array,
)

#: Most cells of one grid: every scheme and exact average keeps several arrays of this length (and the schemes
#: take more steps on more cells); 1e8 cells ended in a MemoryError after minutes (issue 30). The pipeline's
#: finest grid has 128,000 cells.
MAX_CELLS = 10**7


def checked_edges(x_edges, name: str = "x_edges") -> np.ndarray:
    """Strictly increasing cell edges, at least two, at most :data:`MAX_CELLS` cells."""
    edges = sorted_array(name, x_edges)
    if edges.size < 2:
        raise ValueError(f"{name} must contain at least 2 edges, got {edges.size}")
    if edges.size - 1 > MAX_CELLS:
        raise ValueError(f"{name} holds {edges.size - 1} cells, more than MAX_CELLS = {MAX_CELLS:.0e}")
    if np.any(np.diff(edges) <= 0):
        raise ValueError(f"{name} must be strictly increasing")
    if not np.isfinite(edges[-1] - edges[0]):
        raise ValueError(f"{name} must span a finite length ({name}[-1] - {name}[0] overflows)")
    return edges


def uniform_width(edges: np.ndarray) -> float:
    """Common width of the cells, or a ValueError if the edges are not uniformly spaced."""
    edges = checked_edges(edges, "edges")
    dx = (edges[-1] - edges[0]) / (edges.size - 1)
    rounding = 8.0 * np.spacing(np.max(np.abs(edges)))
    if not np.allclose(np.diff(edges), dx, rtol=1e-9, atol=rounding):
        raise ValueError("x_edges must be uniformly spaced")
    return float(dx)


def check_cells_match(name: str, values, edges, edges_name: str = "x_edges") -> None:
    """A ValueError unless the last axis of ``values`` has one entry per cell of ``edges`` (names as given)."""
    values = real_array(name, values)
    edges = real_array(edges_name, edges)
    if values.ndim == 0:
        raise ValueError(f"{name} must be an array of cell values, got a number")
    if values.shape[-1] != edges.size - 1:
        raise ValueError(f"{name} has {values.shape[-1]} cells but {edges_name} has {edges.size} edges: need "
                         f"len({edges_name}) == {name}.shape[-1] + 1")


def checked_time_and_cfl(t, cfl) -> tuple[float, float]:
    """A final time t >= 0 and a Courant number in (0, 1]."""
    t = finite_number("t", t)
    if t < 0:
        raise ValueError(f"t must be non-negative, got {t}")
    cfl = positive("cfl", cfl)
    if cfl > 1:
        raise ValueError(f"cfl must lie in (0, 1], got {cfl}")
    return t, cfl


def check_cell_steps(t: float, dt: float, cells: int, limit: int, speeds: str = "the data") -> None:
    """Refuse a run of ceil(t / dt) steps over ``cells`` cells beyond ``limit`` cell updates (and a time step that
    underflows to 0, from a cfl near the smallest double)."""
    t = nonnegative("t", t)
    dt = nonnegative("dt", dt)
    cells = integer_at_least("cells", cells, 0, MAX_CELLS)
    limit = integer_at_least("limit", limit, 0, 2**63)
    if t > 0 and not dt > 0:
        raise ValueError(f"the time step cfl dx / speed underflows to {dt}: raise cfl")
    with np.errstate(divide="ignore", over="ignore"):
        steps = np.ceil(np.float64(t) / np.float64(dt)) if t > 0 else 0.0
    if steps * float(cells) > limit:
        raise ValueError(
            f"t={t} on x_edges with {cells} cells needs {steps:.3g} time steps of dt = {dt:.3g}, more than the limit "
            f"of {limit:.0e} cell updates: reduce t, use fewer cells, raise cfl or lower the speeds of {speeds}"
        )


def _points(points) -> np.ndarray:
    x = sorted_array("points", points)
    if x.size == 0:
        raise ValueError("points must contain at least one position")
    return x


def cell_averages_of_step_cdf(points, x_edges) -> np.ndarray:
    """Exact averages over each cell of H(x) = (1/n) #{k : x_k <= x}, for sorted ``points``.

    On the cell [a, b) a point x_k < a contributes 1/n and a point a <= x_k < b
    contributes (b - x_k) / (n (b - a)), the fraction of the cell where it is
    counted. ``x_edges`` must be strictly increasing, not necessarily uniform.
    """
    x = _points(points)
    edges = checked_edges(x_edges)
    cells = edges.size - 1
    before = np.searchsorted(x, edges[:-1], side="left")
    cell = np.searchsorted(edges, x, side="right") - 1
    inside = (cell >= 0) & (cell < cells)
    cell = cell[inside]
    fraction = (edges[cell + 1] - x[inside]) / (edges[cell + 1] - edges[cell])
    return (before + np.bincount(cell, weights=fraction, minlength=cells)) / x.size


def l1_distance_to_step_cdf(values, x_edges, points) -> float:
    """Exact int over [x_edges[0], x_edges[-1]] of |v(x) - H(x)|, v = values[i] on cell i.

    H(x) = (1/n) #{k : x_k <= x} is the distribution function of the sorted
    ``points`` with masses 1/n. Merging the edges with the points splits the
    interval into pieces where both functions are constant, so the sum over the
    pieces is exact. Points outside the grid still count through H: one left of
    it raises H by 1/n on the whole grid. To measure the L1 distance on the real
    line (W1 of section 1.1) the caller must choose a grid containing the support
    of the solution and of the points, where both functions are 0 on the left and
    1 on the right.
    """
    v = finite_array("values", values)
    edges = checked_edges(x_edges)
    check_cells_match("values", v, edges)
    x = _points(points)
    breaks = np.union1d(edges, np.clip(x, edges[0], edges[-1]))
    starts = breaks[:-1]
    cell = np.searchsorted(edges, starts, side="right") - 1
    cdf = np.searchsorted(x, starts, side="right") / x.size
    return finite_result("the L1 distance", float(np.sum(np.abs(v[cell] - cdf) * np.diff(breaks))),
                         "values times the width of x_edges overflow")


def l1_between_cell_functions(values_a, edges_a, values_b, edges_b) -> float:
    """Exact int |a(x) - b(x)| dx of two piecewise-constant functions over their common span.

    a = values_a[i] on [edges_a[i], edges_a[i + 1]) and b likewise; the two edge sets are
    strictly increasing, not necessarily uniform nor nested, and must span the same interval
    (the ends may differ by rounding only: 8 ulps of the largest edge). Both functions are
    constant between consecutive points of the merged edges, so summing over those pieces is
    exact; this compares two finite-volume solutions on different grids, for instance a run
    against a finer reference run.
    """
    a = finite_array("values_a", values_a)
    first = checked_edges(edges_a, "edges_a")
    check_cells_match("values_a", a, first, "edges_a")
    b = finite_array("values_b", values_b)
    second = checked_edges(edges_b, "edges_b")
    check_cells_match("values_b", b, second, "edges_b")
    ends = np.array([first[0], second[0], first[-1], second[-1]])
    rounding = 8.0 * np.spacing(np.max(np.abs(ends)))
    if abs(first[0] - second[0]) > rounding or abs(first[-1] - second[-1]) > rounding:
        raise ValueError(f"edges_a and edges_b must span the same interval, got [{first[0]}, {first[-1]}] and "
                         f"[{second[0]}, {second[-1]}]")
    breaks = np.union1d(first, second)
    starts = breaks[:-1]
    in_a = np.clip(np.searchsorted(first, starts, side="right") - 1, 0, a.size - 1)
    in_b = np.clip(np.searchsorted(second, starts, side="right") - 1, 0, b.size - 1)
    with np.errstate(over="ignore", invalid="ignore"):
        total = float(np.sum(np.abs(a[in_a] - b[in_b]) * np.diff(breaks)))
    return finite_result("the L1 distance", total, "values_a - values_b times the widths of the cells overflows")
