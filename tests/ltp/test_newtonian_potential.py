"""The Newtonian potential of 1D, W = c|x| (exponent a = 1): W' = c sign(x), W'' = 2c delta.

The kernels convolve it exactly, (W' * rho_h)(x) = c (2 F_h(x) - M) with F_h the cumulative mass and
(W'' * rho_h)(x) = 2c rho_h(x); checked against adaptive quadrature. Outside the paper's theory, the
exact solution for W = |x|/2 blows up at t = 1 / max rho^0 (along characteristics d rho/dt = rho^2):
the LTP run is refused by the stability bound of (2.31) before, the SP run with a fixed width is not.
"""

import re

import numpy as np
import pytest
from scipy import integrate

from particle_methods.ltp import B3, HAT, InitialDensity, Particles, Potential, potential, simulate
from particle_methods.ltp.kernels import convolutions, cumulative_mass_at, density_at

CENTRES = np.array([-0.4, 0.0, 0.013, 0.5])
WEIGHTS = np.array([0.2, 0.3, 0.1, 0.4])
WIDTHS = np.array([0.05, 0.01, 0.004, 0.2])
# Inside and outside the supports, at centres and at piece boundaries of the b3 and hat particles.
TARGETS = np.array([-3.0, -0.5, -0.45, -0.4, -0.37, -0.35, -0.3, 0.0, 0.006, 0.01, 0.013, 0.021, 0.05, 0.1, 0.5,
                    0.63, 0.9, 0.93, 1.7])
SHAPES = [HAT, B3]


def knots(shape, centres=CENTRES, widths=WIDTHS):
    """Every piece boundary of every particle, sorted."""
    return np.sort((centres[:, None] + widths[:, None] * shape.breaks[None, :]).ravel())


def sign_convolution(shape, c, t):
    """int c sign(t - y) rho_h(y) dy by quadrature on each polynomial piece, split at t."""
    total = 0.0
    for xk, wk, hk in zip(CENTRES, WEIGHTS, WIDTHS):
        def phi(y, xk=xk, hk=hk):
            return float(shape((y - xk) / hk)) / hk

        edges = xk + hk * shape.breaks
        for lo, hi in zip(edges[:-1], edges[1:]):
            for a, b in ((lo, min(hi, t)), (max(lo, t), hi)):
                if a < b:
                    total += wk * c * np.sign(t - 0.5 * (a + b)) * integrate.quad(phi, a, b, epsabs=1e-16)[0]
    return total


def newtonian(c):
    return Potential(f"{c:g}|x|", (c,), (1.0,))


@pytest.mark.parametrize("shape", SHAPES, ids=lambda s: s.name)
@pytest.mark.parametrize("c", [0.5, -1.3])
def test_convolutions_of_the_newtonian_kernel_match_quadrature(shape, c):
    first, second = convolutions(TARGETS, CENTRES, WEIGHTS, WIDTHS, *newtonian(c).as_arrays(), shape.breaks,
                                 shape.coefficients)
    for i, t in enumerate(TARGETS):
        assert first[i] == pytest.approx(sign_convolution(shape, c, t), abs=1e-13)
    rho = sum(w * shape((TARGETS - x) / h) / h for x, w, h in zip(CENTRES, WEIGHTS, WIDTHS))
    np.testing.assert_allclose(second, 2 * c * rho, rtol=1e-14, atol=1e-13)
    # far left and far right of every particle: W' * rho_h = -c M and c M exactly
    assert first[0] == -c * WEIGHTS.sum() and first[-1] == c * WEIGHTS.sum() and second[[0, -1]].tolist() == [0, 0]


