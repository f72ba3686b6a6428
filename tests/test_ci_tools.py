"""CI's background install of the tools, as the quick run's fixture waits for it (tests/ci_tools.py)."""

import threading

import ci_tools
import pytest


def test_no_install_is_waited_for_where_none_was_started():
    assert not ci_tools.installing({})
    assert ci_tools.wait({}) is None


def test_the_install_is_running_until_its_status_is_written_and_its_outcome_is_read(tmp_path):
    environ = {ci_tools.VARIABLE: str(tmp_path / "tools-status")}
    assert ci_tools.installing(environ)
    with pytest.raises(TimeoutError, match=ci_tools.VARIABLE):
        ci_tools.wait(environ, timeout=0.05, poll=0.01)
    writer = threading.Timer(0.1, (tmp_path / "tools-status").write_text, args=("failed\n",))
    writer.start()
    assert ci_tools.wait(environ, timeout=30, poll=0.01) == "failed"
    assert not ci_tools.installing(environ)


def fake_scontrol(folder, exit_code):
    """A folder holding an ``scontrol`` whose ``ping`` exits with ``exit_code`` (1: the controller is down)."""
    folder.mkdir()
    script = folder / "scontrol"
    script.write_text(f"#!/bin/sh\nexit {exit_code}\n")
    script.chmod(0o755)
    return str(folder)


def test_the_header_warns_where_slurm_is_installed_but_no_controller_answers(tmp_path):
    pytest.importorskip("snakemake_executor_plugin_slurm")
    assert "scontrol ping" in ci_tools.slurm_wait_warning(fake_scontrol(tmp_path / "down", 1))
    assert ci_tools.slurm_wait_warning(fake_scontrol(tmp_path / "up", 0)) is None
    assert ci_tools.slurm_wait_warning(str(tmp_path / "no-slurm")) is None
