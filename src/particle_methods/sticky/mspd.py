"""Multitype sticky particles by the iterated typewise SPD (sections 1.2.2, 4.1, 5.2.1).

A configuration is an array x of shape (d, n): row gamma holds the sorted
positions of the n particles of type gamma (mass 1/n each). On each time step
Delta every type moves by the SPD of its own particles (the TSPD), with
velocities (1.8) frozen at the start of the step and computed from the ranks of
each particle among the other types.

A diagonal system is any object with an integer attribute ``d`` and a method
``speed_primitive(gamma, levels)`` returning an antiderivative, in its own
variable levels[..., gamma], of the characteristic speed lambda^gamma evaluated
at ``levels`` (an array whose last axis has length d). With it the integral in
(1.8) is exact: n (P(k/n) - P((k-1)/n)).

One call may ask for at most :data:`MAX_STEPS` steps and :data:`MAX_WORK` rank entries
(n d^2 per step, the cost of section 5.2.1); a trajectory holds at most
:data:`~particle_methods.sticky.spd.MAX_POSITIONS` positions.
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
    speed_primitive_formula,
    speed_primitives_into,
)
from ..validation import ParameterTypeError, instance, integer_at_least, positive, real_array, sorted_array
from .spd import LARGEST, MAX_POSITIONS, check_reach, hull_positions_kernel

#: Largest number of steps L one call accepts: besides its particles a step costs about 0.1 ms on the Python
#: path (calls of the system; a PSystem's compiled steps about 10 us), so 10**6 steps take at most one to two
#: minutes. The figures take at most 10**4.
MAX_STEPS = 10**6

#: Largest n d^2 L (rank entries over L steps, the O(n d^2) cost per step of section 5.2.1) one
#: call accepts: one to two minutes at the 0.02 to 0.035 us per entry measured (0.04 to 0.07 us
#: per particle and step for d = 2). The figures take at most 8 * 10**7 (config ``sticky.cost``).
MAX_WORK = 4 * 10**9


@njit
def ranks_kernel(x):
    """Merge of the d sorted rows, pseudo-code of section 5.2.1, in O(n d^2).

    Returns (counts, operations): counts[gamma, k, g] is the number of particles of type g placed
    before particle gamma:k (own type included, so counts[gamma, k, gamma] = k + 1); operations
    counts, where they are made, the heads of the rows examined to choose each next particle and the
    rank entries written (section 5.2.1's O(n d^2) is a statement about them).
    Among particles at the same place the highest type is taken first, the
    post-collisional order imposed by (USH): strict inequality towards lower
    types, non-strict towards higher ones, as in (1.8).
    """
    d, n = x.shape
    counts = np.empty((d, n, d), dtype=np.int64)
    current = np.zeros(d, dtype=np.int64)
    operations = 0
    for _ in range(d * n):
        chosen = -1
        for g in range(d):
            operations += 1  # a row's head examined
            if current[g] < n and (chosen < 0 or x[g, current[g]] <= x[chosen, current[chosen]]):
                chosen = g
        k = current[chosen]
        current[chosen] = k + 1
        for g in range(d):
            counts[chosen, k, g] = current[g]
            operations += 1  # a rank entry written
    return counts, operations


class ScalarLaw:
    """A scalar conservation law u_t + A(u)_x = 0 (1.1) seen as a diagonal system with d = 1.

    Its primitive of lambda = A' is the flux A itself, so the velocities (1.8) are those of
    section 1.1.3 and every diagonal-system solver (the MSPD, the finite volumes of
    :mod:`particle_methods.finite_volume.psystem`) reduces to its scalar counterpart.
    """

    d = 1

    def __init__(self, flux):
        if not callable(flux):
            raise ParameterTypeError(f"flux must be callable, got {flux!r}")
        # One evaluation at the ends of the levels [0, 1] of a probability: a flux answering NaN, inf or no
        # number is refused here, by its name, not inside a solver.
        try:
            probe = real_array("flux(u)", flux(np.array([0.0, 1.0])))
        except (ValueError, TypeError) as error:
            kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
            raise kind(f"flux failed at u = 0, 1: {error}") from None
        if not np.all(np.isfinite(probe)):
            raise ValueError(f"flux must be finite at u = 0 and 1, got {probe}")
        self.flux = flux

    def speed_primitive(self, gamma, levels):
        """A(levels[..., 0]); gamma must be 0."""
        if integer_at_least("gamma", gamma, 0) != 0:
            raise ValueError(f"gamma must be 0 for a scalar law, got {gamma}")
        levels = real_array("levels", levels)
        if levels.ndim == 0 or levels.shape[-1] != 1:
            raise ValueError(f"levels must have a last axis of length d = 1 for a scalar law, got shape {levels.shape}")
        try:
            return self.flux(levels[..., 0])
        except (ValueError, TypeError) as error:  # the flux's own refusal (u^2/2 overflows): name the levels
            kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
            raise kind(f"flux refused levels: {error}") from None


def checked_configuration(name: str, x, system) -> np.ndarray:
    d = checked_system(system)
    x = sorted_array(name, x, ndim=2)
    if x.shape[0] != d:
        raise ValueError(f"{name} must have one row per type: expected {d} rows, got {x.shape[0]}")
    n = integer_at_least("number of particles per type n", x.shape[1], 1)
    if d * d * n > MAX_POSITIONS:
        raise ValueError(f"{name} has d = {d} types of n = {n} particles: the ranks need d^2 n = {d * d * n:.3g} "
                         f"entries, more than MAX_POSITIONS = {MAX_POSITIONS:.0e}")
    return x


def _checked_steps(steps, x0: np.ndarray) -> int:
    steps = integer_at_least("steps", steps, 0, MAX_STEPS)
    d, n = x0.shape
    if steps * d * d * n > MAX_WORK:
        raise ValueError(f"{steps} steps of d = {d} types of n = {n} particles ask for n d^2 steps = "
                         f"{steps * d * d * n:.3g} rank entries, more than MAX_WORK = {MAX_WORK:.0e} (about two "
                         "minutes): take fewer steps or particles")
    return steps


def rank_velocities(x, system) -> np.ndarray:
    """Velocities (1.8) of every particle of the configuration ``x`` (shape (d, n))."""
    x = checked_configuration("x", x, system)
    return _checked_velocities(x, system)[0]


def _primitive(system):
    """The primitive (gamma, levels) -> values of (1.8) for levels that are ranks over n, in [0, 1] by
    construction: for a :class:`PSystem` its formula (:func:`speed_primitive_formula`, the arithmetic of
    :meth:`PSystem.speed_primitive` without the checks of its input, which cost more than the formula
    at every step), else the system's own, checked."""
    if isinstance(system, PSystem):
        a, coefficient = system.a, system.primitive_coefficient
        return lambda gamma, levels: speed_primitive_formula(levels[:, PLUS] - levels[:, MINUS], a, coefficient)
    return lambda gamma, levels: checked_primitive(system, gamma, levels)


def _checked_velocities(x, system) -> tuple[np.ndarray, float, int]:
    """Velocities (1.8), their largest magnitude (after checking that they are finite) and the operations of the
    ranks (:func:`ranks_kernel`)."""
    d, n = x.shape
    counts, operations = ranks_kernel(x)
    levels = counts / n
    velocities = np.empty((d, n))
    primitive = _primitive(system)
    for gamma in range(d):
        upper = levels[gamma]
        lower = upper.copy()
        lower[:, gamma] -= 1.0 / n
        velocities[gamma] = n * (primitive(gamma, upper) - primitive(gamma, lower))
    speed = float(np.abs(velocities).max())  # one pass: NaN or inf if any velocity is
    if not math.isfinite(speed):
        raise ValueError("the velocities (1.8) are not finite: system.speed_primitive returned non-finite values, "
                         "or values whose differences overflow")
    return velocities, speed, operations


def _tspd_step(x, system, delta, out, position_name: str = "x") -> int:
    """One TSPD step from ``x`` into ``out``; returns its operations, as the kernels count them: those of the
    ranks (:func:`ranks_kernel`) and of the d hull passes (:func:`.spd.hull_positions_kernel`); ``position_name``
    names ``x`` in the errors (x0 at the first step)."""
    velocities, speed, operations = _checked_velocities(x, system)
    check_reach(x, speed, delta, "Delta", "velocities", position_name=position_name)
    for gamma in range(x.shape[0]):
        operations += hull_positions_kernel(x[gamma], velocities[gamma], delta, out[gamma])[1]
    return operations


#: Status of :func:`_tspd_psystem_kernel`: all steps taken, velocities not finite, free positions beyond the reach
#: :func:`~.spd.check_reach` allows.
_DONE, _NOT_FINITE, _TOO_FAR = 0, 1, 2


@njit(nogil=False)  # it takes the GIL for NumPy at every step
def _tspd_psystem_kernel(x, out, delta, steps, a, coefficient, spreads, primitives, velocities, report):
    """The steps of :func:`mspd_positions` for the p-system (d = 2), compiled, on checked input: each step is
    :func:`_tspd_step`'s, operation for operation (ranks, levels k/n, the primitive of (5.7) at the upper and
    lower levels of both types by NumPy in one object-mode call, velocities n (P(upper) - P(lower)), the finite
    and reach checks, the two hull passes). ``x`` and ``out`` (2, n) alternate as current and next state;
    ``spreads`` and ``primitives`` (4, n) and ``velocities`` (2, n) are scratch. Returns :data:`_DONE` with
    ``report`` = (operations, index of the array holding the result), or a failure status with ``report`` =
    (the step, the speed or reach that failed) for the caller to raise."""
    d, n = x.shape
    step_of_n = 1.0 / n
    limit = LARGEST / max(float(n), 1.0) ** 2
    current, following = x, out
    operations = 0
    for step in range(steps):
        counts, ranked = ranks_kernel(current)
        operations += ranked
        for gamma in range(d):
            for k in range(n):
                plus, minus = counts[gamma, k, PLUS] / n, counts[gamma, k, MINUS] / n
                spreads[2 * gamma, k] = plus - minus
                if gamma == PLUS:
                    spreads[2 * gamma + 1, k] = (plus - step_of_n) - minus
                else:
                    spreads[2 * gamma + 1, k] = plus - (minus - step_of_n)
        with numba.objmode():
            speed_primitives_into(spreads, a, coefficient, primitives)
        speed = 0.0
        for gamma in range(d):
            for k in range(n):
                velocities[gamma, k] = n * (primitives[2 * gamma, k] - primitives[2 * gamma + 1, k])
                speed = max(speed, abs(velocities[gamma, k])) if np.isfinite(velocities[gamma, k]) else np.inf
        if not np.isfinite(speed):
            report[0], report[1] = step, speed
            return _NOT_FINITE
        largest = 0.0
        for g in range(d):
            largest = max(largest, abs(current[g, 0]), abs(current[g, n - 1]))
        reach = largest + delta * speed
        if not reach <= limit:
            report[0], report[1] = step, reach
            return _TOO_FAR
        for gamma in range(d):
            operations += hull_positions_kernel(current[gamma], velocities[gamma], delta, following[gamma])[1]
        current, following = following, current
    report[0], report[1] = operations, 0.0 if steps % 2 == 0 else 1.0
    return _DONE


def _compiled_tspd(system) -> bool:
    """True for a :class:`PSystem` itself (not a subclass): :func:`mspd_positions` then runs its steps compiled."""
    return type(system) is PSystem and system.d == 2


def _tspd_psystem(x0, system, delta, steps):
    """:func:`mspd_positions`' steps by :func:`_tspd_psystem_kernel`, with :func:`_tspd_step`'s errors."""
    n = x0.shape[1]
    buffers = [x0.copy(), np.empty_like(x0)]
    spreads, primitives = np.empty((2, 4, n))
    velocities = np.empty((2, n))
    report = np.zeros(2)
    status = _tspd_psystem_kernel(buffers[0], buffers[1], delta, steps, system.a, system.primitive_coefficient,
                                  spreads, primitives, velocities, report)
    if status == _NOT_FINITE:
        raise ValueError("the velocities (1.8) are not finite: system.speed_primitive returned non-finite values, "
                         "or values whose differences overflow")
    if status == _TOO_FAR:
        step = int(report[0])
        check_reach(buffers[step % 2], np.abs(velocities).max(), delta, "Delta", "velocities",
                    position_name="x0" if step == 0 else "x")
        raise AssertionError("the compiled reach check and check_reach disagree")  # check_reach raised above
    return buffers[int(report[1])], int(report[0])


def mspd_trajectory(x0, system, delta: float, steps: int) -> np.ndarray:
    """Iterated TSPD: configurations at times 0, Delta, ..., steps*Delta, shape (steps+1, d, n)."""
    x0 = checked_configuration("x0", x0, system)
    delta = positive("Delta", delta)
    steps = _checked_steps(steps, x0)
    if (steps + 1) * x0.size > MAX_POSITIONS:
        raise ValueError(f"a trajectory of {steps} steps of {x0.size} particles holds {(steps + 1) * x0.size:.3g} "
                         f"positions, more than MAX_POSITIONS = {MAX_POSITIONS:.0e}: use mspd_positions or fewer steps")
    path = np.empty((steps + 1, *x0.shape))
    path[0] = x0
    for step in range(steps):
        _tspd_step(path[step], system, delta, path[step + 1], "x0" if step == 0 else "x")
    return path


def mspd_positions(x0, system, delta: float, steps: int, return_operations: bool = False):
    """Iterated TSPD after ``steps`` steps of length Delta, keeping only the current state; with
    ``return_operations`` also the operations counted over the steps (see :func:`_tspd_step`)."""
    x0 = checked_configuration("x0", x0, system)
    delta = positive("Delta", delta)
    steps = _checked_steps(steps, x0)
    return_operations = instance("return_operations", return_operations, (bool, np.bool_))
    if _compiled_tspd(system):
        current, operations = _tspd_psystem(x0, system, delta, steps)
        return (current, operations) if return_operations else current
    current, following = x0.copy(), np.empty_like(x0)
    operations = 0
    for step in range(steps):
        operations += _tspd_step(current, system, delta, following, "x0" if step == 0 else "x")
        current, following = following, current
    return (current, operations) if return_operations else current
