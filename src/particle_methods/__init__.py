"""Particle methods for aggregation equations and 1D conservation laws.

Subpackages hold one paper each (``sticky`` for Jourdain and Reygner's sticky
particle dynamics); the modules at this level are shared by all papers:
``validation`` (input checks), ``norms`` (error norms), ``convergence``
(order fitting), ``claims`` (the table of checked claims), ``plotting``
(figure style), ``configuration`` (checks of the pipeline configuration
beyond its schema), ``environment`` (software versions and the commit of a
run) and ``jit`` (numba settings).
"""

__version__ = "0.1.0"
