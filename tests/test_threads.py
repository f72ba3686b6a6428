"""One thread mechanism for numba and the BLAS/OpenMP libraries (particle_methods.threads)."""

import os
import subprocess
import sys
import textwrap

import numba
import pytest
import threadpoolctl

from particle_methods.threads import _LIBRARY_VARIABLES, available, numba_threads, threads_for, use_threads
from particle_replication.workflow import logged


@pytest.fixture
def restore_threads(monkeypatch):
    """use_threads changes the whole process: put back numba's threads, the libraries' and their variables."""
    for variable in _LIBRARY_VARIABLES:  # monkeypatch restores (or deletes) them afterwards
        if variable in os.environ:
            monkeypatch.setenv(variable, os.environ[variable])
        else:
            monkeypatch.delenv(variable, raising=False)
    numba_count = numba.get_num_threads()
    controller = threadpoolctl.ThreadpoolController()
    libraries = [(library, library.num_threads) for library in controller.lib_controllers]
    yield
    numba.set_num_threads(numba_count)
    for library, count in libraries:
        library.set_num_threads(count)


def test_available_is_numba_limit():
    assert available() == numba.config.NUMBA_NUM_THREADS >= 1
    assert numba.get_num_threads() <= available()


@pytest.mark.parametrize("count", [0, -3])
def test_use_threads_refuses_fewer_than_one(restore_threads, count):
    with pytest.raises(ValueError, match="threads"):
        use_threads(count)


@pytest.mark.parametrize("count", [1.5, "2", None, True])
def test_use_threads_refuses_non_integers(restore_threads, count):
    with pytest.raises((TypeError, ValueError), match="threads"):
        use_threads(count)


def test_use_threads_clamps_to_available(restore_threads):
    assert use_threads(10_000) == available()
    assert numba.get_num_threads() == available()
    assert all(os.environ[variable] == str(available()) for variable in _LIBRARY_VARIABLES)


def test_use_threads_sets_numba_and_libraries(restore_threads):
    assert use_threads(1) == 1
    assert numba.get_num_threads() == 1
    assert all(os.environ[variable] == "1" for variable in _LIBRARY_VARIABLES)
    info = threadpoolctl.threadpool_info()
    assert info and all(library["num_threads"] == 1 for library in info)


def test_use_threads_under_a_numba_limit_of_one():
    """With NUMBA_NUM_THREADS=1 the process may use one thread: asking for two gives one, without an error
    (numba.set_num_threads(2) alone would raise)."""
    script = textwrap.dedent("""
        import numba
        from particle_methods.threads import available, use_threads
        used = use_threads(2)
        print(available(), used, numba.get_num_threads())
    """)
    environment = {**os.environ, "NUMBA_NUM_THREADS": "1"}
    result = subprocess.run([sys.executable, "-c", script], env=environment, capture_output=True, text=True,
                            timeout=120)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["1", "1", "1"]


def test_threads_for_uses_one_thread_below_the_threshold():
    before = numba.get_num_threads()
    with threads_for(99, 100):
        assert numba.get_num_threads() == 1
    assert numba.get_num_threads() == before
    with threads_for(100, 100):
        assert numba.get_num_threads() == before
    assert numba.get_num_threads() == before


def test_threads_for_restores_after_an_error():
    before = numba.get_num_threads()
    with pytest.raises(RuntimeError), threads_for(0, 100):
        assert numba.get_num_threads() == 1
        raise RuntimeError("inside")
    assert numba.get_num_threads() == before


def test_numba_threads_stays_within_the_current_count():
    before = numba.get_num_threads()
    with numba_threads(before + 5):
        assert numba.get_num_threads() == before
    with numba_threads(0):
        assert numba.get_num_threads() == 1
    with numba_threads(1), threads_for(10**6, 100):  # nested: at most the current count
        assert numba.get_num_threads() == 1
    assert numba.get_num_threads() == before


@pytest.mark.parametrize("threads", [1, 64])
def test_logged_writes_the_threads_line(restore_threads, tmp_path, threads):
    log = tmp_path / "logs" / "rule.log"
    with logged(log, threads=threads):
        print("working")
        inside = numba.get_num_threads()
    used = min(threads, available())
    assert inside == used
    lines = log.read_text().splitlines()
    assert lines[0] == f"threads: {used} (the job's {threads}, at most {available()} in this process)"
    assert lines[1] == "working"
    assert lines[2].startswith("wall time: ")


def test_logged_refuses_zero_threads(restore_threads, tmp_path):
    with pytest.raises(ValueError, match="threads"), logged(tmp_path / "rule.log", threads=0):
        pass
