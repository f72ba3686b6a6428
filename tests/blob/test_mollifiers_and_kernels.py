"""Mollifiers (4.1), (4.2) and the closed-form mollified kernels against numerical convolution."""

import numpy as np
import pytest
from scipy import integrate

from particle_methods.blob import pair_sums as sums
from particle_methods.blob.kernels import POWER, Kernel, kernel_1d, kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.pair_sums import pair_energy, pair_sums


@pytest.mark.parametrize("order", [4, 6])
def test_1d_moment_conditions(order):
    psi = mollifier(order, 1)
    moments = [integrate.quad(lambda x, k=k: x**k * float(psi(abs(x))), -np.inf, np.inf)[0] for k in range(order + 1)]
    assert moments[0] == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(moments[1:order], 0.0, atol=1e-12)
    assert abs(moments[order]) > 0.1  # exactly order m, not more


def test_2d_moment_conditions():
    psi = mollifier(4, 2)
    radial = [integrate.quad(lambda r, k=k: 2 * np.pi * r ** (k + 1) * float(psi(r)), 0, np.inf)[0] for k in (0, 2, 4)]
    assert radial[0] == pytest.approx(1.0, abs=1e-12)
    assert radial[1] == pytest.approx(0.0, abs=1e-12)  # |x|^2 moment: the only even one below m = 4
    assert abs(radial[2]) > 0.1


def test_scaled_mollifier_keeps_unit_mass():
    psi = mollifier(6, 1)
    for delta in (0.01, 0.3):
        mass = integrate.quad(lambda x, delta=delta: float(psi(abs(x), delta)), -np.inf, np.inf)[0]
        assert mass == pytest.approx(1.0)


@pytest.mark.parametrize("name", ["newtonian_attractive", "newtonian_repulsive", "cubic"])
@pytest.mark.parametrize("order", [4, 6])
def test_closed_forms_match_numerical_convolution(name, order):
    psi, delta = mollifier(order, 1), 0.2
    smooth, raw = kernel_1d(name, psi, delta), kernel_1d(name)

    def convolve(column, x, odd):
        def integrand(y):
            z = x - y
            value = float(raw.profile(np.array(abs(z)))[column])
            return (value * z if odd else value) * float(psi(abs(y), delta))
        return integrate.quad(integrand, -10, 10, points=[x], limit=400, epsabs=1e-14)[0]

    for x in (0.0, 0.03, 0.25, 1.1):
        k, g, lap = (float(v) for v in smooth.profile(np.array(x)))
        assert k == pytest.approx(convolve(0, x, False), abs=1e-12)
        if x > 0:
            assert g * x == pytest.approx(convolve(1, x, True), abs=1e-12)
        if name == "cubic":
            assert lap == pytest.approx(convolve(2, x, False), abs=1e-12)
        else:  # Delta K_delta = +-psi_delta for the Newtonian kernels
            sign = 1 if name == "newtonian_attractive" else -1
            assert lap == pytest.approx(sign * float(psi(x, delta)), rel=1e-12)


def test_pair_sums_match_numpy_broadcasting(rng):
    for dimension in (1, 2):
        x = rng.normal(size=(40, dimension))
        m = rng.uniform(0.1, 1, 40)
        kernel = Kernel("test", dimension, (POWER, POWER), (1.0, -1.0), (4.0, 2.5))
        velocity, divergence = pair_sums(x, m, *kernel.arrays())
        diff = x[:, None, :] - x[None, :, :]
        r = np.linalg.norm(diff, axis=-1)
        g = r**2 - r**0.5
        lap = (4 + dimension - 2) * r**2 - (2.5 + dimension - 2) * r**0.5
        np.testing.assert_allclose(velocity, -(m[None, :, None] * g[..., None] * diff).sum(axis=1), atol=1e-12)
        np.testing.assert_allclose(divergence, -(m[None, :] * lap).sum(axis=1), atol=1e-12)
        energy = 0.5 * (m[:, None] * m[None, :] * (r**4 / 4 - r**2.5 / 2.5)).sum()
        assert pair_energy(x, m, *kernel.arrays()) == pytest.approx(energy, rel=1e-12)


def on_one_thread(function, *args):
    """function(*args) with numba limited to one thread."""
    import numba

    threads = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        return function(*args)
    finally:
        numba.set_num_threads(threads)


