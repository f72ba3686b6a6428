"""Interaction kernels and their mollified versions in closed form: the catalogue of section 4.

A kernel is a sum of terms. Each term has a ``kind``, a coefficient and a parameter
and gives, at distance r, three radial values: the potential k(r), the factor
g(r) with grad K(x) = x g(|x|), and the Laplacian l(r). Mollification by a mixture
of Gaussians (:mod:`particle_methods.blob.mollifiers`) turns a term into one term
per Gaussian, each in closed form:

- GAUSS_ABS_1D, (|x|/2) * G_s:  k = (x erf(x/s) + s e^{-x^2/s^2}/sqrt(pi))/2,
  grad = erf(x/s)/2, Laplacian = G_s(x): the 1D Newtonian kernel (Delta K = delta_0).
- GAUSS_CUBIC_1D, (|x|^3/3) * G_s: with Z ~ N(x, s^2/2),
  k = E|Z|^3/3, grad = E[Z|Z|] = (x^2 + s^2/2) erf(x/s) + x s e^{-x^2/s^2}/sqrt(pi),
  Laplacian = 2 E|Z| = 2 (x erf(x/s) + s e^{-x^2/s^2}/sqrt(pi)).
- LOG, log|x|/(2 pi) in d dimensions: grad = x/(2 pi |x|^2), Laplacian (d - 2)/(2 pi |x|^2) away
  from the origin (in 2D, the Newtonian kernel, a Dirac mass), grad K(0) := 0.
- GAUSS_LOG_1D, (log|x|/(2 pi)) * G_s in 1D: with Dawson's integral F and z = |x|/s,
  grad = F(z)/(pi s) sign(x) (the principal value (1/x) * G_s = (2/s) F(x/s)),
  Laplacian = F'(z)/(pi s^2) = (1 - 2 z F(z))/(pi s^2); its potential is not needed here.
- GAUSS_LOG_2D, (log|x|/(2 pi)) * G_s in 2D: grad = x (1 - e^{-r^2/s^2})/(2 pi r^2),
  Laplacian = G_s = e^{-r^2/s^2}/(pi s^2), k = (log r + E1(r^2/s^2)/2)/(2 pi).
- TABLE, a mollified term tabulated on a radial grid (:mod:`particle_methods.blob.radial`),
  interpolated linearly; the parameter is the table's row in the ``tables`` array.
- EXP, e^{-|x|/lambda} unmollified in 2D (Morse terms, parameter lambda): grad = -x e^{-r/lambda}/(lambda r),
  Laplacian = e^{-r/lambda}/lambda^2 - e^{-r/lambda}/(lambda r); grad K(0) := 0.
- POWER, |x|^a/a unmollified in d dimensions: grad = x |x|^{a-2},
  Laplacian = (a + d - 2)|x|^{a-2}; grad K(0) := 0 as in the particle method, and a
  polynomial kernel of degree below m is left unchanged by mollification (Remark 3.4).

The compiled pair sums over these kernels live in :mod:`particle_methods.blob.pair_sums`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..jit import njit
from ..validation import (
    finite_array,
    finite_result,
    in_interval,
    instance,
    integer_at_least,
    one_of,
    positive,
    real_array,
    same_length,
)
from .checks import MAX_FMM_PARTICLES, MAX_PARTICLES, MAX_TABLE_WORK
from .mollifiers import Mollifier
from .radial import RadialTable, tabulate
from .special import EULER_GAMMA, dawson_and_slope, exp1

GAUSS_ABS_1D, GAUSS_CUBIC_1D, POWER, LOG, GAUSS_LOG_2D, TABLE, EXP, GAUSS_LOG_1D = 0, 1, 2, 3, 4, 5, 6, 7
#: The dimensions each kind of term is written for (its Laplacian, or its Gaussian convolution, depends on d).
KIND_DIMENSIONS = {GAUSS_ABS_1D: (1,), GAUSS_CUBIC_1D: (1,), GAUSS_LOG_1D: (1,), POWER: (1, 2, 3), LOG: (1, 2, 3),
                   GAUSS_LOG_2D: (2,), TABLE: (2,), EXP: (2,)}
#: Distances beyond this many steps of a radial table would overflow its integer index.
TABLE_REACH = 2.0**40
_SQRT_PI = math.sqrt(math.pi)
#: Beyond this many widths erfc and the Gaussian are below 1e-17 relative: erf = 1, e = 0 exactly
#: in double precision, and the mollified kernel equals the raw one.
_GAUSS_CUTOFF = 6.5


@njit
def _gauss_parts(r, s):
    """(erf(r/s), exp(-r^2/s^2)), skipping both special functions far from the origin."""
    if r > _GAUSS_CUTOFF * s:
        return 1.0, 0.0
    return math.erf(r / s), math.exp(-(r / s) ** 2)


@njit
def _forces(kind, coefficient, parameter, r, dimension):
    """(g(r), l(r)) of one term at distance r >= 0: grad K = x g(|x|), Delta K = l(|x|)."""
    if kind == GAUSS_ABS_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        g = erf / (2.0 * r) if r > 0 else 1.0 / (s * _SQRT_PI)
        return coefficient * g, coefficient * e / (s * _SQRT_PI)
    if kind == GAUSS_CUBIC_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        g = (r * r + 0.5 * s * s) * erf / r + s * e / _SQRT_PI if r > 0 else 2.0 * s / _SQRT_PI
        return coefficient * g, coefficient * 2.0 * (r * erf + s * e / _SQRT_PI)
    if kind == GAUSS_LOG_2D:
        s = parameter
        if r > _GAUSS_CUTOFF * s:  # e^{-r^2/s^2} < 1e-18: the raw kernel in double precision
            return coefficient / (2 * math.pi * r * r), 0.0
        if r == 0.0:
            return coefficient / (2 * math.pi * s * s), coefficient / (math.pi * s * s)
        z = (r / s) ** 2
        e = math.exp(-z)
        one_minus_e = 1.0 - e if z > 1e-3 else -math.expm1(-z)
        return coefficient * one_minus_e / (2 * math.pi * r * r), coefficient * e / (math.pi * s * s)
    if kind == LOG:
        if r == 0.0:
            return 0.0, 0.0
        g = coefficient / (2 * math.pi * r * r)
        return g, (dimension - 2.0) * g
    if kind == GAUSS_LOG_1D:
        s = parameter
        if r == 0.0:
            return coefficient / (math.pi * s * s), coefficient / (math.pi * s * s)
        f, slope = dawson_and_slope(r / s)
        return coefficient * f / (math.pi * s * r), coefficient * slope / (math.pi * s * s)
    if kind == EXP:
        if r == 0.0:
            return 0.0, 0.0
        lam = parameter
        e = math.exp(-r / lam)
        return -coefficient * e / (lam * r), coefficient * (e / (lam * lam) - e / (lam * r))
    # POWER: |x|^a / a
    a = parameter
    if r == 0.0:
        return (coefficient, coefficient * (a + dimension - 2.0)) if a == 2.0 else (0.0, 0.0)
    ra = radial_power(r, a - 2.0)
    return coefficient * ra, coefficient * (a + dimension - 2.0) * ra


@njit
def radial_power(r, b):
    """r^b, r > 0, by products and a square root for the exponents of section 4 (a call to pow costs
    several times more); pow for the others. A compiled helper of the pair sums: it trusts its caller's checks."""
    if b == 0.0:
        return 1.0
    if b == 1.0:
        return r
    if b == 2.0:
        return r * r
    if b == 5.0:
        r2 = r * r
        return r2 * r2 * r
    if b == -0.5:
        return 1.0 / math.sqrt(r)
    return r**b


