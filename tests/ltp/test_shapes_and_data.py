"""Shapes (2.12), (2.13), bi-orthogonal kernel, initial data (6.1)-(6.3) and weights (2.14), (2.16)."""

import math

import numpy as np
import pytest
from scipy import integrate

from particle_methods.ltp import B3, HAT, density_named, grid_particles, hat_biorthogonal_kernel, potential, shape_named


@pytest.mark.parametrize("shape", [HAT, B3], ids=lambda s: s.name)
def test_unit_mass_and_partition_of_unity(shape):
    assert integrate.quad(lambda s: float(shape(s)), -3, 3, points=list(shape.breaks))[0] == pytest.approx(1.0)
    s = np.linspace(-0.5, 0.5, 101)
    total = sum(shape(s - k) for k in range(-3, 4))
    np.testing.assert_allclose(total, 1.0, atol=1e-14)
    expected = {"hat": 1 / 6, "b3": 1 / 3}[shape.name]
    assert shape.second_moment == pytest.approx(expected)
    assert shape(shape.radius + 1e-9) == 0.0 and shape(-shape.radius - 1e-9) == 0.0


def test_b3_matches_2_13():
    s = np.array([0.0, 0.5, 1.0, 1.5, -1.5])
    np.testing.assert_allclose(B3(s), [4 / 6, (4 - 1.5 + 0.375) / 6, 1 / 6, 0.125 / 6, 0.125 / 6])


def test_hat_kernel_is_biorthogonal_2_17():
    for shift in (-2, -1, 0, 1, 2):
        value = integrate.quad(lambda s, shift=shift: float(HAT(s) * hat_biorthogonal_kernel(s - shift)), -3, 3,
                               points=[-1, -0.5, 0, 0.5, 1, shift - 0.5, shift + 0.5])[0]
        assert value == pytest.approx(1.0 if shift == 0 else 0.0, abs=1e-12)


@pytest.mark.parametrize("name", ["rho1", "rho2", "rho3"])
def test_initial_densities_have_unit_mass_and_consistent_cdf(name):
    density = density_named(name)
    assert float(density.cdf(density.upper) - density.cdf(density.lower)) == pytest.approx(1.0, abs=1e-13)
    x = np.linspace(-0.9, 0.9, 7)
    step = 1e-5
    derivative = (density.cdf(x + step) - density.cdf(x - step)) / (2 * step)
    np.testing.assert_allclose(derivative, density.pdf(x), rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("weights, shape", [("cell", B3), ("cell", HAT), ("biorthogonal", HAT)])
def test_weights_sum_to_the_mass(weights, shape):
    centres, omega = grid_particles(density_named("rho1"), 0.05, shape, weights)
    assert omega.sum() == pytest.approx(1.0, abs=1e-13)
    np.testing.assert_allclose(np.diff(centres), 0.05)
    np.testing.assert_allclose(centres / 0.05, np.round(centres / 0.05), atol=1e-9)


@pytest.mark.parametrize("weights, shape", [("cell", B3), ("biorthogonal", HAT)])
def test_shifted_grid_has_centres_k_plus_half_h_and_the_same_mass(weights, shape):
    centres, omega = grid_particles(density_named("rho2"), 0.05, shape, weights, offset=0.5)
    assert omega.sum() == pytest.approx(1.0, abs=1e-13)
    np.testing.assert_allclose(centres / 0.05 - 0.5, np.round(centres / 0.05 - 0.5), atol=1e-9)
    assert np.abs(centres).min() == pytest.approx(0.025)  # no particle at x = 0


def test_shifted_cell_weights_are_the_integrals_over_the_shifted_cells():
    density = density_named("rho2")
    centres, omega = grid_particles(density, 0.05, B3, offset=0.5)
    np.testing.assert_allclose(omega, density.cdf(centres + 0.025) - density.cdf(centres - 0.025), atol=1e-15)


@pytest.mark.parametrize("offset", [-0.1, 1.0, math.nan, "half", True])
def test_offset_outside_zero_one_is_refused(offset):
    with pytest.raises((ValueError, TypeError)):
        grid_particles(density_named("rho2"), 0.05, B3, offset=offset)


def test_biorthogonal_weights_make_the_error_orthogonal_to_the_kernels():
    """(2.16)-(2.17): <rho^0 - rho_h^0, phi~_k> = 0, the identity behind Proposition 2."""
    density = density_named("rho1")
    h = 0.1
    centres, omega = grid_particles(density, h, HAT, "biorthogonal")

    def rho_h(x):
        return float(sum(w * HAT((x - c) / h) / h for c, w in zip(centres, omega)))

    for k in (3, 8, 12):
        kernel = lambda x, k=k: float(hat_biorthogonal_kernel((x - centres[k]) / h))  # noqa: E731
        knots = list(centres[k] + h * np.array([-1, -0.5, 0, 0.5, 1]))
        lo, hi = knots[0], knots[-1]
        approx = integrate.quad(lambda x, kernel=kernel: rho_h(x) * kernel(x), lo, hi, points=knots[1:-1])[0]
        exact = integrate.quad(lambda x, kernel=kernel: float(density.pdf(x)) * kernel(x), lo, hi,
                               points=knots[1:-1])[0]
        assert approx == pytest.approx(exact, abs=1e-10)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: shape_named("b5"), "unknown shape"),
        (lambda: density_named("rho9"), "unknown initial density"),
        (lambda: grid_particles(density_named("rho2"), 0.1, B3, "biorthogonal"), "hat shape only"),
        (lambda: grid_particles(density_named("rho2"), 0.1, B3, "pointwise"), "unknown weights"),
        (lambda: grid_particles(density_named("rho2"), -0.1, B3), "h must be positive"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_a_density_whose_cdf_or_pdf_gives_nan_is_refused_at_its_construction():
    """Census (issue 46): InitialDensity took any callables, and a NaN CDF reached the weights; it now tries its
    cdf at [lower, upper] and its pdf at the middle (a pdf that refuses, as an atomic measure's, passes)."""
    from particle_methods.ltp.initial import InitialDensity, atomic

    def nan(x):
        return np.full(np.shape(x), np.nan)

    rho2 = density_named("rho2")
    with pytest.raises(ValueError, match="cdf must give finite non-decreasing values"):
        InitialDensity("nan cdf", rho2.pdf, nan, -1.0, 1.0)
    with pytest.raises(ValueError, match="pdf must give finite values"):
        InitialDensity("nan pdf", nan, rho2.cdf, -1.0, 1.0)
    assert atomic([0.0, 0.5], [0.5, 0.5]).lower < 0.0
    with pytest.raises(ValueError, match="positions must leave room for a margin"):
        atomic([1e300, 1e300], [0.5, 0.5])


def test_shape_and_potential_messages_name_their_parameter():
    """Census (issue 46): 'shape ... must have unit mass' and 'potential must be one of' named no parameter."""
    from particle_methods.ltp import Shape

    with pytest.raises(ValueError, match="the coefficients of shape 'double' on its breaks must give unit mass"):
        Shape("double", HAT.breaks, 2 * HAT.coefficients)
    with pytest.raises(TypeError, match="kind of potential must be one of"):
        potential(None)
