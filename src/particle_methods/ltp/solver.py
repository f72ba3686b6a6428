"""The LTP method (sections 2.2-2.3) and the smooth-particle (SP) method it is compared with.

Both start from particles on the grid x_k = k h with weights (2.14) or (2.16) and
move the centres by explicit Euler (2.31):

    x_k^{n+1} = x_k^n - dt (W' * rho_h^n)(x_k^n).

LTP particles also change size: in 1D the Jacobian (2.31)-(2.32) is the scalar
j_k^n = exp(-dt (W'' * rho_h^n)(x_k^n)) and the width becomes h_k^{n+1} = j_k^n h_k^n
(2.24), with rho_h^n = sum_k omega_k phi((x - x_k^n)/h_k^n)/h_k^n (2.23), (2.27).
SP particles keep one fixed width eps.
"""

from __future__ import annotations

from dataclasses import dataclass
from numbers import Integral

import numpy as np

from ..validation import (
    ParameterTypeError,
    finite_array,
    finite_result,
    finite_values,
    instance,
    integer_at_least,
    nonnegative,
    positive,
    real_array,
    same_length,
)
from .checks import particle_arrays
from .initial import InitialDensity, density_named, grid_particles
from .kernels import OVERFLOW, convolution_sums, convolutions, cumulative_mass_at, density_at, takes_pair_sums
from .potentials import Potential
from .shapes import Shape, shape_named

METHODS = ("ltp", "sp")

#: Work limits of one run of :func:`simulate`, far above the repository's largest runs (5000 steps;
#: 1.6e8 pair interactions for 803 particles over 250 steps; 1.2e5 recorded values). About 4e6 pair
#: interactions run per second on two cores, so MAX_PAIRS bounds a run to about ten minutes.
MAX_STEPS = 100_000
MAX_PAIRS = 2_000_000_000
MAX_RECORDED = 20_000_000
#: Explicit Euler (2.31) needs dt * max_k (W'' * rho_h^n)(x_k^n) below this bound (see :func:`simulate`).
STABILITY = 1.0


def _points(x) -> np.ndarray:
    """Evaluation points: a finite real number or a one-dimensional array of them."""
    x = finite_values("x", x)
    if x.ndim > 1:
        raise ValueError(f"x must be a number or a one-dimensional array, got shape {x.shape}")
    return np.atleast_1d(x)


@dataclass(frozen=True)
class Particles:
    """Particles at one time: centres x_k, weights omega_k, widths h_k > 0 and their shape.

    The arrays must be finite, one-dimensional and of one length (1 to MAX_PARTICLES).
    """

    centres: np.ndarray
    weights: np.ndarray
    widths: np.ndarray
    shape: Shape

    def __post_init__(self):
        for name, array in zip(("centres", "weights", "widths"), particle_arrays(self.centres, self.weights,
                                                                                   self.widths)):
            object.__setattr__(self, name, array)
        instance("shape", self.shape, Shape)

    def density(self, x) -> np.ndarray:
        """Reconstructed density rho_h(x) = sum_k omega_k phi((x - x_k)/h_k)/h_k, (2.27)."""
        return density_at(_points(x), self.centres, self.weights, self.widths, self.shape.breaks,
                          self.shape.coefficients)

    def cumulative_mass(self, x) -> np.ndarray:
        """Cumulative mass F_h(x) = int_{-inf}^x rho_h = sum_k omega_k Phi((x - x_k)/h_k) of (2.27), Phi the CDF
        of the shape: 0 left of every particle, :attr:`mass` right of them."""
        return cumulative_mass_at(_points(x), self.centres, self.weights, self.widths, self.shape.breaks,
                                  self.shape.coefficients)

    def convolutions(self, potential: Potential, x=None):
        """((W' * rho_h)(x), (W'' * rho_h)(x)), at the centres by default."""
        instance("potential", potential, Potential)
        x = self.centres if x is None else _points(x)
        coefficients, exponents = potential.as_arrays()
        return convolutions(x, self.centres, self.weights, self.widths, coefficients, exponents,
                            self.shape.breaks, self.shape.coefficients)

    @property
    def breaks(self) -> np.ndarray:
        """The sorted points where the reconstruction (2.27) is not a polynomial: every particle's shape breaks."""
        return np.unique(self.centres[:, None] + self.widths[:, None] * self.shape.breaks)

    @property
    def mass(self) -> float:
        """int rho_h = sum_k omega_k (each shape has unit mass)."""
        with np.errstate(over="ignore"):
            return finite_result("the mass", float(self.weights.sum()), "the weights overflow")

    @property
    def centre_of_mass(self) -> float:
        """int x rho_h = sum_k omega_k x_k (each shape is symmetric about its centre)."""
        with np.errstate(over="ignore", invalid="ignore"):
            if self.weights.sum() == 0:
                raise ValueError("the centre of mass needs weights of non-zero sum")
            return finite_result("the centre of mass", float(self.weights @ self.centres / self.weights.sum()),
                                 "the weights or centres overflow")