def assert_matches_generic_on_any_thread_count(x, m, arrays):
    """The tiled sums agree with the generic loop to 1e-13 and are bit-identical on one thread."""
    fast = pair_sums(x, m, *arrays)
    generic = generic_sums(x, m, arrays)
    for ours, reference in zip(fast, generic):
        assert np.all(np.isfinite(ours))
        assert np.abs(ours - reference).max() <= 1e-13 * np.abs(reference).max()
    one_thread = on_one_thread(pair_sums, x, m, *arrays)
    assert all(np.array_equal(a, b) for a, b in zip(one_thread, fast))


def generic_sums(x, m, arrays):
    """The generic loop of every kernel, which the vectorised paths must reproduce."""
    return sums.generic_sums_kernel(np.ascontiguousarray(x), m, *arrays)


def test_raw_newtonian_2d_fast_path_matches_the_generic_sums(rng):
    """The particle method's kernel log|x|/(2 pi) (grad K(0) := 0) on the vectorised path."""
    from particle_methods.blob import kernels

    for n in (40, sums.PARALLEL_MIN_PARTICLES + 5):
        x = rng.normal(scale=0.5, size=(n, 2))
        x[1] = x[0]
        m = rng.uniform(0.1, 1, n) / n
        arrays = kernels.kernel_2d("newtonian").arrays()
        fast = pair_sums(x, m, *arrays)
        generic = generic_sums(x, m, arrays)
        assert np.abs(fast[0] - generic[0]).max() <= 1e-13 * np.abs(generic[0]).max()
        assert np.all(fast[1] == 0.0) and np.all(generic[1] == 0.0)


def test_newtonian_2d_fast_path_matches_the_generic_sums(rng):
    """The vectorised path of the mollified 2D Newtonian kernel against the generic loop (closed forms
    with the library exp, erf-free), including two coincident particles; and it is thread-independent."""
    from particle_methods.blob import kernels
    from particle_methods.blob.mollifiers import mollifier

    n = sums.PARALLEL_MIN_PARTICLES + 300
    x = rng.normal(scale=0.5, size=(n, 2))
    x[1] = x[0]
    m = rng.uniform(0.1, 1, n) / n
    arrays = kernels.kernel_2d("newtonian", mollifier(4, 2), 0.05).arrays()
    assert_matches_generic_on_any_thread_count(x, m, arrays)
    few = x[:40]   # below PARALLEL_MIN_PARTICLES: one thread
    small = pair_sums(few, m[:40], *arrays)
    small_generic = generic_sums(few, m[:40], arrays)
    for ours, reference in zip(small, small_generic):
        assert np.abs(ours - reference).max() <= 1e-13 * np.abs(reference).max()


@pytest.mark.parametrize("name", ["newtonian_attractive", "newtonian_repulsive", "cubic"])
@pytest.mark.parametrize("order", [None, 4, 6])
def test_sorted_1d_sums_match_the_generic_sums(rng, name, order):
    """The 1D path (far field by sorted moments, near field by windows, erfc in plain arithmetic)
    against the generic loop, with coincident particles, partners exactly one window apart and
    unsorted input; on one thread and several, bit for bit."""
    from particle_methods.blob import sums_1d

    delta = 0.03
    kernel = kernel_1d(name) if order is None else kernel_1d(name, mollifier(order, 1), delta)
    arrays = kernel.arrays()
    assert sums_1d.supported(arrays[0], arrays[2])
    for n in (9, sums.PARALLEL_MIN_PARTICLES + 77):
        x = rng.uniform(-1, 1, n)
        x[1] = x[2] = x[0]
        if order is not None:
            x[3] = x[4] + sums_1d.CUTOFF * arrays[2].max()
        m = rng.uniform(0.1, 1, n) / n
        fast = pair_sums(x[:, None], m, *arrays)
        generic = generic_sums(x[:, None], m, arrays)
        for ours, reference in zip(fast, generic):
            assert np.all(np.isfinite(ours))
            assert np.abs(ours - reference).max() <= 2e-14 * max(np.abs(reference).max(), 1e-300)
        one_thread = on_one_thread(pair_sums, x[:, None], m, *arrays)
        assert all(np.array_equal(a, b) for a, b in zip(one_thread, fast))


