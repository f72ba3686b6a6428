"""Data of the convergence studies of Theorems 1, 3 and 4 (sections 3-5), for the claims of the LTP paper.

- :func:`theorem1_time_error`: Theorem 1's dt/h term. At fixed h, the L1 distance of runs with several dt to
  the run with the smallest dt (the time part of the error at that h), on a potential whose flow is not affine.
- :func:`theorem3_atomic`: Theorem 3 for a measure: atomic initial data (Remark 4: the cell weights (2.14) move
  each atom's mass to its cell's centre), a fixed small dt, the W1 distance to the exact measure solution (the
  atoms moved by the particle ODE) against h. :func:`theorem3_rough` keeps the earlier study: the indicator (6.2),
  dt proportional to h, so the distance mixes the space and time errors.
- :func:`theorem4_differences`: Theorem 4 on data that satisfy its hypotheses (rho^0 in W^{2,p}), dt = c h^2:
  the distances between runs at h and h/2, largest over the record times, in L1 and Linf, with the weights
  (2.14) (B3 shape) and (2.16) (hat shape). If the error is C h^q, these distances are C (1 - 2^-q) h^q:
  same order, with no reference run.

Each function takes its config section (a dict) and the solver (``run``, :func:`~.solver.simulate` by default,
so that a test can hand it a wrong one) and returns the arrays the claims read.
"""

from __future__ import annotations

import inspect

import numpy as np

from ..norms import grid_errors
from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    instance,
    integer_at_least,
    positive,
    same_length,
    sorted_array,
)
from .checks import MAX_PARTICLES
from .initial import InitialDensity, atomic, density_named, golden_atoms
from .potentials import Potential, potential
from .solver import Particles, Simulation, simulate

#: Theorem 4's weights: (2.14) with the B3 shape of the other runs, and (2.16), defined for the hat shape only.
WEIGHTS = {"cell": "b3", "biorthogonal": "hat"}
#: Gauss-Legendre nodes per piece of |F_h - F| in :func:`w1_to_atoms` (exact for the quartic CDF of B3).
GAUSS_NODES = 3
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(GAUSS_NODES)
#: Bisection steps locating the zero of F_h - F in a piece (2^-60 of its length).
ROOT_STEPS = 60
#: Most points of the grid on which the studies compare densities or CDFs (the config's finest: 40001).
MAX_GRID_POINTS = 10**6
#: Latest time of :func:`atom_flow` (the studies' records end by t = 0.5): a limit on the work of one call, since
#: the steps of an adaptive integrator over a long time have no a priori bound.
MAX_FLOW_TIME = 1000.0
#: Tolerances of :func:`atom_flow`: below RTOL_RANGE[0] the integrator cannot resolve it in double precision.
RTOL_RANGE = (1e-14, 0.1)


def _study(q, keys, run):
    """Check a study's arguments: its config section ``q``, a dict holding ``keys``, and ``run``, a function
    called like :func:`~.solver.simulate`."""
    instance("q", q, dict)
    missing = [key for key in keys if key not in q]
    if missing:
        raise ValueError(f"q (the study's config section) lacks {', '.join(missing)}")
    if not callable(run):
        raise ParameterTypeError(f"run must be a function called like simulate, got {run!r}")


def _run(run, *args, **kwargs) -> Simulation:
    """``run(*args, **kwargs)``, refused by name when ``run`` does not take simulate's arguments or returns no
    :class:`~.solver.Simulation`."""
    try:
        inspect.signature(run).bind(*args, **kwargs)
    except TypeError as error:
        raise ParameterTypeError(f"run must take the arguments of simulate: {error}") from None
    except ValueError:  # no signature to read (a builtin): the call decides
        pass
    return instance("the result of run", run(*args, **kwargs), Simulation)


