"""The 2D Newtonian pair sums by the fast multipole method against the direct sums, side by side.

    python benchmarks/bench_fmm.py [--largest 320]
    python benchmarks/bench_fmm.py --million

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

With --million, only: the near field's CPU time per examined pair on one thread on Figure 5's grids at
1/h = 160, 320 and 560 (newtonian_fmm.MAX_NEAR_PAIRS is read off it), then one evaluation of the sums on
Figure 5's grid at 1/h = 560 (985,089 points) on the current threads, timed twice (wall and CPU time, the
load average beside each), its peak memory, and its largest difference from the direct sums on 2,000
random targets (each summed over all N sources with the direct path's formula, relative to the largest
value over the targets).
"""

import argparse
import os
import resource
import time

import numba
import numpy as np
from timing import best_time, print_cpu

from particle_methods.blob import newtonian_fmm
from particle_methods.blob.kernels import kernel_2d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.pair_sums import FMM_MIN_PARTICLES, newtonian_2d_constants, newtonian_2d_forces, pair_sums
from particle_methods.blob.solver import integrate_particles, setup_2d
from particle_methods.blob.tile_sums import row_share


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


def load():
    return f"load average {os.getloadavg()[0]:.2f}"


def near_field_per_pair():
    """CPU time of the near field alone per examined pair, on one thread (this thread's CPU time)."""
    for inverse_h in (160, 320, 560):
        points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1.0 / inverse_h, method="blob", q=0.9)
        _, coefficients, widths, _, _ = kernel.arrays()
        _, pairs, arguments = newtonian_fmm.near_field(points, masses, coefficients, widths)
        newtonian_fmm.near_sums(arguments, 1)  # compiled (or loaded from the cache) and warm
        start = time.thread_time()
        newtonian_fmm.near_sums(arguments, 1)
        cpu = time.thread_time() - start
        print(f"near field, 1/h = {inverse_h}, N = {points.shape[0]}: {pairs:.3g} pairs in {cpu:.2f} s of CPU, "
              f"{1e9 * cpu / pairs:.1f} ns per pair ({load()})", flush=True)


#: Partners per tile of the direct sums over all sources for one target (as the direct path's tiles).
_TILE = 256


@numba.njit(parallel=True)
def direct_targets(targets, x, y, masses, constants):
    """v_i and div_i of the targets i over all N sources j (i included: grad K(0) X = 0 and Delta K(0) is the
    self term), with the direct path's kernel formula (pair_sums.newtonian_2d_forces), tile by tile."""
    velocity = np.zeros((targets.size, 2))
    divergence = np.zeros(targets.size)
    for t in numba.prange(targets.size):
        i = targets[t]
        wx, wy, lap = np.empty(_TILE), np.empty(_TILE), np.empty(_TILE)
        sx = sy = sd = 0.0
        for start in range(0, x.size, _TILE):
            stop = min(start + _TILE, x.size)
            newtonian_2d_forces(x[i], y[i], x, y, start, stop, constants, wx, wy, lap)
            tx, ty, td = row_share(start, stop, masses, wx, wy, lap)
            sx += tx
            sy += ty
            sd += td
        velocity[t, 0], velocity[t, 1], divergence[t] = -sx, -sy, -sd
    return velocity, divergence


def million(inverse_h=560, targets=2000):
    """One evaluation on Figure 5's grid at 1/h = 560, timed twice, against the direct sums on a subsample."""
    near_field_per_pair()
    small, _, small_masses, small_kernel, _ = setup_2d("regular", "newtonian", 1.0 / 40, method="blob", q=0.9)
    pair_sums(small, small_masses, *small_kernel.arrays(), newtonian_2d="fmm")  # compiled, pools started
    points, _, masses, kernel, _ = setup_2d("regular", "newtonian", 1.0 / inverse_h, method="blob", q=0.9)
    arrays = kernel.arrays()
    threads = numba.get_num_threads()
    for _ in range(2):
        wall, cpu = time.perf_counter(), time.process_time()
        velocity, divergence = pair_sums(points, masses, *arrays, newtonian_2d="fmm")
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        print(f"1/h = {inverse_h}, N = {points.shape[0]}, {threads} thread(s): one evaluation {wall:.2f} s "
              f"({cpu:.2f} s of CPU; {load()})", flush=True)
    print(f"peak memory of the process: {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20:.2f} GiB")
    _, coefficients, widths, _, _ = arrays
    # the formula with each Gaussian's own exponential (flag 1), independent of the squaring both paths use
    constants = (1.0, *newtonian_2d_constants(coefficients, widths)[1:])
    chosen = np.random.default_rng(inverse_h).choice(points.shape[0], targets, replace=False)
    start = time.perf_counter()
    direct = direct_targets(chosen, np.ascontiguousarray(points[:, 0]), np.ascontiguousarray(points[:, 1]),
                            masses, constants)
    seconds = time.perf_counter() - start
    print(f"direct sums on {targets} random targets from all {points.shape[0]} sources ({seconds:.1f} s): largest "
          f"difference {difference((velocity[chosen], divergence[chosen]), direct):.2e} of the largest value")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--largest", type=int, default=320, help="finest 1/h of the grid timings")
    parser.add_argument("--million", action="store_true",
                        help="only the near field's time per pair and one evaluation at 1/h = 560 (985,089 points)")
    arguments = parser.parse_args()
    print_cpu()
    if arguments.million:
        million()
        return
    grids(arguments.largest)
    random_points()
    crossover()
    solve()


if __name__ == "__main__":
    main()
