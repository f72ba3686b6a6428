"""Every method of the three papers applied to one equation: rho_t + (rho v)_x = 0, v = -K' * rho,
K = |x|/2 (so v = (M - 2F)/2), from the symmetric data of :mod:`.profiles` and (SPDs, blob method,
Godunov) the asymmetric bump data of :mod:`.hull` ('two_bumps', 'skewed_bumps').

Each function returns the method's own output at time t, the object W1 is measured on
(:mod:`.distances`): positions and masses of point masses, cell values of F, or LTP/SP particles.

- :func:`spd_equal`: the SPD of the sticky paper for the flux Lambda(F) = M F/2 - F^2/2, n equal
  masses M/n at the median quantiles (2.1), velocities n (Lambda(kM/n) - Lambda((k-1)M/n))/M.
- :func:`spd_grid`: the SPD with the blob paper's grid particles, weighted (the weighted
  Brenier-Grenier hull), velocities (mass right - mass left)/2.
- :func:`particle_method`: the blob paper's particle method (Definition 2.2 with grad K(0) = 0),
  integrated by DOP853; defined up to the first collision of two particles.
- :func:`blob_method`: Definition 2.2 with K_delta = K * psi_delta, delta = h^q (:func:`blob_paths`: at
  several times from one integration).
- :func:`ltp_method`: LTP (and SP) of Campos Pinto et al. with W = |x|/2 (:func:`ltp_paths`: at several
  times from one run).
- :func:`godunov_mass`: Godunov for F; with u = F/M and tau = M t the law is (5.3),
  u_tau + (u(1 - u)/2)_x = 0, solved by :func:`particle_methods.finite_volume.godunov` (:func:`godunov_paths`: at
  several times from one run; :func:`godunov_advance`: from any state).

The grid particles sit at jh on [-1, 1] with masses rho0(jh) h, except the two ends, whose masses
are halved (the trapezoid rule): the blob paper puts mass h at +-1 for the indicator (4.4), so its
particles carry 2 + h instead of 2, and W1 between measures of different masses is infinite. For
the smooth data rho0(+-1) = 0 and nothing changes. Particles of zero mass are left out.
"""

from __future__ import annotations

import numpy as np

from ..blob.checks import MAX_PARTICLES
from ..blob.checks import MAX_TIME as MAX_BLOB_TIME
from ..blob.kernels import kernel_1d
from ..blob.mollifiers import mollifier
from ..blob.pair_sums import pair_sums
from ..blob.solver import integrate_particles
from ..finite_volume.fluxes import CONCAVE
from ..finite_volume.grids import MAX_CELLS
from ..finite_volume.scalar import MAX_CELL_STEPS, cfl_time_step, godunov
from ..ltp.initial import InitialDensity
from ..ltp.potentials import potential
from ..ltp.solver import MAX_STEPS as MAX_LTP_STEPS
from ..ltp.solver import simulate
from ..norms import cdf_antiderivative
from ..perturbation import nudged
from ..sticky.spd import MAX_POSITIONS, spd_positions
from ..validation import finite_array, finite_result, integer_at_least, nonnegative, positive, same_length, time_within
from .exact import solution
from .hull import BUMP_DATA, BumpData, bump_data
from .profiles import Profile, profile

#: The attractive Newtonian kernel |x|/2 of the blob package.
KERNEL = "newtonian_attractive"
#: Shape of the LTP and SP particles: the cubic B-spline (2.13) of the LTP paper's runs.
SHAPE = "b3"
#: Largest n of :func:`spd_equal`: its quantiles take one Newton iteration per particle (2^22 in about 10 s).
MAX_EQUAL_MASSES = 2**22
#: Latest time of the SPDs: their velocities carry rounding errors of about 1e-16 (a cluster at rest moves at
#: that speed), which t multiplies; up to 1e6 they move positions of order 1 by at most about 1e-10.
MAX_TIME = 1e6
#: Widest span, and largest magnitude, of the positions :func:`particle_velocities` takes: the pair sums square the
#: distances between them (and the positions), which overflow from 1.3e154 on (NaN velocities before issue 46).
MAX_VELOCITY_SPAN = 1e150
#: Rounding allowed in the values of F that :func:`godunov_advance` takes, relative to the mass: the robustness run's
#: nudge (1024 units in the last place, 2.3e-13) and a rounding error of one of its own runs (clipped to [0, M]).
F_ROUNDING = 1e-12
#: Most times of one :func:`godunov_paths` call: each ends a run of the scheme (about 0.25 ms of fixed cost) and
#: keeps its state; the pipeline asks for about 20.
MAX_PATH_TIMES = 10**5
#: Most cell values :func:`godunov_paths` keeps, times x cells (800 MB); the pipeline keeps about 3 * 10**5.
MAX_PATH_VALUES = 10**8