def _memoized(initial: InitialDensity) -> InitialDensity:
    """``initial`` with a CDF that remembers its values: the runs at one h and several dt ask for the same cell
    edges, and the CDF of (6.3) is an adaptive quadrature per point."""
    cache = {}

    def cdf(x):
        x = np.asarray(x, dtype=np.float64)
        key = (x.shape, x.tobytes())
        if key not in cache:
            cache[key] = initial.cdf(x)
        return cache[key]

    return InitialDensity(initial.name, initial.pdf, cdf, initial.lower, initial.upper)


def records(sim, times):
    """Indices of ``sim``'s records at ``times`` (at most one per record), which must be multiples of its dt (and of
    its record step)."""
    instance("sim", sim, Simulation)
    times = finite_array("times", times)
    integer_at_least("the number of times", times.size, 1, sim.times.size)
    recorded = [int(np.argmin(np.abs(sim.times - t))) for t in times]
    if not np.allclose(sim.times[recorded], times, rtol=0, atol=1e-9):
        raise ValueError("times must be record times of sim (multiples of every run's dt and record step)")
    return recorded


def atom_flow(positions, masses, w: Potential, times, rtol: float = 1e-12) -> np.ndarray:
    """The exact solution of (1.1) from sum_i m_i delta_{a_i} when W' is Lipschitz (section 4): the atoms move by
    x_i' = -sum_j m_j W'(x_i - x_j), integrated by DOP853 to ``rtol``; positions at ``times`` (rows)."""
    positions, masses = finite_array("positions", positions), finite_array("masses", masses)
    integer_at_least("the number of positions", same_length(positions=positions, masses=masses), 1, MAX_PARTICLES)
    if np.any(masses < 0):
        raise ValueError("masses must be non-negative")
    instance("w", w, Potential)
    times = sorted_array("times", times)
    if times.size == 0 or times[0] < 0 or np.any(np.diff(times) <= 0) or not 0 < times[-1] <= MAX_FLOW_TIME:
        raise ValueError(f"times must increase strictly from t >= 0 to a last time in (0, {MAX_FLOW_TIME:g}] (a "
                         f"limit on the work of one call), got {times}")
    rtol = positive("rtol", rtol)
    if not RTOL_RANGE[0] <= rtol <= RTOL_RANGE[1]:
        raise ValueError(f"rtol must lie in [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}], got {rtol:g}")

    def velocity(_, x):
        with np.errstate(over="ignore", invalid="ignore"):
            return -(w.derivative(x[:, None] - x[None, :]) @ masses)

    finite_result("the atoms' initial velocities", velocity(0.0, positions), "the masses or positions overflow")
    try:
        from scipy import integrate

        solution = integrate.solve_ivp(velocity, (0.0, float(times[-1])), positions, method="DOP853",
                                       t_eval=times, rtol=rtol, atol=rtol * 1e-2)
    except ValueError as error:  # W' overflowed on the way (refused by finite_values)
        raise ValueError(f"the atoms' flow overflowed: the masses or positions are too large ({error})") from None
    if not solution.success:
        raise ValueError(f"the atoms' flow failed (masses or positions too large for the times): {solution.message}")
    return solution.y.T


