"""Census of the whole public API (issue 46): every public callable of ``particle_methods``, generated from the
package, called with one argument at a time replaced by bad and extreme values.

:func:`public_callables` walks the package's modules and lists every public name defined in its module (no
leading underscore) that can be called: functions, compiled functions, classes (their constructors), their public
methods and ``__call__``, and callable module constants (``ltp.shapes.HAT``). Each must have an entry in
:data:`ENTRIES` (a call with good arguments, by keyword) or in :data:`EXEMPT` (with the reason), so that a new
function cannot escape the census (``tests/test_census.py`` fails on one that has neither).

Each argument of an entry is replaced in turn by the values of its kind: for a number, :data:`fuzzing.BAD_SCALARS`
and :data:`SCALAR_EXTREMES` (1e300, 1.7e308, the denormal 5e-324, -0.0, ...); for a count, the same and counts
beyond every work limit; for an array, :data:`fuzzing.BAD_ARRAYS` and the extreme arrays of :func:`array_extremes`
(filled with 1e300, 1.7e308 or denormals, scaled by 1e300 or 5e-324, zero-stride views of the good shape and of
10**9 entries, a read-only non-contiguous copy); for a name, an object or a function, values of the wrong kind.
Every call is classified (:func:`classify`); the failures are a hang (more than :data:`CALL_SECONDS` of CPU time, a
profiling timer: a loaded machine slows the wall clock, not this), a silent non-finite result, an exception other
than ValueError/TypeError, a refusal whose message names no parameter, and a bad value (None, a string, NaN, inf,
...) answered instead of refused where the parameter does not take it (its default, or the entry's ``accepts``).

The test tries :data:`SAMPLE` of the values per argument (a fixed subset); ``python tests/census.py --all`` tries
them all and prints the counts (``-v``: every failing call).
"""

from __future__ import annotations

import collections
import faulthandler
import importlib
import inspect
import pkgutil
import re
import signal
import sys
import zlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from fuzzing import BAD_ARRAYS, BAD_SCALARS, all_finite, built

import particle_methods

#: CPU seconds after which a call is a hang (a profiling timer: the process's CPU time, not the wall clock).
CALL_SECONDS = 10.0
#: Wall-clock seconds after which a call that cannot be interrupted (a compiled loop) ends the process.
WALL_BACKSTOP = 300.0
#: Bad and extreme values tried per argument by the test (``python tests/census.py --all``: every value): a fixed
#: subset, drawn by a hash of the callable's and the argument's names, so that it differs between arguments (every
#: value is tried on some of them) yet never between runs.
SAMPLE = 8
#: Entries of the zero-stride arrays that stand for a huge input: beyond every size limit, yet no memory.
HUGE = 10**9

SCALAR_EXTREMES = [1e300, -1e300, 1.7e308, -1.7e308, 5e-324, -5e-324, 0.0, -0.0, -1.0, 1e-300]
COUNT_EXTREMES = [0, -1, 2**31, 2**63, 10**18, 2.5, np.int64(3), np.uint8(255)]
OBJECT_BAD = [None, "x", b"x", 1.0, np.array([1.0]), object()]
FUNCTION_BAD = [None, "x", 1.0]


def nan_function(*args):
    """A function (a flux, a density) that returns NaN: its result must be refused, never passed on."""
    return np.full(np.shape(args[0]) if args else (), np.nan)


def array_extremes(good: np.ndarray) -> list:
    """Extreme finite arrays standing in for ``good``: filled or scaled to the ends of the double range, zero-stride
    views (of the good shape and of :data:`HUGE` entries, which cost no memory), a read-only non-contiguous copy."""
    good = np.asarray(good, dtype=float)
    values = [np.full(good.shape, 1e300), np.full(good.shape, -1.7e308), np.full(good.shape, 5e-324),
              good * 1e300, good * 5e-324, -good]
    if good.size:
        values.append(np.broadcast_to(good.flat[0], good.shape))
        values.append(np.broadcast_to(good.flat[0], (HUGE,) + good.shape[1:]))
    strided = np.repeat(good, 2, axis=-1)[..., ::2] if good.ndim else good.copy()
    strided.flags.writeable = False
    values.append(strided)
    return values


