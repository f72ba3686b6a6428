"""Threads: two processes sharing the cores, and the sizes from which a kernel goes parallel.

    python benchmarks/bench_threads.py

1. The LTP workload of issue 25 (three runs of rho1 with W = x^2/2, h = 0.04, 0.02, 0.01, dt = 1e-4, to
   t = 0.5), in a fresh process with the default threads, timed after a warm-up run: alone, then two
   such processes started together. Each should take at most 1.3 times as long as one alone.
2. The compiled kernels on one thread and on all (numba's threads), against the problem size: the LTP
   convolutions (W = |x|^3/3, pair sums), the direct 2D blob sums (mollified Newtonian kernel) and the
   FMM's near field. The PARALLEL_MIN_* constant of each family is read off where two threads start to
   pay (they are printed beside the table).
"""

import subprocess
import sys
import textwrap
import time

import numba
import numpy as np
from timing import best_time

WORKLOAD = textwrap.dedent("""
    import time
    from particle_methods.ltp import potential, simulate
    def work():
        for h in (0.04, 0.02, 0.01):
            simulate("rho1", potential("quadratic"), h=h, dt=1e-4, t_final=0.5)
    work()                      # compiled code loaded or built, caches warm
    start = time.perf_counter()
    work()
    print(time.perf_counter() - start)
""")


def side_by_side():
    def start():
        return subprocess.Popen([sys.executable, "-c", WORKLOAD], stdout=subprocess.PIPE, text=True)

    alone = float(start().communicate()[0])
    pair = [start(), start()]
    together = [float(process.communicate()[0]) for process in pair]
    print(f"LTP workload: alone {alone:.3f} s; two processes side by side {together[0]:.3f} s and "
          f"{together[1]:.3f} s: {max(together) / alone:.2f} times one alone (at most 1.3 wanted)")


def scaling(name, module, constant, make, sizes):
    """Times of one kernel family on one thread and on all, with its threshold set to 1 meanwhile (so that
    the kernel really runs on the threads asked for)."""
    threads, threshold = numba.get_num_threads(), getattr(module, constant)
    setattr(module, constant, 1)
    cells = []
    try:
        for size in sizes:
            call = make(size)
            times = []
            for count in (1, threads):
                numba.set_num_threads(count)
                times.append(best_time(call, 5)[0])
            numba.set_num_threads(threads)
            cells.append(f"{size}: {1e3 * times[0]:.3g}/{1e3 * times[1]:.3g}")
    finally:
        setattr(module, constant, threshold)
    print(f"{name} (ms on 1/{threads} threads; {constant} = {threshold}):\n  " + ", ".join(cells))


def ltp_convolutions(size):
    from particle_methods.ltp import kernels
    from particle_methods.ltp.shapes import shape_named

    shape = shape_named("b3")
    x = np.linspace(-1, 1, size)
    weights, widths = np.full(size, 1.0 / size), np.full(size, 2.0 / size)
    coefficients, exponents = np.array([1.0]), np.array([3.0])
    return lambda: kernels.convolutions(x, x, weights, widths, coefficients, exponents, shape.breaks,
                                        shape.coefficients)


def blob_direct(size):
    from particle_methods.blob.kernels import kernel_2d, pair_sums
    from particle_methods.blob.mollifiers import mollifier

    rng = np.random.default_rng(0)
    points = rng.uniform(-1, 1, (size, 2))
    arrays = kernel_2d("newtonian", mollifier(4, 2), 0.1).arrays()
    masses = np.full(size, 1.0 / size)
    return lambda: pair_sums(points, masses, *arrays, newtonian_2d="direct")


def fmm_near(size):
    from particle_methods.blob.kernels import kernel_2d, pair_sums
    from particle_methods.blob.mollifiers import mollifier

    rng = np.random.default_rng(0)
    radius, angle = np.sqrt(rng.uniform(0, 1, size)), rng.uniform(0, 2 * np.pi, size)
    points = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=1)
    delta = (np.sqrt(np.pi / size)) ** 0.9      # delta = h^0.9 for the grid of the same density
    arrays = kernel_2d("newtonian", mollifier(4, 2), delta).arrays()
    masses = np.full(size, 1.0 / size)
    return lambda: pair_sums(points, masses, *arrays, newtonian_2d="fmm")


def main():
    from particle_methods.blob import kernels as blob_kernels
    from particle_methods.blob import newtonian_fmm
    from particle_methods.ltp import kernels as ltp_kernels

    side_by_side()
    start = time.perf_counter()
    scaling("LTP convolutions, |x|^3/3", ltp_kernels, "PARALLEL_MIN_TARGETS", ltp_convolutions,
            (50, 100, 200, 400, 800, 1600, 3200))
    scaling("blob direct 2D sums, Newtonian m = 4", blob_kernels, "PARALLEL_MIN_PARTICLES", blob_direct,
            (128, 256, 512, 1024, 2048))
    scaling("2D Newtonian sums by the FMM (near field on the threads but one)", newtonian_fmm,
            "PARALLEL_MIN_PARTICLES", fmm_near, (500, 1000, 2000, 4000, 8000))
    print(f"({time.perf_counter() - start:.1f} s)")


if __name__ == "__main__":
    main()