def w1_to_atoms(particles: Particles, positions, masses) -> float:
    """W1 = int |F_h - F| between the particles' reconstruction (2.27) and sum_i m_i delta_{x_i} (equal masses).

    Between consecutive points of the union of the particles' shape breaks and the atoms, F_h is a polynomial
    (quartic for B3) and F a constant; F_h is non-decreasing (non-negative weights), so F_h - F vanishes at most
    once there: that zero is bisected and each side integrated by Gauss-Legendre, exact up to rounding."""
    instance("particles", particles, Particles)
    positions, masses = finite_array("positions", positions), finite_array("masses", masses)
    same_length(positions=positions, masses=masses)
    if np.any(particles.weights < 0) or np.any(masses < 0):
        raise ValueError("W1 needs non-negative weights and masses")
    if not abs(particles.mass - masses.sum()) <= 1e-9 * masses.sum():
        raise ValueError(f"masses must sum to the particles' mass {particles.mass!r}, got {masses.sum()!r}")
    order = np.argsort(positions, kind="stable")
    x, levels = positions[order], np.concatenate([[0.0], np.cumsum(masses[order])])
    points = np.union1d(particles.breaks, x)
    a, b = points[:-1], points[1:]
    steps = levels[np.searchsorted(x, 0.5 * (a + b), side="right")]

    def gap(points):
        return particles.cumulative_mass(points.ravel()).reshape(points.shape) - steps[:, None]

    ends = gap(np.column_stack([a, b]))
    low, high = a.copy(), b.copy()
    crossing = (ends[:, 0] < 0) & (ends[:, 1] > 0)
    for _ in range(ROOT_STEPS):
        middle = 0.5 * (low + high)
        below = gap(middle[:, None])[:, 0] < 0
        low, high = np.where(below, middle, low), np.where(below, high, middle)
    root = np.where(crossing, 0.5 * (low + high), b)

    def integral(start, stop):
        nodes = 0.5 * (start + stop)[:, None] + 0.5 * (stop - start)[:, None] * _NODES
        return np.abs(0.5 * (stop - start) * (gap(nodes) @ _WEIGHTS))

    return finite_result("W1", float(np.sum(integral(a, root) + integral(root, b))), "the positions overflow")


def theorem3_atomic(q, run=simulate) -> dict:
    """Theorem 3 on a measure: ``q["atoms"]`` atoms of equal mass (:func:`golden_atoms` on [-0.9, 0.9]),
    W = |x|^a/a, dt = ``q["dt"]`` at every h, the W1 distance to the exact atoms (:func:`atom_flow`), largest over
    the record times; and the same distance at h_min with dt / ``q["dt_factor"]``, whose change measures the
    time error's share."""
    _study(q, ("atoms", "a", "dt", "dt_factor", "h_values", "times"), run)
    positions, masses = golden_atoms(q["atoms"], -0.9, 0.9)
    initial = atomic(positions, masses)
    w = potential("power", a=q["a"])
    h_values, times = np.asarray(q["h_values"], float), np.asarray(q["times"], float)
    exact = atom_flow(positions, masses, w, times)

    def distance(h, dt):
        sim = _run(run, initial, w, h, dt, times[-1], record_every=int(round(times[0] / dt)))
        return max(w1_to_atoms(sim.at(i), x, masses) for i, x in zip(records(sim, times), exact))

    distances = np.array([distance(h, q["dt"]) for h in h_values])
    finer = distance(h_values.min(), q["dt"] / q["dt_factor"])
    return {"theorem3_atomic_h": h_values, "theorem3_atomic_dt": q["dt"], "theorem3_atomic_times": times,
            "theorem3_atomic_label": np.array(f"{w.name} on {initial.name}"),
            "theorem3_atomic_distances": distances,
            "theorem3_atomic_time_share": abs(distances[np.argmin(h_values)] - finer) / distances.min()}


def theorem3_rough(q, grid_points: int, run=simulate) -> dict:
    """Theorem 3 with dt = dt_over_h h on rough data: largest W1 distance over the record times for each h to the
    reference (h_min / reference_factor, its own dt), and the reference's distance to the run with twice its h."""
    _study(q, ("initial", "a", "h_values", "dt_over_h", "reference_factor", "times"), run)
    grid_points = integer_at_least("grid_points", grid_points, 2, MAX_GRID_POINTS)
    initial = density_named(q["initial"])
    w = potential("power", a=q["a"])
    grid = np.linspace(initial.lower, initial.upper, grid_points)
    h_values, times = np.asarray(q["h_values"], float), np.asarray(q["times"], float)
    reference_h = h_values.min() / q["reference_factor"]

    def cdfs(h):
        dt = q["dt_over_h"] * h
        sim = _run(run, initial, w, h, dt, times[-1], record_every=int(round(times[0] / dt)))
        return [sim.at(i).cumulative_mass(grid) for i in records(sim, times)]

    def distance(a, b):
        return max(grid_errors(x, y, grid)[0] for x, y in zip(a, b))

    reference = cdfs(reference_h)
    return {"theorem3_h": h_values, "theorem3_dt": q["dt_over_h"] * h_values, "theorem3_times": times,
            "theorem3_reference_h": reference_h, "theorem3_label": np.array(f"{w.name} on {initial.name}"),
            "theorem3_distances": np.array([distance(cdfs(h), reference) for h in h_values]),
            "theorem3_reference_gap": distance(cdfs(2 * reference_h), reference)}


