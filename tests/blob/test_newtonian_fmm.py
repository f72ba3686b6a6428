"""The 2D Newtonian pair sums by the fast multipole method (blob/newtonian_fmm.py) against the direct sums."""

import math
import time

import numba
import numpy as np
import pytest

from particle_methods.blob import newtonian_fmm
from particle_methods.blob import pair_sums as pair_sums_module
from particle_methods.blob.checks import MAX_FMM_PARTICLES, MAX_PARTICLES
from particle_methods.blob.kernels import GAUSS_LOG_2D, LOG, kernel_1d, kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.pair_sums import FMM_MIN_PARTICLES, FMM_MIN_PARTICLES_RAW, pair_sums
from particle_methods.blob.solver import integrate_particles, setup_2d
from particle_methods.threads import numba_threads

PSI = mollifier(4, 2)
#: The agreement asked of the FMM: 1e-13 relative to the largest value of the direct sums.
TOLERANCE = 1e-13
TWO_THREADS = pytest.mark.skipif(numba.config.NUMBA_NUM_THREADS < 2, reason="needs 2 numba threads")


def assert_agree(got, expected, tolerance=TOLERANCE):
    """max |got - expected| <= tolerance * max |expected| (exact equality when expected is all zero)."""
    assert got.shape == expected.shape
    assert np.all(np.isfinite(got))
    gap, scale = np.abs(got - expected).max(), np.abs(expected).max()
    assert gap <= tolerance * scale, f"max gap {gap:.3g} exceeds {tolerance:g} x max value {scale:.3g}"


def both_paths(points, masses, kernel):
    arrays = kernel.arrays()
    return (pair_sums(points, masses, *arrays, newtonian_2d="fmm"),
            pair_sums(points, masses, *arrays, newtonian_2d="direct"))


def random_disk(rng, n):
    """n points uniform in the unit disk and unequal masses (a factor 10 apart) of total about 1."""
    radius, angle = np.sqrt(rng.random(n)), 2 * np.pi * rng.random(n)
    return np.column_stack([radius * np.cos(angle), radius * np.sin(angle)]), rng.uniform(0.2, 2.0, n) / n


def near_arguments(points, masses, kernel):
    """The arguments newtonian_sums gives the compiled near field (points sorted by cell key)."""
    _, coefficients, widths, _, _ = kernel.arrays()
    return newtonian_fmm.near_field(points, masses, coefficients, widths)[2]


@pytest.fixture(scope="module")
def disk_points():
    return random_disk(np.random.default_rng(20261122), 3000)


@pytest.fixture(scope="module")
def grid_blob_20():
    points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1 / 20, method="blob", q=0.9)
    return points, masses, kernel


# (a) The grids of Figure 5.

@pytest.mark.parametrize("method", ["blob", "particle"])
@pytest.mark.parametrize("n", [20, 40])
@pytest.mark.parametrize("data", ["regular", "disk"])
def test_fmm_matches_direct_sums_on_figure_5_grids(data, n, method):
    points, _, masses, kernel, _ = setup_2d(data, "newtonian", 1 / n, method=method, q=0.9)
    assert kernel.kinds == ((GAUSS_LOG_2D, GAUSS_LOG_2D) if method == "blob" else (LOG,))
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    assert_agree(velocity, velocity_direct)
    assert_agree(divergence, divergence_direct)
    if method == "particle":  # Delta K = 0 away from the origin: no divergence on either path
        assert not divergence.any() and not divergence_direct.any()


# (b) Random points in the unit disk, unequal masses.

@pytest.mark.parametrize("mollified", [True, False], ids=["delta=0.02", "raw"])
def test_fmm_matches_direct_sums_on_random_points(disk_points, mollified):
    points, masses = disk_points
    kernel = kernel_2d("newtonian", PSI, 0.02) if mollified else kernel_2d("newtonian")
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    assert_agree(velocity, velocity_direct)
    assert_agree(divergence, divergence_direct)
    assert np.abs(divergence_direct).max() > 1.0 if mollified else not divergence.any()


