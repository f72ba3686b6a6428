"""Pair interactions per second of the compiled blob pair sums against NumPy broadcasting.

    python benchmarks/bench_blob_pairs.py

Both compute v_i = -sum_j m_j grad K_delta(X_i - X_j) and div_i = -sum_j m_j Delta K_delta(X_i - X_j)
for the m = 4 mollified cubic kernel (two Gaussian terms, erf and exp per pair) on N
random particles in [-1, 1], with delta = 0.05, and for the kernels of Figure 4 on its finest
grids (the 1D sums now take a far field from sorted moments and a near field over windows of
6.5 mollifier widths: particle_methods.blob.sums_1d); then the 2D pair sums of Figure 5's finest grid
(closed-form log kernel), the raw log kernel and a tabulated power-law kernel, each against the
previous implementation (particle_methods.blob.pair_sums.generic_sums_kernel), with the fraction of the arithmetic peak
reached by the vectorised path.

"pairs/s" counts the N^2 ordered pairs the sums cover, whatever the algorithm: the previous loop
evaluates each unordered pair once (grad K is odd, Delta K even), NumPy all N^2, the 1D sums only
the pairs closer than 6.5 widths.
"""

import numpy as np
from scipy import special
from timing import best_time, print_cpu

from particle_methods.blob.kernels import kernel_1d
from particle_methods.blob.mollifiers import mollifier
from particle_methods.blob.pair_sums import pair_sums


def numpy_pair_sums(x, m, weights, widths):
    """The same sums by broadcasting: an (N, N) array per intermediate."""
    z = x[:, None] - x[None, :]
    r = np.abs(z)
    velocity = np.zeros(x.size)
    divergence = np.zeros(x.size)
    for weight, s in zip(weights, widths):
        erf, e = special.erf(r / s), np.exp(-((r / s) ** 2))
        grad = (z * z + 0.5 * s * s) * erf * np.sign(z) + z * s * e / np.sqrt(np.pi)
        laplacian = 2 * (r * erf + s * e / np.sqrt(np.pi))
        velocity -= weight * grad @ m
        divergence -= weight * laplacian @ m
    return velocity, divergence


def main():
    """1D: the issue's input (cubic kernel, m = 4, delta = 0.05, random particles, the same as the
    benchmark of the last build), Figure 4's finest runs (delta = h^0.9 on a grid) and the m = 6 reference
    of its log reading (K = -log|x|/(2 pi), Dawson's integral per Gaussian near, its series far), each against
    the previous implementation (particle_methods.blob.pair_sums.generic_sums_kernel) and NumPy broadcasting."""
    from particle_methods.blob.initial import grid_1d
    from particle_methods.blob.pair_sums import generic_sums_kernel as reference_pair_sums

    print_cpu()
    rng = np.random.default_rng(0)
    cases = []
    for n in (1000, 10000):
        cases.append(("cubic", 4, 0.05, np.sort(rng.uniform(-1, 1, n))))
    for name, order, inverse_h in (("newtonian_repulsive", 4, 1280), ("cubic", 6, 1280),
                                   ("newtonian_attractive", 4, 5000), ("log_repulsive", 6, 640)):
        h = 1.0 / inverse_h
        x = grid_1d(h)[:, 0]
        cases.append((name, order, h**0.9, x))
    print(f"{'1D kernel':>36} {'N':>6} {'before [s]':>10} {'now [s]':>9} {'numpy [s]':>9} {'vs before':>9} "
          f"{'vs numpy':>8} {'pairs/s':>9}")
    for name, order, delta, x in cases:
        psi = mollifier(order, 1)
        kernel = kernel_1d(name, psi, delta)
        arrays = kernel.arrays()
        n = x.size
        m = np.full(n, 2.0 / n)
        now, _ = best_time(lambda x=x, m=m, arrays=arrays: pair_sums(x[:, None], m, *arrays))
        before, _ = best_time(lambda x=x, m=m, arrays=arrays: reference_pair_sums(x[:, None], m, *arrays), repeats=2)
        ours, theirs = pair_sums(x[:, None], m, *arrays), reference_pair_sums(x[:, None], m, *arrays)
        for a, b in zip(ours, theirs):
            # the old loop accumulates its own rounding: 5e-14 at N = 2561, more at N = 10^4
            assert np.abs(a - b).max() <= 1e-12 * np.abs(b).max()
        numpy_time = float("nan")
        if name == "cubic" and n <= 10000:
            widths = psi.scaled_widths(delta)
            numpy_time, _ = best_time(lambda x=x, m=m, w=widths, p=psi: numpy_pair_sums(x, m, p.weights, w),
                                      repeats=1)
            v, d = numpy_pair_sums(x, m, psi.weights, psi.scaled_widths(delta))
            assert np.allclose(ours[0][:, 0], v, atol=1e-10) and np.allclose(ours[1], d, atol=1e-10)
        print(f"{kernel.name:>36} {n:>6} {before:10.4f} {now:9.4f} {numpy_time:9.3f} {before / now:9.1f} "
              f"{numpy_time / now:8.1f} {n * n / now:9.2e}")


