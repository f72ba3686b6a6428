"""Result files checked against the CRC-32s written with them, the tables computed from files that are gone,
and the owners of Snakemake's locks (particle_replication.workflow; issue 46)."""

import json
import os
import socket
import subprocess
import sys
import time

import numpy as np
import pytest

from particle_replication import workflow


def written(tmp_path, name="result.npz"):
    path = tmp_path / "results" / name
    workflow.save_results(path, x=np.arange(10_000.0), y=np.ones(3))
    return path


def test_a_whole_result_reads_back_and_leaves_no_temporary(tmp_path):
    path = written(tmp_path)
    assert workflow.damaged(path) == "" and workflow.damaged_results(tmp_path / "results") == {}
    np.testing.assert_array_equal(workflow.load_results(path)["x"], np.arange(10_000.0))
    assert [p.name for p in path.parent.iterdir()] == ["result.npz"]


@pytest.mark.parametrize("damage", ["truncated", "one byte changed", "emptied"])
def test_a_damaged_result_is_found_and_refused_where_it_is_read(tmp_path, damage):
    path = written(tmp_path)
    stat = path.stat()
    data = bytearray(path.read_bytes())
    if damage == "truncated":
        data = data[:1000]
    elif damage == "one byte changed":
        data[40_000] ^= 0x01  # inside the array x
    else:
        data = b""
    path.write_bytes(bytes(data))
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))  # its time kept: only the content tells
    found = workflow.damaged_results(tmp_path / "results")
    assert list(found) == [str(path)], found
    if damage == "one byte changed":
        assert "CRC-32 of its array x" in found[str(path)]
    with pytest.raises(ValueError, match=rf"{path} is damaged .*rebuilds it"):
        workflow.load_results(path)


def test_an_intermediate_file_of_another_configuration_is_refused_where_it_is_read(tmp_path):
    """A job reading another job's file (beyond_limits reads the upwind runs of beyond_upwind) requires its case and
    grid: the file of another case or cell count is refused naming the key."""
    path = tmp_path / "upwind.npz"
    workflow.save_results(path, case=np.array("rarefaction"), upwind_reference_cells=64000, upwind_gap=1e-3)
    found = workflow.load_results(path, expect={"case": "rarefaction", "upwind_reference_cells": 64000})
    assert float(found["upwind_gap"]) == 1e-3
    with pytest.raises(ValueError, match=r"holds case = .*'rarefaction'.*not the .*'shocks'.*rerun its rule"):
        workflow.load_results(path, expect={"case": "shocks"})
    with pytest.raises(ValueError, match=r"holds upwind_reference_cells = .*64000.*not the .*32000"):
        workflow.load_results(path, expect={"case": "rarefaction", "upwind_reference_cells": 32000})
    with pytest.raises(ValueError, match="holds no upwind_w"):
        workflow.load_results(path, expect={"upwind_w": 0})


def test_damaged_results_checks_its_arguments(tmp_path):
    with pytest.raises(TypeError, match="path"):
        workflow.damaged(None)
    (tmp_path / "file").write_text("")
    with pytest.raises(ValueError, match="root"):
        workflow.damaged_results(tmp_path / "file")
    assert workflow.damaged_results(tmp_path / "none") == {}


def test_tables_of_results_that_are_gone(tmp_path):
    table, kept, gone = (tmp_path / name for name in ("claims.csv", "a.npz", "b.npz"))
    table.write_text("")
    kept.write_text("")
    never_made = str(tmp_path / "never.csv")
    steps = {str(table): [str(kept), str(gone)], never_made: [str(gone)]}
    assert workflow.missing_inputs(steps) == {str(table): [str(gone)]}
    assert workflow.missing_inputs({str(table): [str(kept)]}) == {}
    with pytest.raises(TypeError, match="steps"):
        workflow.missing_inputs([str(table)])
    with pytest.raises(TypeError, match="list of paths"):
        workflow.missing_inputs({str(table): str(kept)})


def gone_process():
    """The id of a process that has ended (and been reaped)."""
    process = subprocess.Popen([sys.executable, "-c", "pass"])
    process.wait()
    return process.pid


def lock_with_owner(lockdir, name, **owner):
    lockdir.mkdir(parents=True, exist_ok=True)
    lock = lockdir / name
    lock.write_text("results/x.npz\n")
    record = {"pid": os.getpid(), "started": workflow._started(os.getpid()), "group": os.getpgrp(),
              "host": socket.gethostname(), **owner}
    (lockdir / f"{name}.owner").write_text(json.dumps(record))
    return lock


def test_the_lock_of_a_run_that_is_gone_is_stale(tmp_path):
    locks = tmp_path / ".snakemake" / "locks"
    mine = lock_with_owner(locks, "0.input.lock")  # this process: alive
    dead = gone_process()
    killed = lock_with_owner(locks, "1.input.lock", pid=dead, group=dead)
    reused = lock_with_owner(locks, "2.output.lock", started="1")  # this process's id, another start time
    lock_with_owner(locks, "3.output.lock", pid=dead, host="another-machine")  # not judged
    (locks / "4.input.lock").write_text("results/x.npz\n")  # no owner record: Snakemake's check decides
    stale, running = workflow.stale_locks(locks)
    assert stale == [killed, reused] and running == {}
    assert mine.exists()
    assert workflow.stale_locks(tmp_path / "nowhere") == ([], {})


def test_a_killed_run_whose_jobs_still_run_is_not_stale(tmp_path):
    """A run that led its process group left its jobs there: while one runs, its lock stays."""
    import signal

    # a group's leader that has ended, with a job of its own still running in its group
    run = subprocess.Popen(["sh", "-c", "sleep 60 & exit 0"], start_new_session=True)
    run.wait()
    try:
        lock = lock_with_owner(tmp_path, "0.output.lock", pid=run.pid, group=run.pid)
        assert workflow.stale_locks(tmp_path) == ([], {run.pid: run.pid})
    finally:
        os.killpg(run.pid, signal.SIGKILL)
    for _ in range(100):  # the job, reparented, is reaped by init
        if not workflow._group_running(run.pid):
            break
        time.sleep(0.05)
    assert workflow.stale_locks(tmp_path) == ([lock], {})


def test_the_owner_of_a_lock_is_recorded(tmp_path):
    lock = tmp_path / "0.input.lock"
    lock.write_text("results/x.npz\n")
    workflow.record_lock_owner([lock])
    owner = json.loads((tmp_path / "0.input.lock.owner").read_text())
    assert owner["pid"] == os.getpid() and owner["host"] == socket.gethostname()
    assert workflow.stale_locks(tmp_path) == ([], {})
    with pytest.raises(TypeError, match="lockfiles"):
        workflow.record_lock_owner(str(lock))
