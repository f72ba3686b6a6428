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
