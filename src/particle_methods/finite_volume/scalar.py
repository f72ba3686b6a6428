"""First-order Godunov finite volumes for scalar conservation laws u_t + f(u)_x = 0 in 1D.

The reference against which the sticky particle dynamics of Jourdain and Reygner
is compared on data that have no closed-form solution: the Burgers flux (5.1),
f(u) = u^2/2, and the concave flux (5.3), f(u) = u(1 - u)/2.

Cell averages u_i on a uniform grid of width dx are updated by

    u_i <- u_i - (dt/dx) (F(u_i, u_{i+1}) - F(u_{i-1}, u_i)),

with the exact Godunov flux F of :mod:`.fluxes`.

The scheme satisfies the maximum principle, so every state stays in the range of
the initial data and ghost states, and one time step dt = cfl dx / max|f'| over
that range keeps the CFL condition for the whole run. The two ends carry constant
ghost states, which makes the boundaries transparent for data constant near them.
"""

from __future__ import annotations

import numpy as np

from ..jit import njit
from ..validation import finite_array, finite_number, finite_result, instance, positive
from .fluxes import COMPILED_FLUXES, ScalarFlux, checked_flux, face_flux_kernel
from .grids import check_cell_steps, check_cells_match, checked_edges, checked_time_and_cfl, uniform_width

#: Largest number of cell updates (cells x time steps) one call of :func:`godunov` accepts: about a
#: second at the 0.5 ns per update measured; the figures need at most 3 * 10**8 (Remark 3.3,
#: 6400 cells per unit).
MAX_CELL_STEPS = 2 * 10**9


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
        faces[0] = face_flux_kernel(flux_id, convex, extremum, left, u[0])
        for i in range(1, n):
            faces[i] = face_flux_kernel(flux_id, convex, extremum, u[i - 1], u[i])
        faces[n] = face_flux_kernel(flux_id, convex, extremum, u[n - 1], right)
        ratio = step / dx
        for i in range(n):
            u[i] -= ratio * (faces[i + 1] - faces[i])
        time += step
    return steps



def cfl_time_step(flux: ScalarFlux, low: float, high: float, dx: float, cfl: float = 0.9) -> float:
    """The time step of :func:`godunov` on cells of width ``dx`` for states (ghost states included) in
    [low, high]: cfl dx / max|f'| there, cfl in (0, 1]. ValueError if the flux moves none of these states."""
    flux = checked_flux(flux)
    _, cfl = checked_time_and_cfl(0.0, cfl)
    dx = positive("dx", dx)
    low, high = finite_number("low", low), finite_number("high", high)
    if low > high:
        raise ValueError(f"low must not exceed high, got low = {low} > high = {high}")
    speed = flux.max_speed(low, high)
    if speed == 0:
        raise ValueError(f"the flux moves no state in [low, high] = [{low}, {high}]: no time step")
    with np.errstate(over="ignore"):
        step = float(np.float64(cfl) * dx / speed)
    return finite_result("the time step cfl dx / max|f'|", step,
                         f"dx = {dx:g} is too large for the speed {speed:g} of the states in [low, high]")


def godunov(flux: ScalarFlux, u0, x_edges, t, cfl: float = 0.9, left=None, right=None, return_steps: bool = False):
    """Cell averages at time t of the Godunov scheme started from the cell averages ``u0``.

    ``x_edges`` are the len(u0) + 1 uniformly spaced edges of the cells. ``left``
    and ``right`` are the constant ghost states beyond the two ends (default: the
    end values of ``u0``). The time step is cfl dx / max|f'| over the range of the
    data, shortened at the end to land exactly on t. ``flux`` must be
    :data:`BURGERS` or :data:`CONCAVE`, the fluxes the compiled kernel knows. With
    ``return_steps`` the number of time steps taken is returned too (cells x steps is the work).
    """
    flux = checked_flux(flux)
    if flux not in COMPILED_FLUXES:
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
    # One step of length t keeps the CFL condition when t speed <= cfl dx: then cfl dx / speed, possibly beyond
    # the double range (speeds of 1e-320), is never needed.
    dt = t if t * speed <= cfl * dx else cfl_time_step(flux, states.min(), states.max(), dx, cfl)
    check_cell_steps(t, dt, u.size, MAX_CELL_STEPS, speeds="u0 and the ghost states left, right")
    taken = _evolve(u, dx, float(dt), t, COMPILED_FLUXES.index(flux), flux.shape == "convex", flux.extremum, left,
                    right)
    if not np.all(np.isfinite(u)):
        raise ValueError("u0 and the ghost states are too large: the flux overflowed")
    return (u, int(taken)) if return_steps else u
