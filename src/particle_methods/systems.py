"""Diagonal systems (1.7) of the sticky paper: the protocol every scheme takes, and the p-system.

A diagonal system is any object with an integer ``d`` (the number of types) and a method
``speed_primitive(gamma, levels)``: the antiderivative of lambda^gamma in its own variable at the
rows of ``levels`` (shape (..., d)). :func:`checked_system` and :func:`checked_primitive` check
both for the MSPD (:mod:`particle_methods.sticky`) and the finite volumes
(:mod:`particle_methods.finite_volume`) alike.

The p-system of section 5.2.2 in Riemann invariants, as a 2x2 diagonal system (5.7):

Unknowns: specific volume u in [0, nu] and velocity v; pressure

    p(u) = kappa / (4 nu asinh^2(kappa/2)) [atan(kappa/2) - atan(kappa (u/nu - 1/2))],

which satisfies (5.5). With a = asinh(kappa/2), c = sqrt(-p') and
g(u) = int_0^u c - 1/2 = asinh(kappa (u/nu - 1/2)) / (2a), the Riemann invariants
w^{+-} = v +- g(u) solve (5.7) with speeds

    lambda^{+-}(w^-, w^+) = -+ kappa / (2 nu a) / cosh((w^+ - w^-) a),

and (5.6) maps them back: u = nu (1/2 + sinh((w^+ - w^-) a) / kappa), v = (w^+ + w^-)/2.

Types follow assumption (USH), fastest first: type 0 is w^- (lambda^- > 0) and
type 1 is w^+ (lambda^+ < 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .threads import pool
from .validation import ParameterTypeError, in_interval, integer_at_least, positive, real_array

MINUS, PLUS = 0, 1


def checked_system(system) -> int:
    """Number of types d of a diagonal system (an integer d and a method speed_primitive)."""
    if not callable(getattr(system, "speed_primitive", None)):
        raise ParameterTypeError(
            f"system must be a diagonal system with a method speed_primitive(gamma, levels), got {system!r}"
        )
    return integer_at_least("system.d (the number of types)", getattr(system, "d", None), 1)


def checked_primitive(system, gamma: int, levels: np.ndarray) -> np.ndarray:
    """system.speed_primitive(gamma, levels), one real value per row of ``levels`` (else a ValueError)."""
    checked_system(system)
    name = f"system.speed_primitive({gamma}, levels)"
    values = real_array(name, system.speed_primitive(gamma, levels))
    if values.shape != levels.shape[:1]:
        raise ValueError(f"{name} must return one value per particle, shape {levels.shape[:1]}, got {values.shape}")
    return values


_LARGEST_SCALE = 1e300
"""Bound on the speed constants of a :class:`PSystem`, so that pressures and primitives stay finite."""


def pressure_formula(u, nu, kappa):
    """p(u) of section 5.2.2 without checks: plain arithmetic, for arrays and for compiled kernels.
    It trusts its caller's checks."""
    a = np.arcsinh(0.5 * kappa)
    scale = kappa / (4.0 * nu * a**2)
    return scale * (np.arctan(0.5 * kappa) - np.arctan(kappa * (u / nu - 0.5)))


def sound_speed_formula(u, nu, kappa):
    """c(u) = sqrt(-p'(u)) = kappa / (2 nu a) / sqrt(1 + kappa^2 (u/nu - 1/2)^2), without checks (as above).
    It trusts its caller's checks."""
    speed_scale = kappa / (2.0 * nu * np.arcsinh(0.5 * kappa))
    return speed_scale / np.sqrt(1.0 + (kappa * (u / nu - 0.5)) ** 2)


def speed_primitive_formula(spread, a, coefficient):
    """The p-system's primitive coefficient * atan(sinh(a spread)) of :meth:`PSystem.speed_primitive`
    (coefficient = -A/a, spread = w^+ - w^-), without checks (as above): the compiled MSPD
    (:mod:`particle_methods.sticky.multitype_events`) evaluates the same expression.
    It trusts its caller's checks."""
    return coefficient * np.arctan(np.sinh(a * spread))