def _spd_time(t) -> float:
    return time_within("t", t, MAX_TIME, "MAX_TIME", "the rounding of the velocities, times t, would move the "
                       "particles by more than their positions' accuracy")


def aggregation_flux(mass: float):
    """Lambda(F) = M F/2 - F^2/2, the flux of the law of the cumulative mass F (M > 0 finite: the total mass)."""
    mass = positive("mass", mass)
    return lambda level: 0.5 * mass * np.asarray(level) - 0.5 * np.asarray(level) ** 2


def _compact(shape: Profile) -> Profile:
    if not np.isfinite(shape.radius) or shape.radius != 1.0:
        raise ValueError(f"the grid methods need data supported in [-1, 1], got {shape.name}")
    return shape


def _is_bumps(data) -> bool:
    return isinstance(data, BumpData) or (isinstance(data, str) and data in BUMP_DATA)


def _grid_density(data):
    """rho0 of data the grid methods take: a symmetric profile on [-1, 1], or bump data inside [-1, 1]."""
    if _is_bumps(data):
        bumps = bump_data(data)
        low, high = bumps.support
        if low < -1.0 or high > 1.0:
            raise ValueError(f"the grid methods need data supported in [-1, 1], got {bumps.name} on [{low}, {high}]")
        return bumps.density
    return _compact(profile(data)).density


def grid_particles(data, h: float):
    """(positions, densities rho0(jh), masses) of the grid particles jh in [-1, 1] with positive
    mass; masses rho0(jh) h, halved at the two ends (trapezoid rule, total mass exact for (4.4)).
    1/h must be a whole number k (the grid then holds +-1); at most MAX_POSITIONS = 2k + 1 points.
    For bump data (two_bumps, skewed_bumps) the masses are scaled to the exact total: c (1 - s^2)^2 is only C^1 at the
    ends of its support, where the trapezoid rule then errs by O(h^2) (6e-5 of the mass at h = 1/20), and W1
    between measures of different masses is infinite; for (4.3)-(4.5) the sum is exact to rounding."""
    density_of = _grid_density(data)
    h = positive("h", h)
    if not 1.0 / h <= MAX_POSITIONS:  # (1/h overflows to inf for the smallest h)
        raise ValueError(f"h = {h} gives more than MAX_POSITIONS = {MAX_POSITIONS} grid points")
    k = round(1.0 / h)
    if not (k >= 1 and abs(k * h - 1.0) <= 1e-9):
        raise ValueError(f"1/h must be a whole number, got h = {h}")
    if 2 * k + 1 > MAX_POSITIONS:
        raise ValueError(f"h = {h} gives {2 * k + 1} grid points, more than MAX_POSITIONS = {MAX_POSITIONS}")
    points = np.arange(-k, k + 1) / k
    density = density_of(points)
    masses = density * h
    masses[[0, -1]] *= 0.5
    keep = masses > 0
    masses = masses[keep]
    if _is_bumps(data):
        masses *= bump_data(data).mass / np.sum(masses)
    return nudged(points[keep], keep_sorted=True), density[keep], nudged(masses)


def _levels(masses):
    return np.concatenate(([0.0], np.cumsum(masses)))


def weighted_velocities(masses) -> np.ndarray:
    """(mass right - mass left)/2 of each particle, sorted by position: the particle method's velocity
    -sum_j m_j K'(x_i - x_j) with K'(0) = 0, and the SPD velocity (Lambda(c_k) - Lambda(c_{k-1}))/m_k
    of the flux Lambda(F) = M F/2 - F^2/2 on the level interval (c_{k-1}, c_k] of the particle, which
    is (M - c_{k-1} - c_k)/2 (in this closed form, so that masses below the rounding of the levels,
    such as rho0(jh) h ~ 1e-100 near the ends of (4.3), keep their velocity)."""
    masses = finite_array("masses", masses)
    if masses.size == 0 or np.any(masses <= 0):
        raise ValueError("masses must be positive, at least one")
    with np.errstate(over="ignore"):
        levels = _levels(masses)
    if not np.isfinite(levels[-1]):
        raise ValueError("masses must have a finite sum: their total overflows")
    return 0.5 * (levels[-1] - levels[:-1] - levels[1:])


