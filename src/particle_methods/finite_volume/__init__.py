"""Finite volumes in 1D: the references the sticky particle dynamics are measured against.

- :mod:`.grids`: cell edges, time steps and Courant numbers checked once; exact L1 distances between
  piecewise-constant functions and the step CDFs of particle configurations;
- :mod:`.fluxes`: the scalar fluxes (5.1) and (5.3) of the sticky paper and the exact Godunov flux;
- :mod:`.scalar`: the first-order Godunov scheme for u_t + f(u)_x = 0;
- :mod:`.psystem`: the HLL scheme for the p-system (5.5) and the upwind scheme for diagonal systems (1.7);
- :mod:`.riemann`: the exact Riemann solutions of the p-system.

They import :mod:`particle_methods.systems` (the p-system and the protocol of diagonal systems) and
nothing of the particle methods; the sticky code imports them.
"""

import importlib

#: Where each public name lives; loaded on first use (PEP 562), so that importing one submodule (the
#: scalar scheme for the sticky figures) does not load the others (the p-system's, and scipy.optimize).
_HOMES = {
    "BURGERS": "fluxes", "CONCAVE": "fluxes", "ScalarFlux": "fluxes", "burgers_flux": "fluxes",
    "concave_flux": "fluxes", "godunov_flux": "fluxes",
    "cell_averages_of_step_cdf": "grids", "l1_between_cell_functions": "grids", "l1_distance_to_step_cdf": "grids",
    "hll_psystem": "psystem", "invariants_from_conservative": "psystem", "upwind_diagonal": "psystem",
    "PSystemRiemann": "riemann",
    "MAX_CELL_STEPS": "scalar", "godunov": "scalar",
}


def __getattr__(name):
    if name not in _HOMES:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f".{_HOMES[name]}", __name__), name)


def __dir__():
    return sorted(__all__)


__all__ = [
    "BURGERS",
    "CONCAVE",
    "MAX_CELL_STEPS",
    "PSystemRiemann",
    "ScalarFlux",
    "burgers_flux",
    "cell_averages_of_step_cdf",
    "concave_flux",
    "godunov",
    "godunov_flux",
    "hll_psystem",
    "invariants_from_conservative",
    "l1_between_cell_functions",
    "l1_distance_to_step_cdf",
    "upwind_diagonal",
]
