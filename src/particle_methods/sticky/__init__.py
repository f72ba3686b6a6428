"""Sticky particle dynamics for 1D conservation laws and diagonal systems (Jourdain-Reygner).

Public entry points:

- :func:`spd_positions`, :func:`spd_trajectories`: SPD at given times (section 5.1.1),
  with equal masses 1/n or with given ``masses`` (for instance grid weights rho0(x_j) h);
- :func:`velocities_from_flux`: initial velocities of section 1.1.3; :func:`velocities_from_levels`:
  the same at cumulative masses 0 = c_0 < ... < c_n, for unequal masses c_k - c_{k-1};
- :func:`median_quantiles` (2.1), :func:`averaged_quantiles` (1.9): initial positions;
- measures with exact quantiles (:class:`Atoms`, :class:`Laplace`, ...) and exact
  entropy solutions (:class:`BurgersSolution`, :class:`ConcaveLaplaceSolution`);
- :func:`mspd_trajectory`, :func:`mspd_positions`, :func:`rank_velocities`: the
  iterated typewise SPD for diagonal systems (sections 4.1, 5.2.1), :class:`ScalarLaw` a scalar
  law as a system with d = 1; :func:`mspd_exact`: the
  MSPD itself, event by event (section 5.2); :func:`mspd_exact_at`: the same at one time, over the grid of
  crossings where particles of one type never meet;
- :class:`PSystem`: the p-system of section 5.2.2 in Riemann invariants;
- :func:`spd_state`, :func:`admissibility_violation`: the SPD's positions and velocities at time t, and
  the Rankine-Hugoniot speeds and Oleinik's condition at every jump; :func:`hopf_gap`: the exact test of
  Remark 3.3, a state against Hopf's formula for the entropy solution of the discretised data.
"""

from ..finite_volume.fluxes import burgers_flux, concave_flux
from ..systems import PSystem
from .admissibility import Admissibility, admissibility_violation, spd_state
from .exact import BurgersSolution, ConcaveLaplaceSolution
from .hopf import hopf_gap
from .measures import (
    Atoms,
    Laplace,
    Pareto,
    QuantileMeasure,
    TruncatedExponential,
    TruncatedPareto,
    Uniform,
    Weibull,
    averaged_quantiles,
    median_quantiles,
)
from .mspd import ScalarLaw, mspd_positions, mspd_trajectory, rank_velocities
from .multitype_events import EventCounts, mspd_exact, mspd_exact_at
from .spd import cluster_sizes, spd_positions, spd_trajectories, velocities_from_flux, velocities_from_levels

__all__ = [
    "Admissibility",
    "Atoms",
    "BurgersSolution",
    "ConcaveLaplaceSolution",
    "EventCounts",
    "Laplace",
    "PSystem",
    "Pareto",
    "QuantileMeasure",
    "ScalarLaw",
    "TruncatedExponential",
    "TruncatedPareto",
    "Uniform",
    "Weibull",
    "admissibility_violation",
    "averaged_quantiles",
    "burgers_flux",
    "cluster_sizes",
    "concave_flux",
    "hopf_gap",
    "median_quantiles",
    "mspd_exact",
    "mspd_exact_at",
    "mspd_positions",
    "mspd_trajectory",
    "rank_velocities",
    "spd_positions",
    "spd_state",
    "spd_trajectories",
    "velocities_from_flux",
    "velocities_from_levels",
]
