"""First-order Godunov finite volumes for scalar conservation laws u_t + f(u)_x = 0 in 1D.

The reference against which the sticky particle dynamics of Jourdain and Reygner
is compared on data that have no closed-form solution: the Burgers flux (5.1),
f(u) = u^2/2, and the concave flux (5.3), f(u) = u(1 - u)/2.

Cell averages u_i on a uniform grid of width dx are updated by

    u_i <- u_i - (dt/dx) (F(u_i, u_{i+1}) - F(u_{i-1}, u_i)),

with the exact Godunov flux, the flux of the entropy solution of the Riemann
problem at the face (Godunov 1959; LeVeque, Finite Volume Methods, eq. (12.4)):

    F(a, b) = min_{a <= u <= b} f(u)  if a <= b,    F(a, b) = max_{b <= u <= a} f(u)  if a > b.

For a flux with one extremum u* (f' changes sign once) both optimisations have a
closed form: the minimum of a convex f over [a, b] is f(clip(u*, a, b)) and its
maximum is max(f(a), f(b)); a concave f swaps the two.

The scheme satisfies the maximum principle, so every state stays in the range of
the initial data and ghost states, and one time step dt = cfl dx / max|f'| over
that range keeps the CFL condition for the whole run. The two ends carry constant
ghost states, which makes the boundaries transparent for data constant near them.

Particle configurations enter through the empirical distribution function
H(x) = (1/n) #{k : x_k <= x} (the solution u = H * m_t of section 1.1):
:func:`cell_averages_of_step_cdf` discretises it exactly and
:func:`l1_distance_to_step_cdf` measures a finite-volume solution against it
with exact piecewise integration, as :mod:`particle_methods.norms` does for
quantile functions.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .jit import njit
from .validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    in_interval,
    instance,
    positive,
    real_array,
    sorted_array,
)

#: Largest number of cell updates (cells x time steps) one call of :func:`godunov` accepts: about a
#: minute at the 20-30 ns per update measured; the figures need at most 3 * 10**8 (Remark 3.3,
#: 6400 cells per unit).
MAX_CELL_STEPS = 2 * 10**9

_SHAPES = ("convex", "concave")


def burgers_formula(u):
    """u^2/2 without checks, for finite float states or arrays of them (compiled kernels call it on
    scalars: no array is made)."""
    return 0.5 * u ** 2


def concave_formula(u):
    """u(1 - u)/2 without checks, for finite float states or arrays of them (compiled kernels call it
    on scalars: no array is made)."""
    return 0.5 * u * (1.0 - u)


def burgers_flux(u):
    """Flux of the Burgers equation (5.1), Lambda(u) = u^2/2."""
    u = in_interval("u", u, -np.inf, np.inf)  # any finite real array
    return finite_result("the Burgers flux u^2/2", burgers_formula(u), "u is too large")


def concave_flux(u):
    """Concave flux of (5.3), Lambda(u) = u(1 - u)/2."""
    u = in_interval("u", u, -np.inf, np.inf)
    return finite_result("the concave flux u(1 - u)/2", concave_formula(u), "u is too large")


@dataclass(frozen=True)
class ScalarFlux:
    """A flux f with a single extremum u*, where f' vanishes and changes sign.

    ``f`` and ``derivative`` act element-wise on arrays. Because f' is monotone,
    the largest |f'| over an interval is reached at one of its ends.
    """

    f: Callable
    derivative: Callable
    extremum: float
    shape: str

    def __post_init__(self):
        if not callable(self.f):
            raise ParameterTypeError(f"f must be callable, got {self.f!r}")
        if not callable(self.derivative):
            raise ParameterTypeError(f"derivative must be callable, got {self.derivative!r}")
        object.__setattr__(self, "extremum", finite_number("extremum", self.extremum))
        if not isinstance(self.shape, str) or self.shape not in _SHAPES:
            raise ValueError(f"shape must be one of {_SHAPES}, got {self.shape!r}")

    def max_speed(self, lo, hi) -> float:
        """max |f'(u)| over lo <= u <= hi."""
        lo = finite_number("lo", lo)
        hi = finite_number("hi", hi)
        if lo > hi:
            raise ValueError(f"lo must not exceed hi, got lo={lo} > hi={hi}")
        speeds = real_array("derivative(u)", self.derivative(np.array([lo, hi])))
        return float(finite_result("max |f'|", np.max(np.abs(speeds)), "derivative returned non-finite values"))