def test_sorted_1d_sums_see_a_wrong_far_field():
    """The check above can fail: dropping the polynomial part of a mollified kernel (a plausible slip in
    the far-field moments) is far outside its tolerance."""
    from particle_methods.blob import sums_1d

    x = np.linspace(-1, 1, 200)
    m = np.full(200, 0.01)
    arrays = kernel_1d("cubic", mollifier(4, 1), 0.03).arrays()
    v, _ = sums_1d.sorted_sums(x, m, arrays[0], arrays[1], arrays[2], (0.0, 0.0, 0.0),
                               sums_1d.CUTOFF * arrays[2].max())
    generic = generic_sums(x[:, None], m, arrays)[0][:, 0]
    assert np.abs(v - generic).max() > 1e-3


@pytest.mark.parametrize("order", [None, 4, 6])
def test_1d_log_sums_match_the_generic_sums(rng, order):
    """The 1D log kernel's path (far field by Dawson's asymptotic series, near field by the closed forms)
    against the generic loop, with coincident particles, partners exactly one window apart and unsorted
    input; on one thread and several, bit for bit."""
    from particle_methods.blob import sums_1d
    from particle_methods.blob.special import DAWSON_ASYMPTOTIC

    kernel = kernel_1d("log_repulsive") if order is None else kernel_1d("log_repulsive", mollifier(order, 1), 0.01)
    arrays = kernel.arrays()
    assert sums_1d.log_supported(arrays[0]) and not sums_1d.supported(arrays[0], arrays[2])
    for n in (9, sums.PARALLEL_MIN_PARTICLES + 77):
        x = rng.uniform(-1, 1, n)
        x[1] = x[2] = x[0]
        x[3] = x[4] + DAWSON_ASYMPTOTIC * arrays[2].max()
        m = rng.uniform(0.1, 1, n) / n
        fast = pair_sums(x[:, None], m, *arrays)
        generic = generic_sums(x[:, None], m, arrays)
        for ours, reference in zip(fast, generic):
            assert np.all(np.isfinite(ours))
            assert np.abs(ours - reference).max() <= 2e-14 * np.abs(reference).max()
        one_thread = on_one_thread(pair_sums, x[:, None], m, *arrays)
        assert all(np.array_equal(a, b) for a, b in zip(one_thread, fast))


def test_1d_log_sums_see_a_truncated_series():
    """The check above can fail: the far field with the raw kernel's term alone (the series cut after
    its first term, a plausible slip) misses the mollifier's s^2/r^3 tail by far more than its tolerance."""
    from particle_methods.blob import sums_1d

    x = np.linspace(-1, 1, 200)
    m = np.full(200, 0.01)
    arrays = kernel_1d("log_repulsive", mollifier(4, 1), 0.03).arrays()
    series_g, series_l = sums_1d.log_series(arrays[0], arrays[1], arrays[2])
    assert series_g.size == sums_1d.SERIES_TERMS == 15
    series_g[1:] = series_l[1:] = 0.0
    _, divergence = sums_1d.sorted_log_sums(x, m, arrays, series_g, series_l, 10.0 * arrays[2].max())
    generic = generic_sums(x[:, None], m, arrays)[1]
    assert np.abs(divergence - generic).max() > 1e-8 * np.abs(generic).max()


@pytest.mark.parametrize("name", ["quadratic", "cubic", "quartic_log", "quartic_power", "septic_power", "morse_1"])
def test_tiled_2d_path_matches_the_generic_sums(rng, name):
    """The mollified kernels of section 4.4 (even powers, Gaussian log terms, radial tables) on the
    tiled path against the generic loop, with coincident particles and partners beyond the table;
    bit-identical on one thread and several."""

    kernel = kernel_2d(name, mollifier(4, 2), 0.2, table_radius=2.0, table_points=801)
    arrays = kernel.arrays()
    assert sums.tiled_2d_supported(arrays[0])
    n = sums.PARALLEL_MIN_PARTICLES + 41
    x = rng.normal(scale=0.8, size=(n, 2))
    x[1] = x[0]
    x[2] = (3.0, 0.0)   # beyond the table's radius 2 from most partners
    m = rng.uniform(0.1, 1, n) / n
    assert_matches_generic_on_any_thread_count(x, m, arrays)


