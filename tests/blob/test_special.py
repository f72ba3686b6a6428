"""Dawson's integral and E1 against high-precision values; the 1D log kernel of Figure 4's row label
against a numerical principal-value convolution; the radial tables built once and read-only."""

import mpmath
import numpy as np
import pytest
from scipy import integrate, special

from particle_methods.blob.kernels import kernel_1d, kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.radial import mollified_laplacian
from particle_methods.blob.solver import run_1d
from particle_methods.blob.special import dawson, dawson_and_slope, exp1

mpmath.mp.dps = 40
# Every range the kernels use: below, across and above the Taylor nodes (step 1/8 up to 10), the
# midpoints between nodes, and the asymptotic branch.
Z = np.concatenate([np.geomspace(1e-10, 1e4, 300), np.arange(1, 161) / 16 - 1 / 32, [9.999, 10.0, 10.001]])


def exact_dawson(z):
    z = mpmath.mpf(float(z))
    f = mpmath.sqrt(mpmath.pi) / 2 * mpmath.exp(-z * z) * mpmath.erfi(z)
    return float(f), float(1 - 2 * z * f)


def test_dawson_and_its_slope_to_full_precision():
    ours = np.array([dawson_and_slope(z) for z in Z])
    exact = np.array([exact_dawson(z) for z in Z])
    assert np.abs(ours[:, 0] / exact[:, 0] - 1).max() < 2e-15
    assert np.abs(ours[:, 1] / exact[:, 1] - 1).max() < 5e-13


def test_dawson_is_odd_and_its_slope_even():
    for z in (0.3, 2.7, 11.0):
        assert dawson(-z) == -dawson(z)
        assert dawson_and_slope(-z)[1] == dawson_and_slope(z)[1]
    assert dawson(0.0) == 0.0 and dawson_and_slope(0.0)[1] == 1.0


def test_dawson_of_nan_is_nan_and_of_infinity_its_limit():
    assert np.isnan(dawson(np.nan)) and np.isnan(dawson_and_slope(np.nan)[1])
    assert dawson(np.inf) == 0.0 and dawson(-np.inf) == 0.0


def test_vectorised_exponential_refuses_negative_and_non_finite_input():
    from particle_methods.blob.vector_exp import exp_minus_and_complement_array

    for bad in ([-1.0], [np.nan], [np.inf]):
        with pytest.raises(ValueError, match="z"):
            exp_minus_and_complement_array(bad)


def test_exp1_matches_scipy():
    x = np.geomspace(1e-8, 700, 500)
    assert np.abs(np.array([exp1(v) for v in x]) / special.exp1(x) - 1).max() < 2e-14


@pytest.mark.parametrize("order", [4, 6])
def test_mollified_log_kernel_is_the_principal_value_convolution(order):
    """K = -log|x|/(2 pi): grad K_delta = K' * psi_delta with K' = -1/(2 pi x), a principal value."""
    psi, delta = mollifier(order, 1), 0.1
    kernel = kernel_1d("log_repulsive", psi, delta)
    x = np.array([0.02, 0.1, 0.3, 1.5])
    _, g, _ = kernel.profile(x)
    for xi, gi in zip(x, g):
        # int psi(y) / (y - x) dy as a Cauchy principal value, times 1/(2 pi)
        pv = integrate.quad(lambda y: float(psi(np.array(y), delta)), -2.0, 2.0, weight="cauchy", wvar=xi,
                            epsabs=1e-14, epsrel=1e-12, limit=500)[0]
        assert xi * gi == pytest.approx(pv / (2 * np.pi), rel=1e-9)


def test_mollified_log_laplacian_is_the_derivative_of_the_gradient():
    kernel = kernel_1d("log_repulsive", mollifier(4, 1), 0.1)
    x, step = np.array([0.0, 0.05, 0.2, 0.9]), 1e-5
    _, _, lap = kernel.profile(x)
    _, g_plus, _ = kernel.profile(x + step)
    _, g_minus, _ = kernel.profile(np.abs(x - step))
    derivative = ((x + step) * g_plus - (x - step) * g_minus) / (2 * step)
    np.testing.assert_allclose(lap, derivative, rtol=1e-7)


def test_raw_log_kernel_and_its_missing_potential():
    k, g, lap = kernel_1d("log_repulsive").profile(np.array([0.5]))
    assert k[0] == pytest.approx(-np.log(0.5) / (2 * np.pi))
    assert g[0] * 0.5 == pytest.approx(-1 / (2 * np.pi * 0.5))     # K'(x) = -1/(2 pi x)
    assert lap[0] == pytest.approx(1 / (2 * np.pi * 0.25))        # K''(x) = 1/(2 pi x^2)
    run = run_1d("smooth10", "log_repulsive", 0.25, [0.0, 0.01])
    assert not run.kernel.has_potential
    with pytest.raises(ValueError, match="energy"):
        run.energies()


