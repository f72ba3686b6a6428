"""Throughput of the O(N^2) LTP convolution kernel against the arithmetic it must do.

    python benchmarks/bench_ltp_convolution.py

For particles spread like those of Figures 5-8 (N on [-1, 1], widths h = 2/N) it
times one evaluation of W' * rho_h and W'' * rho_h at every centre, reports pair
interactions per second, counts the kernel evaluations the piecewise rule needs
per pair (one power for a particle beyond EXPANSION piece lengths, which takes the
binomial series; else Gauss-Legendre nodes on far pieces, two antiderivative ends on
near ones) and compares the time per evaluation with a compiled loop doing nothing but
the same power function: the ratio says how close the kernel is to its floor.
"""

import numba
import numpy as np
from timing import best_time, print_cpu

from particle_methods.ltp import B3, potential
from particle_methods.ltp.kernels import EXPANSION, GAUSS_TIERS, NEAR, convolutions


@numba.njit(parallel=True, cache=True)
def power_floor(values, exponent):
    """The one power each kernel evaluation needs: |z|^(a-2), a square root for a = 1.5."""
    total = np.zeros(values.size)
    for i in numba.prange(values.size):
        total[i] = 1.0 / np.sqrt(values[i]) if exponent == -0.5 else values[i] ** exponent
    return total.sum()


def evaluations_per_pair(centres, widths):
    """Kernel evaluations per (target, particle) pair for the B3 pieces, as the kernel chooses them."""
    d = centres[:, None] - centres[None, :]
    count = np.zeros(d.shape)
    for lo, hi in zip(B3.breaks[:-1], B3.breaks[1:]):
        length = widths[None, :] * (hi - lo)
        distance = np.maximum(d - widths[None, :] * hi, -(d - widths[None, :] * lo))
        nodes = np.full(d.shape, 2.0)  # near piece: the antiderivative at both ends
        for threshold, points in reversed(GAUSS_TIERS):
            nodes = np.where(distance > threshold * length, points, nodes)
        count += np.where(distance > NEAR * length, nodes, 2.0)
    support = np.maximum(d - widths[None, :] * B3.breaks[-1], widths[None, :] * B3.breaks[0] - d)
    count = np.where(support > EXPANSION * widths[None, :] * np.diff(B3.breaks).max(), 1.0, count)
    return float(count.mean())


def main():
    print_cpu()
    for a in (1.5, 1.1):
        report(a)


def report(a):
    w = potential("power", a=a)
    coefficients, exponents = w.as_arrays()
    samples = np.random.default_rng(0).uniform(1e-3, 2.0, 10**7)
    floor = best_time(lambda: power_floor(samples, a - 2.0))[0] / samples.size
    print(f"W = {w.name}: the power |z|^{a - 2:g} alone costs {floor * 1e9:.2f} ns per call (all threads)")
    print(f"{'N':>6} {'time [ms]':>10} {'pairs/s':>12} {'evals/pair':>11} {'ns/eval':>8} {'vs floor':>9}")
    for n in (200, 400, 800, 1600, 3200):
        centres = np.linspace(-1, 1, n)
        widths = np.full(n, 2.0 / n)
        weights = np.full(n, 1.0 / n)
        elapsed, _ = best_time(lambda c=centres, h=widths, m=weights: convolutions(
            c, c, m, h, coefficients, exponents, B3.breaks, B3.coefficients))
        per_pair = evaluations_per_pair(centres, widths)
        per_eval = elapsed / (n * n * per_pair)
        print(f"{n:>6} {elapsed * 1e3:10.3f} {n * n / elapsed:12.3e} {per_pair:11.2f} {per_eval * 1e9:8.2f} "
              f"{per_eval / floor:9.2f}")


if __name__ == "__main__":
    main()