def particle_velocities(x, masses) -> np.ndarray:
    """-sum_j m_j K'(x_i - x_j) with K = |x|/2 and K'(0) = 0 at any positions (ties exert no force): the
    right-hand side of the particle method, by the blob package's pair sums. Masses are non-negative with a finite
    sum; the positions span at most :data:`MAX_VELOCITY_SPAN` (the pair sums square the distances)."""
    if isinstance(x, np.ndarray) and x.size > MAX_PARTICLES:  # from the shape, before any copy
        raise ValueError(f"x has {x.size} points, more than MAX_PARTICLES = {MAX_PARTICLES} (a limit on the O(n^2) "
                         "work of the pair sums)")
    x = finite_array("x", x)
    masses = finite_array("masses", masses)
    same_length(x=x, masses=masses)
    if x.size > MAX_PARTICLES:
        raise ValueError(f"x has {x.size} points, more than MAX_PARTICLES = {MAX_PARTICLES} (a limit on the O(n^2) "
                         "work of the pair sums)")
    if np.any(masses < 0):
        raise ValueError(f"masses must be non-negative, got {float(masses.min())!r} at index {int(masses.argmin())}")
    with np.errstate(over="ignore"):
        if not np.isfinite(np.sum(masses)):
            raise ValueError("masses must have a finite sum: their total overflows")
        span = np.ptp(x) if x.size else 0.0
    if not span <= MAX_VELOCITY_SPAN:
        raise ValueError(f"x spans {span:.3g}, more than MAX_VELOCITY_SPAN = {MAX_VELOCITY_SPAN:.0e}: the pair sums "
                         "square the distances, which overflow beyond 1.3e154")
    if x.size and not np.max(np.abs(x)) <= MAX_VELOCITY_SPAN:
        raise ValueError(f"x must lie in [-MAX_VELOCITY_SPAN, MAX_VELOCITY_SPAN] = +-{MAX_VELOCITY_SPAN:.0e}, got "
                         f"{float(np.max(np.abs(x))):.3g}: the pair sums square the positions")
    velocity, _ = pair_sums(x[:, None], masses, *kernel_1d(KERNEL).arrays())
    return finite_result("the velocities", velocity[:, 0], "the masses are too large: their sums overflow")


def spd_equal(data, n: int, t: float):
    """(positions, masses) of the SPD with n equal masses at the median quantiles (2.1), at time t."""
    initial = solution(data, 0.0)
    n = integer_at_least("n", n, 1, MAX_EQUAL_MASSES)
    t = _spd_time(t)
    x = nudged(initial.quantile((np.arange(n) + 0.5) * (initial.mass / n)), keep_sorted=True)
    masses = nudged(np.full(n, initial.mass / n))
    return spd_positions(x, weighted_velocities(masses), t), masses


def spd_grid(data, h: float, t: float):
    """(positions, masses) of the weighted SPD from the grid particles of :func:`grid_particles`."""
    x, _, masses = grid_particles(data, h)
    return spd_positions(x, weighted_velocities(masses), _spd_time(t), masses=masses), masses


def particle_method(data, h: float, t: float, *, rtol: float = 1e-12, atol: float = 1e-14):
    """(positions, masses) of the blob paper's particle method at t (before the first collision)."""
    x, density, masses = grid_particles(data, h)
    run = integrate_particles(x[:, None], density, masses, kernel_1d(KERNEL), [_blob_time(t)],
                              with_density=False, rtol=rtol, atol=atol, h=h)
    return run.positions[-1, :, 0], masses


def blob_method(data, h: float, t: float, *, order: int, q: float, rtol: float = 1e-12, atol: float = 1e-14):
    """(positions, masses) of the blob method with the mollifier of ``order`` and delta = h^q at t."""
    positions, masses = blob_paths(data, h, [_blob_time(t)], order=order, q=q, rtol=rtol, atol=atol)
    return positions[-1], masses


def _blob_time(t) -> float:
    """The time of one particle or blob run, checked here so that the errors name ``t``, not the solver's times."""
    return time_within("t", t, MAX_BLOB_TIME, "the particle solver's MAX_TIME", "a limit on the work of one run")


def blob_paths(data, h: float, times, *, order: int, q: float, rtol: float = 1e-12, atol: float = 1e-14):
    """(positions at each of the increasing ``times``, shape (times, particles); masses) of the blob method with
    the mollifier of ``order`` and delta = h^q, from one integration."""
    x, density, masses = grid_particles(data, h)
    h = positive("h", h)
    delta = h ** positive("q", q)
    if not delta > 0:
        raise ValueError(f"q = {q} makes delta = h^q = {h}^{q} underflow to 0")
    kernel = kernel_1d(KERNEL, mollifier(order, 1), delta)
    run = integrate_particles(x[:, None], density, masses, kernel, times, with_density=False, rtol=rtol, atol=atol,
                              h=h)
    return run.positions[:, :, 0], masses


