"""First-order finite volumes for the p-system of section 5.2.2 and for diagonal systems (1.7).

Two references against which the iterated TSPD of section 5.2 can be measured:

- :func:`hll_psystem` solves the p-system in its conservative variables (u, v), with the flux
  F(u, v) = (-v, p(u)), by the HLL scheme (Harten, Lax and van Leer 1983; Toro, Riemann
  Solvers, section 10.3). At a face between the states q_L and q_R the two wave speeds are
  -S and +S with S the largest sound speed c between u_L and u_R; c is largest at u = nu/2,
  so S = c(clip(nu/2, u_L, u_R)). With S_L = -S_R the HLL flux is Rusanov's:

      F(q_L, q_R) = (F(q_L) + F(q_R))/2 - S (q_R - q_L)/2.

- :func:`upwind_diagonal` solves a diagonal system (1.7) directly in its unknowns by a
  first-order upwind scheme in fluctuation form (LeVeque, Finite Volume Methods, section
  4.12), with the speed of each type averaged in its own variable as in the velocities (1.8).
  For the p-system the unknowns are the Riemann invariants (w^-, w^+) of (5.7), and the time loop is
  compiled (the primitive of (5.7) evaluated by NumPy at every step, as on the Python path of any other
  system: the same numbers to the last bit, 6 to 7 times faster; benchmarks/bench_upwind.py).

:func:`invariants_from_conservative` turns an HLL result into Riemann invariants. Nothing in
the scheme keeps u in [0, nu], where (5.6) inverts g: an HLL update is a convex combination
of the cell and of two intermediate states only for S dt <= dx/2 (Guermond and Popov 2016),
and the region w^-+ in [0, 1] is not convex in (u, v) (g changes convexity at nu/2). On the
two data of section 5.2.2 (nu = 0.5, kappa = 5, 4000 to 64000 cells on [-30, 30], up to
t = 2, cfl = 0.9) u stays inside: it never goes below the smallest value of the data, 0.004,
and stays at least 0.0018 below nu. The invariants do leave [0, 1] on the 'shocks' data, by
more than the scheme's error: across a shock of the conservative system the invariant of
the other family jumps too (by an amount of third order in the strength of a weak shock),
and at t = 2 the largest w^- is 1.016, 1.013 and 1.0128 on 4000, 16000 and 64000 cells,
converging to a bound above 1 (1.04 to 1.05 at t = 0.002). The semigroup solution of (5.7),
which the particles approximate and :func:`upwind_diagonal` computes, stays in [0, 1]: the
conservative and the diagonal solutions differ once shocks form. On the 'rarefaction' data
the invariants leave [0, 1] by rounding only (1e-14).

Both schemes carry constant ghost states equal to the end cells of the data, transparent for
data constant near the ends, and end exactly at the time asked for.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ..jit import njit
from ..systems import (
    MINUS,
    PLUS,
    PSystem,
    checked_primitive,
    checked_system,
    pressure_formula,
    sound_speed_formula,
    speed_primitives_into,
)
from ..threads import available
from ..validation import (
    finite_array,
    finite_result,
    finite_values,
    in_interval,
    instance,
    integer_at_least,
    nonnegative,
)
from .grids import check_cell_steps, check_cells_match, checked_edges, checked_time_and_cfl, uniform_width

#: Largest number of cell updates (cells x time steps) one call of :func:`hll_psystem` accepts:
#: about 30 s at the 15 ns per update measured. The data of section 5.2.2 on 64000 cells up to
#: t = 2 take 7200 steps, 4.6 * 10**8 updates.
MAX_CELL_STEPS = 2 * 10**9

#: Largest number of type-cell updates (d x cells x time steps) one call of :func:`upwind_diagonal`
#: accepts: the speed primitive is a Python callable evaluated on whole arrays, about 45 ns per
#: update, so about a minute and a half. The data of section 5.2.2 on 64000 cells up to t = 2 take
#: 9.2 * 10**8 (35 to 42 s through the Python path; the p-system's compiled loop, 5 ns per update, 5 s).
MAX_UPWIND_WORK = 2 * 10**9

#: Largest number of time steps one call of :func:`upwind_diagonal` accepts: a step costs at least
#: 2 d calls of the primitive (tens of microseconds each) whatever the number of cells (a
#: :class:`PSystem`'s compiled step leaves the kernel once, to evaluate the primitive by NumPy).
MAX_UPWIND_STEPS = 10**6

#: Largest excursion of u out of [0, nu], as a fraction of nu, that
#: :func:`invariants_from_conservative` clips by default.
VOLUME_TOLERANCE = 1e-12

#: Rounding allowed beyond 1 in the largest spread |w^+ - w^-| of the box of the data's Riemann invariants that
#: :func:`hll_psystem` takes (data computed from invariants in [0, 1] carry a few rounding errors).
BOX_TOLERANCE = 1e-12

#: Relative size, against |P(a)| + |P(b)|, below which a fluctuation dP = P(a) - P(b) is left out
#: of the time step of :func:`upwind_diagonal`: with primitives computed to a few ulps, 2^16
#: machine epsilons keep the error of the other averaged speeds below about 1e-4.
SPEED_RESOLUTION = 2.0**16 * np.finfo(np.float64).eps

_pressure_kernel = njit(pressure_formula)
_sound_speed_kernel = njit(sound_speed_formula)


def _checked_psystem(system) -> PSystem:
    return instance("system", system, PSystem)


def _conservative_data(system: PSystem, u0, v0, x_edges) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    u = finite_array("u0", u0)
    if np.any(u < 0.0) or np.any(u > system.nu):
        raise ValueError(f"u0 must lie in [0, nu] = [0, {system.nu}]")
    v = finite_array("v0", v0)
    if v.shape != u.shape:
        raise ValueError(f"u0 and v0 must have the same shape, got {u.shape} and {v.shape}")
    edges = checked_edges(x_edges)
    check_cells_match("u0", u, edges)
    return u, v, edges


def _largest_sound_speed(system: PSystem, u: np.ndarray, v: np.ndarray) -> float:
    """Largest c over the box of the initial ranges of the Riemann invariants of the data.

    Solutions of (5.7) keep their invariants in that box (the conservative solution may leave
    it behind shocks: see the module docstring). On it the spread w^+ - w^- = 2 g(u) is nearest
    to 0, u nearest to nu/2 where c peaks, at clip(0, min w^+ - max w^-, max w^+ - min w^-).

    The box must lie in the domain of the p-system, |w^+ - w^-| <= 1 (section 5.2.2: (5.6) recovers u in
    [0, nu] from w^-+ in [0, 1], and v shifts both invariants alike), up to :data:`BOX_TOLERANCE`: otherwise two
    states of the data meet in a middle state (w^- of the left one, w^+ of the right one, or the reverse) with no
    specific volume in [0, nu], and the scheme leaves it (u up to 14 nu from v jumping by 10).
    """
    w_minus, w_plus = system.riemann_invariants(u, v)
    widest = max(w_plus.max() - w_minus.min(), w_minus.max() - w_plus.min())
    if widest > 1.0 + BOX_TOLERANCE:
        raise ValueError(f"u0 and v0 have Riemann invariants w^-+ = v0 -+ g(u0) whose ranges combine into a spread "
                         f"|w^+ - w^-| of {widest:.6g}, more than 1 (section 5.2.2): the data meet in states outside "
                         "u in [0, nu]; reduce the range of v0 or of u0")
    spread = np.clip(0.0, w_plus.min() - w_minus.max(), w_plus.max() - w_minus.min())
    spread = float(np.clip(spread, -1.0, 1.0))  # |w^+ - w^-| = 2 |g(u)| <= 1, up to rounding
    nearest, _ = system.physical_variables(0.5 * (1.0 - spread), 0.5 * (1.0 + spread))
    # At an end of [0, nu] (u = 0 gives spread -1) the inverse of g lands a rounding error outside it.
    return float(system.sound_speed(np.clip(nearest, 0.0, system.nu)))


@njit
def _hll_evolve(u, v, dx, dt, t, nu, kappa):
    """HLL steps of length dt (the last one shortened) from time 0 to t, in place.

    ``u`` and ``v`` hold the cells between two ghost states (first and last entries), which
    stay fixed. Returns the largest face speed S used.
    """
    m = u.size
    pressure = np.empty(m)
    flux_u = np.empty(m - 1)
    flux_v = np.empty(m - 1)
    middle = 0.5 * nu
    largest = 0.0
    time = 0.0
    while time < t:
        step = min(dt, t - time)
        for j in range(m):
            pressure[j] = _pressure_kernel(u[j], nu, kappa)
        for k in range(m - 1):
            low, high = min(u[k], u[k + 1]), max(u[k], u[k + 1])
            s = _sound_speed_kernel(min(max(middle, low), high), nu, kappa)
            largest = max(largest, s)
            flux_u[k] = -0.5 * (v[k] + v[k + 1]) - 0.5 * s * (u[k + 1] - u[k])
            flux_v[k] = 0.5 * (pressure[k] + pressure[k + 1]) - 0.5 * s * (v[k + 1] - v[k])
        ratio = step / dx
        for j in range(1, m - 1):
            u[j] -= ratio * (flux_u[j] - flux_u[j - 1])
            v[j] -= ratio * (flux_v[j] - flux_v[j - 1])
        time += step
    return largest


def hll_psystem(system: PSystem, u0, v0, x_edges, t, cfl: float = 0.9) -> tuple[np.ndarray, np.ndarray]:
    """Cell averages (u, v) at time t of the HLL scheme for the p-system, from the averages (u0, v0).

    ``x_edges`` are the len(u0) + 1 uniformly spaced cell edges and u0 must lie in [0, nu].
    The time step is cfl dx / c_max, shortened at the end to land on t, with c_max the largest
    sound speed over the box of the initial ranges of the Riemann invariants w^-+ = v -+ g(u)
    (the peak c(nu/2) as soon as the data have w^+ - w^- of both signs, as both data of
    section 5.2.2 do). A run whose face speeds S exceed dx/dt, possible only if its states
    leave that box towards nu/2, is refused; so are data whose box leaves the domain |w^+ - w^-| <= 1 of
    section 5.2.2 (:func:`_largest_sound_speed`). Nothing keeps the result in [0, nu] (see the module docstring and
    :func:`invariants_from_conservative`): one outside it by more than VOLUME_TOLERANCE nu is refused.
    """
    system = _checked_psystem(system)
    u, v, edges = _conservative_data(system, u0, v0, x_edges)
    dx = uniform_width(edges)
    t, cfl = checked_time_and_cfl(t, cfl)
    speed = _largest_sound_speed(system, u, v)
    dt = cfl * dx / speed
    check_cell_steps(t, dt, u.size, MAX_CELL_STEPS, speeds="u0, v0")
    u_all = np.concatenate([u[:1], u, u[-1:]])
    v_all = np.concatenate([v[:1], v, v[-1:]])
    if t > 0:
        largest = _hll_evolve(u_all, v_all, dx, dt, t, system.nu, system.kappa)
        if largest * dt > dx:
            raise ValueError(f"a face speed S = {largest:.6g} exceeded dx/dt = {dx / dt:.6g}: the scheme left the "
                             "invariant region of the data and broke the CFL condition; reduce cfl")
    u, v = u_all[1:-1], v_all[1:-1]
    finite_result("the HLL solution", np.concatenate([u, v]), "the scheme overflowed on data u0, v0 this large")
    if u.max() > (1.0 + VOLUME_TOLERANCE) * system.nu:
        raise ValueError(f"the HLL solution has a specific volume u = {u.max():.6g} above nu = {system.nu}: the scheme "
                         "left [0, nu] (nothing in it keeps u there: module docstring); reduce cfl or the jumps of the "
                         "data")
    if u.min() < -VOLUME_TOLERANCE * system.nu:
        raise ValueError(f"the HLL solution has a negative specific volume, u = {u.min():.6g}: the data (u0, v0) hold "
                         "a rarefaction the scheme does not resolve inside u >= 0 (nothing in it keeps u there: module "
                         "docstring); reduce the jump in v0")
    return u, v


def invariants_from_conservative(system: PSystem, u, v, tolerance: float = VOLUME_TOLERANCE):
    """Riemann invariants (w^-, w^+) = (v - g(u), v + g(u)) of a numerical solution (u, v).

    g is defined on [0, nu] only. Values of u at most ``tolerance`` nu outside it (rounding)
    are clipped to it; a larger excursion raises a ValueError giving its size, never NaN.
    The invariants themselves are returned as they are, even outside [0, 1], where the
    conservative solution may take them (module docstring); :meth:`PSystem.physical_variables`
    and :meth:`PSystem.speeds` refuse such values.
    """
    system = _checked_psystem(system)
    u = finite_values("u", u)
    tolerance = nonnegative("tolerance", tolerance)
    excursion = float(max(0.0, -u.min(initial=0.0), u.max(initial=0.0) - system.nu)) / system.nu
    if excursion > tolerance:
        raise ValueError(f"u leaves [0, nu] by {excursion:.3g} nu, more than tolerance = {tolerance:.3g} nu: "
                         "its Riemann invariants are undefined")
    return system.riemann_invariants(np.clip(u, 0.0, system.nu), v)


def _primitives(system, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """P_gamma on both sides of every face of the ghost-padded states w (shape (d, m)), shape (d, m - 1) each.

    Face k lies between the cells k and k + 1. For type gamma the other types are frozen at
    cell k + 1: ``upper`` is P_gamma(w_{k+1}) and ``lower`` is P_gamma at w_{k+1} with w_k in
    slot gamma, P_gamma the primitive of lambda^gamma in its own variable.
    """
    right = np.ascontiguousarray(w[:, 1:].T)
    upper, lower = np.empty((2, *w.shape[:1], w.shape[1] - 1))
    for gamma in range(w.shape[0]):
        mixed = right.copy()
        mixed[:, gamma] = w[gamma, :-1]
        upper[gamma] = checked_primitive(system, gamma, right)
        lower[gamma] = checked_primitive(system, gamma, mixed)
    return upper, lower


@njit
def _entering(values, right_going, g, i):
    """Sum of ``values`` over the faces of cell i whose fluctuation of type g enters it: the left
    face's if right-going, the right face's if left-going (face k lies between cells k and k + 1
    of the padded row)."""
    total = 0.0
    if right_going[g, i - 1]:
        total += values[g, i - 1]
    if not right_going[g, i]:
        total += values[g, i]
    return total


@njit
def _face_pass(w, upper, lower, fluctuations, right_going, speeds):
    """Fluctuations, directions and averaged speeds at every face; returns the largest inflow speed of a cell.

    The fluctuation dP = upper - lower goes right when its averaged speed dP / (w_{k+1} - w_k),
    as in (1.8), is >= 0. The speed is kept (as its magnitude) only where |dP| exceeds
    SPEED_RESOLUTION (|upper| + |lower|), and is 0 below, where dP is rounding noise: a jump of
    1e-29 in the tail of a Laplace CDF next to primitives of 1e-14 gave 4 for a speed of 3.04.
    A cell's inflow speed adds the speeds of the fluctuations coming in through its two faces.
    NaN or inf is returned if a primitive or a speed is not finite.
    """
    d, m = w.shape
    fastest = 0.0
    for g in range(d):
        for k in range(m - 1):
            dp = upper[g, k] - lower[g, k]
            scale = abs(upper[g, k]) + abs(lower[g, k])
            if not np.isfinite(scale):
                return np.nan
            jump = w[g, k + 1] - w[g, k]
            fluctuations[g, k] = dp
            right_going[g, k] = dp >= 0.0 if jump > 0.0 else dp <= 0.0
            speeds[g, k] = abs(dp) / abs(jump) if abs(dp) > SPEED_RESOLUTION * scale else 0.0
        for i in range(1, m - 1):
            fastest = max(fastest, _entering(speeds, right_going, g, i))
    return fastest


@njit
def _upwind_update(w, fluctuations, right_going, ratio, low, high):
    """w_i -= ratio (right-going fluctuation of the left face + left-going one of the right face), in place.

    The ghost cells (first and last columns) stay fixed; results are clipped to [low, high] of
    their type, which they leave by rounding only.
    """
    d, m = w.shape
    for g in range(d):
        for i in range(1, m - 1):
            w[g, i] = min(max(w[g, i] - ratio * _entering(fluctuations, right_going, g, i), low[g]), high[g])


def _primitive_failure(error: ValueError) -> ValueError:
    return ValueError(f"system.speed_primitive failed on the states of w0 or of the run: {error}")


_NOT_FINITE_SPEEDS = ("the averaged speeds are not finite: system.speed_primitive returned non-finite values, "
                      "or values whose differences overflow")


def _too_much_work(t: float, cells: int, needed) -> ValueError:
    return ValueError(f"t={t} on x_edges with {cells} cells needs about {needed:.3g} time steps at "
                      f"the current speeds, more than MAX_UPWIND_STEPS = {MAX_UPWIND_STEPS:.0e} or "
                      f"MAX_UPWIND_WORK = {MAX_UPWIND_WORK:.0e} type-cell updates: reduce t, use fewer cells or "
                      "raise cfl")


def _upwind_python(system, padded, low, high, dx, t, cfl) -> int:
    """The time loop of :func:`upwind_diagonal` for any diagonal system, ``speed_primitive`` called from Python at
    every step; ``padded`` (d, cells + 2, ghost cells at both ends) is updated in place. Returns the steps taken."""
    d, cells = padded.shape[0], padded.shape[1] - 2
    fluctuations, speeds = np.empty((2, d, cells + 1))
    right_going = np.empty((d, cells + 1), dtype=np.bool_)
    time, steps = 0.0, 0
    while time < t:
        try:
            upper, lower = _primitives(system, padded)
        except ValueError as error:
            raise _primitive_failure(error) from error
        fastest = _face_pass(padded, upper, lower, fluctuations, right_going, speeds)
        if not math.isfinite(fastest):
            raise ValueError(_NOT_FINITE_SPEEDS)
        if fastest == 0.0:
            break
        dt = cfl * dx / fastest
        remaining = math.ceil((t - time) / dt) if math.isfinite((t - time) / dt) else math.inf
        if steps + remaining > MAX_UPWIND_STEPS or (steps + remaining) * d * cells > MAX_UPWIND_WORK:
            raise _too_much_work(t, cells, steps + remaining)
        step = min(dt, t - time)
        _upwind_update(padded, fluctuations, right_going, step / dx, low, high)
        time += step
        steps += 1
    return steps


#: Status of :func:`_upwind_psystem_kernel`: t reached (or a steady state), the averaged speeds not finite, more
#: steps or work than MAX_UPWIND_STEPS or MAX_UPWIND_WORK.
_REACHED, _NOT_FINITE, _TOO_MUCH_WORK = 0, 1, 2


def _compiled_psystem(system) -> bool:
    """True for a :class:`PSystem` itself (not a subclass, d = 2): :func:`upwind_diagonal` then runs its time loop
    compiled, :func:`_upwind_psystem_kernel`."""
    return type(system) is PSystem and system.d == 2


@njit
def _psystem_spreads(w, spreads):
    """Arguments w^+ - w^- of the p-system's primitive at every face k of the padded states w (2, m), the other
    type frozen at cell k + 1 as in :func:`_primitives`: ``spreads[0, k]`` at w_{k+1} (the upper primitive of both
    types), ``spreads[1, k]`` with w^-_k in the slot of w^- (the lower primitive of type w^-), ``spreads[2, k]``
    with w^+_k in the slot of w^+ (that of type w^+)."""
    for k in range(w.shape[1] - 1):
        spreads[0, k] = w[PLUS, k + 1] - w[MINUS, k + 1]
        spreads[1, k] = w[PLUS, k + 1] - w[MINUS, k]
        spreads[2, k] = w[PLUS, k] - w[MINUS, k + 1]


@njit
def _psystem_inflow(w, primitives, fluctuations, speeds, right_going, inflow):
    """:func:`_face_pass` and the sums of :func:`_entering` for the p-system, from the primitives at the spreads of
    :func:`_psystem_spreads`: ``inflow[g, i]`` is the fluctuation of type g entering cell i of the padded row (1 <=
    i <= m - 2) and the largest speed entering a cell is returned, NaN if a primitive is not finite.

    The same operations in the same order as there, so the same numbers to the last bit, with the sums of
    :func:`_entering` written out: a call of it, a compiled function taking arrays, costs about 10 ns (numba
    counts the references of its arrays in and out), and :func:`_face_pass` with :func:`_upwind_update` took
    50 ns per cell and step (both types) on the data of section 5.2.2, against 3 to 4 ns here and in the update
    of :func:`_upwind_psystem_kernel`. ``fluctuations``, ``speeds`` and ``right_going`` are scratch rows of m - 1
    faces."""
    d, m = w.shape
    fastest = 0.0
    finite = True
    for g in range(d):
        upper, lower = primitives[0], primitives[1 + g]
        for k in range(m - 1):
            dp = upper[k] - lower[k]
            scale = abs(upper[k]) + abs(lower[k])
            finite &= np.isfinite(scale)
            jump = w[g, k + 1] - w[g, k]
            fluctuations[k] = dp
            right_going[k] = dp >= 0.0 if jump > 0.0 else dp <= 0.0
            speeds[k] = abs(dp) / abs(jump) if abs(dp) > SPEED_RESOLUTION * scale else 0.0
        for i in range(1, m - 1):
            # 0.0 + x + 0.0 is x to the bit, as in _entering, which adds nothing for a face that does not enter.
            fluctuation = 0.0
            fluctuation += fluctuations[i - 1] if right_going[i - 1] else 0.0
            fluctuation += 0.0 if right_going[i] else fluctuations[i]
            speed = 0.0
            speed += speeds[i - 1] if right_going[i - 1] else 0.0
            speed += 0.0 if right_going[i] else speeds[i]
            inflow[g, i] = fluctuation
            fastest = max(fastest, speed)
    return fastest if finite else np.nan


@njit(nogil=False)  # it takes the GIL for NumPy at every step
def _upwind_psystem_kernel(w, dx, t, cfl, a, coefficient, low, high, max_steps, max_work, spreads, primitives,
                           fluctuations, speeds, right_going, inflow, report, workers):
    """The time loop of :func:`upwind_diagonal` for the p-system, compiled, on checked input: ``w`` (2, m) the
    padded states, updated in place, in [0, 1] (where the primitive is defined; the clipping to [low, high] keeps
    them there); a and coefficient those of :meth:`PSystem.speed_primitive`; ``spreads`` and ``primitives``
    (3, m - 1), ``inflow`` (2, m) and the rows of :func:`_psystem_inflow` are scratch; ``workers`` threads
    evaluate the primitive.

    Each step is that of the Python path, operation for operation: the primitives at the spreads of
    :func:`_psystem_spreads` (evaluated by NumPy, :func:`~particle_methods.systems.speed_primitives_into`: the
    one object-mode call of the loop), the fluctuations, directions and averaged speeds (1.8) of
    :func:`_psystem_inflow`, the time step cfl dx / s_max recomputed and shortened at the end, the update
    clipped to [low, high]. Returns
    :data:`_REACHED` with ``report[0]`` the steps taken (t reached, or a steady state: no fluctuation enters any
    cell), :data:`_NOT_FINITE`, or :data:`_TOO_MUCH_WORK` with ``report[0]`` the steps the run would need, more
    than ``max_steps`` or (with 2 cells updates per step) beyond ``max_work``, for the caller to raise."""
    d, m = w.shape
    cells = m - 2
    time, steps = 0.0, 0
    while time < t:
        _psystem_spreads(w, spreads)
        with numba.objmode():
            speed_primitives_into(spreads, a, coefficient, primitives, workers)
        fastest = _psystem_inflow(w, primitives, fluctuations, speeds, right_going, inflow)
        if not np.isfinite(fastest):
            return _NOT_FINITE
        if fastest == 0.0:
            break
        dt = cfl * dx / fastest
        quotient = (t - time) / dt
        needed = steps + (np.ceil(quotient) if np.isfinite(quotient) else np.inf)
        if needed > max_steps or needed * d * cells > max_work:
            report[0] = needed
            return _TOO_MUCH_WORK
        step = min(dt, t - time)
        ratio = step / dx
        for g in range(d):
            for i in range(1, m - 1):
                w[g, i] = min(max(w[g, i] - ratio * inflow[g, i], low[g]), high[g])
        time += step
        steps += 1
    report[0] = steps
    return _REACHED


def _upwind_psystem(system: PSystem, padded, low, high, dx, t, cfl, threads: int) -> int:
    """The time loop of :func:`upwind_diagonal` for a :class:`PSystem`, compiled (:func:`_upwind_psystem_kernel`),
    the primitive evaluated by ``threads`` threads; the same checks and errors as :func:`_upwind_python`. Returns
    the steps taken."""
    if t > 0.0:  # the Python path's first step evaluates the primitive on every state; the run stays in their range
        try:
            in_interval("levels", padded, 0.0, 1.0)
        except ValueError as error:
            raise _primitive_failure(error) from error
    cells = padded.shape[1] - 2
    spreads, primitives = np.empty((2, 3, cells + 1))
    fluctuations, speeds = np.empty((2, cells + 1))
    right_going = np.empty(cells + 1, dtype=np.bool_)
    inflow = np.zeros((2, cells + 2))
    report = np.zeros(1)
    status = _upwind_psystem_kernel(padded, dx, t, cfl, system.a, system.primitive_coefficient, low, high,
                                    MAX_UPWIND_STEPS, MAX_UPWIND_WORK, spreads, primitives, fluctuations, speeds,
                                    right_going, inflow, report, threads)
    if status == _NOT_FINITE:
        raise ValueError(_NOT_FINITE_SPEEDS)
    if status == _TOO_MUCH_WORK:
        raise _too_much_work(t, cells, float(report[0]))
    return int(report[0])


def upwind_diagonal(system, w0, x_edges, t, cfl: float = 0.9, return_steps: bool = False, threads: int = 1):
    """Cell averages at time t of the first-order upwind scheme for the diagonal system (1.7).

    ``system`` is any diagonal system (an integer ``d`` and a method ``speed_primitive(gamma,
    levels)``, as for :func:`~particle_methods.sticky.mspd.rank_velocities`); ``w0`` has shape
    (d, cells) on the uniformly spaced ``x_edges``. Each type gamma is updated by

        w_i <- w_i - (dt/dx) (positive part of dP_{i-1/2} + negative part of dP_{i+1/2}),

    with dP_{i-1/2} = P_gamma(w_i) - P_gamma(w_i with w_{i-1} in slot gamma) the fluctuation
    across the face between cells i - 1 and i, the other types frozen at cell i, P_gamma the
    primitive of lambda^gamma in its own variable; it goes right (positive part) when its
    averaged speed dP / (w_i - w_{i-1}), as in (1.8), is >= 0, and left otherwise. For d = 1
    and a speed of one sign this is the conservative upwind scheme, that is Godunov's.

    The time step is cfl dx / s_max, recomputed at each step and shortened at the end to land
    on t, with s_max the largest sum of the averaged speeds carrying fluctuations into one cell:
    the largest averaged speed when the speed of each type keeps one sign (the p-system,
    Burgers with positive data), and in any case a bound that makes every update a convex
    combination of the cell and its neighbours. Each type thus stays within the range of its
    data (values beyond it by rounding are clipped back). Speeds of fluctuations at the
    rounding level of the primitives (:data:`SPEED_RESOLUTION`) are left out of s_max. When no
    fluctuation enters any cell the state is steady and is returned as it is; non-finite
    primitives or speeds are refused. With ``return_steps`` the number of time steps taken is
    returned too (d cells steps is the work).

    For a :class:`~particle_methods.systems.PSystem` (the class itself, d = 2) the time loop runs
    compiled (:func:`_upwind_psystem_kernel`), with the same steps, checks and errors: the primitive
    of (5.7), :func:`~particle_methods.systems.speed_primitive_formula`, is evaluated by NumPy at each
    step as :meth:`PSystem.speed_primitive` does, the rest of the step compiled, and the result is that
    of the Python path to the last bit, on any number of ``threads`` (at most the process's,
    :func:`~particle_methods.threads.available`): they split the primitive's evaluation,
    which takes most of a step where NumPy's sinh is libm's. On the repository's AMD EPYC virtual
    machine (AVX2, 2 cores) the p-system cases on 64,000 cells took 44.4 and 37.5 s on one thread,
    33.0 and 33.2 s on two (benchmarks/bench_upwind.py). Other systems take the Python path, on one
    thread. The primitive is not evaluated in compiled code: libm's sinh and
    atan there cost 26 ns a value against NumPy's 2.4 (AVX-512), and differ from NumPy's in the last bit
    for one value in six, which the time step amplifies: s_max is set by averaged speeds in the tails of
    the data, where the fluctuations are near :data:`SPEED_RESOLUTION` and carry relative errors up to
    about 1e-5, so the steps and the results moved by up to 8e-6 and 5e-8 (4000 cells, t = 2).
    """
    d = checked_system(system)
    return_steps = instance("return_steps", return_steps, (bool, np.bool_))
    threads = min(integer_at_least("threads", threads, 1), available())
    w = finite_array("w0", w0, ndim=2)
    if w.shape[0] != d:
        raise ValueError(f"w0 must have one row per type: expected system.d = {d} rows, got {w.shape[0]}")
    edges = checked_edges(x_edges)
    check_cells_match("w0", w, edges)
    dx = uniform_width(edges)
    t, cfl = checked_time_and_cfl(t, cfl)
    padded = np.concatenate([w[:, :1], w, w[:, -1:]], axis=1)
    low, high = w.min(axis=1), w.max(axis=1)
    if _compiled_psystem(system):
        steps = _upwind_psystem(system, padded, low, high, dx, t, cfl, threads)
    else:
        steps = _upwind_python(system, padded, low, high, dx, t, cfl)
    w = padded[:, 1:-1].copy()
    return (w, steps) if return_steps else w