def theorem4_differences(q, grid_points: int, run=simulate) -> dict:
    """Theorem 4: W = |x|^a/a from ``q["initial"]``, each run with dt = dt_over_h2 h^2 at h = h_values and at
    h_min / 2; for each h the L1 and Linf distances (columns) between the runs at h and h/2, largest over the
    record times (the theorem's sup over n), for each weight rule of :data:`WEIGHTS`. The densities are compared
    on a grid of ``grid_points`` and at the shape breaks of both runs, where the hat densities have their kinks
    (their largest difference sits at one of those)."""
    _study(q, ("initial", "a", "h_values", "dt_over_h2", "times"), run)
    grid_points = integer_at_least("grid_points", grid_points, 2, MAX_GRID_POINTS)
    initial = _memoized(density_named(q["initial"]))
    w = potential("power", a=q["a"])
    grid = np.linspace(initial.lower - 0.1, initial.upper + 0.1, grid_points)
    h_values, times = np.asarray(q["h_values"], float), np.asarray(q["times"], float)
    runs = np.append(h_values, h_values.min() / 2)

    def states(h, weights):
        dt = q["dt_over_h2"] * h**2
        sim = _run(run, initial, w, h, dt, times[-1], shape=WEIGHTS[weights], weights=weights,
                   record_every=int(round(times[0] / dt)))
        return [sim.at(i) for i in records(sim, times)]

    def distance(a: Particles, b: Particles):
        points = np.union1d(grid, np.union1d(a.breaks, b.breaks))
        return grid_errors(a.density(points), b.density(points), points)

    out = {"theorem4_h": h_values, "theorem4_dt": q["dt_over_h2"] * h_values**2, "theorem4_times": times,
           "theorem4_weights": np.array(list(WEIGHTS)), "theorem4_label": np.array(f"{w.name} on {initial.name}")}
    for weights in WEIGHTS:
        computed = [states(h, weights) for h in runs]
        out[f"theorem4_{weights}_differences"] = np.array(
            [np.max([distance(a, b) for a, b in zip(coarse, fine)], axis=0)
             for coarse, fine in zip(computed[:-1], computed[1:])])
    return out


def theorem1_time_error(q, grid_points: int, run=simulate) -> dict:
    """Theorem 1's time error: W = |x|^a/a from ``q["initial"]`` at each h of h_values, runs at every dt of
    dt_values (largest first); the L1 and Linf distances at t of each run to the run with the smallest dt
    (rows: h, then dt; columns: L1, Linf)."""
    _study(q, ("initial", "a", "t", "h_values", "dt_values", "fit_points"), run)
    grid_points = integer_at_least("grid_points", grid_points, 2, MAX_GRID_POINTS)
    initial = _memoized(density_named(q["initial"]))
    w = potential("power", a=q["a"])
    grid = np.linspace(initial.lower - 0.1, initial.upper + 0.1, grid_points)
    h_values, dt_values = np.asarray(q["h_values"], float), np.asarray(q["dt_values"], float)
    gaps = []
    for h in h_values:
        final = [_run(run, initial, w, h, dt, q["t"]).at(-1).density(grid) for dt in dt_values]
        gaps.append([grid_errors(density, final[-1], grid) for density in final[:-1]])
    return {"theorem1_h": h_values, "theorem1_dt": dt_values, "theorem1_gaps": np.array(gaps),
            "theorem1_fit_points": q["fit_points"], "theorem1_t": q["t"],
            "theorem1_label": np.array(f"{w.name} on {initial.name}")}

