"""The 2D Newtonian pair sums by the fast multipole method against the direct sums, side by side.

    python benchmarks/bench_fmm.py [--largest 320]

The direct path is the implementation of d064b23 (tiled, vectorised, O(N^2); still the package's path
below FMM_MIN_PARTICLES, selected here with newtonian_2d="direct"); the FMM path is pyfmmlib's Laplace
FMM for the raw field plus the Gaussian terms of (4.2) over near pairs (particle_methods.blob.newtonian_fmm).
Both compute v_i = -sum_j m_j grad K_delta(X_i - X_j) and div_i = -sum_j m_j Delta K_delta(X_i - X_j) for
Figure 5's kernel and regular data, delta = h^0.9, on the current numba threads. Printed:

1. time per evaluation on Figure 5's grids, 1/h = 40 ... --largest, the FMM's fitted exponent in N, and
   the largest difference from the direct sums relative to the largest value (direct up to 1/h = 160);
2. the same difference on random points (uniform in the unit disk, delta = 0.02), raw and mollified;
3. the crossover in N, on one thread and on all: FMM_MIN_PARTICLES is read off it;
4. the ODE solve of Figure 5's blob run at h = 1/80 to t = 0.02 (17 right-hand sides), direct against
   FMM, with the largest difference of the positions.
"""

import argparse
import time

import numpy as np
from timing import best_time, print_cpu

from particle_methods.blob.kernels import kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.pair_sums import FMM_MIN_PARTICLES, pair_sums
from particle_methods.blob.solver import integrate_particles, setup_2d


def sums(points, masses, kernel, method, repeats=3):
    arrays = kernel.arrays()
    return best_time(lambda: pair_sums(points, masses, *arrays, newtonian_2d=method), repeats)


def difference(a, b):
    """Largest difference of velocities and divergences, relative to the largest value of each."""
    return max(np.abs(a[0] - b[0]).max() / np.abs(b[0]).max(),
               np.abs(a[1] - b[1]).max() / max(np.abs(b[1]).max(), 1e-300))


def grids(largest):
    print(f"{'1/h':>5} {'N':>7} {'direct [s]':>10} {'FMM [s]':>9} {'speed-up':>8} {'difference':>10}")
    sizes, times = [], []
    for inverse_h in (40, 80, 160, 320):
        if inverse_h > largest:
            break
        points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1.0 / inverse_h, method="blob", q=0.9)
        fmm_time, fmm = sums(points, masses, kernel, "fmm")
        line = f"{inverse_h:5d} {points.shape[0]:7d} "
        if inverse_h <= 160:
            direct_time, direct = sums(points, masses, kernel, "direct", repeats=1 if inverse_h > 80 else 3)
            line += f"{direct_time:10.3f} {fmm_time:9.4f} {direct_time / fmm_time:8.1f} {difference(fmm, direct):10.2e}"
        else:
            line += f"{'':10} {fmm_time:9.4f}"
        print(line)
        sizes.append(points.shape[0])
        times.append(fmm_time)
    if len(sizes) > 1:
        print(f"FMM time ~ N^{np.polyfit(np.log(sizes), np.log(times), 1)[0]:.2f} (least squares over the grids)")


def random_points():
    rng = np.random.default_rng(1)
    n = 8000
    radius, angle = np.sqrt(rng.uniform(0, 1, n)), rng.uniform(0, 2 * np.pi, n)
    points = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=1)
    masses = rng.uniform(0.5, 1.5, n) / n
    for kernel in (kernel_2d("newtonian"), kernel_2d("newtonian", mollifier(4, 2), 0.02)):
        _, fmm = sums(points, masses, kernel, "fmm", repeats=1)
        _, direct = sums(points, masses, kernel, "direct", repeats=1)
        print(f"random points, N = {n}, {kernel.name}: difference {difference(fmm, direct):.2e}")


def crossover():
    import numba

    threads = numba.get_num_threads()
    print(f"crossover (FMM_MIN_PARTICLES = {FMM_MIN_PARTICLES}): time per evaluation [ms], direct / FMM")
    for count in sorted({1, threads}):
        numba.set_num_threads(count)
        line = []
        for inverse_h in (10, 20, 25, 30, 35, 40):
            points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1.0 / inverse_h, method="blob", q=0.9)
            direct_time, _ = sums(points, masses, kernel, "direct", repeats=5)
            fmm_time, _ = sums(points, masses, kernel, "fmm", repeats=5)
            line.append(f"N = {points.shape[0]}: {1e3 * direct_time:.1f} / {1e3 * fmm_time:.1f}")
        print(f"  {count} thread(s): " + ", ".join(line))
    numba.set_num_threads(threads)


def solve():
    points, rho0, masses, kernel, _ = setup_2d("regular", "newtonian", 1.0 / 80, method="blob", q=0.9)
    results = {}
    for method in ("direct", "fmm"):
        start = time.perf_counter()
        run = integrate_particles(points, rho0, masses, kernel, [0.0, 0.02], rtol=1e-10, atol=1e-12,
                                  newtonian_2d=method)
        results[method] = (time.perf_counter() - start, run.positions[-1], run.evaluations)
    (direct_time, direct, evaluations), (fmm_time, fmm, _) = results["direct"], results["fmm"]
    print(f"2D solve, h = 1/80 ({points.shape[0]} particles), t = 0.02, {evaluations} right-hand sides: "
          f"direct {direct_time:.2f} s, FMM {fmm_time:.2f} s, speed-up {direct_time / fmm_time:.2f}, "
          f"positions differ by {np.abs(fmm - direct).max():.2e}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--largest", type=int, default=320, help="finest 1/h of the grid timings")
    largest = parser.parse_args().largest
    print_cpu()
    grids(largest)
    random_points()
    crossover()
    solve()


if __name__ == "__main__":
    main()
