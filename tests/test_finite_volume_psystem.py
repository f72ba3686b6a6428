"""Finite volumes for the p-system of section 5.2.2: HLL, exact Riemann solutions, upwind for (1.7)."""

import re

import numpy as np
import pytest
from fuzzing import FUZZ, bad_array, bad_scalar, safe_call
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from particle_methods.convergence import fit_order, order_table
from particle_methods.finite_volume import BURGERS, cell_averages_of_step_cdf, godunov, l1_between_cell_functions
from particle_methods.finite_volume import psystem as fv_psystem
from particle_methods.finite_volume.psystem import (
    MAX_CELL_STEPS,
    _face_pass,
    hll_psystem,
    invariants_from_conservative,
    upwind_diagonal,
)
from particle_methods.finite_volume.riemann import PSystemRiemann
from particle_methods.norms import cdf_antiderivative
from particle_methods.sticky import ScalarLaw, burgers_flux
from particle_methods.sticky.cases import psystem_initial_measures
from particle_methods.systems import MINUS, PLUS, PSystem, speed_primitive_formula
from particle_methods.validation import ParameterTypeError

SYSTEM = PSystem(nu=0.5, kappa=5.0)
BURGERS_LAW = ScalarLaw(burgers_flux)


# Riemann problems of the lower half u <= nu/2 = 0.25, where c increases: a 1-wave (2-wave) is a
# shock when u rises (falls) across it, from left to right.
RIEMANN = {
    "two shocks": ((0.1, 0.0), (0.1, 0.1)),
    "two rarefactions": ((0.15, 0.1), (0.15, 0.0)),
    "1-shock and 2-rarefaction": ((0.05, 0.0), (0.15, 0.05)),
}
T = 0.25  # the waves, slower than c(nu/2) = 3.04, stay inside [-1, 1]
CELLS = np.array([401, 801, 1601])  # odd: the jump sits in the middle of a cell


def jump_data(left, right, edges):
    fraction = cell_averages_of_step_cdf([0.0], edges)
    return tuple(a + (b - a) * fraction for a, b in zip(left, right))


def hll_riemann_error(case, cells, subsamples=16):
    """L1 error in (u, v) on [-1, 1] at time T of HLL started from the exact averages of the jump."""
    left, right = RIEMANN[case]
    exact = PSystemRiemann(SYSTEM, left, right)
    edges = np.linspace(-1.0, 1.0, cells + 1)
    u, v = hll_psystem(SYSTEM, *jump_data(left, right, edges), edges, T)
    dx = edges[1] - edges[0]
    x = edges[:-1, None] + dx * (np.arange(subsamples) + 0.5) / subsamples
    u_exact, v_exact = exact.state(x / T)
    return dx * (np.abs(u[:, None] - u_exact).mean(axis=1).sum() + np.abs(v[:, None] - v_exact).mean(axis=1).sum())


def test_riemann_cases_have_the_announced_waves():
    kinds = {case: tuple(wave.shock for wave in PSystemRiemann(SYSTEM, *states).waves)
             for case, states in RIEMANN.items()}
    assert kinds == {"two shocks": (True, True), "two rarefactions": (False, False),
                     "1-shock and 2-rarefaction": (True, False)}


@pytest.mark.parametrize("case, lowest", [("two shocks", 0.8), ("two rarefactions", 0.5),
                                          ("1-shock and 2-rarefaction", 0.5)])
def test_hll_converges_to_the_exact_riemann_solution(case, lowest):
    errors = np.array([hll_riemann_error(case, n) for n in CELLS])
    table = order_table(2.0 / CELLS, errors, "dx")
    assert np.all(np.diff(errors) < 0), table
    assert lowest <= fit_order(2.0 / CELLS, errors) <= 1.2, table


def test_hll_conserves_u_and_v_up_to_the_boundary_fluxes(rng):
    """Constant states near both ends: the boundary fluxes F = (-v, p(u)) of those states enter. (Random data in
    the p-system's domain: every spread |w^+ - w^-| of their invariants' box at most 0.83.)"""
    edges = np.linspace(-2.0, 2.0, 401)
    centres = 0.5 * (edges[1:] + edges[:-1])
    (u_left, v_left), (u_right, v_right) = (0.1, 0.05), (0.4, -0.05)
    u0 = np.where(centres < 0, u_left, u_right)
    v0 = np.where(centres < 0, v_left, v_right)
    middle = np.abs(centres) < 0.5
    u0[middle] = rng.uniform(0.1, 0.4, middle.sum())
    v0[middle] = rng.uniform(-0.05, 0.05, middle.sum())
    t, dx = 0.2, 0.01
    u, v = hll_psystem(SYSTEM, u0, v0, edges, t)
    assert (u[0], v[0], u[-1], v[-1]) == (u_left, v_left, u_right, v_right)  # nothing reached the ends
    assert not np.allclose(u, u0)
    # d/dt sum(q) dx = F(left) - F(right), with F = (-v, p(u)).
    assert np.sum(u) * dx == pytest.approx(np.sum(u0) * dx + t * (v_right - v_left), abs=1e-12)
    pressure_jump = float(SYSTEM.pressure(u_right) - SYSTEM.pressure(u_left))
    assert np.sum(v) * dx == pytest.approx(np.sum(v0) * dx - t * pressure_jump, abs=1e-12)


def test_constant_states_stay_constant():
    edges = np.linspace(-1.0, 1.0, 51)
    u, v = hll_psystem(SYSTEM, np.full(50, 0.37), np.full(50, -0.2), edges, 1.0)
    np.testing.assert_array_equal(u, 0.37)
    np.testing.assert_array_equal(v, -0.2)
    np.testing.assert_array_equal(upwind_diagonal(SYSTEM, np.full((2, 50), 0.3), edges, 1.0), 0.3)


