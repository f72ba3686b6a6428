"""One equation, every method: the 1D aggregation equation with the Newtonian kernel K = |x|/2.

With v = -K' * rho = (M - 2F)/2 the cumulative mass F solves F_t + (M F/2 - F^2/2)_x = 0, a scalar
conservation law with a concave flux, so the sticky paper's SPD, the blob paper's particle and
blob methods, the LTP and SP methods and a finite-volume scheme all approximate one entropy
solution, known exactly (:mod:`.exact`). Public entry points:

- :func:`exact_mass_function`, :class:`AggregationSolution`: the exact solution, before and after
  the blow-up (:mod:`.exact`); :class:`HullSolution` for asymmetric data whose aggregates move and merge
  ('two_bumps', 'skewed_bumps', :mod:`.hull`);
- :mod:`.methods`: every method's output at time t;
- :mod:`.distances`: W1 distances computed on each output;
- :mod:`.aggregates`: a method's aggregates read on its output (the mean of its quantile over an exact
  aggregate's levels) and its merger time, against the exact ones of :class:`HullSolution`;
- the claims of the comparison are measured in :mod:`particle_replication.verdicts.cross`.
"""

from .exact import AggregationSolution, exact_mass_function, solution
from .hull import SKEWED_BUMPS, TWO_BUMPS, BumpData, HullSolution, aggregate_paths, merger_time
from .profiles import PROFILES, Profile, profile

__all__ = ["PROFILES", "SKEWED_BUMPS", "TWO_BUMPS", "AggregationSolution", "BumpData", "HullSolution", "Profile",
           "aggregate_paths", "exact_mass_function", "merger_time", "profile", "solution"]