def _burgers_speed(u):
    """f'(u) = u for the Burgers flux."""
    return np.asarray(u, dtype=np.float64)


def _concave_speed(u):
    """f'(u) = 1/2 - u for the concave flux (5.3)."""
    return 0.5 - np.asarray(u, dtype=np.float64)


#: Burgers flux (5.1), f(u) = u^2/2: convex, minimum at u* = 0.
BURGERS = ScalarFlux(f=burgers_flux, derivative=_burgers_speed, extremum=0.0, shape="convex")

#: Concave flux (5.3), f(u) = u(1 - u)/2: maximum at u* = 1/2.
CONCAVE = ScalarFlux(f=concave_flux, derivative=_concave_speed, extremum=0.5, shape="concave")

# The compiled kernel evaluates these fluxes by their position in this tuple.
_COMPILED_FLUXES = (BURGERS, CONCAVE)
_burgers_kernel = njit(burgers_formula)
_concave_kernel = njit(concave_formula)


def _checked_flux(flux) -> ScalarFlux:
    if not isinstance(flux, ScalarFlux):
        raise ParameterTypeError(f"flux must be a ScalarFlux, got {type(flux).__name__}")
    return flux


def godunov_flux(flux: ScalarFlux, left, right):
    """Exact Godunov flux F(left, right), element-wise over broadcast arrays.

    Returns a float for scalar inputs and an array otherwise.
    """
    flux = _checked_flux(flux)
    a = in_interval("left", left, -np.inf, np.inf)  # any finite real array
    b = in_interval("right", right, -np.inf, np.inf)
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError(f"left and right must broadcast together, got shapes {a.shape} and {b.shape}") from None
    low, high = np.minimum(a, b), np.maximum(a, b)
    at_extremum = flux.f(np.clip(flux.extremum, low, high))
    f_a, f_b = flux.f(a), flux.f(b)
    if flux.shape == "convex":
        value = np.where(a <= b, at_extremum, np.maximum(f_a, f_b))
    else:
        value = np.where(a <= b, np.minimum(f_a, f_b), at_extremum)
    value = finite_result("the Godunov flux", real_array("f(u)", value), "f overflowed at these states")
    return float(value) if value.ndim == 0 else value


@njit
def _flux_value(flux_id, u):
    if flux_id == 0:
        return _burgers_kernel(u)
    return _concave_kernel(u)


@njit
def _face_flux(flux_id, convex, extremum, a, b):
    """Godunov flux F(a, b) of the flux number ``flux_id`` in ``_COMPILED_FLUXES``."""
    low, high = min(a, b), max(a, b)
    if convex == (a <= b):
        return _flux_value(flux_id, min(max(extremum, low), high))
    if convex:
        return max(_flux_value(flux_id, a), _flux_value(flux_id, b))
    return min(_flux_value(flux_id, a), _flux_value(flux_id, b))


@njit
def _evolve(u, dx, dt, t, flux_id, convex, extremum, left, right):
    """Godunov steps of length dt (the last one shortened) from time 0 to t, in place; returns their number."""
    n = u.size
    faces = np.empty(n + 1)
    time = 0.0
    steps = 0
    while time < t:
        steps += 1
        step = min(dt, t - time)
        faces[0] = _face_flux(flux_id, convex, extremum, left, u[0])
        for i in range(1, n):
            faces[i] = _face_flux(flux_id, convex, extremum, u[i - 1], u[i])
        faces[n] = _face_flux(flux_id, convex, extremum, u[n - 1], right)
        ratio = step / dx
        for i in range(n):
            u[i] -= ratio * (faces[i + 1] - faces[i])
        time += step
    return steps