@pytest.mark.parametrize("shape", SHAPES, ids=lambda s: s.name)
def test_cumulative_mass_is_the_integral_of_the_density(shape):
    edges = knots(shape)

    def rho(y):
        return density_at([y], CENTRES, WEIGHTS, WIDTHS, shape.breaks, shape.coefficients)[0]

    cumulative = cumulative_mass_at(TARGETS, CENTRES, WEIGHTS, WIDTHS, shape.breaks, shape.coefficients)
    # rho_h is one polynomial between consecutive knots: integrate it there, then add up from the first knot
    ends = np.union1d(edges, TARGETS)
    pieces = [integrate.quad(rho, lo, hi, epsabs=1e-16)[0] for lo, hi in zip(ends[:-1], ends[1:])]
    expected = dict(zip(ends, np.concatenate([[0.0], np.cumsum(pieces)])))
    for t, value in zip(TARGETS, cumulative):
        assert value == pytest.approx(expected[t], abs=1e-13)
    assert cumulative[0] == 0.0 and cumulative[-1] == pytest.approx(WEIGHTS.sum(), rel=1e-15)
    assert np.all(np.diff(cumulative) >= 0)
    particles = Particles(CENTRES, WEIGHTS, WIDTHS, shape)
    np.testing.assert_array_equal(particles.cumulative_mass(TARGETS), cumulative)
    assert particles.cumulative_mass(edges[-1])[0] == pytest.approx(particles.mass, rel=1e-15)


def test_cumulative_mass_checks_its_arrays():
    with pytest.raises(ValueError, match="weights has 3"):
        cumulative_mass_at(TARGETS, CENTRES, WEIGHTS[:3], WIDTHS, B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="widths must be positive"):
        cumulative_mass_at(TARGETS, CENTRES, WEIGHTS, -WIDTHS, B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="points contains NaN"):
        cumulative_mass_at([np.nan], CENTRES, WEIGHTS, WIDTHS, B3.breaks, B3.coefficients)
    with pytest.raises(ValueError, match="pieces must have shape"):
        cumulative_mass_at(TARGETS, CENTRES, WEIGHTS, WIDTHS, B3.breaks, HAT.coefficients)


MASS = 0.39
#: A symmetric density of mass 0.39: 0.195 on [-1, 1].
FLAT = InitialDensity("flat", lambda x: np.where(np.abs(np.asarray(x, float)) <= 1.0, MASS / 2, 0.0),
                      lambda x: MASS / 2 * np.clip(np.asarray(x, float) + 1.0, 0.0, 2.0), -1.0, 1.0)


@pytest.mark.parametrize("shape", ["b3", "hat"])
def test_one_ltp_step_moves_by_c_times_the_mass_on_the_right_minus_the_mass_on_the_left(shape):
    c, dt = 0.5, 0.01
    sim = simulate(FLAT, potential("newtonian"), 0.1, dt, dt, shape=shape, record_every=1)
    start = sim.at(0)
    assert start.mass == pytest.approx(MASS, rel=1e-14)
    velocity = c * (start.mass - 2 * start.cumulative_mass(start.centres))
    np.testing.assert_allclose(sim.velocities[0], velocity, rtol=0, atol=1e-15)
    np.testing.assert_allclose(sim.velocities[0], -sim.velocities[0][::-1], atol=1e-15)  # symmetric data
    np.testing.assert_allclose(sim.centres[1], start.centres + dt * velocity, atol=1e-15)
    # (2.31), (2.32): h_k^1 = h_k^0 exp(-dt (W'' * rho_h)(x_k)) with W'' * rho_h = 2c rho_h
    np.testing.assert_allclose(sim.widths[1], 0.1 * np.exp(-dt * 2 * c * start.density(start.centres)), rtol=1e-14)


