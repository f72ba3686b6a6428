"""Time the SPD positions at one time against the alternatives a user would reach for.

    python benchmarks/bench_spd.py [--max-exponent 7] [--repeats 5]

On the same inputs (sorted normal positions, normal velocities: many collisions)
it times, for n = 10^3 .. 10^max:
  - numba:  particle_methods.sticky.spd_positions (input checks included);
  - scipy:  scipy.optimize.isotonic_regression(x + t v), the same L2 projection
            onto D_n computed by scipy's compiled pool-adjacent-violators;
  - python: the paper's pseudo-code on cumulative sums in plain Python/NumPy.
It prints best-of-repeats wall times, the ratios to numba and the fitted scaling
exponent of each method (time ~ n^slope) over n >= 10^5; then, at the largest n, the
compiled hull alone in nanoseconds per particle for three kinds of data, against a
memory-bandwidth estimate of the same pass: 48 bytes per particle (read x and v, write and
read back the segment stack of sums and counts, write the positions) at the bandwidth of a
NumPy copy measured on the spot.
"""

import argparse

import numpy as np
from scipy.optimize import isotonic_regression
from timing import best_time, print_cpu

from particle_methods.convergence import fit_order
from particle_methods.sticky import spd_positions
from particle_methods.sticky.hull_reference import spd_positions_python


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--max-exponent", type=int, default=7)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--python-max-exponent", type=int, default=7)
    args = parser.parse_args()
    print_cpu()
    rng = np.random.default_rng(0)
    t = 1.0
    spd_positions(np.zeros(2), np.zeros(2), t)  # compile (or load the cache) outside the timings
    sizes, timings = [], {"numba": [], "scipy": [], "python": []}
    print(f"{'n':>10} {'numba [s]':>11} {'scipy [s]':>11} {'python [s]':>11} {'scipy/numba':>12} "
          f"{'python/numba':>13} {'max |diff|':>11}")
    for exponent in range(3, args.max_exponent + 1):
        n = 10**exponent
        x = np.sort(rng.normal(size=n))
        v = rng.normal(size=n)
        numba_time, ours = best_time(lambda x=x, v=v: spd_positions(x, v, t), args.repeats)
        scipy_time, theirs = best_time(lambda x=x, v=v: isotonic_regression(x + t * v).x, args.repeats)
        difference = np.abs(ours - theirs).max()
        python_time = np.nan
        if exponent <= args.python_max_exponent:
            python_time, plain = best_time(lambda x=x, v=v: spd_positions_python(x, v, t), 1 if exponent >= 6 else 3)
            difference = max(difference, np.abs(ours - plain).max())
        sizes.append(n)
        for key, value in zip(timings, (numba_time, scipy_time, python_time)):
            timings[key].append(value)
        print(f"{n:>10} {numba_time:11.4g} {scipy_time:11.4g} {python_time:11.4g} {scipy_time / numba_time:12.2f} "
              f"{python_time / numba_time:13.1f} {difference:11.2e}")
    sizes = np.array(sizes, dtype=float)
    large = sizes >= 1e5
    if large.sum() >= 2:
        print("scaling exponent (time ~ n^slope, n >= 1e5):")
        for key, values in timings.items():
            values = np.array(values)
            usable = large & np.isfinite(values)
            if usable.sum() >= 2:
                print(f"  {key:7} {fit_order(sizes[usable], values[usable]):.3f}")



def hull_against_bandwidth(n, repeats):
    """ns per particle of the compiled hull against the memory-bandwidth estimate of its pass."""
    from particle_methods.sticky.spd import hull_positions_kernel

    rng = np.random.default_rng(1)
    x = np.sort(rng.normal(size=n))
    out = np.empty(n)
    copy = np.empty(n)
    seconds, _ = best_time(lambda: np.copyto(copy, x), repeats)
    bandwidth = 16 * n / seconds
    print(f"\nhull at n = {n:.0e}: copy bandwidth {bandwidth / 1e9:.1f} GB/s, estimate "
          f"{48 / bandwidth * 1e9:.2f} ns per particle (48 bytes)")
    cases = (("random velocities (many collisions)", rng.normal(size=n)),
             ("sorted velocities (no collision)", np.sort(rng.normal(size=n))),
             ("one cluster (every particle collides)", -100 * np.sort(rng.normal(size=n))))
    for name, v in cases:
        seconds, _ = best_time(lambda v=v: hull_positions_kernel(x, v, 1.0, out), repeats)
        print(f"  {name:40} {seconds / n * 1e9:6.2f} ns per particle")


if __name__ == "__main__":
    main()
    hull_against_bandwidth(10**7, 5)
