"""Timing helpers shared by the benchmark scripts: the best of repeated calls, and the header that names the CPU
every time printed below it was measured on."""

import sys
import time

from particle_replication.environment import cpu


def best_time(function, repeats: int = 3):
    """(best wall time over ``repeats`` calls after one warm-up call, last result)."""
    result = function()
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result


def print_cpu(file=None) -> None:
    """Print the header of a benchmark's output: the CPU its times are measured on (model, widest vector
    extension, cores: :func:`particle_replication.environment.cpu`), to ``file`` (default: standard output)."""
    print(f"Measured on {cpu()}", file=sys.stdout if file is None else file, flush=True)