@njit
def _potential(kind, coefficient, parameter, r):
    """k(r) of one (untabulated) term."""
    if kind == GAUSS_ABS_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        return coefficient * 0.5 * (r * erf + s * e / _SQRT_PI)
    if kind == GAUSS_CUBIC_1D:
        s = parameter
        erf, e = _gauss_parts(r, s)
        # E|Z|^3 for Z ~ N(r, s^2/2): (r^3 + 3 r s^2/2) erf(r/s) + (r^2 + s^2) s e^{-r^2/s^2}/sqrt(pi)
        return coefficient * ((r**3 + 1.5 * r * s * s) * erf + (r * r + s * s) * s * e / _SQRT_PI) / 3.0
    if kind == GAUSS_LOG_2D:
        s = parameter
        if r == 0.0:
            return coefficient * (math.log(s) - 0.5 * EULER_GAMMA) / (2 * math.pi)
        z = (r / s) ** 2
        tail = 0.5 * exp1(z) if z < 745.0 else 0.0
        return coefficient * (math.log(r) + tail) / (2 * math.pi)
    if kind == GAUSS_LOG_1D:  # not tabulated: Kernel.has_potential is False
        return math.nan
    if kind == LOG:
        return coefficient * math.log(r) / (2 * math.pi) if r > 0 else 0.0
    if kind == EXP:
        return coefficient * math.exp(-r / parameter)
    return coefficient * r**parameter / parameter if r > 0 else 0.0


