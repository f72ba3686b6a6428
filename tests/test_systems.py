"""The p-system of section 5.2.2: pressure, Riemann invariants, speeds."""

import numpy as np
import pytest
from scipy import integrate

from particle_methods.systems import MINUS, PLUS, PSystem

SYSTEM = PSystem(nu=0.5, kappa=5.0)


def test_condition_5_5_and_g():
    c = lambda u: float(SYSTEM.sound_speed(u))  # noqa: E731
    assert integrate.quad(c, 0, SYSTEM.nu)[0] == pytest.approx(1.0, abs=1e-12)
    for u in (0.0, 0.1, 0.37, 0.5):
        assert float(SYSTEM.g(u)) == pytest.approx(integrate.quad(c, 0, u)[0] - 0.5, abs=1e-12)


def test_sound_speed_is_sqrt_of_minus_pressure_derivative():
    u = np.linspace(0.01, 0.49, 9)
    h = 1e-6
    derivative = (SYSTEM.pressure(u + h) - SYSTEM.pressure(u - h)) / (2 * h)
    np.testing.assert_allclose(SYSTEM.sound_speed(u), np.sqrt(-derivative), rtol=1e-7)


def test_riemann_invariants_round_trip(rng):
    w_minus, w_plus = rng.uniform(0, 1, 50), rng.uniform(0, 1, 50)
    u, v = SYSTEM.physical_variables(w_minus, w_plus)
    assert np.all((0 <= u) & (u <= SYSTEM.nu))
    back = SYSTEM.riemann_invariants(u, v)
    np.testing.assert_allclose(back[0], w_minus, atol=1e-12)
    np.testing.assert_allclose(back[1], w_plus, atol=1e-12)


def test_speeds_are_sound_speed_and_strictly_hyperbolic(rng):
    w_minus, w_plus = rng.uniform(0, 1, 200), rng.uniform(0, 1, 200)
    lam_minus, lam_plus = SYSTEM.speeds(w_minus, w_plus)
    u, _ = SYSTEM.physical_variables(w_minus, w_plus)
    np.testing.assert_allclose(lam_minus, SYSTEM.sound_speed(u), rtol=1e-12)
    np.testing.assert_allclose(lam_plus, -SYSTEM.sound_speed(u), rtol=1e-12)
    ell = float(SYSTEM.sound_speed(np.linspace(0, SYSTEM.nu, 1001)).min())
    assert np.all(lam_plus <= -ell + 1e-12) and np.all(lam_minus >= ell - 1e-12)  # (5.8)


@pytest.mark.parametrize("gamma", [MINUS, PLUS])
def test_speed_primitive_differentiates_to_the_speed(gamma, rng):
    levels = rng.uniform(0.05, 0.95, size=(20, 2))
    h = 1e-6
    up, down = levels.copy(), levels.copy()
    up[:, gamma] += h
    down[:, gamma] -= h
    derivative = (SYSTEM.speed_primitive(gamma, up) - SYSTEM.speed_primitive(gamma, down)) / (2 * h)
    np.testing.assert_allclose(derivative, SYSTEM.speeds(levels[:, MINUS], levels[:, PLUS])[gamma], rtol=1e-7)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: PSystem(nu=0.0), "nu must be positive"),
        (lambda: PSystem(kappa=-1.0), "kappa must be positive"),
        (lambda: SYSTEM.pressure(0.6), r"specific volume u must lie in \[0.0, 0.5\]"),
        (lambda: SYSTEM.physical_variables(1.2, 0.5), "w_minus must lie"),
        (lambda: SYSTEM.speeds(0.5, np.nan), "w_plus contains NaN"),
        (lambda: SYSTEM.speed_primitive(2, np.zeros(2)), "gamma must be 0"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_checked_primitive_refuses_what_is_not_a_system():
    """Issue 46 (census): an AttributeError before."""
    from particle_methods.systems import checked_primitive

    with pytest.raises(TypeError, match="system must be a diagonal system"):
        checked_primitive(None, 0, np.array([[0.2, 0.5]]))