def test_a_newtonian_term_combines_with_another_power():
    w = Potential("|x| - |x|^1.5/1.5", (1.0, -1.0), (1.0, 1.5))
    shape_arrays = (B3.breaks, B3.coefficients)
    combined = convolutions(TARGETS, CENTRES, WEIGHTS, WIDTHS, *w.as_arrays(), *shape_arrays)
    attractive = convolutions(TARGETS, CENTRES, WEIGHTS, WIDTHS, *newtonian(1.0).as_arrays(), *shape_arrays)
    repulsive = convolutions(TARGETS, CENTRES, WEIGHTS, WIDTHS, *potential("power", a=1.5).as_arrays(), *shape_arrays)
    for together, one, other in zip(combined, attractive, repulsive):
        np.testing.assert_allclose(together, one - other, rtol=1e-14, atol=1e-14)
    x = np.array([-2.0, -0.25, 0.04, 1.0])
    np.testing.assert_allclose(w(x), np.abs(x) - np.abs(x) ** 1.5 / 1.5)
    np.testing.assert_allclose(w.derivative(x), np.sign(x) * (1 - np.abs(x) ** 0.5))
    np.testing.assert_allclose(w.second_derivative(x), -0.5 / np.sqrt(np.abs(x)))  # the regular part
    sim = simulate("rho1", w, 0.1, 0.01, 0.05, record_every=1)
    assert np.all(np.isfinite(sim.centres)) and np.all(sim.widths > 0)


def test_newtonian_potential_values():
    w = potential("newtonian")
    assert w == Potential("|x|/2", (0.5,), (1.0,))
    x = np.array([-3.0, -1e-320, 0.0, 2.0])
    np.testing.assert_array_equal(w(x), np.abs(x) / 2)
    np.testing.assert_array_equal(w.derivative(x), np.sign(x) / 2)
    np.testing.assert_array_equal(w.second_derivative(x[x != 0]), 0.0)  # away from the Dirac mass, even at 1e-320
    with pytest.raises(ValueError, match="x must not contain 0: .* Dirac mass"):
        w.second_derivative(x)
    assert potential("power", a=1.0).exponents == (1.0,)


@pytest.mark.parametrize("make, message", [
    (lambda: Potential("sub-Newtonian", (1.0,), (0.5,)), r"exponents must all be at least 1 .*got \[0\.5\]"),
    (lambda: Potential("mixed", (1.0, 1.0), (1.0, 0.99)), r"at least 1 .*got \[1\.   0\.99\]"),
    (lambda: potential("power", a=0.9), r"at least 1 .*0\.9"),
    (lambda: potential("attractive_repulsive", a=2.0, b=0.0), r"b must be at least 1 .*got 0\.0"),
    (lambda: convolutions(TARGETS, CENTRES, WEIGHTS, WIDTHS, [1.0], [0.999], B3.breaks, B3.coefficients),
     r"at least 1 .*0\.999"),
    (lambda: potential("newtonian", a=1), "the newtonian potential takes no exponent a, got 1"),
    (lambda: potential("newtonian", b=1.0), "takes no exponent b"),
])
def test_exponents_below_one_and_exponents_of_the_newtonian_kind_are_refused(make, message):
    with pytest.raises(ValueError, match=message):
        make()


#: Density 1 on [-1/2, 1/2]: for W = |x|/2 the exact solution stays flat, rho(t) = 1/(1 - t), and collapses at t = 1.
BOX = InitialDensity("box", lambda x: np.where(np.abs(np.asarray(x, float)) <= 0.5, 1.0, 0.0),
                     lambda x: np.clip(np.asarray(x, float) + 0.5, 0.0, 1.0), -0.5, 0.5)


def test_ltp_is_refused_before_the_newtonian_blow_up_and_sp_is_not():
    w, dt = potential("newtonian"), 0.01
    sim = simulate(BOX, w, 0.05, dt, 0.5, record_every=50)
    assert sim.peak_densities()[-1] == pytest.approx(1 / (1 - 0.5), rel=0.05)
    with pytest.raises(ValueError, match=r"exceeds the stability bound .* the particles collapse") as refused:
        simulate(BOX, w, 0.05, dt, 1.5)
    assert 0.5 < float(re.search(r"\(t = ([0-9.]+)\)", str(refused.value)).group(1)) < 1.0
    sp = simulate(BOX, w, 0.05, dt, 1.5, method="sp", eps=0.1, record_every=50)
    assert np.all(np.isfinite(sp.centres)) and np.ptp(sp.centres[-1]) < 0.01  # aggregated, rho_h <= max phi / eps
    assert sp.peak_densities().max() <= B3(0.0) / 0.1
