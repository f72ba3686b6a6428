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

import numpy as np

from ..validation import finite_array, integer_at_least, nonnegative, positive
from .initial import InitialDensity, density_named, grid_particles
from .kernels import convolutions, density_at
from .potentials import Potential
from .shapes import Shape, shape_named

METHODS = ("ltp", "sp")


@dataclass(frozen=True)
class Particles:
    """Particles at one time: centres x_k, weights omega_k, widths h_k and their shape."""

    centres: np.ndarray
    weights: np.ndarray
    widths: np.ndarray
    shape: Shape

    def density(self, x) -> np.ndarray:
        """Reconstructed density rho_h(x) = sum_k omega_k phi((x - x_k)/h_k)/h_k, (2.27)."""
        x = finite_array("x", np.atleast_1d(x))
        return density_at(x, self.centres, self.weights, self.widths, self.shape.breaks, self.shape.coefficients)

    def convolutions(self, potential: Potential, x=None):
        """((W' * rho_h)(x), (W'' * rho_h)(x)), at the centres by default."""
        x = self.centres if x is None else finite_array("x", np.atleast_1d(x))
        coefficients, exponents = potential.as_arrays()
        return convolutions(x, self.centres, self.weights, self.widths, coefficients, exponents,
                            self.shape.breaks, self.shape.coefficients)

    @property
    def mass(self) -> float:
        """int rho_h = sum_k omega_k (each shape has unit mass)."""
        return float(self.weights.sum())

    @property
    def centre_of_mass(self) -> float:
        """int x rho_h = sum_k omega_k x_k (each shape is symmetric about its centre)."""
        return float(self.weights @ self.centres / self.weights.sum())


@dataclass(frozen=True)
class Simulation:
    """Particles recorded at the steps ``steps`` (times ``times``) of one run."""

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

    def at(self, index: int) -> Particles:
        """The particles at the ``index``-th recorded step (-1 for the last)."""
        return Particles(self.centres[index], self.weights, self.widths[index], self.shape)

    def densities(self, x) -> np.ndarray:
        """rho_h at the points x for every recorded step: shape (recorded steps, len(x))."""
        return np.array([self.at(i).density(x) for i in range(self.steps.size)])

    def peak_densities(self) -> np.ndarray:
        """max_k rho_h(x_k) at every recorded step: the height of the highest particle peak."""
        return np.array([self.at(i).density(self.centres[i]).max() for i in range(self.steps.size)])


def simulate(initial, potential: Potential, h: float, dt: float, t_final: float, *, shape: str = "b3",
             weights: str = "cell", method: str = "ltp", eps: float | None = None, record_every: int | None = None,
             log=None) -> Simulation:
    """Run the LTP (default) or SP method from ``initial`` up to ``t_final``.

    Parameters
    ----------
    initial : an :class:`InitialDensity` or the name of one of (6.1)-(6.3): 'rho1', 'rho2', 'rho3'.
    potential : a :class:`Potential` (see :func:`particle_methods.ltp.potential`).
    h, dt : grid step and time step, both positive; ``t_final`` must be a multiple of dt.
    shape : 'b3' (2.13) or 'hat' (2.12).  weights : 'cell' (2.14) or 'biorthogonal' (2.16, hat only).
    method : 'ltp' or 'sp'; the SP method needs the fixed particle width ``eps``.
    record_every : keep every this many steps (default: only the first and the last).
    log : optional callable receiving progress lines.
    """
    if isinstance(initial, str):
        initial = density_named(initial)
    if not isinstance(initial, InitialDensity):
        raise ValueError(f"initial must be an InitialDensity or its name, got {initial!r}")
    if not isinstance(potential, Potential):
        raise ValueError(f"potential must be a Potential, got {potential!r}")
    h = positive("h", h)
    dt = positive("dt", dt)
    t_final = nonnegative("t_final", t_final)
    steps = int(round(t_final / dt))
    if abs(steps * dt - t_final) > 1e-9 * max(t_final, dt):
        raise ValueError(f"t_final = {t_final} must be a whole number of steps dt = {dt}")
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}: expected 'ltp' or 'sp'")
    if method == "sp":
        if eps is None:
            raise ValueError("the SP method needs the particle width eps")
        eps = positive("eps", eps)
    elif eps is not None:
        raise ValueError("eps is a parameter of the SP method only")
    reference = shape_named(shape)
    every = steps if record_every is None else integer_at_least("record_every", record_every, 1)
    recorded = sorted(set(range(0, steps + 1, max(every, 1))) | {steps})

    x, omega = grid_particles(initial, h, reference, weights)
    widths = np.full(x.size, h if method == "ltp" else eps)
    coefficients, exponents = potential.as_arrays()
    centres_out, widths_out, velocity_out = [], [], []
    for n in range(steps + 1):
        first, second = convolutions(x, x, omega, widths, coefficients, exponents, reference.breaks,
                                     reference.coefficients)
        if n in recorded:
            centres_out.append(x.copy())
            widths_out.append(widths.copy())
            velocity_out.append(-first)
            if log is not None:
                log(f"{method} step {n}/{steps}: t = {n * dt:.4g}, max density width ratio "
                    f"{widths.min() / h:.3g}")
        if n == steps:
            break
        x = x - dt * first
        if method == "ltp":
            widths = widths * np.exp(-dt * second)
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(widths)) and np.all(widths > 0)):
            raise ValueError(f"particle widths or centres collapsed or became non-finite at step {n + 1} "
                             f"(t = {(n + 1) * dt:.6g}); reduce dt or the final time")
    return Simulation(method, reference, potential, h, dt, np.array(recorded), dt * np.array(recorded), omega,
                      np.array(centres_out), np.array(widths_out), np.array(velocity_out))