def initial_density(data) -> InitialDensity:
    """The data as an LTP initial density (cell weights (2.14) are differences of its CDF)."""
    if _is_bumps(data):
        _grid_density(data)  # supported in [-1, 1]
        bumps = bump_data(data)
        return InitialDensity(bumps.name, bumps.density, bumps.cdf, -1.0, 1.0)
    shape = _compact(profile(data))

    def cdf(x):
        return 0.5 * shape.mass + shape.mass_from_origin(np.clip(x, -1.0, 1.0))

    return InitialDensity(shape.name, shape.density, cdf, -1.0, 1.0)


def ltp_method(data, h: float, dt: float, t: float, *, method: str = "ltp", eps: float | None = None):
    """The LTP (or SP, with width ``eps``) particles at t for W = |x|/2: a
    :class:`~particle_methods.ltp.solver.Particles` with ``cumulative_mass``."""
    t = positive("t", t)  # checked here so that the errors name this function's parameter, not simulate's t_final
    _check_ltp_run("t", t, dt)
    return simulate(initial_density(data), potential("newtonian"), h, dt, t, shape=SHAPE, method=method,
                    eps=eps).at(-1)


def _check_ltp_run(name: str, t: float, dt) -> None:
    """simulate's checks of its final time, naming this module's parameter (``t`` or ``times``) instead of its
    t_final: at most MAX_STEPS steps, a whole number of steps dt. (Its limit on pair interactions does not apply:
    the Newtonian potential's sums take one pass per particle.)"""
    dt = positive("dt", dt)
    ratio = t / dt
    if not ratio <= MAX_LTP_STEPS:
        raise ValueError(f"{name} / dt = {ratio:.3g} steps, beyond the limit MAX_STEPS = {MAX_LTP_STEPS} of one run")
    if abs(round(ratio) * dt - t) > 1e-9 * max(t, dt):
        raise ValueError(f"{name} = {t} must be a whole number of steps dt = {dt}")


def ltp_paths(data, h: float, dt: float, times, *, method: str = "ltp", eps: float | None = None):
    """The LTP (or SP) particles at each of the increasing ``times`` (each a whole number of steps dt), from one
    run: a list of :class:`~particle_methods.ltp.solver.Particles`."""
    times = finite_array("times", times)
    dt = positive("dt", dt)
    if times.size == 0 or np.any(np.diff(times) <= 0) or times[0] < 0:
        raise ValueError("times must be non-negative and increasing, at least one")
    _check_ltp_run("times", float(times[-1]), dt)  # (before the steps: times / dt may overflow an integer)
    steps = np.rint(times / dt).astype(np.int64)
    if np.any(np.abs(steps * dt - times) > 1e-9 * np.maximum(times, dt)):
        raise ValueError(f"every entry of times must be a whole number of steps dt = {dt}, got {times}")
    run = simulate(initial_density(data), potential("newtonian"), h, dt, float(times[-1]), shape=SHAPE, method=method,
                   eps=eps, record_every=1)
    return [run.at(int(np.searchsorted(run.steps, step))) for step in steps]


def godunov_mass(data, cells: int, t: float, *, cfl: float = 0.9):
    """(edges, F values) of Godunov's scheme for F on ``cells`` cells of [-1, 1] at time t, started
    from the exact cell averages of F0 (ghost states 0 and M)."""
    return _godunov_paths(data, cells, [nonnegative("t", t)], cfl, "t")[0]


def godunov_paths(data, cells: int, times, *, cfl: float = 0.9):
    """(edges, F values) of :func:`godunov_mass` at each of the increasing ``times``, from one run (each stretch
    ends with a step shortened to land on its time)."""
    return _godunov_paths(data, cells, times, cfl, "times")


