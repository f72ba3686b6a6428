"""Particle methods for aggregation equations and 1D conservation laws: the numerics only.

Subpackages hold one paper each: ``sticky`` (Jourdain and Reygner, sticky particle dynamics and their
multitype version), ``ltp`` (Campos Pinto, Carrillo, Charles and Choi, linearly transformed particles
(LTP) and smooth particles (SP)), ``blob`` (Craig and Bertozzi, the blob and particle methods), and
``cross`` (the 1D aggregation equation with K = |x|/2 solved by every method against its exact
solution); ``finite_volume`` holds the finite-volume references. The modules at this level are shared:
``validation`` (input checks), ``norms`` (error norms), ``convergence`` (order fitting), ``systems``
(the diagonal systems (1.7) of the sticky paper and the p-system), ``perturbation`` (initial data
nudged by a few ulps), ``threads`` (thread pools of the kernels and libraries) and ``jit`` (numba
settings).

The claims, verdicts, plotting, configuration checks and the pipeline's helpers are the replication
layer, the package ``particle_replication``.
"""

__version__ = "0.1.0"