@dataclass
class Entry:
    """A call of ``function`` with good keyword arguments ``good``; ``kinds`` overrides the kind of an argument
    (number, count, array, name, object, function, flag, fixed: the last two are not fuzzed), ``names`` the
    parameter names its error may name, ``accepts`` the bad values an argument takes, ``documented`` maps a result
    to the part that must be finite (a documented sentinel such as -inf for "none" replaced)."""

    function: object
    good: dict
    kinds: dict = field(default_factory=dict)
    names: dict = field(default_factory=dict)
    accepts: dict = field(default_factory=dict)
    documented: object = None

    def kind(self, parameter: str) -> str:
        if parameter in self.kinds:
            return self.kinds[parameter]
        value = built(self.good[parameter])
        if isinstance(value, (bool, np.bool_)):
            return "flag"
        if isinstance(value, (int, np.integer)):
            return "count"
        if isinstance(value, (float, np.floating)):
            return "number"
        if isinstance(value, str):
            return "name"
        if isinstance(value, (np.ndarray, list)):
            return "array"
        if callable(value):
            return "function"
        return "object"

    def values(self, parameter: str) -> list:
        """(value, must_refuse) for every replacement of ``parameter``."""
        kind = self.kind(parameter)
        if kind in ("flag", "fixed"):
            return []
        if kind == "number":
            bad, extreme = BAD_SCALARS, SCALAR_EXTREMES
        elif kind == "count":
            bad, extreme = BAD_SCALARS, COUNT_EXTREMES
        elif kind == "array":
            bad, extreme = BAD_ARRAYS, array_extremes(built(self.good[parameter]))
        elif kind == "name":
            bad, extreme = BAD_SCALARS, []
        elif kind == "function":
            bad, extreme = FUNCTION_BAD + [nan_function], []
        else:
            bad, extreme = OBJECT_BAD, []
        accepted = self.accepts.get(parameter, [])
        default = self.default(parameter)
        out = []
        for value in bad:
            takes = any(value is a or (type(value) is type(a) and _same(value, a)) for a in accepted)
            takes = takes or (value is None and default is None)
            out.append((value, must_refuse(kind, value) and not takes))
        return out + [(value, False) for value in extreme]

    def default(self, parameter: str):
        try:
            signature = inspect.signature(self.function)
        except (TypeError, ValueError):
            return inspect.Parameter.empty
        found = signature.parameters.get(parameter)
        return inspect.Parameter.empty if found is None else found.default


def _same(a, b) -> bool:
    try:
        return bool(np.all(a == b))
    except Exception:
        return False


def must_refuse(kind: str, value) -> bool:
    """Whether a bad value may not be answered: of the wrong kind, or non-finite (an empty list, a scalar for an
    array or an array of another rank may be a valid input of some functions, checked by their results)."""
    if value is None or isinstance(value, (str, bytes, complex, dict)) or type(value) is object:
        return True
    if kind in ("number", "count"):
        return True  # lists, booleans, NaN, inf, 10**400: never a number
    if kind == "array":
        array = np.asarray(value) if not isinstance(value, list) or _rectangular(value) else None
        if array is None or array.dtype.kind not in "biuf":
            return True
        return not bool(np.all(np.isfinite(array)))
    return True


def _rectangular(value) -> bool:
    try:
        np.asarray(value, dtype=float)
        return True
    except (ValueError, TypeError):
        return False


CLASSES = ("refused, named", "answered", "refused, unclear", "accepted a bad value", "silent non-finite",
           "other exception", "hang")
FAILURES = CLASSES[2:]


class _Hang(BaseException):
    pass


def _alarm(signum, frame):
    raise _Hang


def classify(function, arguments: dict, names, must: bool, documented=None) -> tuple[str, str]:
    """(outcome, detail) of one call, under a CPU-time limit (Python code) and a wall-clock backstop (compiled)."""
    previous = signal.signal(signal.SIGPROF, _alarm)
    faulthandler.dump_traceback_later(WALL_BACKSTOP, exit=True)
    signal.setitimer(signal.ITIMER_PROF, CALL_SECONDS)
    try:
        result = function(**arguments)
    except _Hang:
        return "hang", f"more than {CALL_SECONDS:g} s of CPU"
    except (ValueError, TypeError) as error:
        named = any(re.search(rf"(?<![a-z0-9_]){re.escape(name.lower())}(?![a-z0-9_])", str(error).lower())
                    for name in names)  # a whole word ("t" is not named by "times"); "Delta" names delta
        return ("refused, named" if named else "refused, unclear"), f"{type(error).__name__}: {error}"[:200]
    except Exception as error:  # every other type is what the census counts
        return "other exception", f"{type(error).__name__}: {error}"[:200]
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        faulthandler.cancel_dump_traceback_later()
        signal.signal(signal.SIGPROF, previous)
    if not _finite(result if documented is None else documented(result)):
        return "silent non-finite", "NaN or inf returned"
    if must:
        return "accepted a bad value", f"returned {type(result).__name__}"
    return "answered", ""


