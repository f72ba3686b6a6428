"""Initial data moved by a few units in the last place: the robustness run's nudge.

A verdict is a property of the mathematics only if the last bits of the initial data do not decide
it. :func:`nudged` returns its argument unchanged unless a nudge is active (:func:`nudge`, or
:func:`set_nudge`); then every entry x becomes x (1 + k eps) with k a pseudo-random whole number in
[-ulps, ulps], drawn from a generator seeded once (eps = 2^-52: a change of at most ``ulps`` units in the
last place, relative, so that zeros, signs and positivity are kept). The constructors of initial data
call it on what they return (positions, masses, weights): :func:`particle_methods.blob.solver.setup_1d`
and ``setup_2d``, :func:`particle_methods.ltp.initial.grid_particles`,
:func:`particle_methods.sticky.measures.median_quantiles` and ``averaged_quantiles`` (the positions (2.1) and
(1.9)), :func:`particle_methods.sticky.spd.velocities_from_flux` (section 1.1.3),
:func:`particle_methods.sticky.cases.psystem_initial_cells` (the finite volumes' cell averages), and
:func:`particle_methods.cross.methods.grid_particles`, ``spd_equal`` and ``godunov_paths``, so one setting
reaches every datum of the pipeline. The pipeline sets it from the configuration key ``nudge`` (0 ulps: off) through
:func:`particle_replication.workflow.logged`.
"""

from __future__ import annotations

import contextlib

import numpy as np

from .validation import finite_values, integer_at_least

#: Largest nudge accepted, in units in the last place: beyond it the change is no longer rounding.
MAX_ULPS = 1024

_state: dict = {"ulps": 0, "generator": None}


def set_nudge(ulps, seed=0) -> None:
    """Nudge every later initial datum by at most ``ulps`` units in the last place (0: off), with the
    pseudo-random draws of a generator seeded with ``seed``."""
    ulps = integer_at_least("ulps", ulps, 0, MAX_ULPS)
    seed = integer_at_least("seed", seed, 0)
    _state.update(ulps=ulps, generator=np.random.default_rng(seed) if ulps else None)


@contextlib.contextmanager
def nudge(ulps, seed=0):
    """:func:`set_nudge` inside the block, the previous setting restored on exit."""
    saved = dict(_state)
    set_nudge(ulps, seed)
    try:
        yield
    finally:
        _state.update(saved)


def nudged(values, *, keep_sorted: bool = False) -> np.ndarray:
    """``values`` (finite reals, any shape) moved by the active nudge, or unchanged when none is active.

    ``keep_sorted``: sort along the last axis afterwards, for data whose order is part of the datum
    (positions at equal places, ties, may come apart in either order)."""
    array = finite_values("values", values)
    if not _state["ulps"]:
        return array
    steps = _state["generator"].integers(-_state["ulps"], _state["ulps"] + 1, size=array.shape)
    moved = array * (1.0 + steps * np.finfo(float).eps)
    return np.sort(moved, axis=-1) if keep_sorted and moved.ndim else moved