def test_fmm_matches_direct_sums_on_a_dense_cluster():
    """5,000 points of which 4,500 lie in one cell of the near-field list: a row of partners holds more than its
    buffer (4,096), so it is taken in chunks; the rest spread over [-1, 1]^2, corners included."""
    rng = np.random.default_rng(7)
    kernel = kernel_2d("newtonian", PSI, 0.02)
    side = newtonian_fmm.GAUSS_CUTOFF * max(kernel.parameters) / newtonian_fmm.CELL_SPLIT
    cluster, masses = random_disk(rng, 4500)
    spread = np.concatenate([[[-1.0, -1.0], [1.0, 1.0]], rng.uniform(-1, 1, (498, 2))])
    points = np.concatenate([-1 + 10.5 * side + 0.4 * side * cluster, spread])  # the middle of cell (10, 10)
    masses = np.concatenate([masses, rng.uniform(0.2, 2.0, 500) / 500])
    keys, _ = newtonian_fmm._cell_keys(points[:, 0], points[:, 1], side)
    assert np.bincount(keys).max() >= 4500 > newtonian_fmm._ROW_BUFFER
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    assert_agree(velocity, velocity_direct)
    assert_agree(divergence, divergence_direct)


def test_auto_switches_to_the_fmm_at_its_thresholds(grid_blob_20):
    points, masses, kernel = grid_blob_20
    arrays = kernel.arrays()
    assert points.shape[0] < FMM_MIN_PARTICLES
    small = pair_sums(points, masses, *arrays)
    for got, expected in zip(small, pair_sums(points, masses, *arrays, newtonian_2d="direct")):
        np.testing.assert_array_equal(got, expected)
    points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1 / 30, method="blob", q=0.9)
    assert FMM_MIN_PARTICLES <= points.shape[0] < FMM_MIN_PARTICLES_RAW
    large = pair_sums(points, masses, *kernel.arrays())
    for got, expected in zip(large, pair_sums(points, masses, *kernel.arrays(), newtonian_2d="fmm")):
        np.testing.assert_array_equal(got, expected)
    raw = kernel_2d("newtonian").arrays()  # the raw kernel switches later
    for got, expected in zip(pair_sums(points, masses, *raw), pair_sums(points, masses, *raw, newtonian_2d="direct")):
        np.testing.assert_array_equal(got, expected)


# (c) The near field does not depend on the number of threads.

@TWO_THREADS
@pytest.mark.parametrize("n", [1500, 3000], ids=["one-thread path", "FMM beside near field"])
def test_sums_are_bit_identical_on_one_and_two_threads(n):
    points, masses = random_disk(np.random.default_rng(n), n)
    _, coefficients, widths, _, _ = kernel_2d("newtonian", PSI, 0.02).arrays()
    results = []
    for threads in (1, 2):
        with numba_threads(threads):
            assert numba.get_num_threads() == threads
            results.append(newtonian_fmm.newtonian_sums(points, masses, coefficients, widths))
    for one, two in zip(*results):
        np.testing.assert_array_equal(one, two)


def test_near_field_is_bit_identical_on_one_two_and_three_threads(disk_points):
    """The near field's accumulators go to the threads as they come free (the FMM's thread joins once the FMM is
    done): on one, two or three threads, with or without a task beside, the same bits."""
    arguments = near_arguments(*disk_points, kernel_2d("newtonian", PSI, 0.02))
    results = [newtonian_fmm.near_sums(arguments, threads, beside)[0]
               for threads, beside in ((1, lambda: None), (2, lambda: time.sleep(0.01)), (3, lambda: None))]
    for other in results[1:]:
        for one, two in zip(results[0], other):
            assert np.abs(one).max() > 0
            np.testing.assert_array_equal(one, two)


# (d) Coincident points: the FMM cannot take them, the direct sums do.

@pytest.mark.parametrize("mollified", [True, False], ids=["blob", "particle"])
def test_coincident_points_fall_back_to_the_direct_sums(grid_blob_20, mollified):
    points, masses, kernel = grid_blob_20
    kernel = kernel if mollified else kernel_2d("newtonian")
    points, masses = np.concatenate([points, points[[5]]]), np.concatenate([masses, 0.5 * masses[[5]]])
    with np.errstate(all="ignore"), pytest.raises(ValueError, match="far field is not finite"):
        newtonian_fmm.far_field(points, masses)  # the FMM alone: NaN at the pair, refused
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    assert np.all(np.isfinite(velocity)) and np.all(np.isfinite(divergence))
    np.testing.assert_array_equal(velocity, velocity_direct)
    np.testing.assert_array_equal(divergence, divergence_direct)