@dataclass(frozen=True)
class Simulation:
    """Particles recorded at the steps ``steps`` (times ``times``) of one run.

    One row of ``centres``, ``widths`` and ``velocities`` per recorded step, one column per particle.
    """

    method: str
    shape: Shape
    potential: Potential
    h: float
    dt: float
    steps: np.ndarray
    times: np.ndarray
    weights: np.ndarray
    centres: np.ndarray
    widths: np.ndarray
    velocities: np.ndarray

    def __post_init__(self):
        _method(self.method)
        instance("shape", self.shape, Shape)
        instance("potential", self.potential, Potential)
        positive("h", self.h)
        positive("dt", self.dt)
        real_array("steps", self.steps)  # the type and a rectangular shape
        if np.asarray(self.steps).dtype.kind not in "iu":
            raise ParameterTypeError(f"steps must hold integers, got {self.steps!r}")
        rows = {name: finite_array(name, getattr(self, name), ndim=2) for name in ("centres", "widths", "velocities")}
        columns = {name: finite_array(name, getattr(self, name)) for name in ("times", "weights")}
        same_length(weights=columns["weights"], **rows)
        same_length(steps=np.asarray(self.steps), times=columns["times"], **{name: a.T for name, a in rows.items()})
        if np.any(rows["widths"] <= 0):
            raise ValueError("widths must be positive")
        for name, array in {**rows, **columns}.items():
            object.__setattr__(self, name, array)

    def at(self, index: int) -> Particles:
        """The particles at the ``index``-th recorded step (-1 for the last)."""
        records = self.steps.size
        if isinstance(index, bool) or not isinstance(index, (Integral, np.integer)):
            raise ParameterTypeError(f"index must be an integer, got {index!r}")
        if not -records <= index < records:
            raise ValueError(f"index must lie in [{-records}, {records - 1}], got {index}")
        return Particles(self.centres[index], self.weights, self.widths[index], self.shape)

    def densities(self, x) -> np.ndarray:
        """rho_h at the points x for every recorded step: shape (recorded steps, len(x))."""
        x = _points(x)
        return np.array([self.at(i).density(x) for i in range(self.steps.size)])

    def peak_densities(self) -> np.ndarray:
        """max_k rho_h(x_k) at every recorded step: the height of the highest particle peak."""
        return np.array([self.at(i).density(self.centres[i]).max() for i in range(self.steps.size)])


def _method(method) -> str:
    """'ltp' or 'sp'."""
    instance("method", method, str)
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}: expected 'ltp' or 'sp'")
    return method


def _step_count(t_final: float, dt: float) -> int:
    """N = t_final / dt, at most MAX_STEPS; ValueError if t_final is not a whole number of steps."""
    ratio = t_final / dt
    if not ratio <= MAX_STEPS:
        raise ValueError(f"t_final / dt = {ratio:.3g} steps, beyond the limit MAX_STEPS = {MAX_STEPS} of one run")
    steps = round(ratio)
    if abs(steps * dt - t_final) > 1e-9 * max(t_final, dt):
        raise ValueError(f"t_final = {t_final} must be a whole number of steps dt = {dt}")
    return steps


def _check_work(steps: int, count: int, potential: Potential, records: int):
    """Refuse a run beyond MAX_PAIRS pair interactions or MAX_RECORDED values per recorded array
    (a potential whose exponents need no pair sums, :func:`.kernels.takes_pair_sums`, counts one per particle)."""
    pairs = (steps + 1) * count * (count if takes_pair_sums(potential.exponents) else 1)
    if pairs > MAX_PAIRS:
        raise ValueError(f"{steps} steps of {count} particles need {pairs:.3g} pair interactions, beyond the limit "
                         f"MAX_PAIRS = {MAX_PAIRS:.3g} of one run: increase h or dt, or reduce t_final")
    if records * count > MAX_RECORDED:
        raise ValueError(f"{records} records of {count} particles are {records * count:.3g} values, beyond the limit "
                         f"MAX_RECORDED = {MAX_RECORDED:.3g} of one run: increase record_every")


class StabilityError(ValueError):
    """Explicit Euler (2.31) is refused at ``step`` (time ``time``): dt max_k (W'' * rho_h)(x_k) >= STABILITY."""

    def __init__(self, message: str, step: int, time: float):
        super().__init__(message)
        self.step = step
        self.time = time


def _check_stability(n: int, dt: float, second: np.ndarray):
    """Refuse step n unless dt < STABILITY / max_k (W'' * rho_h^n)(x_k^n) (see :func:`simulate`)."""
    steepest = float(second.max())
    if dt * steepest >= STABILITY:
        raise StabilityError(f"dt = {dt:g} exceeds the stability bound {STABILITY:g} / max_k (W'' * rho_h)(x_k) = "
                             f"{STABILITY / steepest:.3g} of explicit Euler (2.31) at step {n} (t = {n * dt:.6g})"
                             + (": the particles collapse; reduce dt or the final time" if n else ""), n, n * dt)


