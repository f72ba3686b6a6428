"""The test cases of section 5: initial data, flux or system, and exact solutions."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..finite_volume.fluxes import burgers_flux, concave_flux
from ..finite_volume.grids import checked_edges, l1_between_cell_functions, l1_distance_to_step_cdf
from ..norms import cdf_antiderivative, w1_between_samples, w1_to_measure
from ..perturbation import nudged
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_number,
    finite_result,
    instance,
    integer_at_least,
    nonnegative,
    sorted_array,
)
from .admissibility import flux_values
from .exact import BurgersSolution, ConcaveLaplaceSolution
from .measures import Atoms, Laplace, QuantileMeasure, averaged_quantiles, checked_measure, median_quantiles
from .spd import spd_positions, velocities_from_flux


@dataclass(frozen=True)
class ScalarCase:
    """A scalar conservation law (1.1) with u_0 = H*m and its exact entropy solution."""

    initial: QuantileMeasure
    flux: Callable
    solution: Callable[[float], QuantileMeasure]
    flux_lipschitz: float
    """L_LC, the Lipschitz constant of lambda = flux' (assumption (LC))."""

    def __post_init__(self):
        checked_measure("initial", self.initial)
        flux_values(self.flux, np.array([0.0, 1.0]), "the levels 0 and 1 of u")  # u is a CDF: its levels
        if not callable(self.solution):
            raise ParameterTypeError(f"solution must be callable (t -> the entropy solution's measure), got "
                                     f"{self.solution!r}")
        checked_measure("solution(1)", self.solution(1.0))  # one evaluation: a measure, or refused by its name
        object.__setattr__(self, "flux_lipschitz", nonnegative("flux_lipschitz", self.flux_lipschitz))

    def initial_state(self, n: int):
        """Positions (2.1) and velocities (section 1.1.3) of n particles."""
        return median_quantiles(self.initial, n), velocities_from_flux(self.flux, n)

    def positions(self, n: int, t: float) -> np.ndarray:
        """SPD positions at time t of n particles started from (2.1)."""
        return spd_positions(*self.initial_state(n), t)

    def error(self, n: int, t: float) -> float:
        """L1 distance between the SPD CDF with n particles and u(t, .), exactly."""
        return w1_to_measure(self.solution(t), self.positions(n, t))


_TWO_ATOMS = Atoms([-1.0, 1.0])

SCALAR_CASES = {
    "burgers_two_atoms": ScalarCase(
        initial=_TWO_ATOMS,
        flux=burgers_flux,
        solution=lambda t: BurgersSolution(_TWO_ATOMS, t),
        flux_lipschitz=1.0,
    ),
    "concave_laplace": ScalarCase(
        initial=Laplace(0.0),
        flux=concave_flux,
        solution=ConcaveLaplaceSolution,
        flux_lipschitz=1.0,
    ),
}


def psystem_initial_measures(case: str, x0: float) -> tuple[QuantileMeasure, QuantileMeasure]:
    """Initial measures (m^-, m^+) of the two p-system cases of section 5.2.2.

    ``rarefaction``: m^{+-}(dx) = exp(-|x +- x0|)/2, so w_0^+ >= w_0^- (Figures 4, 5).
    ``shocks``: m^-(dx) = exp(-|x - x0|)/2 and w_0^+ = 1{x >= 0} (Figures 6, 7).
    """
    x0 = finite_number("x0", x0)
    instance("case", case, str)
    if case == "rarefaction":
        return Laplace(x0), Laplace(-x0)
    if case == "shocks":
        return Laplace(x0), Atoms([0.0])
    raise ValueError(f"unknown p-system case {case!r}: expected 'rarefaction' or 'shocks'")


def psystem_initial_configuration(case: str, x0: float, n: int) -> np.ndarray:
    """Configuration (1.9) of n particles per type, rows (w^-, w^+) as in :class:`PSystem`."""
    n = integer_at_least("n", n, 1)
    return np.array([averaged_quantiles(m, n) for m in psystem_initial_measures(case, x0)])


def psystem_initial_cells(case: str, x0: float, x_edges) -> np.ndarray:
    """Exact cell averages of (w_0^-, w_0^+) on the cells of ``x_edges``, shape (2, cells).

    Averages of a CDF lie in [0, 1]; the differences of its antiderivative can pass 1 by rounding
    far in the tails, which the clip removes. Initial data: moved by the active nudge of
    :mod:`particle_methods.perturbation`, if any."""
    edges = sorted_array("x_edges", x_edges)
    if edges.size < 2 or np.any(np.diff(edges) <= 0):
        raise ValueError("x_edges must hold at least 2 strictly increasing edges")
    return np.clip(nudged([np.diff(cdf_antiderivative(m, edges)) / np.diff(edges)
                            for m in psystem_initial_measures(case, x0)]), 0.0, 1.0)