def test_radial_tables_are_built_once_and_read_only():
    psi = mollifier(4, 2)
    first = kernel_2d("morse_1", psi, 0.3, table_points=201)
    second = kernel_2d("morse_2", psi, 0.3, table_points=201)
    assert all(a is b for a, b in zip(first.tables, second.tables))   # the same two exponentials
    with pytest.raises(ValueError):
        first.tables[0].gradient[0] = 1.0


def test_vectorised_radial_quadrature_matches_one_quadrature_per_radius():
    """L_delta(r) for |x|^1.5/1.5 (Laplacian 1.5 r^-0.5, singular at 0) by scipy.quad per radius."""
    psi, delta = mollifier(4, 2), 0.32
    r = np.array([0.0, 0.1, 0.7, 2.0])
    ours = mollified_laplacian(lambda rho: 1.5 * rho**-0.5, psi, delta, r)
    for ri, value in zip(r, ours):
        total = 0.0
        for weight, s in zip(psi.weights, psi.scaled_widths(delta)):
            def integrand(rho, s=s, ri=ri):
                return 1.5 * rho**0.5 * (2 / s**2) * np.exp(-((ri - rho) / s) ** 2) * special.i0e(2 * ri * rho / s**2)
            total += weight * integrate.quad(integrand, 0.0, ri + 9 * s, limit=200, epsabs=1e-13, epsrel=1e-12)[0]
        assert value == pytest.approx(total, rel=1e-10, abs=1e-12)


def test_vectorised_exponential_and_its_complement_to_one_ulp():
    from particle_methods.blob.vector_exp import exp_minus_and_complement_array

    z = np.concatenate([np.geomspace(1e-300, 1e-3, 2001), np.linspace(0, 50, 200001),
                        np.random.default_rng(0).uniform(0, 745, 100000)])
    e, complement = exp_minus_and_complement_array(z)
    exact = np.exp(-z)
    normal = exact > 2.3e-308
    assert np.max(np.abs(e - exact)[normal] / exact[normal]) < 4e-16
    assert np.max(np.abs(e - exact)[~normal]) <= 5e-324          # subnormal results to the last bit
    positive = z > 0
    exact_complement = -np.expm1(-z[positive])
    assert np.max(np.abs(complement[positive] - exact_complement) / exact_complement) < 4e-16


def test_vectorised_exponential_at_the_ends_of_its_range():
    from particle_methods.blob.vector_exp import exp_minus_and_complement_array

    e, complement = exp_minus_and_complement_array(np.array([0.0, 745.2, 800.0, 1e4, 1e12]))
    assert e[0] == 1.0 and complement[0] == 0.0
    assert np.all(e[1:] == 0.0) and np.all(complement[1:] == 1.0)


def test_vectorised_erfc_to_a_few_ulps():
    """erfc(z) and e^{-z^2} in plain arithmetic against mpmath at 40 digits over the range the 1D pair
    sums use, [0, 16]; beyond it, negligible values, never NaN."""
    from particle_methods.blob.vector_erfc import erfc_and_gauss_array

    mpmath.mp.dps = 40
    z = np.concatenate([[0.0, 1e-300, 1e-12], np.linspace(0, 16, 1601),
                        np.random.default_rng(1).uniform(0, 16, 1000)])
    tail, gauss = erfc_and_gauss_array(z)
    exact_tail = np.array([float(mpmath.erfc(mpmath.mpf(v))) for v in z])
    exact_gauss = np.array([float(mpmath.exp(-mpmath.mpf(v) ** 2)) for v in z])
    assert np.max(np.abs(tail / exact_tail - 1)) < 3e-15
    assert np.max(np.abs(gauss / exact_gauss - 1)) < 4e-16
    far_tail, far_gauss = erfc_and_gauss_array(np.array([16.5, 100.0, 2.0**25]))
    assert np.all(np.isfinite(far_tail)) and np.all(far_tail < 1e-112) and np.all(far_gauss < 1e-110)


def test_vectorised_functions_refuse_input_outside_their_range():
    from particle_methods.blob.vector_erfc import erfc_and_gauss_array
    from particle_methods.blob.vector_exp import Z_LIMIT, exp_minus_and_complement_array

    for bad in ([-1.0], [np.nan], [np.inf], [2.0 * Z_LIMIT]):
        with pytest.raises(ValueError, match="z"):
            exp_minus_and_complement_array(bad)
        with pytest.raises(ValueError, match="z"):
            erfc_and_gauss_array(bad)
    e, complement = exp_minus_and_complement_array(np.array([Z_LIMIT]))
    assert e[0] == 0.0 and complement[0] == 1.0