def simulate(initial, potential: Potential, h: float, dt: float, t_final: float, *, shape: str = "b3",
             weights: str = "cell", offset: float = 0.0, method: str = "ltp", eps: float | None = None,
             record_every: int | None = None, log=None) -> Simulation:
    """Run the LTP (default) or SP method from ``initial`` up to ``t_final``.

    Parameters
    ----------
    initial : an :class:`InitialDensity` or the name of one of (6.1)-(6.3): 'rho1', 'rho2', 'rho3'.
    potential : a :class:`Potential` (see :func:`particle_methods.ltp.potential`).
    h, dt : grid step and time step, both positive; ``t_final`` must be a multiple of dt.
    shape : 'b3' (2.13) or 'hat' (2.12).  weights : 'cell' (2.14) or 'biorthogonal' (2.16, hat only).
    offset : the initial centres are (k + offset) h, offset in [0, 1) (see :func:`grid_particles`).
    method : 'ltp' or 'sp'; the SP method needs the fixed particle width ``eps``.
    record_every : keep every this many steps (default: only the first and the last).
    log : optional callable receiving progress lines.

    Stability: the Euler map x -> x - dt (W' * rho_h^n)(x) of (2.31) has derivative
    1 - dt (W'' * rho_h^n)(x). It keeps the particles in order, as the exact flow does, when
    dt * max (W'' * rho_h^n) < STABILITY = 1 (the paper only asks for dt small enough, gamma dt < 1
    in the proof of Proposition 5); the maximum is taken over the centres x_k^n, where W'' * rho_h^n
    is computed anyway. For W = c x^2/2, W'' * rho_h = c times the mass at every step: dt c < 1
    (beyond 2/c Euler diverges). Other potentials change W'' * rho_h in time and have no a priori
    bound (W'' is singular for exponents below 2), so the bound is checked at every step: at step
    0 it refuses dt, later it reports the collapse (finite-time blow-up for |x|^a, a < 2). For the
    Newtonian W = c|x| (a = 1), W'' * rho_h = 2c rho_h: the bound is dt 2c max_k rho_h(x_k) < 1, and
    as the exact density blows up (at t = 1 / (2c max rho^0)) an LTP run is refused; SP particles
    keep their width eps, so rho_h stays below sum_k |omega_k| max phi / eps. Every step also
    checks that the convolutions, centres and widths stay finite and the widths positive.

    Work limits: at most MAX_STEPS steps, MAX_PARTICLES particles (:func:`grid_particles`),
    MAX_PAIRS pair interactions and MAX_RECORDED recorded values per array.
    """
    initial = density_named(initial) if isinstance(initial, str) else instance("initial", initial, InitialDensity)
    instance("potential", potential, Potential)
    h = positive("h", h)
    dt = positive("dt", dt)
    steps = _step_count(nonnegative("t_final", t_final), dt)
    if _method(method) == "sp":
        if eps is None:
            raise ValueError("the SP method needs the particle width eps")
        eps = positive("eps", eps)
    elif eps is not None:
        raise ValueError("eps is a parameter of the SP method only")
    reference = shape_named(shape)
    every = max(steps, 1) if record_every is None else integer_at_least("record_every", record_every, 1, MAX_STEPS)
    recorded = sorted(set(range(0, steps + 1, every)) | {steps})
    if log is not None and not callable(log):
        raise ParameterTypeError(f"log must be callable, got {log!r}")

    x, omega = grid_particles(initial, h, reference, weights, offset)
    _check_work(steps, x.size, potential, len(recorded))
    widths = np.full(x.size, h if method == "ltp" else eps)
    coefficients, exponents = potential.as_arrays()
    centres_out, widths_out, velocity_out = [], [], []
    for n in range(steps + 1):
        # the arrays were checked: by grid_particles, Shape, Potential, and after every step below
        first, second = convolution_sums(x, x, omega, widths, coefficients, exponents, reference.breaks,
                                         reference.coefficients)
        if not (np.all(np.isfinite(first)) and np.all(np.isfinite(second))):
            raise ValueError(f"W' * rho_h or W'' * rho_h is not finite at step {n} (t = {n * dt:.6g}, h = {h:.6g}): "
                             f"{OVERFLOW}")
        if n % every == 0 or n == steps:
            centres_out.append(x.copy())
            widths_out.append(widths.copy())
            velocity_out.append(-first)
            if log is not None:
                log(f"{method} step {n}/{steps}: t = {n * dt:.4g}, max density width ratio "
                    f"{widths.min() / h:.3g}")
        if n == steps:
            break
        _check_stability(n, dt, second)
        with np.errstate(over="ignore", invalid="ignore"):  # overflow is reported just below
            x = x - dt * first
            if method == "ltp":
                widths = widths * np.exp(-dt * second)
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(widths)) and np.all(widths > 0)):
            raise ValueError(f"particle widths or centres collapsed or became non-finite at step {n + 1} "
                             f"(t = {(n + 1) * dt:.6g}); reduce dt or the final time")
    return Simulation(method, reference, potential, h, dt, np.array(recorded), dt * np.array(recorded), omega,
                      np.array(centres_out), np.array(widths_out), np.array(velocity_out))