@njit
def _table_forces(coefficient, row, r, tables, steps):
    """(g, l) of a tabulated term by linear interpolation; the last node beyond the table."""
    table = tables[row]
    x = r / steps[row]
    j = min(int(x), table.shape[1] - 2)
    w = min(x - j, 1.0)
    g = table[0, j] * (1.0 - w) + table[0, j + 1] * w
    lap = table[1, j] * (1.0 - w) + table[1, j + 1] * w
    return coefficient * g, coefficient * lap


@njit
def profile_forces_kernel(kinds, coefficients, parameters, r, dimension, tables, steps):
    g = lap = 0.0
    for term in range(kinds.size):
        if kinds[term] == TABLE:
            tg, tl = _table_forces(coefficients[term], int(parameters[term]), r, tables, steps)
        else:
            tg, tl = _forces(kinds[term], coefficients[term], parameters[term], r, dimension)
        g += tg
        lap += tl
    return g, lap


@njit
def profile_potential_kernel(kinds, coefficients, parameters, r):
    k = 0.0
    for term in range(kinds.size):
        k += _potential(kinds[term], coefficients[term], parameters[term], r)
    return k



def is_newtonian_2d(kinds) -> bool:
    """Whether 2D terms are the Newtonian kernel, raw (one LOG term) or mollified by (4.2) (two
    GAUSS_LOG_2D terms): its sums have a path of their own (:func:`_newtonian_2d_sums`). A predicate on the
    kinds of a checked :class:`Kernel` or of :func:`.pair_sums.pair_sums`'s checked arrays: it trusts its caller's
    checks."""
    kinds = tuple(int(kind) for kind in kinds)
    return kinds in ((LOG,), (GAUSS_LOG_2D, GAUSS_LOG_2D))


