"""The census's calls (:mod:`census`) for ``particle_methods.finite_volume``: one good call of each public callable, by
keyword (:data:`ENTRIES`, built with :class:`census.Entry`), and the callables exempt from it with the reason
(:data:`EXEMPT`). Merged into :mod:`census_entries`. Tiny sizes and short times, so that the census stays cheap."""

from __future__ import annotations

import numpy as np
from census import Entry as E

from particle_methods import systems
from particle_methods.finite_volume import fluxes, grids, psystem, riemann

PM = "particle_methods."
A = np.array

EDGES = np.linspace(-1.0, 1.0, 11)
POINTS = A([-0.5, 0.0, 0.25, 0.5])
HALF = systems.PSystem(nu=0.5, kappa=5.0)
U0 = np.full(10, 0.2)
V0 = np.linspace(0.0, 0.05, 10)
W0 = np.vstack([np.linspace(0.3, 0.4, 10), np.linspace(0.6, 0.7, 10)])
LEFT, RIGHT = (0.1, 0.0), (0.15, 0.05)


def riemann_problem():
    """A Riemann problem of the p-system whose three states lie in the lower half u <= nu/2."""
    return riemann.PSystemRiemann(HALF, LEFT, RIGHT)


def method(factory, name):
    """The bound method ``name`` of a fresh good instance (a function of the census's keyword arguments)."""
    return getattr(factory(), name)


ENTRIES = {
    PM + "finite_volume.fluxes.ScalarFlux": E(fluxes.ScalarFlux, {
        "f": fluxes.burgers_flux, "derivative": fluxes.BURGERS.derivative, "extremum": 0.0, "shape": "convex"}),
    PM + "finite_volume.grids.cell_averages_of_step_cdf": E(grids.cell_averages_of_step_cdf, {"points": POINTS,
                                                                                          "x_edges": EDGES}),
    PM + "finite_volume.grids.l1_distance_to_step_cdf": E(grids.l1_distance_to_step_cdf, {
        "values": np.linspace(0.0, 1.0, 10), "x_edges": EDGES, "points": POINTS}),
    PM + "finite_volume.grids.check_cell_steps": E(grids.check_cell_steps, {"t": 0.1, "dt": 0.01, "cells": 10,
                                                                            "limit": 1000},
                                                   names={"dt": ("time step",)}),
    PM + "finite_volume.grids.check_cells_match": E(grids.check_cells_match, {
        "name": "u0", "values": np.zeros(10), "edges": EDGES, "edges_name": "x_edges"},
        kinds={"name": "fixed", "edges_name": "fixed"}, names={"values": ("u0",), "edges": ("x_edges",)}),
    PM + "finite_volume.grids.checked_time_and_cfl": E(grids.checked_time_and_cfl, {"t": 0.1, "cfl": 0.9}),
    PM + "finite_volume.psystem.hll_psystem": E(psystem.hll_psystem, {"system": HALF, "u0": U0, "v0": V0,
                                                                      "x_edges": EDGES, "t": 0.05, "cfl": 0.9}),
    PM + "finite_volume.psystem.invariants_from_conservative": E(psystem.invariants_from_conservative, {
        "system": HALF, "u": U0, "v": V0, "tolerance": 1e-12}),
    PM + "finite_volume.psystem.upwind_diagonal": E(psystem.upwind_diagonal, {
        "system": HALF, "w0": W0, "x_edges": EDGES, "t": 0.05, "cfl": 0.9, "return_steps": False, "threads": 1},
        accepts={"threads": [10**400]}),  # clamped to the process's threads
    PM + "finite_volume.riemann.PSystemRiemann": E(riemann.PSystemRiemann, {"system": HALF, "left": LEFT,
                                                                            "right": RIGHT},
                                                   kinds={"left": "object", "right": "object"}),
    PM + "finite_volume.riemann.PSystemRiemann.state": E(method(riemann_problem, "state"), {"xi": A([-1.0, 0.0, 1.0])}),
    PM + "finite_volume.riemann.PSystemRiemann.cell_averages": E(method(riemann_problem, "cell_averages"), {
        "x_edges": EDGES, "t": 0.5}),
    PM + "finite_volume.riemann.Wave": E(riemann.Wave, {"family": 1, "left_edge": -0.5, "right_edge": -0.4}),
}

EXEMPT: dict = {}
