"""Timing helper shared by the benchmark scripts."""

import time


def best_time(function, repeats: int = 3):
    """(best wall time over ``repeats`` calls after one warm-up call, last result)."""
    result = function()
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result
