"""W1 distances to the exact solution, computed on each method's own output.

For measures of equal mass M on the line, W1 is the L1 distance between cumulative mass
functions, ||F - F_h||_{L1(R)} ((1.6) of the sticky paper). Point masses (SPD, particle and blob
methods) and finite-volume cell values of F are step functions, for which
:func:`particle_methods.norms.l1_to_step_function` is exact. The LTP and SP reconstructions
rho_h = sum_k omega_k phi((x - x_k)/h_k)/h_k have a piecewise polynomial F_h: there
:func:`w1_smooth` integrates |F - F_h| by Gauss-Legendre on the pieces where both are smooth,
split at every sign change of F - F_h (found by bisection), so the only error is the Gauss rule's
on smooth integrands.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..ltp.solver import Particles
from ..norms import check_within_range, l1_to_step_function, tail_integrals
from ..validation import ParameterTypeError, finite_array, finite_result, instance, positive, sorted_array
from .exact import AggregationSolution
from .hull import HullSolution

#: The exact solutions W1 is measured against.
SOLUTIONS = (AggregationSolution, HullSolution)

#: Gauss-Legendre nodes per smooth piece of |F - F_h| (exact for polynomials of degree 19).
GAUSS_NODES = 10
#: Largest number of pieces of :func:`w1_smooth` (about 100 MB of samples).
MAX_PIECES = 10**6
#: Bisection steps locating a sign change of F - F_h inside a piece (2^-50 of its length).
ROOT_STEPS = 50
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(GAUSS_NODES)


def w1_atoms(solution: AggregationSolution, positions, masses) -> float:
    """W1 between the exact solution and sum_k masses[k] delta_{positions[k]} (sorted here).

    The masses must be non-negative and add up to the solution's mass M (within 1e-9 relative).
    """
    instance("solution", solution, SOLUTIONS)
    x = finite_array("positions", positions)
    m = finite_array("masses", masses)
    if x.shape != m.shape or x.size == 0:
        raise ValueError(f"positions and masses must have the same non-zero length, got {x.size} and {m.size}")
    if np.any(m < 0):
        raise ValueError("masses must be non-negative")
    check_within_range("positions", x, solution.mass)
    order = np.argsort(x, kind="stable")
    with np.errstate(over="ignore"):  # an overflow fails the check just below
        levels = np.cumsum(m[order])
    if not abs(levels[-1] - solution.mass) <= 1e-9 * solution.mass:
        raise ValueError(f"masses must add up to the mass {solution.mass!r} of the solution, got {levels[-1]!r}")
    return l1_to_step_function(solution, x[order], levels)


def w1_cells(solution: AggregationSolution, edges, values) -> float:
    """W1 between the exact solution and the finite-volume F_h, values[i] on [edges[i], edges[i+1]),
    0 left of the grid and M right of it."""
    instance("solution", solution, SOLUTIONS)
    edges = sorted_array("edges", edges)
    values = finite_array("values", values)
    if values.size + 1 != edges.size:
        raise ValueError(f"need one value per cell: {edges.size} edges and {values.size} values")
    check_within_range("edges", edges, solution.mass)
    return l1_to_step_function(solution, edges, np.append(values, solution.mass))


def _pieces(breaks: np.ndarray, largest: float) -> np.ndarray:
    """The breaks, with pieces longer than ``largest`` cut into equal parts."""
    lengths = np.diff(breaks)
    parts = np.maximum(np.ceil(lengths / largest), 1).astype(np.int64)
    starts = np.repeat(breaks[:-1], parts)
    within = np.arange(parts.sum()) - np.repeat(np.cumsum(parts) - parts, parts)
    return np.append(starts + within * np.repeat(lengths / parts, parts), breaks[-1])


def w1_smooth(solution, cumulative: Callable, breaks, largest: float) -> float:
    """W1 between the exact solution and a measure with continuous cumulative mass ``cumulative``.

    ``breaks`` (sorted) must contain every point where ``cumulative`` is not smooth, and the
    support of the measure: ``cumulative`` is 0 left of breaks[0] and M right of breaks[-1].
    Pieces are cut to at most ``largest`` in length (below the features of both functions); the
    kinks of the exact F (``solution.kinks``: its support's ends, its Dirac masses) are added here.
    On each piece the difference is sampled at the nodes and ends, every sign change is bisected to
    2^-50 of the piece, and each sub-piece is integrated by Gauss-Legendre with GAUSS_NODES nodes.
    """
    instance("solution", solution, SOLUTIONS)
    if not callable(cumulative):
        raise ParameterTypeError(f"cumulative must be callable, got {cumulative!r}")
    breaks = sorted_array("breaks", breaks)
    if breaks.size < 2:
        raise ValueError("breaks must contain at least two points")
    largest = positive("largest", largest)
    with np.errstate(over="ignore"):
        pieces = float(np.ceil((breaks[-1] - breaks[0]) / largest)) + breaks.size
    if not pieces <= MAX_PIECES:
        raise ValueError(f"largest = {largest:g} cuts the breaks' span [{breaks[0]:g}, {breaks[-1]:g}] into about "
                         f"{pieces:.3g} pieces, more than MAX_PIECES = {MAX_PIECES} (each takes {GAUSS_NODES + 2} "
                         "samples): raise largest")
    kinks = [k for k in solution.kinks if breaks[0] < k < breaks[-1]]
    grid = _pieces(np.union1d(breaks, kinks), largest)

    def difference(x):
        values = np.asarray(cumulative(x))
        if np.iscomplexobj(values) or values.shape != x.shape:
            raise ParameterTypeError(f"cumulative must return one real value per point, got {values.dtype} of shape "
                                     f"{values.shape}")
        if not np.all(np.isfinite(values)):
            raise ValueError("cumulative returned NaN or infinite values (a cumulative mass lies in [0, M])")
        return solution.cdf(x) - values

    a, b = grid[:-1], grid[1:]
    samples = np.concatenate([a[:, None], 0.5 * (a + b)[:, None] + 0.5 * (b - a)[:, None] * _NODES, b[:, None]],
                             axis=1)
    values = difference(samples.ravel()).reshape(samples.shape)
    changes = np.sign(values[:, :-1]) * np.sign(values[:, 1:]) < 0
    piece, slot = np.nonzero(changes)
    low, high = samples[piece, slot], samples[piece, slot + 1]
    sign_low = np.sign(values[piece, slot])
    for _ in range(ROOT_STEPS):
        middle = 0.5 * (low + high)
        same = np.sign(difference(middle)) == sign_low
        low, high = np.where(same, middle, low), np.where(same, high, middle)
    cuts = np.union1d(grid, 0.5 * (low + high))
    a, b = cuts[:-1], cuts[1:]
    nodes = 0.5 * (a + b)[:, None] + 0.5 * (b - a)[:, None] * _NODES
    integrals = 0.5 * (b - a) * (difference(nodes.ravel()).reshape(nodes.shape) @ _WEIGHTS)
    total = float(np.sum(np.abs(integrals)))
    total += sum(tail_integrals(solution, breaks[0], breaks[-1]))  # F_h is 0, then M, outside
    return finite_result("W1", total, "the measure's values overflow")


def w1_particles(solution, particles) -> float:
    """W1 between the exact solution and LTP or SP particles (a :class:`~particle_methods.ltp.solver.Particles`):
    :func:`w1_smooth` with the breaks of every particle's shape, where F_h is a polynomial between them, and pieces
    at most the smallest particle width."""
    instance("particles", particles, Particles)
    breaks = np.unique(particles.centres[:, None] + particles.widths[:, None] * particles.shape.breaks[None, :])
    return w1_smooth(solution, particles.cumulative_mass, breaks, particles.widths.min())