@pytest.mark.parametrize("offset", [1e-6, 1e-8, "next float"])
def test_nearly_coincident_points_match_the_direct_sums(grid_blob_20, offset):
    """Point 600 of the h = 1/20 grid, (-0.05, 0.85), doubled at a distance 1e-6, 1e-8, or at the next float in x
    (7e-18). Without the fall-back to the direct sums for pairs closer than CLOSE_FRACTION delta, the FMM path was
    off by 3.3e-12 and 4.8e-3 of the largest velocity at the last two (the raw field of the pair and its Gaussian
    correction cancel); the direct sums are exact to rounding."""
    points, masses, kernel = grid_blob_20
    x, y = points[600]
    twin = [x + offset, y] if offset != "next float" else [np.nextafter(x, 1.0), y]
    points, masses = np.concatenate([points, [twin]]), np.concatenate([masses, masses[[600]]])
    assert not np.array_equal(points[-1], points[600])
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    assert_agree(divergence, divergence_direct)
    assert_agree(velocity, velocity_direct)


def test_coincident_points_above_the_threshold_take_the_direct_sums():
    points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1 / 40, method="blob", q=0.9)
    points, masses = np.concatenate([points, points[[100]]]), np.concatenate([masses, masses[[100]]])
    arrays = kernel.arrays()
    for got, expected in zip(pair_sums(points, masses, *arrays),
                             pair_sums(points, masses, *arrays, newtonian_2d="direct")):
        assert np.all(np.isfinite(got))
        np.testing.assert_array_equal(got, expected)


# (e) The comparison of (a) rejects plausible wrong sums.

def test_far_field_alone_is_rejected(grid_blob_20):
    """Dropping the near-field Gaussian correction leaves the raw field: off by far more than 1e-13."""
    points, masses, kernel = grid_blob_20
    _, coefficients, _, _, _ = kernel.arrays()
    velocity_direct, divergence_direct = pair_sums(points, masses, *kernel.arrays(), newtonian_2d="direct")
    raw_only = (-coefficients.sum() / (2 * math.pi)) * newtonian_fmm.far_field(points, masses)
    assert np.abs(raw_only - velocity_direct).max() > 1e-3 * np.abs(velocity_direct).max()
    with pytest.raises(AssertionError, match="exceeds"):
        assert_agree(raw_only, velocity_direct)
    with pytest.raises(AssertionError, match="exceeds"):
        assert_agree(np.zeros_like(divergence_direct), divergence_direct)  # the raw kernel's divergence


def test_divergence_without_self_term_is_rejected(grid_blob_20):
    points, masses, kernel = grid_blob_20
    _, coefficients, widths, _, _ = kernel.arrays()
    _, divergence = pair_sums(points, masses, *kernel.arrays(), newtonian_2d="fmm")
    self_laplacian = np.sum(coefficients / (math.pi * widths**2))  # Delta K_delta(0)
    _, divergence_direct = pair_sums(points, masses, *kernel.arrays(), newtonian_2d="direct")
    assert_agree(divergence, divergence_direct)
    with pytest.raises(AssertionError, match="exceeds"):
        assert_agree(divergence + masses * self_laplacian, divergence_direct)


def test_short_gaussian_cutoff_is_rejected(disk_points, monkeypatch):
    """A near field cut at 3 widths instead of 6.5 misses Gaussian terms of e^{-9} ~ 1e-4: rejected."""
    points, masses = disk_points
    kernel = kernel_2d("newtonian", PSI, 0.02)
    (velocity, divergence), (velocity_direct, divergence_direct) = both_paths(points, masses, kernel)
    monkeypatch.setattr(newtonian_fmm, "GAUSS_CUTOFF", 3.0)
    short_velocity, short_divergence = pair_sums(points, masses, *kernel.arrays(), newtonian_2d="fmm")
    with pytest.raises(AssertionError, match="exceeds"):
        assert_agree(short_velocity, velocity_direct)
    with pytest.raises(AssertionError, match="exceeds"):
        assert_agree(short_divergence, divergence_direct)
    assert_agree(velocity, velocity_direct)


# (f) Arguments and limits.

def test_unknown_method_is_refused(grid_blob_20):
    points, masses, kernel = grid_blob_20
    with pytest.raises(ValueError, match="newtonian_2d"):
        pair_sums(points, masses, *kernel.arrays(), newtonian_2d="bogus")
    with pytest.raises(ValueError, match="newtonian_2d"):
        integrate_particles(points, masses, masses, kernel, [0.0, 0.01], newtonian_2d="bogus")


def test_max_particles_of_each_kernel():
    assert kernel_2d("newtonian").max_particles == MAX_FMM_PARTICLES
    assert kernel_2d("newtonian", PSI, 0.02).max_particles == MAX_FMM_PARTICLES
    assert kernel_2d("quadratic", PSI, 0.3).max_particles == MAX_PARTICLES
    assert kernel_2d("quartic_log", PSI, 0.3).max_particles == MAX_PARTICLES  # two Gaussian log terms and a power
    assert kernel_1d("newtonian_attractive", mollifier(4, 1), 0.1).max_particles == MAX_PARTICLES
    assert kernel_1d("cubic").max_particles == MAX_PARTICLES
    assert kernel_1d("log_repulsive").max_particles == MAX_PARTICLES  # one LOG term, but in 1D
    assert MAX_FMM_PARTICLES > MAX_PARTICLES