#: Elements of the p-system's primitive evaluated by one NumPy call in :func:`speed_primitives_into`: each of the
#: formula's temporaries (64 kB) then stays below glibc's default threshold for mapping a block of its own
#: (128 kB). On the whole (3, cells + 1) array at 64000 cells (temporaries of 1.5 MB) a run in a fresh process
#: took 5.2 million page faults, 718 a step, and 14.4 to 15.2 s, against 1100 faults and 4.4 to 5.1 s in chunks
#: of 8192 (4096: 5.6 s, 2048: 7.0 s, the calls' overhead; measured with benchmarks/bench_upwind.py's data).
PRIMITIVE_CHUNK = 8192


#: Fewest values of the primitive that :func:`speed_primitives_into` splits among threads: below, dispatching to the
#: threads costs about what they save. On an AMD EPYC virtual machine (AVX2, 2 cores; benchmarks/bench_upwind.py, the
#: upwind scheme's 3 (cells + 1) values a step) two threads made a run 0.56 to 0.64 times as fast as one at 4000 cells
#: (12,003 values), 0.96 to 1.24 times at 16,000 (48,003) and 1.13 to 1.35 times at 64,000 (192,003).
PARALLEL_MIN_PRIMITIVES = 8 * PRIMITIVE_CHUNK


