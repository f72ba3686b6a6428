"""Numba settings for every compiled kernel of the package, set in one place."""

from __future__ import annotations

import numba

#: Options passed to :func:`numba.njit` for every kernel. ``cache=True`` keeps the
#: compiled machine code on disk so that pipeline steps do not pay the JIT again.
JIT_OPTIONS = {"cache": True, "nogil": True, "error_model": "numpy"}


def njit(function=None, **overrides):
    """``numba.njit`` with the package's options; usable bare or with overrides."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: numba.njit(**options)(f)
    return numba.njit(**options)(function)