@pytest.mark.parametrize(("kernel", "limit"), [(kernel_2d("newtonian"), MAX_FMM_PARTICLES),
                                               (kernel_2d("quadratic"), MAX_PARTICLES)], ids=["newtonian", "quadratic"])
def test_solve_refuses_more_particles_than_its_kernel_takes(kernel, limit):
    points = np.zeros((limit + 1, 2))
    with pytest.raises(ValueError, match=str(limit)):
        integrate_particles(points, np.ones(limit + 1), np.ones(limit + 1), kernel, [0.0, 1.0])


# (g) An ODE solve on either path.

def test_ode_solve_is_the_same_on_either_path():
    h = 1 / 40
    points, rho0, masses, kernel, with_density = setup_2d("regular", "newtonian", h, method="blob", q=0.9)
    runs = [integrate_particles(points, rho0, masses, kernel, [0.0, 0.005, 0.01], with_density=with_density, h=h,
                                newtonian_2d=method) for method in ("fmm", "direct")]
    fmm, direct = runs
    assert np.abs(fmm.positions[-1] - fmm.positions[0]).max() > 1e-3  # the particles moved
    np.testing.assert_allclose(fmm.positions, direct.positions, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fmm.densities, direct.densities, rtol=0, atol=1e-12 * np.abs(direct.densities).max())


def test_the_narrower_gaussian_taken_as_the_square_of_the_wider_matches_its_own_exponential(disk_points):
    """(4.2)'s widths 1 and sqrt(2): the narrower Gaussian's exponential is the wider's squared (one exponential a
    pair), within the 1.9e-14 relative that sqrt(2)^2 = 2 + 4.4e-16 allows at the cut-off; each Gaussian's own
    exponential (powers -1, the path of widths whose squares are no power-of-two multiples) gives the same sums."""
    arguments = near_arguments(*disk_points, kernel_2d("newtonian", PSI, 0.02))
    powers = arguments[8]
    np.testing.assert_array_equal(powers, [1, 0])
    np.testing.assert_array_equal(newtonian_fmm.squarings([1.0, 1 / 1.5**2]), [-1, 0])  # widths 1 and 1.5
    squared = newtonian_fmm.near_sums(arguments, 1)[0]
    own = newtonian_fmm.near_sums((*arguments[:8], np.full_like(powers, -1), arguments[9]), 1)[0]
    for one, two in zip(squared[:3], own[:3]):
        assert np.abs(one - two).max() <= 1e-14 * np.abs(two).max()
    assert squared[3] == own[3]  # the closest pair


def test_the_direct_sums_take_the_narrower_gaussian_as_the_square_of_the_wider(disk_points):
    """The direct path too: (4.2)'s constants carry flag 2 (one exponential a pair, the narrower Gaussian first
    whichever order the widths come in), and its rows match each Gaussian's own exponential (flag 1) to rounding,
    the complement 1 - e^2 taken as (1 - e)(1 + e) without cancellation, also for pairs far closer than a width."""
    coefficients, widths = kernel_2d("newtonian", PSI, 0.02).arrays()[1:3]
    squared = pair_sums_module.newtonian_2d_constants(coefficients, widths)
    assert squared[0] == 2.0 and squared[3] > squared[4]
    assert pair_sums_module.newtonian_2d_constants(coefficients[::-1], widths[::-1]) == squared
    assert pair_sums_module.newtonian_2d_constants(coefficients, np.array([1.0, 1.5]))[0] == 1.0
    own = (1.0, *squared[1:])
    x, y = np.ascontiguousarray(disk_points[0][:, 0]), np.ascontiguousarray(disk_points[0][:, 1])
    x[1], y[1] = x[0] + 1e-9, y[0]   # a pair 2e-8 widths apart: the complement is about 2.5e-15
    rows = {}
    for name, constants in (("squared", squared), ("own", own)):
        buffers = [np.empty(x.size - 1) for _ in range(3)]
        pair_sums_module.newtonian_2d_forces(x[0], y[0], x, y, 1, x.size, constants, *buffers)
        rows[name] = buffers
    for one, two in zip(rows["squared"], rows["own"]):
        np.testing.assert_allclose(one, two, rtol=1e-14, atol=1e-15 * np.abs(two).max())