@dataclass(frozen=True)
class Kernel:
    """K as a sum of terms (kind, coefficient, parameter), with its name, dimension and any radial
    tables its TABLE terms point to (rows of ``tables``, each (g, Laplacian) on a grid of ``steps``)."""

    name: str
    dimension: int
    kinds: tuple[int, ...]
    coefficients: tuple[float, ...]
    parameters: tuple[float, ...]
    tables: tuple = ()

    def __post_init__(self):
        """Check the terms before any compiled sum reads them; store them as tuples of Python numbers."""
        instance("name", self.name, str)
        dimension = integer_at_least("dimension", self.dimension, 1, 3)
        kinds = real_array("kinds", self.kinds)
        coefficients = finite_array("coefficients", self.coefficients)
        parameters = finite_array("parameters", self.parameters)
        tables = tuple(instance("tables", self.tables, (tuple, list)))
        for table in tables:
            instance("tables", table, RadialTable)
        if kinds.ndim != 1 or not np.all(np.isin(kinds, list(KIND_DIMENSIONS))):
            raise ValueError(f"kinds must be a sequence of term kinds {sorted(KIND_DIMENSIONS)}, got {self.kinds!r}")
        if same_length(kinds=kinds, coefficients=coefficients, parameters=parameters) == 0:
            raise ValueError("a kernel needs at least one term")
        for kind, parameter in zip(kinds.astype(int), parameters):
            if dimension not in KIND_DIMENSIONS[kind]:
                raise ValueError(f"terms of kind {kind} are written for dimension {KIND_DIMENSIONS[kind]}, "
                                 f"not {dimension}")
            if kind == TABLE and parameter not in range(len(tables)):
                raise ValueError(f"the parameter of a TABLE term must index one of the {len(tables)} tables, "
                                 f"got {parameter}")
            if kind not in (LOG, TABLE) and parameter <= 0:
                raise ValueError(f"parameters: the parameter of a term of kind {kind} (width, power or length) must be "
                                 f"positive, got {parameter}")
        if len({table.gradient.size for table in tables}) > 1:
            raise ValueError("the radial tables of one kernel must have the same number of nodes")
        object.__setattr__(self, "kinds", tuple(int(kind) for kind in kinds))
        object.__setattr__(self, "coefficients", tuple(float(c) for c in coefficients))
        object.__setattr__(self, "parameters", tuple(float(p) for p in parameters))
        object.__setattr__(self, "tables", tables)

    @property
    def jumps_at_origin(self) -> bool:
        """Whether grad K jumps or blows up at 0 (a raw |x|^a/a with a <= 1, log|x| or e^{-|x|/lambda}
        term): the particle method's ODE then stops being defined where two particles meet."""
        return any(kind in (LOG, EXP) or (kind == POWER and a <= 1.0) for kind, a in zip(self.kinds, self.parameters))

    @property
    def max_particles(self) -> int:
        """The most particles of one ODE solve with this kernel: :data:`~.checks.MAX_FMM_PARTICLES` for the 2D
        Newtonian kernel (O(N) sums by the fast multipole method), :data:`~.checks.MAX_PARTICLES` otherwise."""
        return MAX_FMM_PARTICLES if self.dimension == 2 and is_newtonian_2d(self.kinds) else MAX_PARTICLES

    @property
    def has_potential(self) -> bool:
        """Whether K itself is known (tabulated terms and the mollified 1D log kernel carry only grad
        and Laplacian)."""
        return TABLE not in self.kinds and GAUSS_LOG_1D not in self.kinds

    def arrays(self):
        if self.tables:
            size = max(t.gradient.size for t in self.tables)
            tables = np.zeros((len(self.tables), 2, size))
            for row, t in enumerate(self.tables):
                tables[row, 0, : t.gradient.size] = t.gradient
                tables[row, 1, : t.laplacian.size] = t.laplacian
            steps = np.array([t.step for t in self.tables])
        else:
            tables, steps = np.zeros((1, 2, 2)), np.ones(1)
        return (np.array(self.kinds, dtype=np.int64), np.array(self.coefficients, dtype=np.float64),
                np.array(self.parameters, dtype=np.float64), tables, steps)

    def profile(self, r):
        """(k, g, l) at the distances r >= 0 (any shape), vectorised (for plots and tests): K = k(|x|),
        grad K = x g(|x|), Delta K = l(|x|); k is None when K itself is not known (:attr:`has_potential`)."""
        r = in_interval("r", r, 0.0, np.inf)
        kinds, coefficients, parameters, tables, steps = self.arrays()
        if self.tables and r.size and r.max() > TABLE_REACH * steps.min():
            raise ValueError(f"r must stay within 2^40 steps of the kernel's radial table, got {r.max()}")
        cause = "the kernel overflows at these distances r"
        forces = [profile_forces_kernel(kinds, coefficients, parameters, float(x), self.dimension, tables, steps)
                  for x in r.ravel()]
        g, lap = np.moveaxis(finite_result("grad K and Delta K", np.reshape(forces, r.shape + (2,)), cause), -1, 0)
        if not self.has_potential:
            return None, g, lap
        k = np.reshape([profile_potential_kernel(kinds, coefficients, parameters, float(x)) for x in r.ravel()],
                       r.shape)
        return finite_result("K", k, cause), g, lap


