"""The blob method and the particle method for the aggregation equation (Craig and Bertozzi).

Public entry points:

- :func:`run_1d`: blob (Definition 2.2) or particle method in 1D, returning a
  :class:`BlobRun` with trajectories, densities along them and the energy E_delta;
- :func:`integrate_particles`: the same ODE system for any particles, masses and kernel
  (any dimension);
- :func:`mollifier`: the mollifiers (4.1), (4.2); :func:`kernel_1d`: 1D kernels, raw or
  mollified in closed form;
- :func:`newtonian_exact`: exact 1D Newtonian solutions by mass coordinates.
"""

from .exact import blowup_time, newtonian_exact
from .initial import Data1D, data_1d, grid_1d
from .kernels import Kernel, kernel_1d
from .mollifiers import Mollifier, mollifier
from .solver import BlobRun, integrate_particles, run_1d

__all__ = [
    "BlobRun",
    "Data1D",
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