def _godunov_paths(data, cells: int, times, cfl: float, name: str):
    """:func:`godunov_paths`, whose limit on the steps names the caller's parameter ``name`` (``t`` or ``times``)."""
    _grid_density(data)  # supported in [-1, 1]
    cells = integer_at_least("cells", cells, 1, MAX_CELLS)
    if isinstance(times, np.ndarray):  # from the shape, before any copy of the times
        _check_path_size(times.size, cells)
    times = finite_array("times", times)
    _check_path_size(times.size, cells)
    if times.size == 0 or times[0] < 0 or np.any(np.diff(times) < 0):
        raise ValueError(f"times must be non-negative and non-decreasing, at least one, got {times}")
    edges = np.linspace(-1.0, 1.0, cells + 1)
    initial = solution(data, 0.0)
    # Every stretch checks its own steps; together they take at least t_last / dt steps of every cell.
    with np.errstate(divide="ignore"):  # (a step that underflows to 0 needs infinitely many)
        steps = times[-1] / np.float64(godunov_time_step(edges, initial.mass, cfl))
    if steps * cells > MAX_CELL_STEPS:
        raise ValueError(f"{name} up to {times[-1]:g} on {cells} cells need {steps:.3g} steps of the scheme, more than "
                         f"MAX_CELL_STEPS = {MAX_CELL_STEPS:.0e} cell updates: reduce {name} or the cells or raise cfl")
    # The exact cell averages of F0, in [0, M] (their differences' rounding, about eps M / dx, clipped).
    values = nudged(np.clip(np.diff(cdf_antiderivative(initial, edges)) / np.diff(edges), 0.0, initial.mass))
    out, now = [], 0.0
    for t in times:
        values = godunov_advance(edges, values, initial.mass, float(t) - now, cfl=cfl)
        out.append((edges, values))
        now = float(t)
    return out


def _check_path_size(times: int, cells: int) -> None:
    if times > MAX_PATH_TIMES:
        raise ValueError(f"times holds {times} times, more than MAX_PATH_TIMES = {MAX_PATH_TIMES:.0e}")
    if times * cells > MAX_PATH_VALUES:
        raise ValueError(f"times holds {times} times of {cells} cells, {times * cells:.3g} values to keep, more than "
                         f"MAX_PATH_VALUES = {MAX_PATH_VALUES:.0e}")


def godunov_advance(edges, values, mass: float, t: float, *, cfl: float = 0.9) -> np.ndarray:
    """F after a time t of Godunov's scheme from the cell values ``values`` of F on ``edges`` (ghost states 0 and
    ``mass``): with u = F/M and tau = M t, :func:`particle_methods.finite_volume.godunov` for (5.3). F is a
    cumulative mass: ``values`` lie in [0, M] up to :data:`F_ROUNDING` M, and the scheme, which keeps the range of
    its data and ghost states (the maximum principle) up to its rounding (5e-12 M after t = 3 on 16384 cells), is
    read in [0, M] (both clipped there)."""
    mass = positive("mass", mass)
    values = finite_array("values", values)
    edges = finite_array("edges", edges)
    if values.size == 0 or edges.size != values.size + 1:
        raise ValueError(f"values must hold one value per cell of edges (at least one), got {values.size} values and "
                         f"{edges.size} edges")
    if values.size and not (values.min() >= -F_ROUNDING * mass and values.max() <= (1.0 + F_ROUNDING) * mass):
        raise ValueError(f"values must lie in [0, mass] = [0, {mass!r}] (a cumulative mass), got values from "
                         f"{float(values.min())!r} to {float(values.max())!r}")
    t = nonnegative("t", t)
    # The scheme's own limit on its work, checked here so that the error names mass and t (its time is mass t).
    with np.errstate(divide="ignore", over="ignore"):  # (a step that underflows to 0 needs infinitely many)
        steps = t / np.float64(godunov_time_step(edges, mass, cfl))
    if not steps * values.size <= MAX_CELL_STEPS:
        raise ValueError(f"t = {t:g} with mass = {mass:g} and cfl = {cfl:g} takes {steps:.3g} steps of the scheme on "
                         f"{values.size} cells, more than MAX_CELL_STEPS = {MAX_CELL_STEPS:.0e} cell updates: reduce t "
                         "or the cells, or raise cfl")
    u = godunov(CONCAVE, np.clip(values / mass, 0.0, 1.0), edges, mass * t, cfl=cfl, left=0.0, right=1.0)
    return mass * np.clip(u, 0.0, 1.0)


def godunov_time_step(edges, mass: float, cfl: float = 0.9) -> float:
    """The time step (in t) of :func:`godunov_advance` on ``edges``: cfl dx / (M max|f'|), the flux's largest
    speed over the states from 0 to 1 (ghost states included) in tau = M t."""
    edges = finite_array("edges", edges)
    if edges.size < 2:
        raise ValueError(f"edges must hold at least two values, got {edges.size}")
    width = edges[1] - edges[0]
    if not width > 0.0:
        raise ValueError(f"edges must increase: the first cell's width is {width!r}")
    with np.errstate(over="ignore"):  # an overflow is reported just below
        step = cfl_time_step(CONCAVE, 0.0, 1.0, width, positive("cfl", cfl)) / positive("mass", mass)
    return finite_result("the time step", step, "mass is too small: cfl dx / mass overflows")