def distance_to_cells(configuration, w, x_edges) -> float:
    """W1^(d) (1.10) between a configuration (d, n) and cell values w (d, cells) of the CDFs: the sum
    over types of the exact L1 distances on the grid, which must hold every particle."""
    configuration = sorted_array("configuration", configuration, ndim=2)
    w = finite_array("w", w, ndim=2)
    if configuration.shape[0] != w.shape[0]:
        raise ValueError(f"configuration (d, n) and w (d, cells) must have the same d, got shapes "
                         f"{configuration.shape} and {w.shape}")
    edges = checked_edges(x_edges)
    if configuration.size and (configuration.min() < edges[0] or configuration.max() > edges[-1]):
        raise ValueError(f"the particles of configuration span [{configuration.min():.6g}, "
                         f"{configuration.max():.6g}], beyond the grid [{edges[0]:.6g}, {edges[-1]:.6g}]: "
                         "widen x_edges")
    distance = 0.0
    for k, (values, points) in enumerate(zip(w, configuration)):
        try:
            distance += l1_distance_to_step_cdf(values, edges, points)
        except ValueError as error:  # its message names its own arguments: say which row of w it was
            raise ValueError(f"w[{k}] against configuration[{k}]: {error}") from None
    return finite_result("the distance between configuration and w", distance, "w is too large")


def cells_distance(w_a, edges_a, w_b, edges_b) -> float:
    """W1^(d) (1.10) between two cell functions of the CDFs, w_a (d, cells_a) on ``edges_a`` and w_b
    (d, cells_b) on ``edges_b`` (the same span): the sum over types of their exact L1 distances."""
    w_a, w_b = finite_array("w_a", w_a, ndim=2), finite_array("w_b", w_b, ndim=2)
    if w_a.shape[0] != w_b.shape[0]:
        raise ValueError(f"w_a and w_b must have the same number of types d, got shapes {w_a.shape} and {w_b.shape}")
    total = 0.0
    for gamma, (a, b) in enumerate(zip(w_a, w_b)):
        try:
            total += l1_between_cell_functions(a, edges_a, b, edges_b)
        except ValueError as error:  # it names values_a and values_b: these are the rows gamma of w_a and w_b
            kind = ParameterTypeError if isinstance(error, TypeError) else ValueError
            raise kind(f"w_a[{gamma}] and w_b[{gamma}]: {error}") from None
    return finite_result("the distance between w_a and w_b", total, "their rows' distances overflow in the sum")


def cells_quantile(w, x_edges, level: float) -> float:
    """inf{x : F(x) >= level} for the CDF F equal to w[i] on the cell [x_edges[i], x_edges[i + 1]): the
    left edge of the first cell whose value reaches ``level`` in (0, 1] (the right end if none does)."""
    w = finite_array("w", w)
    edges = sorted_array("x_edges", x_edges)
    if edges.size != w.size + 1:
        raise ValueError(f"x_edges must hold len(w) + 1 = {w.size + 1} edges, got {edges.size}")
    level = finite_number("level", level)
    if not 0.0 < level <= 1.0:
        raise ValueError(f"level must lie in (0, 1], got {level}")
    reached = np.flatnonzero(w >= level)
    return float(edges[reached[0]] if reached.size else edges[-1])


def configuration_distance(a, b) -> float:
    """W1^(d) (1.10) between two configurations (d, n) and (d, m) of equal-mass particles: the sum over
    types of the W1 distances between their empirical measures."""
    a, b = finite_array("a", a, ndim=2), finite_array("b", b, ndim=2)
    if a.shape[0] != b.shape[0]:
        raise ValueError(f"a and b must be configurations (d, n) with the same d, got shapes {a.shape} and {b.shape}")
    for name, rows in (("a", a), ("b", b)):
        if np.any(np.diff(rows, axis=1) < 0):
            raise ValueError(f"{name} must hold each type's positions sorted in non-decreasing order")
    distance = float(sum(w1_between_samples(x, y) for x, y in zip(a, b)))
    return finite_result("the distance between a and b", distance, "their positions are too far apart")


def empirical_cdf(points, x) -> np.ndarray:
    """CDF (1/n) #{k : points_k <= x} of the empirical measure of sorted ``points``."""
    points = sorted_array("points", points)
    if points.size == 0:
        raise ValueError("points must contain at least one position")
    return np.searchsorted(points, finite_array("x", x), side="right") / points.size