def checked_edges(x_edges, name: str = "x_edges") -> np.ndarray:
    """Strictly increasing cell edges, at least two."""
    edges = sorted_array(name, x_edges)
    if edges.size < 2:
        raise ValueError(f"{name} must contain at least 2 edges, got {edges.size}")
    if np.any(np.diff(edges) <= 0):
        raise ValueError(f"{name} must be strictly increasing")
    if not np.isfinite(edges[-1] - edges[0]):
        raise ValueError(f"{name} must span a finite length ({name}[-1] - {name}[0] overflows)")
    return edges


def uniform_width(edges: np.ndarray) -> float:
    """Common width of the cells, or a ValueError if the edges are not uniformly spaced."""
    dx = (edges[-1] - edges[0]) / (edges.size - 1)
    rounding = 8.0 * np.spacing(np.max(np.abs(edges)))
    if not np.allclose(np.diff(edges), dx, rtol=1e-9, atol=rounding):
        raise ValueError("x_edges must be uniformly spaced")
    return float(dx)


def check_cells_match(name: str, values: np.ndarray, edges: np.ndarray, edges_name: str = "x_edges") -> None:
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


def check_cell_steps(t: float, dt: float, cells: int, limit: int) -> None:
    """Refuse a run of ceil(t / dt) steps over ``cells`` cells beyond ``limit`` cell updates."""
    with np.errstate(divide="ignore", over="ignore"):
        steps = np.ceil(t / dt)
    if steps * cells > limit:
        raise ValueError(
            f"t={t} on x_edges with {cells} cells needs {steps:.3g} time steps, more than "
            f"{limit:.0e} cell updates: reduce t or use fewer cells"
        )


def godunov(flux: ScalarFlux, u0, x_edges, t, cfl: float = 0.9, left=None, right=None, return_steps: bool = False):
    """Cell averages at time t of the Godunov scheme started from the cell averages ``u0``.

    ``x_edges`` are the len(u0) + 1 uniformly spaced edges of the cells. ``left``
    and ``right`` are the constant ghost states beyond the two ends (default: the
    end values of ``u0``). The time step is cfl dx / max|f'| over the range of the
    data, shortened at the end to land exactly on t. ``flux`` must be
    :data:`BURGERS` or :data:`CONCAVE`, the fluxes the compiled kernel knows. With
    ``return_steps`` the number of time steps taken is returned too (cells x steps is the work).
    """
    flux = _checked_flux(flux)
    if flux not in _COMPILED_FLUXES:
        raise ValueError("flux must be BURGERS or CONCAVE: the compiled kernel evaluates only these fluxes")
    u = finite_array("u0", u0).copy()
    edges = checked_edges(x_edges)
    check_cells_match("u0", u, edges)
    dx = uniform_width(edges)
    t, cfl = checked_time_and_cfl(t, cfl)
    left = u[0] if left is None else finite_number("left", left)
    right = u[-1] if right is None else finite_number("right", right)
    states = np.concatenate([u, [left, right]])
    speed = flux.max_speed(states.min(), states.max())
    instance("return_steps", return_steps, (bool, np.bool_))
    if t == 0 or speed == 0:
        # No time to evolve, or every state sits at u*, where nothing moves.
        return (u, 0) if return_steps else u
    dt = np.float64(cfl) * dx / speed
    check_cell_steps(t, dt, u.size, MAX_CELL_STEPS)
    taken = _evolve(u, dx, float(dt), t, _COMPILED_FLUXES.index(flux), flux.shape == "convex", flux.extremum, left,
                    right)
    if not np.all(np.isfinite(u)):
        raise ValueError("u0 and the ghost states are too large: the flux overflowed")
    return (u, int(taken)) if return_steps else u


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
    return finite_result("the L1 distance", total, "the values times the widths of the cells overflow")