def _finite(value) -> bool:
    if isinstance(value, np.ndarray) and 0 in value.strides:  # a zero-stride view: its distinct entries only
        value = value[tuple(slice(0, 1) if stride == 0 else slice(None) for stride in value.strides)]
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if hasattr(value, "__dataclass_fields__") and not hasattr(value, "centres"):
        return all(_finite(getattr(value, name)) for name in value.__dataclass_fields__)
    if isinstance(value, tuple) and hasattr(value, "_fields"):
        return all(_finite(v) for v in value)
    return all_finite(value)


def sampled(name: str, parameter: str, values: list, size: int | None = SAMPLE) -> list:
    """A fixed subset of ``size`` of ``values`` (all if None): those whose hash with the names ranks first."""
    if size is None or len(values) <= size:
        return values
    rank = sorted(range(len(values)), key=lambda i: zlib.crc32(f"{name}:{parameter}:{i}".encode()))
    return [values[i] for i in sorted(rank[:size])]


def census(name: str, entry: Entry, size: int | None = SAMPLE):
    """Every call of one entry: a list of (parameter, value, outcome, detail). The good call comes first, under the
    wall-clock backstop only: it compiles the entry's kernels (numba, seconds of CPU on a fresh clone), which the
    CPU-time limit would otherwise interrupt, and so count as a hang, at every bad call; it must be answered."""
    faulthandler.dump_traceback_later(WALL_BACKSTOP, exit=True)
    try:
        function, good = built(entry.function), built(entry.good)  # good values built on first use (Later)
        function(**good)
    except Exception as error:  # a good call must be answered: the census reports it, never hides it
        return [("(good call)", None, "other exception", f"{type(error).__name__}: {error}"[:200])]
    finally:
        faulthandler.cancel_dump_traceback_later()
    outcomes = []
    for parameter in good:
        names = (parameter, *entry.names.get(parameter, ()))
        for value, must in sampled(name, parameter, entry.values(parameter), size):
            arguments = {**good, parameter: value}
            outcome, detail = classify(function, arguments, names, must, entry.documented)
            outcomes.append((parameter, value, outcome, detail))
    return outcomes


def public_callables() -> list[str]:
    """Qualified names of every public callable of the package (see the module docstring)."""
    found = []
    for info in pkgutil.walk_packages(particle_methods.__path__, "particle_methods."):
        module = importlib.import_module(info.name)
        for name, value in vars(module).items():
            if name.startswith("_") or not callable(value):
                continue
            if inspect.isroutine(value) or inspect.isclass(value) or hasattr(value, "py_func"):
                home = getattr(value, "__module__", None)
            else:  # a callable instance (a shape): counted in the module of its class
                home = type(value).__module__
            if home != info.name:
                continue
            found.append(f"{info.name}.{name}")
            if inspect.isclass(value):
                for attribute, member in vars(value).items():
                    if attribute.startswith("_") and attribute != "__call__":
                        continue
                    if isinstance(member, (staticmethod, classmethod)) or inspect.isfunction(member):
                        found.append(f"{info.name}.{name}.{attribute}")
    return sorted(found)


def run(verbose: bool = False, size: int | None = SAMPLE):
    from census_entries import ENTRIES

    counts = collections.Counter()
    for name, entry in sorted(ENTRIES.items()):
        for parameter, value, outcome, detail in census(name, entry, size):
            counts[outcome] += 1
            if verbose and outcome in FAILURES:
                print(f"{outcome:22} {name}({parameter} = {value!r:.40}): {detail}", flush=True)
    return counts


if __name__ == "__main__":
    from census_entries import ENTRIES, EXEMPT

    totals = run(verbose="-v" in sys.argv, size=None if "--all" in sys.argv else SAMPLE)
    print(f"{len(ENTRIES)} callables covered, {len(EXEMPT)} exempt; {sum(totals.values())} calls")
    for outcome in CLASSES:
        print(f"  {outcome:22} {totals[outcome]}")
