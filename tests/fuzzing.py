"""Property-based fuzzing of the public API: the shared harness (issue: safe API).

Every public entry point is called with values drawn from :data:`BAD` and with well-formed but
extreme values. A call must return finite results or raise ``ValueError`` or ``TypeError``
naming the parameter; anything else (another exception, NaN or inf returned, a hang) fails.
Each call runs under a watchdog that measures the call's CPU time, not the wall clock, so that a
call that is only slow because the machine is loaded is no hang: a call that spends more than
``CALL_SECONDS`` of CPU fails its test, and one that does not return within ``WALL_BACKSTOP``
seconds (a true hang: an endless loop, a deadlock) ends the test process with a traceback
(compiled loops cannot be interrupted any other way).
"""

from __future__ import annotations

import faulthandler
import functools
import os
import time
from contextlib import contextmanager

import numpy as np
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from particle_methods.validation import ParameterTypeError

CALL_SECONDS = 20.0
#: Wall-clock seconds after which a call is taken for hung whatever the load: ten times CALL_SECONDS.
WALL_BACKSTOP = 10 * CALL_SECONDS

FUZZ = settings(
    max_examples=40,
    deadline=None,  # the watchdog bounds each call; hypothesis' deadline would only report it
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
    derandomize=True,
)


class Later:
    """A good value whose building runs compiled kernels (a run, a simulation, an exact solution): built on first
    use, once. Every pytest-xdist worker imports every test module to collect the tests, and a value built at
    import compiled its kernels in each (numba, about 20 s of CPU per worker on a fresh clone, the pipeline
    worker's before its quick run could start); built later, only the worker that runs its tests compiles them.
    An attribute, an item or a call of a Later value is a Later value too (``SIM.at(0)``, ``SMALL_RUN.times``);
    :func:`built` gives the value."""

    def __init__(self, build):
        self._build = build

    @functools.cached_property
    def value(self):
        return built(self._build())

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        return Later(lambda: getattr(self.value, name))

    def __getitem__(self, key):
        return Later(lambda: self.value[key])

    def __call__(self, *args, **kwargs):
        return Later(lambda: self.value(*map(built, args), **{key: built(v) for key, v in kwargs.items()}))


def built(value):
    """``value``, built if it is :class:`Later` (its entries too, for a dict of good arguments)."""
    if isinstance(value, Later):
        return value.value
    if isinstance(value, dict) and any(isinstance(item, Later) for item in value.values()):
        return {key: built(item) for key, item in value.items()}
    return value


# Values no public function should accept silently where a number or an array is expected.
BAD_SCALARS = [None, "1", b"1", 1j, float("nan"), float("inf"), -float("inf"), 10**400, -(10**400), [], [1.0, 2.0],
               {}, object(), True]
BAD_ARRAYS = [None, "abc", [], [[1.0], [2.0, 3.0]], np.array([1.0, np.nan]), np.array([1.0, np.inf]),
              np.array([1 + 1j, 2.0]), np.array(["a", "b"]), np.ones((2, 2, 2)), 3.0]

bad_scalar = st.sampled_from(BAD_SCALARS)
bad_array = st.sampled_from(BAD_ARRAYS)
extreme = st.sampled_from([0.0, -0.0, 5e-324, 1e-300, -1e-300, 1e300, -1e300, 1.7e308, -1.7e308, 1e-8, 1e8])


@contextmanager
def watchdog(seconds: float = CALL_SECONDS, backstop: float = WALL_BACKSTOP):
    """Fail if the block spends more than ``seconds`` of CPU time (the process's, every thread's); end the
    process with a traceback if it runs longer than ``backstop`` seconds of wall time."""
    faulthandler.dump_traceback_later(backstop, exit=True)
    start = time.process_time()
    try:
        yield
    finally:
        faulthandler.cancel_dump_traceback_later()
    spent = time.process_time() - start
    assert spent <= seconds, f"the call spent {spent:.1f} s of CPU, more than {seconds:g} s"


def all_finite(value) -> bool:
    """No NaN or inf in a result: arrays, floats, tuples and lists of them, particles (their centres and widths)."""
    if isinstance(value, np.ndarray):
        return value.dtype.kind not in "fc" or bool(np.all(np.isfinite(value)))
    if isinstance(value, float):
        return bool(np.isfinite(value))
    if isinstance(value, (tuple, list)):
        return all(all_finite(item) for item in value)
    if hasattr(value, "centres") and hasattr(value, "widths"):
        return all_finite(value.centres) and all_finite(value.widths)
    return True


def safe_call(function, *args, **kwargs):
    """Call under the watchdog; return the result if finite, None if rejected by ValueError/TypeError.

    Any other exception propagates (the test fails on it), as does a non-finite result.
    """
    with watchdog():
        try:
            result = function(*args, **kwargs)
        except (ValueError, TypeError) as error:
            assert str(error), f"{function.__name__} raised {type(error).__name__} without a message"
            _count_type_refusal(function, [*args, *kwargs.values()], error)
            return None
    assert all_finite(result), f"{function.__name__}{args} returned non-finite values silently"
    return result


#: With the environment variable FUZZ_TYPE_CENSUS set to a file, every refusal of a call given None or bytes is
#: appended to it: the function, and whether the error was a ParameterTypeError (the README's promise for values
#: of the wrong kind) or a plain ValueError/TypeError (issue 30's census).
TYPE_CENSUS = os.environ.get("FUZZ_TYPE_CENSUS")


def _count_type_refusal(function, values, error) -> None:
    if TYPE_CENSUS and any(value is None or isinstance(value, bytes) for value in values):
        kind = "ParameterTypeError" if isinstance(error, ParameterTypeError) else type(error).__name__
        with open(TYPE_CENSUS, "a") as census:
            census.write(f"{getattr(function, '__module__', '?')}.{getattr(function, '__name__', repr(function))}\t"
                         f"{kind}\t{str(error)[:120]!r}\n")


def naming(function, *names):
    """``function``, whose ValueError/TypeError must name one of ``names`` (its parameters)."""

    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except (ValueError, TypeError) as error:
            assert any(name in str(error) for name in names), f"{call.__name__}: {error!r} names none of {names}"
            raise

    call.__name__ = getattr(function, "__name__", repr(function))
    return call
