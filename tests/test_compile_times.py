"""benchmarks/compile_times.py: exclusive compile times from nested numba:compile events."""

import importlib.util
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

SCRIPT = Path(__file__).resolve().parent.parent / "benchmarks" / "compile_times.py"
sys.path.insert(0, str(SCRIPT.parent))  # its helper module timing.py, as when the script runs
spec = importlib.util.spec_from_file_location("compile_times", SCRIPT)
compile_times = importlib.util.module_from_spec(spec)
spec.loader.exec_module(compile_times)


def event(module, name, start):
    function = SimpleNamespace(__module__=module, __qualname__=name)
    return SimpleNamespace(data={"dispatcher": SimpleNamespace(py_func=function)}, is_start=start)


def test_nested_compilations_are_counted_once_each():
    # kernel A (0 .. 10 s) compiles kernel B (1 .. 4 s), which pulls in a numba overload (2 .. 3 s); then C (10 .. 11 s)
    events = [(0.0, event("pkg.a", "A", True)), (1.0, event("pkg.b", "B", True)),
              (2.0, event("numba.np.arrayobj", "ol_copy.<locals>.impl", True)),
              (3.0, event("numba.np.arrayobj", "ol_copy.<locals>.impl", False)), (4.0, event("pkg.b", "B", False)),
              (10.0, event("pkg.a", "A", False)), (10.0, event("pkg.c", "C", True)), (11.0, event("pkg.c", "C", False))]
    exclusive, overloads, outermost = compile_times.exclusive_times(events)
    assert exclusive["pkg.a.A"] == pytest.approx(7.0) and exclusive["pkg.b.B"] == pytest.approx(2.0)
    assert exclusive["numba.np.arrayobj.ol_copy"] == pytest.approx(1.0)
    assert overloads == {"pkg.b.B <- numba.np.arrayobj.ol_copy": pytest.approx(1.0)}
    assert outermost == pytest.approx(11.0)  # A and C, each once
