"""Linearly transformed particles (LTP) and smooth particles (SP) for 1D aggregation equations.

Campos Pinto, Carrillo, Charles and Choi. Public entry points:

- :func:`simulate`: run the LTP or SP method, get a :class:`Simulation` whose
  :meth:`~Simulation.at` gives :class:`Particles` (centres, weights, widths) with a
  ``density(x)`` method evaluating the reconstruction (2.27) and ``cumulative_mass(x)`` its CDF;
- :func:`potential`: the potentials of section 6 and the Newtonian |x|/2; :func:`density_named`: data (6.1)-(6.3);
- :data:`HAT`, :data:`B3` (2.12), (2.13) and :func:`hat_biorthogonal_kernel`;
- :func:`exact_density`: the exact solution (6.4) for quadratic potentials.

Every entry point checks its arguments and results: ValueError or TypeError naming the bad
parameter, never NaN or inf returned. :func:`simulate` refuses a time step beyond the stability
bound of explicit Euler (2.31) and work beyond ``solver.MAX_STEPS``, ``checks.MAX_PARTICLES``,
``solver.MAX_PAIRS`` and ``solver.MAX_RECORDED``.
"""

from .exact import exact_density, exact_support
from .initial import InitialDensity, density_named, grid_particles
from .potentials import Potential, potential
from .shapes import B3, HAT, Shape, hat_biorthogonal_kernel, shape_named
from .solver import Particles, Simulation, StabilityError, simulate

__all__ = [
    "B3",
    "HAT",
    "InitialDensity",
    "Particles",
    "Potential",
    "Shape",
    "Simulation",
    "StabilityError",
    "density_named",
    "exact_density",
    "exact_support",
    "grid_particles",
    "hat_biorthogonal_kernel",
    "potential",
    "shape_named",
    "simulate",
]
