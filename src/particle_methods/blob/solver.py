"""The blob method (Definition 2.2) and the particle method, integrated to high accuracy.

Both move particles X_i from the grid points ih with masses m_j = rho0_j h^d by
dX_i/dt = -sum_j m_j grad K(X_i - X_j) and carry densities by
d rho_i/dt = -div v_i rho_i with div v_i = -sum_j m_j Delta K(X_i - X_j). The blob
method uses K_delta = K * psi_delta with delta = h^q; the particle method uses K with
grad K(0) := 0 (its density exists only where Delta K is a function).

The ODE system is solved by scipy's DOP853 (explicit Runge-Kutta of order 8 with
step control) at tolerances far below the method's error: the claims check that
tightening them does not change the measured errors. A run holds at most
:data:`~particle_methods.blob.checks.MAX_PARTICLES` particles (``MAX_FMM_PARTICLES`` with the 2D
Newtonian kernel, whose sums are O(N)), ends by
:data:`~particle_methods.blob.checks.MAX_TIME` and is refused past
:data:`~particle_methods.blob.checks.MAX_EVALUATIONS` right-hand sides. In 1D, the particle
method with a kernel whose gradient jumps at 0 (|x|/2) is defined only up to the first
collision of two particles: the solve stops there with a ValueError.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..perturbation import nudged
from ..validation import (
    finite_array,
    finite_number,
    finite_result,
    instance,
    integer_at_least,
    nonnegative,
    one_of,
    positive,
    same_length,
    time_within,
)
from .checks import MAX_EVALUATIONS, MAX_FMM_PARTICLES, MAX_STORED, MAX_TIME, MIN_DELTA_OVER_H, output_times
from .initial import as_data_1d, as_data_2d, grid_1d, grid_2d
from .kernels import Kernel, kernel_1d, kernel_2d
from .mollifiers import mollifier
from .pair_sums import NEWTONIAN_2D_METHODS, checked_pair_sums, checked_terms, pair_energy

#: The two methods of :func:`run_1d` and :func:`run_2d`.
METHODS = {"blob": "K_delta = K * psi_delta, delta = h^q (Definition 2.2)", "particle": "K with grad K(0) := 0"}
#: Relative tolerances scipy's DOP853 accepts without raising them (100 machine epsilons) up to 1.
RTOL_RANGE = (100 * np.finfo(float).eps, 1.0)
#: Absolute tolerances of the ODE solver: below 1e-20 a position near 0 would need steps far below the
#: rounding of the others, and the solve runs into MAX_EVALUATIONS instead of refusing the tolerance.
ATOL_RANGE = (1e-20, 1.0)
#: Largest tracer offset of :func:`mass_defect`: a finite-difference step of the labels, far below the data's
#: extent (the unit interval or disk); the default is 1e-5.
MAX_OFFSET = 0.1


class CollisionError(ValueError):
    """Two particles of the 1D particle method with K = |x|/2 meet at ``time``: past it the method's
    ODE has no classical solution (see :func:`integrate_particles`)."""

    def __init__(self, message: str, time: float):
        super().__init__(message)
        self.time = time


@dataclass(frozen=True)
class BlobRun:
    """Trajectories (times, N, d), densities (times, N) or None, masses (N,), the grid step h (None
    when the particles are not on a grid) and the number of right-hand sides evaluated."""

    kernel: Kernel
    h: float | None
    times: np.ndarray
    positions: np.ndarray
    densities: np.ndarray | None
    masses: np.ndarray
    evaluations: int

    def __post_init__(self):
        """Check types, shapes and finiteness (a run never holds NaN or inf); store float arrays."""
        kernel = instance("kernel", self.kernel, Kernel)
        if self.h is not None:
            positive("h", self.h)
        integer_at_least("evaluations", self.evaluations, 0, MAX_EVALUATIONS)
        times = output_times(self.times)
        positions = finite_array("positions", self.positions, ndim=3)
        masses = finite_array("masses", self.masses)
        expected = (times.size, masses.size, kernel.dimension)
        if positions.shape != expected:
            raise ValueError(f"positions must have shape (times, N, d) = {expected} (times, masses and the kernel's "
                             f"dimension), got {positions.shape}")
        if self.densities is not None:
            densities = finite_array("densities", self.densities, ndim=2)
            if densities.shape != positions.shape[:2]:
                raise ValueError(f"densities must have shape (times, N) = {positions.shape[:2]}, got {densities.shape}")
            object.__setattr__(self, "densities", densities)
        for name, value in (("times", times), ("positions", positions), ("masses", masses)):
            object.__setattr__(self, name, value)

    def energies(self) -> np.ndarray:
        """E_delta of (2.4) along the run (the blob kernel's own K_delta)."""
        if not self.kernel.has_potential:
            raise ValueError(f"the energy needs K_delta itself, which {self.kernel.name} does not tabulate")
        arrays = self.kernel.arrays()
        energies = np.array([pair_energy(x, self.masses, *arrays) for x in self.positions])
        return finite_result("the energy E_delta", energies, "K_delta overflows at these positions")


def _collision_event(points, kernel: Kernel):
    """For the 1D particle method with a kernel whose gradient jumps at 0: the smallest gap between
    particles that are distinct neighbours at t = 0, a terminal event of solve_ivp when it reaches 0.
    Two particles then meet, and the velocities of Definition 2.2 with K for K_delta jump as they
    cross: the ODE has no classical solution past that time (the solver would chatter). None otherwise."""
    if kernel.dimension != 1 or not kernel.jumps_at_origin:
        return None
    order = np.argsort(points[:, 0], kind="stable")
    distinct = np.diff(points[order, 0]) > 0
    left, right = order[:-1][distinct], order[1:][distinct]
    if left.size == 0:
        return None

    def gap(_, state):
        return np.min(state[right] - state[left])

    gap.terminal, gap.direction = True, -1
    return gap


def integrate_particles(points, densities0, masses, kernel: Kernel, times, *, with_density: bool = True,
                        rtol: float = 1e-12, atol: float = 1e-14, h: float | None = None,
                        newtonian_2d: str = "auto") -> BlobRun:
    """Integrate Definition 2.2 for ``kernel`` from particles at ``points`` (N, d) with densities0 and
    masses (N,): dX_i/dt = -sum_j m_j grad K(X_i - X_j) and, ``with_density``,
    d rho_i/dt = -div v_i rho_i, at the output ``times`` (strictly increasing from t >= 0; a single
    time 0 returns the initial state). Raises ValueError beyond the limits of
    :mod:`~particle_methods.blob.checks` and at the first collision of a 1D particle method whose
    kernel's gradient jumps at 0 (a :class:`CollisionError`, carrying the time). ``newtonian_2d`` chooses
    how the 2D Newtonian kernel's sums are taken (:data:`~particle_methods.blob.pair_sums.NEWTONIAN_2D_METHODS`)."""
    kernel = instance("kernel", kernel, Kernel)
    points = finite_array("points", points, ndim=2)
    n, dimension = points.shape
    if dimension != kernel.dimension:
        raise ValueError(f"points must have shape (N, {kernel.dimension}) for the kernel {kernel.name}, "
                         f"got {points.shape}")
    if not 1 <= n <= kernel.max_particles:
        limit = "MAX_FMM_PARTICLES" if kernel.max_particles == MAX_FMM_PARTICLES else "MAX_PARTICLES"
        raise ValueError(f"a run with the kernel {kernel.name} takes 1 to {limit} = {kernel.max_particles} particles "
                         f"(a limit on its work), got {n}")
    densities0, masses = finite_array("densities0", densities0), finite_array("masses", masses)
    same_length(points=points[:, 0], densities0=densities0, masses=masses)
    if np.any(masses < 0):
        raise ValueError("masses must be non-negative")
    times = output_times(times)
    if times.size * n * (dimension + 1) > MAX_STORED:
        raise ValueError(f"a run of {n} particles at {times.size} times stores more than MAX_STORED = {MAX_STORED} "
                         "values (a limit on the memory of one run)")
    instance("with_density", with_density, (bool, np.bool_))
    rtol = finite_number("rtol", rtol)
    if not RTOL_RANGE[0] <= rtol <= RTOL_RANGE[1]:
        raise ValueError(f"rtol must lie in [{RTOL_RANGE[0]:.3g}, {RTOL_RANGE[1]:g}], got {rtol}")
    atol = positive("atol", atol)
    if not ATOL_RANGE[0] <= atol <= ATOL_RANGE[1]:
        raise ValueError(f"atol must lie in [{ATOL_RANGE[0]:.3g}, {ATOL_RANGE[1]:g}], got {atol}")
    h = None if h is None else positive("h", h)
    one_of("newtonian_2d", newtonian_2d, NEWTONIAN_2D_METHODS)
    if times[-1] == 0.0:
        return BlobRun(kernel, h, times, points[None], densities0[None] if with_density else None, masses, 0)

    terms = checked_terms(dimension, *kernel.arrays())  # once: every right-hand side sums the same terms
    masses = np.ascontiguousarray(masses, dtype=np.float64)
    evaluations = 0

    def rhs(t, state):
        nonlocal evaluations
        evaluations += 1
        if evaluations > MAX_EVALUATIONS:
            raise ValueError(f"the ODE solve needs more than MAX_EVALUATIONS = {MAX_EVALUATIONS} right-hand sides "
                             f"(stopped at t = {t:.6g} of {times[-1]:.6g}): the system is too stiff for these "
                             "tolerances or the solver stalls")
        x = np.ascontiguousarray(state[: n * dimension].reshape(n, dimension))
        try:
            velocity, divergence = checked_pair_sums(x, masses, *terms, newtonian_2d)
        except ValueError as error:  # the sums' own message names their arrays, not this function's parameters
            raise ValueError(f"the pair sums at t = {t:.6g} refused the particles ({error}): points, masses or "
                             "densities0 too large for the kernel") from None
        if not with_density:
            derivative = velocity.ravel()
        else:
            derivative = np.concatenate([velocity.ravel(), -divergence * state[n * dimension:]])
        return finite_result(f"the right-hand side at t = {t:.6g}", derivative,
                             "the velocities or densities overflow (points, masses, densities0 or the kernel too "
                             "large)")

    start = points.ravel() if not with_density else np.concatenate([points.ravel(), densities0])
    collision = _collision_event(points, kernel)
    solution = solve_ivp(rhs, (0.0, times[-1]), start, method="DOP853", t_eval=times, rtol=rtol, atol=atol,
                         events=collision)
    if solution.status == 1:
        time = float(solution.t_events[0][0])
        raise CollisionError(f"two particles collide at t = {time:.6g}: the particle method with the kernel "
                             f"{kernel.name}, whose gradient jumps at 0, is defined only up to the first collision; "
                             "ask for times before it", time)
    if not solution.success:
        raise ValueError(f"the ODE integrator failed: {solution.message} (points, masses or densities0 too large for "
                         "the tolerances rtol and atol)")
    states = solution.y.T
    positions = states[:, : n * dimension].reshape(times.size, n, dimension)
    densities = states[:, n * dimension:] if with_density else None
    return BlobRun(kernel, h, times, positions, densities, masses, evaluations)


def _exponent_q(q) -> float:
    """The exponent of delta = h^q, 1/2 < q < 1 as in Theorem 3.8."""
    q = finite_number("q", q)
    if not 0.5 < q < 1.0:
        raise ValueError(f"q must lie in (1/2, 1), got {q}")
    return q


def setup_1d(data, kernel: str, h: float, *, method: str = "blob", order: int = 4, q: float = 0.9):
    """(points (N, 1), rho0, masses, kernel, with_density) of the 1D blob or particle method."""
    data = as_data_1d(data)
    one_of("method", method, METHODS)
    psi, q = mollifier(order, 1), _exponent_q(q)
    points = grid_1d(h)
    rho0 = data(points[:, 0])
    # The data nudged as data: the density is evaluated on the grid first, so that a grid point on a jump of the
    # data (the ends of the indicator (4.4)) keeps its value whichever way its position moves.
    points, rho0, masses = nudged(points), nudged(rho0), nudged(rho0 * h)
    if method == "blob":
        return points, rho0, masses, kernel_1d(kernel, psi, h**q), True
    # Delta K is a Dirac mass for the Newtonian kernels: no density.
    return points, rho0, masses, kernel_1d(kernel), kernel == "cubic"


def run_1d(data, kernel: str, h: float, times, *, method: str = "blob", order: int = 4, q: float = 0.9,
           rtol: float = 1e-12, atol: float = 1e-14) -> BlobRun:
    """Blob (default) or particle method in 1D from data (4.3)-(4.5) on the grid hZ of [-1, 1].

    Parameters
    ----------
    data : a :class:`~particle_methods.blob.initial.Data1D` or its name ('smooth20', 'indicator', 'smooth10').
    kernel : 'newtonian_attractive' (|x|/2), 'newtonian_repulsive' (-|x|/2) or 'cubic' (|x|^3/3).
    h : grid step (must divide 1).  times : output times, strictly increasing, from t >= 0 (up to MAX_TIME).
    method : 'blob' (mollifier of ``order`` m, delta = h^q with 1/2 < q < 1) or 'particle'
        (grad K(0) := 0; densities only for kernels whose Laplacian is a function; with |x|/2 the
        run must end before the first collision of two particles).
    """
    points, rho0, masses, k, with_density = setup_1d(data, kernel, h, method=method, order=order, q=q)
    return integrate_particles(points, rho0, masses, k, times, with_density=with_density, rtol=rtol, atol=atol, h=h)


def setup_2d(data, kernel: str, h: float, *, method: str = "blob", q: float = 0.9, delta: float | None = None,
             table_radius: float = 5.0, table_points: int = 8001):
    """(points (N, 2), rho0, masses, kernel, with_density) of the 2D blob (m = 4, (4.2)) or particle method;
    the radial tables of a tabulated blob kernel cover [0, table_radius] with table_points nodes. A given
    delta must be at least MIN_DELTA_OVER_H h (the particle method ignores it)."""
    data = as_data_2d(data)
    one_of("method", method, METHODS)
    q = _exponent_q(q)
    points = grid_2d(h, data)
    h = float(h)
    if delta is not None and positive("delta", delta) < MIN_DELTA_OVER_H * h:
        raise ValueError(f"delta = {delta} must be at least MIN_DELTA_OVER_H h = {MIN_DELTA_OVER_H * h:.4g}: smaller "
                         "blobs barely overlap and the densities blow up")
    rho0 = data(points)
    points, rho0, masses = nudged(points), nudged(rho0), nudged(rho0 * h * h)  # as in setup_1d
    tables = {"table_radius": table_radius, "table_points": table_points}
    if method == "blob":
        k = kernel_2d(kernel, mollifier(4, 2), h**q if delta is None else delta, **tables)
        return points, rho0, masses, k, True
    # Delta K is a Dirac mass for the Newtonian kernel: no density.
    return points, rho0, masses, kernel_2d(kernel, **tables), kernel != "newtonian"


def run_2d(data, kernel: str, h: float, times, *, method: str = "blob", q: float = 0.9, delta: float | None = None,
           rtol: float = 1e-10, atol: float = 1e-12, table_radius: float = 5.0, table_points: int = 8001) -> BlobRun:
    """Blob (m = 4 mollifier (4.2), delta = h^q unless ``delta`` is given) or particle method in 2D
    for a kernel of :data:`~particle_methods.blob.kernels.KERNELS_2D` and data of section 4.4
    (tabulated kernels: radial tables on [0, table_radius] with table_points nodes)."""
    points, rho0, masses, k, with_density = setup_2d(data, kernel, h, method=method, q=q, delta=delta,
                                                     table_radius=table_radius, table_points=table_points)
    return integrate_particles(points, rho0, masses, k, times, with_density=with_density, rtol=rtol, atol=atol, h=h)


def mass_defect(points, rho0, masses, kernel: Kernel, t: float, *, offset: float = 1e-5, rtol: float = 1e-12,
                atol: float = 1e-14, threshold: float = 1e-3) -> float:
    """max_i |rho~_i J_i / rho0_i - 1| at time t: mass conservation along trajectories (2.2).

    J_i = det(dX~/dalpha) at particle i comes from massless tracers at alpha_i +- offset e_k,
    which follow the off-grid trajectory map of Definition 2.3; particles with rho0 below
    ``threshold`` are skipped (relative errors there say nothing). The tracers count towards the
    kernel's limit (:attr:`Kernel.max_particles`): (2d + 1) N in all.
    """
    points = finite_array("points", points, ndim=2)
    rho0, masses = finite_array("rho0", rho0), finite_array("masses", masses)
    n, dimension = points.shape
    if dimension not in (1, 2):
        raise ValueError(f"points must have shape (N, d) with d = 1 or 2, got {points.shape}")
    same_length(points=points[:, 0], rho0=rho0, masses=masses)
    t = time_within("t", t, MAX_TIME, "MAX_TIME", "a limit on the work of one run")
    offset, threshold = positive("offset", offset), nonnegative("threshold", threshold)
    if offset > MAX_OFFSET:
        raise ValueError(f"offset = {offset} must be at most MAX_OFFSET = {MAX_OFFSET} (a finite-difference step)")
    inside = rho0 > threshold
    if not np.any(inside):
        raise ValueError(f"no particle has rho0 above threshold = {threshold}")
    tracers = [points]
    for axis in range(dimension):
        for sign in (-1.0, 1.0):
            shifted = points.copy()
            shifted[:, axis] += sign * offset
            tracers.append(shifted)
    all_points = np.concatenate(tracers)
    all_masses = np.concatenate([masses, np.zeros(2 * dimension * n)])
    all_rho = np.concatenate([rho0] + [rho0] * (2 * dimension))
    run = integrate_particles(all_points, all_rho, all_masses, kernel, [t], rtol=rtol, atol=atol)
    final = run.positions[-1]
    jacobian = np.empty((n, dimension, dimension))
    for axis in range(dimension):
        minus = final[(1 + 2 * axis) * n:(2 + 2 * axis) * n]
        plus = final[(2 + 2 * axis) * n:(3 + 2 * axis) * n]
        jacobian[:, :, axis] = (plus - minus) / (2 * offset)
    determinant = np.linalg.det(jacobian)
    defect = np.abs(run.densities[-1, :n][inside] * determinant[inside] / rho0[inside] - 1).max()
    return float(finite_result("the mass defect", defect, f"offset = {offset} is too small or too large"))