#: Floating-point operations per unordered pair of the vectorised 2D Newtonian path (m = 4, (4.2)),
#: counting an FMA as two: differences and r^2 (5); per Gaussian, the reduction z = k ln 2 - r and
#: the branch-free clamp (about 11), Horner's rule of degree 14 (28) and the two results (5), so 44,
#: once: the narrower Gaussian's exponential and complement are the wider's squared and times 1 + e (3);
#: the gradient and Laplacian (10); the partners' and the row's shares (12). (Two exponentials, 44 twice,
#: until the direct path took one.)
NEWTONIAN_FLOPS = 5 + 44 + 3 + 10 + 12
#: Peak double-precision rate assumed for the machine: 2 cores, each with two 256-bit FMA pipes
#: (AVX-512 instructions are executed as two halves on AMD Zen 4), 16 flops per cycle, at the
#: nominal clock read from /proc/cpuinfo (boost clocks would lower the fraction).
FLOPS_PER_CYCLE_PER_CORE = 16


def clock_hz():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("cpu MHz"):
                return float(line.split(":")[1]) * 1e6
    except OSError:
        pass
    return float("nan")


def two_dimensions():
    """2D pair sums, side by side with the previous implementation (the generic loop):
    the mollified Newtonian kernel of Figure 5 (vectorised path), the raw one (particle method), the
    tabulated power-law and Morse kernels of Figures 7 and 8 (tiled path, scalar table lookups) and the
    raw power-law and Morse kernels of their particle runs (tiled path)."""
    import numba

    from particle_methods.blob.initial import data_2d, grid_2d
    from particle_methods.blob.kernels import kernel_2d
    from particle_methods.blob.pair_sums import generic_sums_kernel as reference_pair_sums

    cores = numba.get_num_threads()
    peak = cores * FLOPS_PER_CYCLE_PER_CORE * clock_hz()
    print(f"\n{'2D kernel':>34} {'N':>6} {'before [s]':>10} {'now [s]':>9} {'speed-up':>8} {'pairs/s':>10} "
          f"{'of peak':>8}")
    cases = (("newtonian", 1 / 40, (1 / 40) ** 0.9, True), ("newtonian", 1 / 80, (1 / 80) ** 0.9, True),
             ("newtonian", 1 / 40, None, False), ("quartic_power", 1 / 40, 0.32, False),
             ("morse_2", 1 / 40, 0.32, False), ("quartic_power", 1 / 40, None, False), ("morse_1", 1 / 40, None, False))
    for name, h, delta, vectorised in cases:
        kernel = kernel_2d(name, mollifier(4, 2), delta) if delta else kernel_2d(name)
        x = grid_2d(h, data_2d("regular"))
        m = np.full(len(x), 1.0 / len(x))
        arrays = kernel.arrays()
        before, _ = best_time(lambda x=x, m=m, arrays=arrays: reference_pair_sums(x, m, *arrays), repeats=2)
        # The vectorised direct path (its flops are counted), not the FMM the package takes from 2,500 particles.
        method = "direct" if vectorised else "auto"
        now, _ = best_time(lambda x=x, m=m, arrays=arrays, method=method: pair_sums(x, m, *arrays, newtonian_2d=method))
        ours, theirs = pair_sums(x, m, *arrays, newtonian_2d=method), reference_pair_sums(x, m, *arrays)
        for a, b in zip(ours, theirs):
            assert np.abs(a - b).max() <= 1e-13 * max(np.abs(b).max(), 1e-300)
        fraction = (len(x) ** 2 / 2 * NEWTONIAN_FLOPS / now / peak) if vectorised else float("nan")
        print(f"{kernel.name:>34} {len(x):>6} {before:10.3f} {now:9.3f} {before / now:8.2f} "
              f"{len(x) ** 2 / now:10.3e} {fraction:8.1%}")
    print(f"peak assumed: {cores} cores x {FLOPS_PER_CYCLE_PER_CORE} flops/cycle x {clock_hz() / 1e9:.2f} GHz = "
          f"{peak / 1e9:.1f} GFLOP/s; {NEWTONIAN_FLOPS} flops per unordered pair on the vectorised path")


if __name__ == "__main__":
    main()
    two_dimensions()