#: 1D kernels of section 4: name -> (sign, kind of its Gaussian convolution, power a).
KERNELS_1D = {
    "newtonian_attractive": (1.0, GAUSS_ABS_1D, 1.0),   # K = (Delta)^{-1} = |x|/2
    "newtonian_repulsive": (-1.0, GAUSS_ABS_1D, 1.0),   # K = (-Delta)^{-1} = -|x|/2
    "cubic": (1.0, GAUSS_CUBIC_1D, 3.0),                # K = |x|^3/3
    "log_repulsive": (-1.0, GAUSS_LOG_1D, 0.0),         # K = -log|x|/(2 pi), Figure 4's row label
}


def kernel_1d(name: str, mollifier: Mollifier | None = None, delta: float | None = None) -> Kernel:
    """A 1D kernel of section 4, mollified by psi_delta, or raw (particle method) without mollifier."""
    sign, gaussian_kind, a = one_of("kernel", name, KERNELS_1D)
    if mollifier is None:
        if delta is not None:
            raise ValueError("delta needs a mollifier")
        if gaussian_kind == GAUSS_LOG_1D:
            return Kernel(name, 1, (LOG,), (sign,), (0.0,))
        # |x|/2 for the Newtonian kernels, |x|^3/3 for the cubic one.
        return Kernel(name, 1, (POWER,), (sign * (0.5 if a == 1.0 else 1.0),), (a,))
    if instance("mollifier", mollifier, Mollifier).dimension != 1:
        raise ValueError("a 1D kernel needs a 1D mollifier")
    delta = positive("delta", delta)
    widths = mollifier.scaled_widths(delta)
    # The Gaussian terms carry the kernel's own factor (1/2, 1/3 or 1/(2 pi)): only sign and weights remain.
    return Kernel(f"{name} (m = {mollifier.order}, delta = {delta:.4g})", 1,
                  tuple(gaussian_kind for _ in widths), tuple(sign * w for w in mollifier.weights),
                  tuple(float(s) for s in widths))


#: 2D kernels of section 4.4: name -> unmollified terms (kind, coefficient, parameter).
KERNELS_2D = {
    "newtonian": ((LOG, 1.0, 0.0),),                           # log|x|/(2 pi) = (Delta)^{-1}
    "quadratic": ((POWER, 1.0, 2.0),),                            # |x|^2/2
    "cubic": ((POWER, 1.0, 3.0),),                                # |x|^3/3
    "quartic_log": ((POWER, 1.0, 4.0), (LOG, -1.0, 0.0)),      # |x|^4/4 - log|x|/(2 pi)
    "quartic_power": ((POWER, 1.0, 4.0), (POWER, -1.0, 1.5)),     # |x|^4/4 - |x|^1.5/1.5
    "septic_power": ((POWER, 1.0, 7.0), (POWER, -1.0, 1.5)),      # |x|^7/7 - |x|^1.5/1.5
    "morse_1": ((EXP, 1.0, 1.0), (EXP, -2.0, 2.0)),               # e^{-|x|} - 2 e^{-|x|/2}
    "morse_2": ((EXP, 2.0, 1.0), (EXP, -2.0, 2.0)),               # 2 e^{-|x|} - 2 e^{-|x|/2}
}