def speed_primitives_into(spreads, a, coefficient, primitives, workers=1):
    """primitives = coefficient atan(sinh(a spreads)), the p-system's primitive of (5.7), by
    :func:`speed_primitive_formula` on NumPy arrays as :meth:`PSystem.speed_primitive`
    evaluates it on the Python path, in chunks of :data:`PRIMITIVE_CHUNK` elements: the same values to the last
    bit (NumPy's vectorised sinh and arctan give an element the same result at any place in any array). With
    ``workers`` > 1 the elements are split into that many contiguous parts, whole chunks each, evaluated by the
    threads of :func:`~particle_methods.threads.pool` (NumPy's ufuncs release the interpreter's lock): the same
    values again, sooner on as many free cores from :data:`PARALLEL_MIN_PRIMITIVES` values on (one thread
    below; :func:`~particle_methods.finite_volume.psystem.upwind_diagonal` gives the times). The compiled loops
    of the upwind scheme and of the iterated TSPD call it in object mode once per step. It trusts its caller's
    checks."""
    spreads, primitives = spreads.reshape(-1), primitives.reshape(-1)

    def evaluate(first, last):
        for start in range(first, last, PRIMITIVE_CHUNK):
            stop = min(start + PRIMITIVE_CHUNK, last)
            primitives[start:stop] = speed_primitive_formula(spreads[start:stop], a, coefficient)

    if workers > 1 and spreads.size >= PARALLEL_MIN_PRIMITIVES:
        part = -(-spreads.size // (workers * PRIMITIVE_CHUNK)) * PRIMITIVE_CHUNK  # whole chunks to each worker
        firsts = range(0, spreads.size, part)
        list(pool(workers).map(lambda first: evaluate(first, min(first + part, spreads.size)), firsts))
    else:
        evaluate(0, spreads.size)


def _same_shape(name_a: str, a: np.ndarray, name_b: str, b: np.ndarray) -> None:
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError(f"{name_a} and {name_b} must have broadcastable shapes, got {a.shape} and {b.shape}") from None


@dataclass(frozen=True)
class PSystem:
    """p-system with reference specific volume ``nu`` and shape parameter ``kappa``."""

    nu: float = 0.5
    kappa: float = 5.0

    def __post_init__(self):
        object.__setattr__(self, "nu", positive("nu", self.nu))
        object.__setattr__(self, "kappa", positive("kappa", self.kappa))
        # The primitive's scale kappa / (2 nu a^2) and L_LC = kappa / (4 nu) bound every speed constant.
        with np.errstate(over="ignore", divide="ignore"):
            scales = self.kappa / (np.array([2.0 * self.a**2, 4.0]) * self.nu)
        if not np.all(scales <= _LARGEST_SCALE):
            raise ValueError(f"nu = {self.nu} and kappa = {self.kappa} give speeds beyond {_LARGEST_SCALE:.0e}: "
                             "kappa / (2 nu asinh(kappa/2)^2) and kappa / (4 nu) must stay below it")

    d = 2

    @property
    def a(self) -> float:
        """asinh(kappa/2)."""
        return float(np.arcsinh(0.5 * self.kappa))

    @property
    def speed_scale(self) -> float:
        """kappa / (2 nu asinh(kappa/2)): the largest characteristic speed."""
        return self.kappa / (2.0 * self.nu * self.a)

    @property
    def primitive_coefficient(self) -> float:
        """-A/a: the factor of atan(sinh(a (w^+ - w^-))) in :meth:`speed_primitive`."""
        return -(self.speed_scale / self.a)

    @property
    def speed_lipschitz(self) -> float:
        """L_LC of assumption (LC): the largest |d lambda^+- / d w^+-|, A a max(sinh/cosh^2) = kappa/(4 nu)."""
        return self.kappa / (4.0 * self.nu)

    def _volume(self, u):
        return in_interval("specific volume u", u, 0.0, self.nu)

    def pressure(self, u):
        """Pressure law p(u) of section 5.2.2."""
        return pressure_formula(self._volume(u), self.nu, self.kappa)

    def sound_speed(self, u):
        """c(u) = sqrt(-p'(u))."""
        return sound_speed_formula(self._volume(u), self.nu, self.kappa)

    def g(self, u):
        """g(u) = int_0^u c(r) dr - 1/2."""
        u = self._volume(u)
        return np.arcsinh(self.kappa * (u / self.nu - 0.5)) / (2.0 * self.a)

    def riemann_invariants(self, u, v):
        """(w^-, w^+) = (v - g(u), v + g(u)); |g| <= 1/2, so both are finite for finite v."""
        g = self.g(u)
        v = in_interval("v", v, -np.inf, np.inf)  # any finite real array
        _same_shape("u", g, "v", v)
        return v - g, v + g

    def _levels(self, w_minus, w_plus):
        w_minus = in_interval("w_minus", w_minus, 0.0, 1.0)
        w_plus = in_interval("w_plus", w_plus, 0.0, 1.0)
        _same_shape("w_minus", w_minus, "w_plus", w_plus)
        return w_minus, w_plus

    def physical_variables(self, w_minus, w_plus):
        """(u, v) from the Riemann invariants, relation (5.6)."""
        w_minus, w_plus = self._levels(w_minus, w_plus)
        u = self.nu * (0.5 + np.sinh((w_plus - w_minus) * self.a) / self.kappa)
        return u, 0.5 * (w_plus + w_minus)

    def speeds(self, w_minus, w_plus):
        """(lambda^-, lambda^+) of (5.7)."""
        w_minus, w_plus = self._levels(w_minus, w_plus)
        magnitude = self.speed_scale / np.cosh((w_plus - w_minus) * self.a)
        return magnitude, -magnitude

    def speed_primitive(self, gamma: int, levels):
        """Antiderivative of lambda^gamma in its own variable, at ``levels[..., :] = (w^-, w^+)``.

        Both speeds are +-A / cosh(a (w^+ - w^-)) with A the speed scale, whose
        antiderivative is the Gudermannian: -(A/a) atan(sinh(a (w^+ - w^-))) serves
        for lambda^- in w^- and for lambda^+ in w^+ alike.
        """
        integer_at_least("gamma", gamma, 0)
        if gamma >= self.d:
            raise ValueError(f"gamma must be 0 (w^-) or 1 (w^+), got {gamma}")
        levels = in_interval("levels", levels, 0.0, 1.0)
        if levels.ndim == 0 or levels.shape[-1] != self.d:
            raise ValueError(f"levels must have a last axis of length d = {self.d} (w^-, w^+), got shape "
                             f"{levels.shape}")
        spread = levels[..., PLUS] - levels[..., MINUS]
        return speed_primitive_formula(spread, self.a, self.primitive_coefficient)
