"""Pair interactions per second of the compiled blob pair sums against NumPy broadcasting.

    python benchmarks/bench_blob_pairs.py

Both compute v_i = -sum_j m_j grad K_delta(X_i - X_j) and div_i = -sum_j m_j Delta K_delta(X_i - X_j)
for the m = 4 mollified cubic kernel (two Gaussian terms, erf and exp per pair) on N
random particles in [-1, 1], with delta = 0.05; then the 2D pair sums of Figure 5's finest grid
(closed-form log kernel) and of a tabulated power-law kernel.

"pairs/s" counts the N^2 ordered pairs the sums cover. The compiled loop evaluates each
unordered pair once (grad K is odd, Delta K even), NumPy evaluates all N^2.
"""

import numpy as np
from scipy import special
from timing import best_time

from particle_methods.blob.kernels import kernel_1d, pair_sums
from particle_methods.blob.mollifiers import mollifier


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
    psi, delta = mollifier(4, 1), 0.05
    kernel = kernel_1d("cubic", psi, delta)
    arrays = kernel.arrays()
    widths = psi.scaled_widths(delta)
    rng = np.random.default_rng(0)
    print(f"{'N':>7} {'numba [s]':>10} {'numpy [s]':>10} {'numba pairs/s':>14} {'numpy pairs/s':>14} {'speed-up':>9}")
    for n in (1000, 10000):
        x = np.sort(rng.uniform(-1, 1, n))
        m = np.full(n, 2.0 / n)
        ours, _ = best_time(lambda x=x, m=m: pair_sums(x[:, None], m, *arrays))
        theirs, _ = best_time(lambda x=x, m=m: numpy_pair_sums(x, m, psi.weights, widths), repeats=1)
        v1, d1 = pair_sums(x[:, None], m, *arrays)
        v2, d2 = numpy_pair_sums(x, m, psi.weights, widths)
        assert np.allclose(v1[:, 0], v2, atol=1e-10) and np.allclose(d1, d2, atol=1e-10)
        print(f"{n:>7} {ours:10.4f} {theirs:10.4f} {n * n / ours:14.3e} {n * n / theirs:14.3e} {theirs / ours:9.1f}")


def two_dimensions():
    """Pair interactions per second in 2D: the closed-form log kernel and a tabulated kernel."""
    from particle_methods.blob.initial import data_2d, grid_2d
    from particle_methods.blob.kernels import kernel_2d

    print(f"{'2D kernel':>32} {'N':>6} {'time [s]':>9} {'pairs/s':>11}")
    for name, h, delta in (("newtonian", 1 / 40, (1 / 40) ** 0.9), ("quartic_power", 1 / 40, 0.32)):
        kernel = kernel_2d(name, mollifier(4, 2), delta)
        x = grid_2d(h, data_2d("regular"))
        m = np.full(len(x), 1.0 / len(x))
        arrays = kernel.arrays()
        elapsed, _ = best_time(lambda x=x, m=m, arrays=arrays: pair_sums(x, m, *arrays))
        print(f"{kernel.name:>32} {len(x):>6} {elapsed:9.3f} {len(x) ** 2 / elapsed:11.3e}")


if __name__ == "__main__":
    main()
    two_dimensions()