def _radial_laplacian(kind, parameter):
    """Delta of one unmollified 2D term (without its coefficient), as a function of r > 0."""
    if kind == POWER:
        return lambda r: parameter * r ** (parameter - 2.0)  # (a + d - 2) r^{a-2} with d = 2
    if kind == EXP:
        return lambda r: np.exp(-r / parameter) * (1.0 / parameter**2 - 1.0 / (parameter * r))
    raise ValueError(f"no radial Laplacian for term kind {kind}")


def _check_table(delta, radius, points):
    """A radial table on [0, radius] with ``points`` nodes must resolve and cover psi_delta (step <= delta <=
    radius), within :data:`~particle_methods.blob.checks.MAX_TABLE_WORK`."""
    step = radius / (points - 1)
    if not step <= delta <= radius:
        raise ValueError(f"delta = {delta} must lie between the radial table's step {step:.4g} and its radius {radius} "
                         "(table_radius, table_points)")
    if points * radius / delta > MAX_TABLE_WORK:
        raise ValueError(f"table_points x table_radius / delta = {points * radius / delta:.4g} exceeds MAX_TABLE_WORK "
                         f"= {MAX_TABLE_WORK:g} (a limit on the work of the radial quadrature)")


@functools.lru_cache(maxsize=32)
def _mollified_table(kind, parameter, mollifier, delta, radius, points):
    """The radial table of one unmollified term (without its coefficient), built once per process:
    the two Morse kernels share theirs, and the runs of a figure rebuild the same kernel."""
    return tabulate(_radial_laplacian(kind, parameter), mollifier, delta, radius, points)


def kernel_2d(name: str, mollifier: Mollifier | None = None, delta: float | None = None, *,
              table_radius: float = 5.0, table_points: int = 8001) -> Kernel:
    """A 2D kernel of section 4.4, raw (particle method) or mollified by psi_delta.

    Mollification: the log term becomes Gaussian terms in closed form; a power |x|^a/a with
    a even and a - 1 < m is unchanged (its gradient and Laplacian are polynomials of degree
    below m, Remark 3.4); every other term is tabulated by numerical radial convolution
    (:func:`particle_methods.blob.radial.tabulate`) on [0, table_radius] with table_points nodes, which
    must resolve and cover psi_delta (step <= delta <= table_radius).
    """
    terms = one_of("2D kernel", name, KERNELS_2D)
    table_radius = positive("table_radius", table_radius)
    table_points = integer_at_least("table_points", table_points, 3, int(MAX_TABLE_WORK))
    if mollifier is None:
        if delta is not None:
            raise ValueError("delta needs a mollifier")
        kinds, coefficients, parameters = zip(*terms)
        return Kernel(name, 2, kinds, coefficients, parameters)
    if instance("mollifier", mollifier, Mollifier).dimension != 2:
        raise ValueError("a 2D kernel needs a 2D mollifier")
    delta = positive("delta", delta)
    kinds, coefficients, parameters, tables = [], [], [], []
    for kind, coefficient, parameter in terms:
        if kind == LOG:
            for weight, width in zip(mollifier.weights, mollifier.scaled_widths(delta)):
                kinds.append(GAUSS_LOG_2D)
                coefficients.append(coefficient * weight)
                parameters.append(float(width))
        elif kind == POWER and parameter % 2 == 0 and parameter - 1 < mollifier.order:
            kinds.append(kind)
            coefficients.append(coefficient)
            parameters.append(parameter)
        else:
            _check_table(delta, table_radius, table_points)
            tables.append(_mollified_table(kind, float(parameter), mollifier, delta, table_radius, table_points))
            kinds.append(TABLE)
            coefficients.append(coefficient)
            parameters.append(float(len(tables) - 1))
    return Kernel(f"{name} (m = {mollifier.order}, delta = {delta:.4g})", 2, tuple(kinds), tuple(coefficients),
                  tuple(parameters), tuple(tables))
