"""The blob method and the particle method for the aggregation equation (Craig and Bertozzi).

Public entry points:

- :func:`run_1d`: blob (Definition 2.2) or particle method in 1D, returning a
  :class:`BlobRun` with trajectories, densities along them and the energy E_delta;
- :func:`integrate_particles`: the same ODE system for any particles, masses and kernel
  (any dimension);
- :func:`mollifier`: the mollifiers (4.1), (4.2); :func:`kernel_1d`: 1D kernels, raw or
  mollified in closed form;
- :func:`newtonian_exact`, :func:`newtonian_exact_2d`: exact Newtonian solutions by mass coordinates;
- :func:`run_2d`, :func:`kernel_2d`: the 2D method and kernels of section 4.4 (closed forms or
  tabulated radial convolution); :func:`uniform_ring_radius`: stationary rings;
- :func:`mass_defect`: mass conservation along trajectories with massless tracers.

Every entry point checks its inputs (ValueError or TypeError naming the parameter) and its results
(no NaN or inf: :func:`blowup_time`'s inf for a repulsive kernel, "never", is the one exception), and
refuses work beyond the limits of :mod:`particle_methods.blob.checks` (particles, final time,
right-hand sides of a solve, radial tables); the 1D particle method with |x|/2 stops at the first
collision of two particles, where its ODE stops being defined.
"""

from .exact import blowup_time, newtonian_exact, newtonian_exact_2d
from .initial import Data1D, Data2D, data_1d, data_2d, grid_1d, grid_2d
from .kernels import Kernel, kernel_1d, kernel_2d
from .mollifiers import Mollifier, mollifier
from .rings import uniform_ring_radius
from .solver import BlobRun, CollisionError, integrate_particles, mass_defect, run_1d, run_2d

__all__ = [
    "BlobRun",
    "CollisionError",
    "Data1D",
    "Data2D",
    "data_2d",
    "grid_2d",
    "kernel_2d",
    "mass_defect",
    "newtonian_exact_2d",
    "run_2d",
    "uniform_ring_radius",
    "Kernel",
    "Mollifier",
    "blowup_time",
    "data_1d",
    "grid_1d",
    "integrate_particles",
    "kernel_1d",
    "mollifier",
    "newtonian_exact",
    "run_1d",
]
