"""Threads: two processes sharing the cores, and the sizes from which a kernel goes parallel.

    python benchmarks/bench_threads.py

1. The LTP workload of issue 25 (three runs of rho1 with W = x^2/2, h = 0.04, 0.02, 0.01, dt = 1e-4, to
   t = 0.5), in a fresh process with the default threads, timed after a warm-up run: alone, then two
   such processes started together. Each should take at most 1.3 times as long as one alone.
2. The compiled kernels on one thread and on two, against the problem size, alone and with a second
   process running the same beside it: the LTP convolutions (W = |x|^3/3, pair sums), the direct 2D blob
   sums (mollified Newtonian kernel) and the FMM path (FMM beside the near field). Alone, two threads pay
   almost from the smallest size; under load, two threads per process fight over two cores and lose
   below some size: the PARALLEL_MIN_* constant of each family is read off there.
"""

import subprocess
import sys
import textwrap
import time

import numba
import numpy as np
from timing import best_time, print_cpu

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


FAMILIES = {}


def family(module, constant):
    """Register a kernel family: its module, the name of its threshold constant, and a function of the size
    that makes a call."""
    def register(make):
        FAMILIES[make.__name__] = (module, constant, make)
        return make
    return register


def worker(name, threads, sizes):
    """Times of one family at each size on ``threads`` threads, with its threshold set to 1 (so that the kernel
    really runs on the threads asked for); printed on one line."""
    import importlib

    module_name, constant, make = FAMILIES[name]
    module = importlib.import_module(module_name)
    setattr(module, constant, 1)
    numba.set_num_threads(threads)
    print(" ".join(f"{best_time(make(size), 5)[0]:.6g}" for size in sizes), flush=True)


def scaling(name, sizes):
    """One family alone (one process) and under load (two processes side by side), on one thread and on two:
    the threshold is where two threads still pay under load."""
    module_name, constant, _ = FAMILIES[name]
    threshold = getattr(__import__(module_name, fromlist=[constant]), constant)

    def run(threads, processes):
        command = [sys.executable, __file__, "--worker", name, str(threads), *map(str, sizes)]
        started = [subprocess.Popen(command, stdout=subprocess.PIPE, text=True) for _ in range(processes)]
        return np.max([[float(v) for v in p.communicate()[0].split()] for p in started], axis=0)

    print(f"{name} ({module_name}.{constant} = {threshold}); ms on 1/2 threads, alone | two processes side by side:")
    alone = (run(1, 1), run(2, 1))
    loaded = (run(1, 2), run(2, 2))
    print("  " + ", ".join(f"{size}: {1e3 * a1:.3g}/{1e3 * a2:.3g} | {1e3 * l1:.3g}/{1e3 * l2:.3g}"
                           for size, a1, a2, l1, l2 in zip(sizes, *alone, *loaded)))


@family("particle_methods.ltp.kernels", "PARALLEL_MIN_TARGETS")
def ltp_convolutions(size):
    from particle_methods.ltp import kernels
    from particle_methods.ltp.shapes import shape_named

    shape = shape_named("b3")
    x = np.linspace(-1, 1, size)
    weights, widths = np.full(size, 1.0 / size), np.full(size, 2.0 / size)
    coefficients, exponents = np.array([1.0]), np.array([3.0])
    return lambda: kernels.convolutions(x, x, weights, widths, coefficients, exponents, shape.breaks,
                                        shape.coefficients)


@family("particle_methods.blob.pair_sums", "PARALLEL_MIN_PARTICLES")
def blob_direct(size):
    from particle_methods.blob.kernels import kernel_2d
    from particle_methods.blob.mollifiers import mollifier
    from particle_methods.blob.pair_sums import pair_sums

    rng = np.random.default_rng(0)
    points = rng.uniform(-1, 1, (size, 2))
    arrays = kernel_2d("newtonian", mollifier(4, 2), 0.1).arrays()
    masses = np.full(size, 1.0 / size)
    return lambda: pair_sums(points, masses, *arrays, newtonian_2d="direct")


@family("particle_methods.blob.newtonian_fmm", "PARALLEL_MIN_PARTICLES")
def fmm_near(size):
    from particle_methods.blob.kernels import kernel_2d
    from particle_methods.blob.mollifiers import mollifier
    from particle_methods.blob.pair_sums import pair_sums

    rng = np.random.default_rng(0)
    radius, angle = np.sqrt(rng.uniform(0, 1, size)), rng.uniform(0, 2 * np.pi, size)
    points = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=1)
    delta = (np.sqrt(np.pi / size)) ** 0.9      # delta = h^0.9 for the grid of the same density
    arrays = kernel_2d("newtonian", mollifier(4, 2), delta).arrays()
    masses = np.full(size, 1.0 / size)
    return lambda: pair_sums(points, masses, *arrays, newtonian_2d="fmm")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        worker(sys.argv[2], int(sys.argv[3]), [int(v) for v in sys.argv[4:]])
        return
    print_cpu()
    side_by_side()
    start = time.perf_counter()
    scaling("ltp_convolutions", (50, 100, 200, 400, 800, 1600, 3200))
    scaling("blob_direct", (128, 256, 512, 1024, 2048))
    scaling("fmm_near", (1000, 2000, 4000, 8000))
    print(f"({time.perf_counter() - start:.1f} s)")


if __name__ == "__main__":
    main()
