"""The exact MSPD over the grid of crossings (sticky.multitype_events): the event loop's configuration bit for bit
where particles of one type never meet, the event loop itself wherever they do, and each pass finding the
meeting of its own type."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from particle_methods.sticky import mspd_exact, mspd_exact_at
from particle_methods.sticky.cases import psystem_initial_configuration, psystem_initial_measures
from particle_methods.sticky.multitype_events import _columns, _primitive_table, _rows
from particle_methods.sticky.theory import sampled_configuration
from particle_methods.systems import PSystem

SYSTEM = PSystem(nu=0.5, kappa=5.0)  # the pipeline's p-system (config sticky.psystem)


@pytest.mark.parametrize("n", [1, 2, 50, 400])
@pytest.mark.parametrize("t", [0.0, 0.5, 2.0])
def test_rarefaction_case_is_the_event_loops_configuration_bit_for_bit(n, t):
    x0 = psystem_initial_configuration("rarefaction", 0.1, n)
    grid, method = mspd_exact_at(x0, SYSTEM, t, return_method=True)
    assert method == "grid"
    np.testing.assert_array_equal(grid, mspd_exact(x0, SYSTEM, [t])[0])


@pytest.mark.parametrize("n", [10, 200])
def test_shock_case_falls_back_to_the_event_loop(n):
    """Clusters form in the shock case (test_mspd_exact): one of the passes finds particles of one type meeting."""
    x0 = psystem_initial_configuration("shocks", -4.0, n)
    result, method = mspd_exact_at(x0, SYSTEM, 2.0, return_method=True)
    assert method == "events"
    np.testing.assert_array_equal(result, mspd_exact(x0, SYSTEM, [2.0])[0])
    found = [_pass(kernel, x0, SYSTEM, 2.0) for kernel in (_rows, _columns)]
    assert min(found) == -1


def _pass(kernel, x0, system, t, start_speeds=None):
    """One pass of the grid on x0 with the p-system's velocities (1.8) at the start, or ``start_speeds``."""
    from particle_methods.sticky.mspd import ranks_kernel
    from particle_methods.sticky.multitype_events import _initial_speeds

    n = x0.shape[1]
    ranks = ranks_kernel(x0)[0]
    behind = np.ascontiguousarray(ranks[[0, 1], :, [1, 0]])
    speeds = _initial_speeds(system, ranks) if start_speeds is None else np.asarray(start_speeds, dtype=float)
    table = _primitive_table(n)
    constants = np.array([system.a, system.primitive_coefficient])
    lam, out = np.empty((2, n)), np.empty((2, n))
    if kernel is _rows:
        return kernel(x0, speeds, behind, t, constants, table, lam, out, np.array([np.inf, -np.inf]))
    return kernel(x0, speeds, behind, t, constants, table, lam, out)


def test_each_pass_finds_the_meeting_of_its_own_type():
    """Type-0 particles 1 apart, the one behind faster by 4: they meet at t = 0.25, before either reaches the
    type-1 particles (at 10 and 11); the pass by rows finds it, the pass by columns has no type-0 neighbours to
    check. Then type-1 particles closing at 3 meet at t = 1/3: the reverse."""
    x0 = np.array([[0.0, 1.0], [10.0, 11.0]])
    type_0_meet = [[5.0, 1.0], [0.0, 0.0]]
    assert _pass(_rows, x0, SYSTEM, 1.0, type_0_meet) == -1
    assert _pass(_columns, x0, SYSTEM, 1.0, type_0_meet) == 0
    type_1_meet = [[5.0, 5.0], [3.0, 0.0]]
    assert _pass(_rows, x0, SYSTEM, 1.0, type_1_meet) == 0
    assert _pass(_columns, x0, SYSTEM, 1.0, type_1_meet) == -1
    # before they meet, neither pass finds anything
    assert _pass(_rows, x0, SYSTEM, 0.2, type_0_meet) == 0 and _pass(_columns, x0, SYSTEM, 0.3, type_1_meet) == 0


def test_particles_of_one_type_at_one_place_or_one_ulp_apart():
    """Two type-0 particles at one place start as a cluster: the event loop computes it. One ulp apart (1e-17 of
    their place, as a nudge makes them) they are two particles, and the grid, if it applies, gives the event loop's
    configuration to rounding: a rounding of the data decides nothing."""
    x0 = psystem_initial_configuration("rarefaction", 0.1, 40)
    together = x0.copy()
    together[0, 20] = together[0, 19]
    assert mspd_exact_at(together, SYSTEM, 2.0, return_method=True)[1] == "events"
    apart = together.copy()
    apart[0, 20] = np.nextafter(apart[0, 19], np.inf)
    for data in (together, apart):
        np.testing.assert_allclose(mspd_exact_at(data, SYSTEM, 2.0), mspd_exact(data, SYSTEM, [2.0])[0], rtol=0,
                                   atol=1e-12)


def test_another_system_runs_the_event_loop():
    class Shifted(PSystem):
        def speed_primitive(self, gamma, levels):
            return super().speed_primitive(gamma, levels)

    x0 = psystem_initial_configuration("rarefaction", 0.1, 8)
    result, method = mspd_exact_at(x0, Shifted(nu=0.5, kappa=5.0), 1.0, return_method=True)
    assert method == "events"
    # Its primitive from Python (NumPy's sinh and arctan, SVML's where NumPy dispatches AVX-512) against the
    # compiled one (libm's): equal to rounding, not bit for bit on every CPU.
    np.testing.assert_allclose(result, mspd_exact(x0, SYSTEM, [1.0])[0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("t, error, message", [(-1.0, ValueError, "t must be non-negative"),
                                               (np.nan, ValueError, "t"), ("1", TypeError, "t")])
def test_bad_time_is_refused(t, error, message):
    with pytest.raises(error, match=message):
        mspd_exact_at(psystem_initial_configuration("rarefaction", 0.1, 4), SYSTEM, t)


def test_return_method_must_be_a_bool():
    with pytest.raises(TypeError, match="return_method"):
        mspd_exact_at(psystem_initial_configuration("rarefaction", 0.1, 4), SYSTEM, 1.0, return_method="yes")


@settings(max_examples=60, deadline=None)
@given(case=st.sampled_from(["rarefaction", "shocks"]), x0=st.floats(-5.0, 5.0), n=st.integers(1, 40),
       seed=st.integers(0, 2**32 - 1), t=st.floats(0.0, 6.0))
def test_random_configurations_give_the_event_loops_configuration(case, x0, n, seed, t):
    """Random draws of either case's measures (sticky.theory.sampled_configuration), at any time: whichever way
    mspd_exact_at takes, its configuration is the event loop's (to rounding): a meeting of one type that the
    passes missed would show here as a configuration of particles passing each other."""
    x = sampled_configuration(psystem_initial_measures(case, x0), n, np.random.default_rng(seed))
    at, method = mspd_exact_at(x, SYSTEM, t, return_method=True)
    events = mspd_exact(x, SYSTEM, [t])[0]
    np.testing.assert_allclose(at, events, rtol=0, atol=1e-12 * max(1.0, np.abs(events).max()))
    if method == "grid":
        np.testing.assert_array_equal(np.diff(at, axis=1) >= 0, True)
