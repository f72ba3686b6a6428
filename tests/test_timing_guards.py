"""The guards that keep timings from deciding anything: the fuzz watchdog counts CPU time, not the wall clock,
and a wall-time check abstains when its timing was disturbed (particle_replication.workflow.LoadGuard)."""

import math
import time
import types

import numpy as np
import pytest
from fuzzing import watchdog

from particle_replication import cost_timing, workflow
from particle_replication.rates import order
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

    timed = interleaved([lambda i=i: run(i) for i in range(3)], 3)
    assert calls == [0, 1, 2] * 3 and timed.results == [0, 10, 20] and timed.count == [3, 3, 3]
    assert all(0 <= best <= slowest for best, slowest in zip(timed.best, timed.slowest))


def test_a_drift_of_the_machine_during_one_round_reaches_no_best_time_when_every_run_repeats(monkeypatch):
    """The sticky cost study's instrument: runs of 1, 2 and 4 s (linear in their size) on a machine that is 1.45
    times slower while the first round times the largest. Timed in one round (the default for runs over
    REPEAT_BELOW) the drift bends the exponent out of [0.8, 1.2]; timed in every round it is gone."""
    clock, rounds = [0.0], []

    def run(seconds):
        slow = 1.45 if len(rounds) < 3 and seconds == 4.0 else 1.0
        rounds.append(seconds)
        clock[0] += seconds * slow

    monkeypatch.setattr(workflow, "time", types.SimpleNamespace(perf_counter=lambda: clock[0]))
    runs = [lambda s=s: run(s) for s in (1.0, 2.0, 4.0)]

    def exponent(best):  # as the check fits it (verdicts.sticky.cost_claims)
        return -order("test.wall_time", "n", 1.0 / np.array([1.0, 2.0, 4.0]), best, 3).slope

    once = interleaved(runs, 5).best
    assert rounds == [1.0, 2.0, 4.0] and exponent(once) > 1.2
    rounds.clear()
    every = interleaved(runs, 5, repeat_below=math.inf)
    assert len(rounds) == 15 and every.best == [1.0, 2.0, 4.0] and exponent(every.best) == pytest.approx(1.0)
    # the drift is recorded: the largest run's slowest round, of its five, was 1.45 times its best
    assert every.count == [5, 5, 5] and every.slowest == [1.0, 2.0, pytest.approx(4.0 * 1.45)]


@pytest.mark.parametrize("repeat_below", [0, -1.0, math.nan, True, "1"])
def test_interleaved_refuses_a_threshold_that_is_no_positive_number(repeat_below):
    with pytest.raises(ValueError, match="repeat_below"):
        interleaved([lambda: None], 2, repeat_below=repeat_below)


#: The cost study's sections at tiny sizes: every series, three sizes each.
TINY_COST = {"hull_n": [100, 200, 400], "rank_n": [100, 200, 400], "tspd_n": [100, 200, 400], "tspd_steps": 1,
             "steps_values": [1, 2, 4], "steps_n": 50, "repeats": 1}


def test_the_cost_study_times_the_same_runs_in_a_fresh_process():
    """The second process (a fresh interpreter) runs the same nudged data: the same counted operations, a best
    time for every size of every series, and the load guard's readings."""
    made = cost_timing.replicated(TINY_COST, 2, ulps=4, seed=1)
    assert len(made) == 2 and made[0]["operations"] == made[1]["operations"]
    for process in made:
        assert all(len(process["times"][name]) == 3 and min(process["times"][name]) > 0 for name in cost_timing.SERIES)
        assert set(process["readings"]) == {"cpu_share", "load", "cores", "threads"}


def test_a_timing_process_that_counts_other_operations_is_refused(monkeypatch):
    """Two processes on the same data must count the same operations; this one's (replaced here) differ."""
    measured = cost_timing.measure(TINY_COST)
    measured["operations"]["hull"][0] += 1
    monkeypatch.setattr(cost_timing, "measure", lambda *args: measured)
    with pytest.raises(RuntimeError, match="different operations"):
        cost_timing.replicated(TINY_COST, 2)
    with pytest.raises(ValueError, match="processes"):
        cost_timing.replicated(TINY_COST, 0)