@pytest.mark.parametrize("name", ["cubic", "quartic_log", "quartic_power", "septic_power", "morse_1", "morse_2"])
def test_tiled_2d_path_matches_the_generic_sums_for_raw_kernels(rng, name):
    """The particle method's raw kernels of section 4.4 (powers, log and exponential terms) on the tiled
    path against the generic loop, with coincident particles ((0, 0) at r = 0); bit-identical on one
    thread and several."""
    arrays = kernel_2d(name).arrays()
    assert sums.tiled_2d_supported(arrays[0])
    n = sums.PARALLEL_MIN_PARTICLES + 41
    x = rng.normal(scale=0.8, size=(n, 2))
    x[1] = x[0]
    m = rng.uniform(0.1, 1, n) / n
    assert_matches_generic_on_any_thread_count(x, m, arrays)


def test_tiled_2d_path_sees_a_wrong_raw_exponent(rng):
    """The check above can fail: r^(a-1) in place of r^(a-2) for the raw |x|^1.5 term (a plausible slip)
    is far outside its tolerance."""
    x = rng.normal(scale=0.8, size=(60, 2))
    m = np.full(60, 1 / 60)
    right = Kernel("test", 2, (POWER,), (1.0,), (1.5,)).arrays()
    wrong = Kernel("test", 2, (POWER,), (1.0,), (2.5,)).arrays()
    fast = pair_sums(x, m, *wrong)[0]
    assert np.abs(fast - generic_sums(x, m, right)[0]).max() > 1e-3 * np.abs(fast).max()


def test_2d_newtonian_sums_refuse_positions_beyond_the_exponential_range():
    from particle_methods.blob.mollifiers import mollifier as make

    arrays = kernel_2d("newtonian", make(4, 2), 1e-9).arrays()
    with pytest.raises(ValueError, match="widths"):
        pair_sums(np.array([[0.0, 0.0], [1e9, 0.0]]), np.ones(2), *arrays)


def test_pair_sums_do_not_depend_on_the_number_of_threads(rng):
    """Each pair is evaluated once and the partial sums are added in a fixed order: bit-identical
    results on one thread or several (the claims table must not depend on the machine's cores)."""

    n = sums.PARALLEL_MIN_PARTICLES + 13
    x = rng.normal(size=(n, 3))   # 3D: the generic loop's own path
    m = rng.uniform(0.1, 1, n)
    arrays = Kernel("test", 3, (POWER, POWER), (1.0, -1.0), (4.0, 1.5)).arrays()
    one_thread = on_one_thread(pair_sums, x, m, *arrays)
    parallel = pair_sums(x, m, *arrays)
    assert all(np.array_equal(a, b) for a, b in zip(one_thread, parallel))
    # Below PARALLEL_MIN_PARTICLES pair_sums itself runs on one thread: the same sums, bit for bit.
    serial = on_one_thread(generic_sums, x, m, arrays)
    assert all(np.array_equal(a, b) for a, b in zip(serial, parallel))


def test_pair_sums_refuse_non_finite_input_and_mismatched_masses():
    arrays = Kernel("test", 2, (POWER,), (1.0,), (2.0,)).arrays()
    x = np.zeros((3, 2))
    with pytest.raises(ValueError, match="finite"):
        pair_sums(np.array([[0.0, 0.0], [np.nan, 1.0], [1.0, 1.0]]), np.ones(3), *arrays)
    with pytest.raises(ValueError, match="finite"):
        pair_sums(x, np.array([1.0, np.inf, 1.0]), *arrays)
    with pytest.raises(ValueError, match="masses"):
        pair_sums(x, np.ones(4), *arrays)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: mollifier(8, 1), "no mollifier of order"),
        (lambda: kernel_1d("morse"), "unknown kernel"),
        (lambda: kernel_1d("cubic", mollifier(4, 1), 0.0), "delta must be positive"),
        (lambda: kernel_1d("cubic", mollifier(4, 2), 0.1), "1D mollifier"),
        (lambda: mollifier(4, 1).scaled_widths(-1.0), "delta must be positive"),
    ],
)
def test_bad_input(make, message):
    with pytest.raises(ValueError, match=message):
        make()
