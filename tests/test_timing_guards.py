"""The guards that keep timings from deciding anything: the fuzz watchdog counts CPU time, not the wall clock,
and a wall-time check abstains when its timing was disturbed (particle_replication.workflow.LoadGuard)."""

import time

import pytest
from fuzzing import watchdog

from particle_replication.workflow import CPU_SHARE_MIN, LoadGuard, disturbance, interleaved


def test_a_call_that_only_waits_is_no_hang():
    """Wall time (a loaded machine, a sleep) does not count against the watchdog."""
    with watchdog(0.05):
        time.sleep(0.2)


def test_a_call_that_spends_cpu_beyond_the_limit_fails():
    with pytest.raises(AssertionError, match="of CPU"), watchdog(0.05):
        end = time.process_time() + 0.2
        while time.process_time() < end:
            pass


QUIET = {"cpu_share": 0.99, "load": 0.2, "cores": 2, "threads": 1}


@pytest.mark.parametrize("change, reason", [
    ({}, ""),
    ({"cpu_share": CPU_SHARE_MIN - 0.01}, "of a core"),
    ({"load": 2.0}, "other processes were runnable"),
    ({"cpu_share": 0.5, "threads": 2}, ""),  # a parallel timing's share says nothing of the load
])
def test_disturbance_names_why_a_timing_was_disturbed(change, reason):
    found = disturbance({**QUIET, **change})
    assert (reason in found) if reason else found == ""


def test_the_guard_reads_the_run_queue_and_the_cpu_share():
    with LoadGuard() as guard:
        end = time.process_time() + 0.05
        while time.process_time() < end:
            pass
    assert len(guard.others) == 2 and all(other >= 0 for other in guard.others)
    assert 0.0 < guard.cpu_share <= 1.5 and set(guard.readings()) == {"cpu_share", "load", "cores", "threads"}


def test_interleaved_rounds_time_every_run_and_keep_the_first_results():
    calls = []

    def run(i):
        calls.append(i)
        return i * 10

    seconds, results = interleaved([lambda i=i: run(i) for i in range(3)], 3)
    assert calls == [0, 1, 2] * 3 and results == [0, 10, 20] and all(s >= 0 for s in seconds)