def test_symmetric_problem_has_a_stationary_middle_state():
    """u_L = u_R and v_L = -v_R: two shocks leave x = 0 in the state (u_*, 0), which HLL reaches there.

    Without a contact wave nothing smears the centre: the cells near x = 0 converge to u_*.
    The data are symmetric (u even, v odd in x), and so is every HLL step, exactly.
    """
    left, right = (0.1, -0.05), (0.1, 0.05)
    exact = PSystemRiemann(SYSTEM, left, right)
    u_star, v_star = exact.middle
    assert abs(v_star) < 1e-15
    assert exact.waves[0].left_edge == -exact.waves[1].right_edge
    misses = []
    for cells in (400, 800):
        edges = np.linspace(-1.0, 1.0, cells + 1)
        u, v = hll_psystem(SYSTEM, *jump_data(left, right, edges), edges, T)
        np.testing.assert_array_equal(u, u[::-1])
        np.testing.assert_array_equal(v, -v[::-1])
        centre = slice(cells // 2 - 20, cells // 2 + 20)  # |x| < 0.1, far from the shocks at |x| = 0.45
        misses.append(max(np.abs(u[centre] - u_star).max(), np.abs(v[centre]).max()))
    assert misses[1] < misses[0] / 2 and misses[1] < 1e-5, misses


def rusanov_step(u, v, tau, dx, ghosts):
    """One HLL step written out: S = c(clip(nu/2, u_L, u_R)), flux (F_L + F_R)/2 - S (q_R - q_L)/2."""
    q_u, q_v = (np.concatenate([[left], a, [right]]) for a, (left, right) in zip((u, v), ghosts))
    s = SYSTEM.sound_speed(np.clip(0.25, np.minimum(q_u[:-1], q_u[1:]), np.maximum(q_u[:-1], q_u[1:])))
    p = SYSTEM.pressure(q_u)
    flux_u = -0.5 * (q_v[:-1] + q_v[1:]) - 0.5 * s * np.diff(q_u)
    flux_v = 0.5 * (p[:-1] + p[1:]) - 0.5 * s * np.diff(q_v)
    return u - tau / dx * np.diff(flux_u), v - tau / dx * np.diff(flux_v)


def test_hll_steps_are_rusanov_updates_with_the_time_step_of_the_invariant_region():
    """Data below nu/2 take c_max from the box of their invariants, here below the peak c(nu/2)."""
    edges = np.linspace(0.0, 1.0, 6)
    u0 = np.array([0.02, 0.05, 0.03, 0.06, 0.04])
    v0 = np.array([0.0, 0.01, -0.01, 0.02, 0.0])
    w_minus, w_plus = SYSTEM.riemann_invariants(u0, v0)
    spread = w_plus.max() - w_minus.min()  # every w^+ - w^- = 2 g(u) < 0: the box's end nearest 0
    c_max = float(SYSTEM.sound_speed(SYSTEM.physical_variables((1 - spread) / 2, (1 + spread) / 2)[0]))
    assert c_max < 0.6 * SYSTEM.speed_scale
    dt = 0.9 * 0.2 / c_max
    ghosts = ((u0[0], u0[-1]), (v0[0], v0[-1]))
    expected = rusanov_step(*rusanov_step(u0, v0, dt, 0.2, ghosts), 0.5 * dt, 0.2, ghosts)
    u, v = hll_psystem(SYSTEM, u0, v0, edges, 1.5 * dt)
    np.testing.assert_allclose(u, expected[0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(v, expected[1], rtol=0, atol=1e-15)


def test_hll_face_speed_is_the_peak_of_c_between_the_states():
    """Faces whose states straddle nu/2 take S = c(nu/2), the largest c between them, not c at either state."""
    edges = np.linspace(0.0, 1.0, 6)
    u0 = np.array([0.2, 0.3, 0.1, 0.45, 0.26])
    v0 = np.array([0.0, 0.1, -0.1, 0.0, 0.05])
    t = 1e-3  # one step
    ghosts = ((u0[0], u0[-1]), (v0[0], v0[-1]))
    u, v = hll_psystem(SYSTEM, u0, v0, edges, t)
    expected = rusanov_step(u0, v0, t, 0.2, ghosts)
    np.testing.assert_allclose(u, expected[0], rtol=0, atol=1e-15)
    np.testing.assert_allclose(v, expected[1], rtol=0, atol=1e-15)


def test_one_upwind_step_by_hand():
    """dP_{i-1/2} = P(w_i) - P(w_{i-1} in slot gamma, the other type at cell i); w^- goes right, w^+ left."""
    edges = np.linspace(0.0, 1.0, 5)
    w0 = np.array([[0.1, 0.3, 0.35, 0.8], [0.9, 0.2, 0.6, 0.7]])
    padded = np.concatenate([w0[:, :1], w0, w0[:, -1:]], axis=1)
    right = padded[:, 1:].T
    fluctuations = []
    for gamma in (MINUS, PLUS):
        mixed = right.copy()
        mixed[:, gamma] = padded[gamma, :-1]
        fluctuations.append(SYSTEM.speed_primitive(gamma, right) - SYSTEM.speed_primitive(gamma, mixed))
    t = 1e-3
    expected = np.array([w0[MINUS] - t / 0.25 * fluctuations[MINUS][:-1], w0[PLUS] - t / 0.25 * fluctuations[PLUS][1:]])
    np.testing.assert_allclose(upwind_diagonal(SYSTEM, w0, edges, t), expected, rtol=0, atol=1e-15)


def study_data(case: str, cells: int):
    """The two data (w^-_0, w^+_0) of section 5.2.2 (x0 = 0.1 and -4) as exact cell averages on [-30, 30]."""
    edges = np.linspace(-30.0, 30.0, cells + 1)
    measures = psystem_initial_measures(case, 0.1 if case == "rarefaction" else -4.0)
    w = np.array([np.diff(cdf_antiderivative(m, edges)) / np.diff(edges) for m in measures])
    return edges, np.clip(w, 0.0, 1.0)  # rounding of the differences


@pytest.mark.parametrize("case", ["rarefaction", "shocks"])
def test_study_cases_run_and_keep_their_bounds(case):
    """Both schemes on the data of section 5.2.2 (coarse grid): w in [0, 1] for upwind, u in [0, nu] for HLL."""
    edges, w0 = study_data(case, 600)
    w = upwind_diagonal(SYSTEM, w0, edges, 2.0)
    assert np.all((w >= 0.0) & (w <= 1.0))
    assert not np.allclose(w, w0)
    u, v = hll_psystem(SYSTEM, *SYSTEM.physical_variables(w0[MINUS], w0[PLUS]), edges, 2.0)
    assert np.all((u >= 0.0) & (u <= SYSTEM.nu))
    w_minus, w_plus = invariants_from_conservative(SYSTEM, u, v)
    # Both schemes approximate the same solution while it is smooth (rarefaction case); once
    # shocks form the conservative solution's w^- exceeds 1 (module docstring of finite_volume.psystem).
    gap = sum(l1_between_cell_functions(a, edges, b, edges) for a, b in zip((w_minus, w_plus), w))
    if case == "rarefaction":
        assert gap < 0.1 and w_minus.max() <= 1.0 + 1e-12
    else:
        assert w_minus.max() > 1.005


def test_upwind_is_godunov_for_burgers_with_positive_data():
    edges = np.linspace(-1.0, 1.0, 201)
    x = 0.5 * (edges[1:] + edges[:-1])
    u0 = 0.5 + 0.4 * np.tanh(-5 * x) + 0.3 * (np.abs(x) < 0.3)  # a shock and a rarefaction, u > 0
    # One step (t below both time steps): the same update, flux f(u_{i-1}) at face i - 1/2.
    t = 0.5 * 0.9 * 0.01 / u0.max()
    np.testing.assert_allclose(upwind_diagonal(BURGERS_LAW, u0[None], edges, t)[0], godunov(BURGERS, u0, edges, t),
                               rtol=0, atol=1e-15)
    # Many steps: the time steps differ (averaged speeds against max f'), the results by O(dx^1.3) only.
    gaps = []
    for cells in (200, 800):
        edges = np.linspace(-1.0, 1.0, cells + 1)
        x = 0.5 * (edges[1:] + edges[:-1])
        u0 = 0.5 + 0.4 * np.tanh(-5 * x) + 0.3 * (np.abs(x) < 0.3)
        upwind = upwind_diagonal(BURGERS_LAW, u0[None], edges, 0.5)[0]
        gaps.append(l1_between_cell_functions(upwind, edges, godunov(BURGERS, u0, edges, 0.5), edges))
        assert gaps[-1] < 2e-3 * l1_between_cell_functions(upwind, edges, u0, edges)
    assert gaps[1] < gaps[0] / 4, gaps


def logistic(x, centre):
    return 1.0 / (1.0 + np.exp(-(x - centre)))


def smooth_run(cells):
    edges = np.linspace(-10.0, 10.0, cells + 1)
    x = 0.5 * (edges[1:] + edges[:-1])
    # w^+ >= w^-: two rarefactions, smooth for all times (section 5.2.2, Figure 5).
    return edges, upwind_diagonal(SYSTEM, np.array([logistic(x, 0.5), logistic(x, -0.5)]), edges, 1.0)


def test_upwind_converges_at_first_order_on_smooth_psystem_data():
    fine_edges, fine = smooth_run(6400)
    cells = np.array([200, 400, 800])
    errors = []
    for n in cells:
        edges, w = smooth_run(n)
        assert np.all((w >= 0.0) & (w <= 1.0))
        errors.append(sum(l1_between_cell_functions(w[g], edges, fine[g], fine_edges) for g in (MINUS, PLUS)))
    table = order_table(20.0 / cells, np.array(errors), "dx")
    assert 0.9 <= fit_order(20.0 / cells, errors) <= 1.15, table


def test_speeds_at_the_rounding_level_of_the_primitives_are_left_out():
    """A jump of 1e-29 across which primitives of 1e-14 differ by a few ulps: no speed (it was 4 for 3.04)."""
    w = np.array([[0.0, 1e-29, 2e-29]])
    x = 1e-14
    fluctuations, speeds = np.empty((2, 1, 2))
    right_going = np.empty((1, 2), dtype=bool)
    noise = np.array([[x - 8 * np.spacing(x), x]])
    assert _face_pass(w, np.full((1, 2), x), noise, fluctuations, right_going, speeds) == 0.0
    np.testing.assert_array_equal(fluctuations, [[8 * np.spacing(x), 0.0]])
    # Resolved: speeds 1e9 (going right) and 3e9 (going left), both into the middle cell.
    resolved = np.array([[x - 1e-20, x + 3e-20]])
    assert _face_pass(w, np.full((1, 2), x), resolved, fluctuations, right_going, speeds) == pytest.approx(4e9)
    np.testing.assert_array_equal(right_going, [[True, False]])


def test_upwind_takes_the_time_steps_of_the_largest_speed_on_the_study_data(monkeypatch):
    """On the data of section 5.2.2 the rounding noise in the Laplace tails must not shorten the steps.

    Both paths: the Python one (a delegating system) counted by its calls of the primitive, one per step,
    and the compiled one of a PSystem by its step count."""
    calls = []
    original = fv_psystem._primitives
    monkeypatch.setattr(fv_psystem, "_primitives", lambda *args: calls.append(1) or original(*args))
    edges, w0 = study_data("rarefaction", 4000)
    dt = 0.9 * (edges[1] - edges[0]) / SYSTEM.speed_scale  # at the peak speed c(nu/2), every step's bound
    upwind_diagonal(Delegating(SYSTEM), w0, edges, 199.5 * dt)  # half a step of slack for the rounding of the speeds
    assert len(calls) == 200
    assert upwind_diagonal(SYSTEM, w0, edges, 199.5 * dt, return_steps=True)[1] == 200
    assert len(calls) == 200  # the compiled path never calls it


# The compiled time loop of a PSystem against the Python path of any other system.

class Delegating:
    """A diagonal system that is not a PSystem, with the primitive of ``system``: upwind_diagonal takes its
    Python path."""

    def __init__(self, system):
        self.system = system
        self.d = system.d

    def speed_primitive(self, gamma, levels):
        return self.system.speed_primitive(gamma, levels)


def both_paths(w0, edges, t, **options):
    """(compiled, Python) results of upwind_diagonal on SYSTEM, with their step counts."""
    return (upwind_diagonal(SYSTEM, w0, edges, t, return_steps=True, **options),
            upwind_diagonal(Delegating(SYSTEM), w0, edges, t, return_steps=True, **options))


@pytest.mark.parametrize("case", ["rarefaction", "shocks"])
@pytest.mark.parametrize("cells", [1000, 4000])
def test_compiled_psystem_loop_equals_the_python_path_on_the_study_cases(case, cells):
    """The pipeline's cases (sticky.beyond: t = 2 on [-30, 30], cfl 0.9): the same steps and the same numbers to
    the last bit (the primitive by NumPy on both paths; libm's, compiled, moved the results by up to 5e-8)."""
    edges, w0 = study_data(case, cells)
    (compiled, steps), (python, python_steps) = both_paths(w0, edges, 2.0, cfl=0.9)
    assert steps == python_steps
    np.testing.assert_array_equal(compiled, python)


def test_compiled_psystem_loop_equals_the_python_path_on_the_other_data():
    """The data of the tests above (a step by hand, smooth rarefactions, constant states, a short time, t = 0),
    and the steady state: no step taken."""
    four = np.linspace(0.0, 1.0, 5)
    x = np.linspace(-10.0, 10.0, 401)
    centres = 0.5 * (x[1:] + x[:-1])
    for w0, edges, t in [
        (np.array([[0.1, 0.3, 0.35, 0.8], [0.9, 0.2, 0.6, 0.7]]), four, 1e-3),
        (np.array([[0.1, 0.3, 0.35, 0.8], [0.9, 0.2, 0.6, 0.7]]), four, 0.3),
        (np.array([logistic(centres, 0.5), logistic(centres, -0.5)]), x, 1.0),
        (np.array([logistic(centres, -0.5), logistic(centres, 0.5)]), x, 3.0),  # w^+ < w^-: shocks
        (np.full((2, 400), 0.3), x, 1.0),
        (np.array([logistic(centres, 0.5), logistic(centres, -0.5)]), x, 0.0),
    ]:
        (compiled, steps), (python, python_steps) = both_paths(w0, edges, t)
        assert steps == python_steps
        np.testing.assert_array_equal(compiled, python)
    assert steps == 0
    assert both_paths(np.full((2, 400), 0.3), x, 1.0)[0][1] == 0  # steady: returned as it is


def test_only_a_psystem_itself_takes_the_compiled_loop(monkeypatch):
    calls = []
    original = fv_psystem._primitives
    monkeypatch.setattr(fv_psystem, "_primitives", lambda *args: calls.append(1) or original(*args))

    class Subclass(PSystem):
        pass

    edges, w0 = study_data("shocks", 200)
    upwind_diagonal(SYSTEM, w0, edges, 0.5)
    assert not calls
    compiled = upwind_diagonal(Subclass(nu=0.5, kappa=5.0), w0, edges, 0.5)
    assert calls
    np.testing.assert_array_equal(compiled, upwind_diagonal(SYSTEM, w0, edges, 0.5))


def test_compiled_psystem_loop_keeps_the_checks_of_the_python_path(monkeypatch):
    """The same errors, raised by upwind_diagonal from the kernel's status: states outside [0, 1] (only when a step
    is taken, as the Python path evaluates the primitive there), the limits on steps and work from the current
    speeds (read at call time), non-finite averaged speeds."""
    edges = np.linspace(0.0, 1.0, 5)
    outside = np.array([[0.0, 0.5, 1.0, 1.5], [0.0] * 4])
    for system in (SYSTEM, Delegating(SYSTEM)):
        np.testing.assert_array_equal(upwind_diagonal(system, outside, edges, 0.0), outside)
        with pytest.raises(ValueError, match=r"states of w0 or of the run: levels must lie in \[0.0, 1.0\]"):
            upwind_diagonal(system, outside, edges, 1e-3)
    study_edges, w0 = study_data("rarefaction", 1000)
    steps = upwind_diagonal(SYSTEM, w0, study_edges, 2.0, return_steps=True)[1]
    for name, limit in [("MAX_UPWIND_STEPS", steps - 1), ("MAX_UPWIND_WORK", 2 * 1000 * steps - 1)]:
        monkeypatch.setattr(fv_psystem, name, limit)
        messages = []
        for system in (SYSTEM, Delegating(SYSTEM)):
            with pytest.raises(ValueError, match=f"needs about {steps:.3g} time steps at the current speeds") as error:
                upwind_diagonal(system, w0, study_edges, 2.0)
            messages.append(str(error.value))
        assert messages[0] == messages[1]
        monkeypatch.setattr(fv_psystem, name, limit + 1)  # the limit itself is allowed
        upwind_diagonal(SYSTEM, w0, study_edges, 2.0)
        monkeypatch.undo()
    monkeypatch.setattr(PSystem, "primitive_coefficient", property(lambda self: np.inf))
    with pytest.raises(ValueError, match="the averaged speeds are not finite"), np.errstate(invalid="ignore"):
        upwind_diagonal(SYSTEM, w0, study_edges, 2.0)


def test_psystem_inflow_is_face_pass_and_entering(rng):
    """The compiled loop's face pass against _face_pass and _entering of the Python path: the same directions,
    sums and largest speed to the last bit, with ties, jumps of 1e-29 and primitives at the rounding level."""
    m = 300
    w = np.sort(rng.uniform(0.0, 1.0, (2, m)), axis=1)
    w[:, 50:60] = w[:, 50:51]  # ties: no jump
    w[:, 100:110] = 1e-29 * np.arange(10)  # jumps far below the rounding of the primitives
    primitives = speed_primitive_formula(rng.uniform(-1.0, 1.0, (3, m - 1)), SYSTEM.a,
                                                    SYSTEM.primitive_coefficient)
    primitives[1:, 100:110] = primitives[0, 100:110] * (1.0 + rng.integers(-8, 9, (2, 10)) * np.finfo(float).eps)
    primitives[1, 50:60] = primitives[0, 50:60]  # no fluctuation across a tie
    upper, lower = primitives[[0, 0]], primitives[1:]
    fluctuations, speeds = np.empty((2, 2, m - 1))
    right_going = np.empty((2, m - 1), dtype=bool)
    fastest = fv_psystem._face_pass(w, upper, lower, fluctuations, right_going, speeds)
    rows, going, inflow = np.empty((2, m - 1)), np.empty(m - 1, dtype=bool), np.zeros((2, m))
    assert fv_psystem._psystem_inflow(w, primitives, *rows, going, inflow) == fastest
    expected = [[fv_psystem._entering(fluctuations, right_going, g, i) for i in range(1, m - 1)] for g in (0, 1)]
    np.testing.assert_array_equal(inflow[:, 1:-1], expected)
    primitives[1, 7] = np.inf
    assert np.isnan(fv_psystem._psystem_inflow(w, primitives, *rows, going, inflow))


# Exact Riemann solutions.

def test_shocks_satisfy_rankine_hugoniot_and_lax():
    for left, right in [RIEMANN["two shocks"], ((0.4, 0.1), (0.4, 0.0)), RIEMANN["1-shock and 2-rarefaction"]]:
        exact = PSystemRiemann(SYSTEM, left, right)
        for wave, (a, b) in zip(exact.waves, [(exact.left, exact.middle), (exact.middle, exact.right)]):
            if not wave.shock:
                continue
            s = wave.left_edge
            (u_a, v_a), (u_b, v_b) = a, b
            assert s * (u_b - u_a) == pytest.approx(-(v_b - v_a), abs=1e-15)
            assert s * (v_b - v_a) == pytest.approx(float(SYSTEM.pressure(u_b) - SYSTEM.pressure(u_a)), abs=1e-15)
            sign = -1.0 if wave.family == 1 else 1.0
            assert sign * SYSTEM.sound_speed(u_a) > s > sign * SYSTEM.sound_speed(u_b)  # Lax


def test_rarefactions_keep_the_other_invariant_and_fan_at_the_characteristic_speed():
    for left, right in [RIEMANN["two rarefactions"], ((0.35, 0.0), (0.35, 0.1)), RIEMANN["1-shock and 2-rarefaction"]]:
        exact = PSystemRiemann(SYSTEM, left, right)
        for wave in exact.waves:
            if wave.shock:
                continue
            xi = np.linspace(wave.left_edge, wave.right_edge, 50)
            u, v = exact.state(xi)
            w_minus, w_plus = SYSTEM.riemann_invariants(u, v)
            kept = w_minus if wave.family == 1 else w_plus
            np.testing.assert_allclose(kept, kept[0], rtol=0, atol=1e-14)
            sign = -1.0 if wave.family == 1 else 1.0
            np.testing.assert_allclose(sign * SYSTEM.sound_speed(u), xi, rtol=1e-12)
            # Continuous at both edges of the fan.
            outside = exact.state(np.array([wave.left_edge - 1e-9, wave.right_edge + 1e-9]))
            np.testing.assert_allclose(np.array(outside).T, np.array([u[[0, -1]], v[[0, -1]]]).T, atol=1e-8)


def test_a_weak_1_shock_changes_w_minus_at_third_order():
    """Right states on the Hugoniot locus of a left state: one 1-shock, across which w^- jumps by O(eps^3)."""
    u_left, v_left = 0.1, 0.2
    jumps = []
    for eps in (0.02, 0.01):
        u_right = u_left + eps  # a 1-shock needs u to rise on the lower half
        v_right = v_left + np.sqrt(-(SYSTEM.pressure(u_right) - SYSTEM.pressure(u_left)) * eps)
        exact = PSystemRiemann(SYSTEM, (u_left, v_left), (u_right, float(v_right)))
        assert exact.middle == pytest.approx((u_right, v_right), abs=1e-13)
        assert exact.waves[0].shock
        jumps.append(float(SYSTEM.riemann_invariants(u_right, v_right)[0] - SYSTEM.riemann_invariants(u_left,
                                                                                                        v_left)[0]))
    assert jumps[0] / jumps[1] == pytest.approx(8.0, rel=0.1), jumps


@pytest.mark.parametrize("case", [*RIEMANN, "upper two shocks"])
def test_cell_averages_are_the_integrals_of_the_state(case):
    left, right = RIEMANN.get(case, ((0.4, 0.1), (0.4, 0.0)))
    exact = PSystemRiemann(SYSTEM, left, right)
    t = 0.3
    edges = np.linspace(-1.0, 1.0, 17)
    averages = exact.cell_averages(edges, t)
    kinks = sorted({t * s for wave in exact.waves for s in (wave.left_edge, wave.right_edge)})
    for component in (0, 1):
        def value(x, component=component):
            return float(exact.state(np.array([x / t]))[component][0])
        expected = [integrate.quad(value, a, b, points=[k for k in kinks if a < k < b] or None, epsabs=1e-13)[0]
                    / (b - a) for a, b in zip(edges[:-1], edges[1:])]
        np.testing.assert_allclose(averages[component], expected, rtol=0, atol=1e-11)


def test_riemann_solution_limits():
    exact = PSystemRiemann(SYSTEM, (0.2, 0.1), (0.2, 0.1))
    assert exact.middle == pytest.approx((0.2, 0.1), abs=1e-15)
    np.testing.assert_allclose(exact.state(np.linspace(-5, 5, 11)), [[0.2] * 11, [0.1] * 11], atol=1e-15)
    left, right = RIEMANN["two shocks"]
    exact = PSystemRiemann(SYSTEM, left, right)
    u, v = exact.state(np.array([-10.0, 0.0, 10.0]))
    assert (u[0], v[0], u[2], v[2]) == (*left, *right)
    assert (u[1], v[1]) == exact.middle


# l1_between_cell_functions.

def test_l1_between_cell_functions_by_hand():
    # a = 1 on [0, 1), 3 on [1, 2); b = 2 on [0, 0.5), 0 on [0.5, 2): |1-2| 0.5 + |1-0| 0.5 + |3-0| 1.
    assert l1_between_cell_functions([1.0, 3.0], [0.0, 1.0, 2.0], [2.0, 0.0], [0.0, 0.5, 2.0]) == 4.0
    assert l1_between_cell_functions([1.0], [0.0, 2.0], [1.0, 1.0], [0.0, 0.3, 2.0]) == 0.0


@settings(max_examples=50, deadline=None)
@given(cells=st.integers(1, 12), split=st.integers(1, 5), data=st.data())
def test_l1_between_cell_functions_under_refinement(cells, split, data):
    """Splitting the cells of a function changes it nowhere: distances are unchanged."""
    values = st.lists(st.floats(-5, 5), min_size=cells, max_size=cells).map(np.array)
    a, b = data.draw(values), data.draw(values)
    edges = np.linspace(-1.0, 2.0, cells + 1)
    fine_edges = np.linspace(-1.0, 2.0, cells * split + 1)
    fine_a = np.repeat(a, split)
    assert l1_between_cell_functions(a, edges, fine_a, fine_edges) == pytest.approx(0.0, abs=1e-12)
    direct = float(np.sum(np.abs(a - b)) * 3.0 / cells)
    assert l1_between_cell_functions(fine_a, fine_edges, b, edges) == pytest.approx(direct, rel=1e-12, abs=1e-12)
    assert l1_between_cell_functions(b, edges, fine_a, fine_edges) == pytest.approx(direct, rel=1e-12, abs=1e-12)


# Bad inputs.

EDGES = np.linspace(0.0, 1.0, 5)
U0, V0 = np.full(4, 0.2), np.zeros(4)
W0 = np.full((2, 4), 0.5)


@pytest.mark.parametrize("call, error, message", [
    (lambda: hll_psystem(None, U0, V0, EDGES, 1.0), ParameterTypeError, "system must be of type PSystem"),
    (lambda: hll_psystem(SYSTEM, U0[:3], V0, EDGES, 1.0), ValueError, "u0 and v0 must have the same shape"),
    (lambda: hll_psystem(SYSTEM, U0[:3], V0[:3], EDGES, 1.0), ValueError, "u0 has 3 cells but x_edges has 5"),
    (lambda: hll_psystem(SYSTEM, [0.2, np.nan, 0.2, 0.2], V0, EDGES, 1.0), ValueError, "u0 contains NaN"),
    (lambda: hll_psystem(SYSTEM, U0, [0.0, np.inf, 0.0, 0.0], EDGES, 1.0), ValueError, "v0 contains NaN"),
    (lambda: hll_psystem(SYSTEM, [0.2, 0.6, 0.2, 0.2], V0, EDGES, 1.0), ValueError, r"u0 must lie in \[0, nu\]"),
    (lambda: hll_psystem(SYSTEM, U0, V0, EDGES[::-1], 1.0), ValueError, "x_edges must be sorted"),
    (lambda: hll_psystem(SYSTEM, U0, V0, [0.0, 0.1, 0.5, 0.7, 1.0], 1.0), ValueError, "x_edges must be uniformly"),
    (lambda: hll_psystem(SYSTEM, U0, V0, EDGES, -1.0), ValueError, "t must be non-negative"),
    (lambda: hll_psystem(SYSTEM, U0, V0, EDGES, 1.0, cfl=1.5), ValueError, r"cfl must lie in \(0, 1\]"),
    (lambda: hll_psystem(SYSTEM, U0, V0, EDGES, 1e12), ValueError,
     re.escape(f"more than the limit of {MAX_CELL_STEPS:.0e} cell updates")),
    (lambda: hll_psystem(SYSTEM, U0[None], V0[None], EDGES, 1.0), ValueError, "u0 must be a 1-dimensional"),
    (lambda: hll_psystem(SYSTEM, U0, np.full(4, -1.7e308), EDGES, 0.05), ValueError,
     "overflowed on data u0, v0 this large"),  # issue 46 (census): named the data
    (lambda: upwind_diagonal(None, W0, EDGES, 1.0), ParameterTypeError, "system must be a diagonal system"),
    (lambda: upwind_diagonal(BURGERS_LAW, W0, EDGES, 1.0), ValueError, "w0 must have one row per type"),
    (lambda: upwind_diagonal(SYSTEM, W0[0], EDGES, 1.0), ValueError, "w0 must be a 2-dimensional"),
    (lambda: upwind_diagonal(SYSTEM, W0[:, :3], EDGES, 1.0), ValueError, "w0 has 3 cells but x_edges has 5"),
    (lambda: upwind_diagonal(SYSTEM, W0 + [[0.0], [np.nan]], EDGES, 1.0), ValueError, "w0 contains NaN"),
    (lambda: upwind_diagonal(SYSTEM, [[0.0, 0.5, 1.0, 1.5], [0.0] * 4], EDGES, 1.0), ValueError,
     r"speed_primitive failed on the states of w0 or of the run: levels must lie in \[0.0, 1.0\]"),
    (lambda: upwind_diagonal(SYSTEM, W0, [0.0, 0.5, 0.4, 0.7, 1.0], 1.0), ValueError, "x_edges must be sorted"),
    (lambda: upwind_diagonal(SYSTEM, W0, EDGES, 1.0, cfl=1.01), ValueError, r"cfl must lie in \(0, 1\]"),
    (lambda: upwind_diagonal(SYSTEM, W0, EDGES, -0.5), ValueError, "t must be non-negative"),
    (lambda: upwind_diagonal(SYSTEM, [[0.0, 0.5, 0.5, 1.0]] * 2, EDGES, 1e9), ValueError, "MAX_UPWIND"),
    (lambda: upwind_diagonal(BURGERS_LAW, [[0.0, 1.0, 1e300, 1.0]], EDGES, 1.0), ValueError, "not finite"),
    (lambda: invariants_from_conservative(SYSTEM, [0.2, 0.5 + 1e-6], [0.0, 0.0]), ValueError,
     "u leaves .* by 2e-06 nu"),
    (lambda: invariants_from_conservative(SYSTEM, [0.2], [0.0], tolerance=-1.0), ValueError,
     "tolerance must be non-negative"),
    (lambda: invariants_from_conservative(SYSTEM, [0.2], [np.nan]), ValueError, "v contains NaN"),
    (lambda: PSystemRiemann(SYSTEM, (0.1, 0.0), (0.4, 0.0)), ValueError, "lie on both sides of nu/2"),
    (lambda: PSystemRiemann(SYSTEM, (0.2, 0.0), (0.2, 1.0)), ValueError, "leaves the half"),
    (lambda: PSystemRiemann(SYSTEM, (0.2, 0.0), (0.6, 0.0)), ValueError, r"right u must lie in \[0, nu\]"),
    (lambda: PSystemRiemann(SYSTEM, 0.2, (0.2, 0.0)), ParameterTypeError, r"left must be a pair \(u, v\)"),
    (lambda: PSystemRiemann(SYSTEM, (0.2, np.nan), (0.2, 0.0)), ValueError, "left v must be finite"),
    (lambda: PSystemRiemann("p", (0.2, 0.0), (0.2, 0.0)), ParameterTypeError, "system must be of type PSystem"),
    (lambda: PSystemRiemann(SYSTEM, (0.1, 0.0), (0.1, 0.1)).cell_averages(EDGES, 0.0), ValueError,
     "t must be positive"),
    (lambda: PSystemRiemann(SYSTEM, (0.1, 0.0), (0.1, 0.1)).state([np.inf]), ValueError, "xi contains NaN"),
    (lambda: l1_between_cell_functions([1.0], [0.0, 1.0], [1.0], [0.0, 2.0]), ValueError,
     "edges_a and edges_b must span the same interval"),
    (lambda: l1_between_cell_functions([1.0, 2.0], [0.0, 1.0], [1.0], [0.0, 1.0]), ValueError,
     "values_a has 2 cells but edges_a has 2"),
    (lambda: l1_between_cell_functions([1.0], [0.0, 1.0], [1.0], [1.0, 0.0]), ValueError, "edges_b must be sorted"),
    (lambda: l1_between_cell_functions([1.0], [0.0, 1.0], [np.nan], [0.0, 1.0]), ValueError, "values_b contains"),
    (lambda: l1_between_cell_functions([1.7e308], [0.0, 10.0], [-1.7e308], [0.0, 10.0]), ValueError,
     "the L1 distance is not finite"),
])
def test_bad_input(call, error, message):
    with pytest.raises(error, match=message):
        call()


NUMBERS = st.sampled_from([0.0, 0.1, 0.25, 0.5, 1.0, -1.0, 5e-324, 1e-300, 1e300, 1.7e308])
STATES = st.lists(NUMBERS, min_size=1, max_size=5).map(np.array)


@FUZZ
@given(u0=st.one_of(STATES, bad_array), v0=st.one_of(STATES, bad_array),
       x_edges=st.one_of(st.sampled_from([EDGES, np.array([0.0, 1e-300]), np.array([-1e300, 1e300])]), bad_array),
       t=st.one_of(st.sampled_from([0.0, 1e-300, 0.5, 1e300]), bad_scalar), cfl=st.one_of(st.just(0.9), bad_scalar),
       system=st.sampled_from([SYSTEM, BURGERS_LAW, None]), left=st.tuples(st.one_of(NUMBERS, bad_scalar), NUMBERS))
def test_fuzz_entry_points(u0, v0, x_edges, t, cfl, system, left):
    """Finite results or a ValueError/TypeError, never NaN and never a hang (tests/fuzzing.py)."""
    safe_call(hll_psystem, system, u0, v0, x_edges, t, cfl)
    safe_call(upwind_diagonal, system, u0, x_edges, t, cfl)
    if isinstance(u0, np.ndarray) and u0.ndim == 1:
        safe_call(upwind_diagonal, system, np.array([u0, u0]), x_edges, t, cfl)
    safe_call(invariants_from_conservative, system, u0, v0)
    safe_call(l1_between_cell_functions, u0, x_edges, v0, x_edges)
    exact = safe_call(PSystemRiemann, system, left, (0.1, 0.05))
    if exact is not None:
        safe_call(exact.state, u0)
        safe_call(exact.cell_averages, x_edges, t)


def test_step_counts_are_returned_on_request():
    # The cost study counts cell updates: the same solution, and the number of steps taken.
    edges = np.linspace(0.0, 1.0, 51)
    u0 = 0.2 + 0.5 * (edges[:-1] > 0.5)
    t = 0.3
    w, steps = upwind_diagonal(BURGERS_LAW, u0[None], edges, t, return_steps=True)
    np.testing.assert_array_equal(w, upwind_diagonal(BURGERS_LAW, u0[None], edges, t))
    # Averaged speeds lie between that of the jump, (0.7^2 - 0.2^2) / (2 * 0.5) = 0.45, and max u = 0.7.
    assert np.ceil(t * 0.45 / (0.9 * 0.02)) <= steps <= np.ceil(t * 0.7 / (0.9 * 0.02))
    u, cells_steps = godunov(BURGERS, u0, edges, t, return_steps=True)
    np.testing.assert_array_equal(u, godunov(BURGERS, u0, edges, t))
    assert cells_steps == np.ceil(t / (0.9 * 0.02 / 0.7))
    for call in (lambda: upwind_diagonal(BURGERS_LAW, u0[None], edges, t, return_steps="yes"),
                 lambda: godunov(BURGERS, u0, edges, t, return_steps=1)):
        with pytest.raises(TypeError, match="return_steps"):
            call()


def test_hll_takes_data_at_the_ends_of_the_volume_range():
    """u0 = 0 and u0 = nu are allowed (found by the fuzz of issue 30: the inverse of g at w+ - w- = -1 landed
    5.6e-17 below 0 and u0 = 0 was refused as 'outside [0, nu]'); a state at rest stays at rest."""
    system = PSystem()
    edges = np.linspace(-1.0, 1.0, 11)
    for level in (0.0, system.nu):
        u, v = hll_psystem(system, np.full(10, level), np.zeros(10), edges, 0.1)
        np.testing.assert_array_equal(u, level)
        np.testing.assert_array_equal(v, 0.0)


def test_hll_refuses_a_specific_volume_outside_zero_nu():
    """Data in the p-system's domain whose Riemann problems have middle states at u = 0 or u = nu: the scheme
    overshoots, to u = -0.14 nu (nu = 1, kappa = 50) and u = 1.014 nu (the paper's nu = 0.5, kappa = 5).
    (The v0 jumping from 5 to -5 of issue 30, which took u to -88, is now refused as data.)"""
    edges = np.linspace(-1.0, 1.0, 31)
    for system, (w_minus, w_plus), message in [
            (PSystem(nu=1.0, kappa=50.0), ([1.0, 1.0, 1.0], [1.0, 0.0, 0.0]), "negative specific volume"),
            (PSystem(), ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]), "above nu")]:
        u0, v0 = system.physical_variables(np.repeat(w_minus, 10), np.repeat(w_plus, 10))
        with pytest.raises(ValueError, match=message):
            hll_psystem(system, u0, v0, edges, 0.5)


def test_hll_refuses_data_outside_the_domain_of_the_psystem():
    """Issue 46: u0 = 0.2 with v0 jumping from -5 to 5 (invariants w^-+ = v0 -+ g(u0) spread over 10.3, where
    section 5.2.2 has them in [0, 1]) returned u up to 6.96 > nu = 0.5. Refused before any step, naming u0 and v0;
    a spread of 1 (invariants at the corners of [0, 1]^2, shifted in v) is taken."""
    system = PSystem()
    edges = np.linspace(-1.0, 1.0, 11)
    with pytest.raises(ValueError, match=r"u0 and v0 .* spread \|w\^\+ - w\^-\| of 10\.29"):
        hll_psystem(system, np.full(10, 0.2), np.r_[np.full(5, -5.0), np.full(5, 5.0)], edges, 0.5)
    u0, v0 = system.physical_variables(np.r_[np.zeros(5), np.full(5, 0.5)], np.r_[np.full(5, 0.5), np.ones(5)])
    u, _ = hll_psystem(system, u0, v0 + 7.0, edges, 0.05)
    assert np.all((u >= 0.0) & (u <= system.nu))


def test_grids_beyond_max_cells_are_refused_before_any_work():
    """Issue 30: 1e8 cells ended in a MemoryError after minutes; every finite-volume grid is now checked
    against MAX_CELLS (grids.checked_edges), the exact cell averages included."""
    from particle_methods.finite_volume.grids import MAX_CELLS

    edges = np.linspace(-1.0, 1.0, MAX_CELLS + 2)
    exact = PSystemRiemann(SYSTEM, *next(iter(RIEMANN.values())))
    with pytest.raises(ValueError, match="MAX_CELLS"):
        exact.cell_averages(edges, 0.5)
    with pytest.raises(ValueError, match="MAX_CELLS"):
        godunov(BURGERS, np.zeros(MAX_CELLS + 1), edges, 0.1)
    assert exact.cell_averages(edges[:: 1000], 0.5)[0].size == (MAX_CELLS + 1) // 1000


@pytest.mark.parametrize("case", ["rarefaction", "shocks"])
def test_threads_split_the_primitive_and_change_no_bit(case, monkeypatch):
    """The pipeline's upwind references run on the job's threads: 6000 cells give 18,003 values of the primitive a
    step, three chunks, split among 2 or 3 threads (each count clamped to the process's: none on one thread) once the
    threshold lets them (the references' 96,003 and 192,003 values a step pass it); the steps and every value are
    those of one thread."""
    from particle_methods import systems
    from particle_methods.threads import available

    assert 3 * 32001 >= systems.PARALLEL_MIN_PRIMITIVES > 3 * 6001
    edges, w0 = study_data(case, 6000)
    one, steps = upwind_diagonal(SYSTEM, w0, edges, 0.05, return_steps=True)
    below = upwind_diagonal(SYSTEM, w0, edges, 0.05, threads=2)  # under the threshold: every value on one thread
    assert np.array_equal(below, one)
    monkeypatch.setattr(systems, "PARALLEL_MIN_PRIMITIVES", 2 * systems.PRIMITIVE_CHUNK)
    calls = []
    real_pool = systems.pool
    monkeypatch.setattr(systems, "pool", lambda workers: calls.append(workers) or real_pool(workers))
    for threads in (2, 3):
        split, split_steps = upwind_diagonal(SYSTEM, w0, edges, 0.05, return_steps=True, threads=threads)
        assert split_steps == steps and np.array_equal(split, one)
    assert set(calls) == {workers for threads in (2, 3) if (workers := min(threads, available())) > 1}
