"""Initial data of section 4.2-4.3 on [-1, 1] and the particles of Definition 2.2.

(4.3) (1 - x^2)^20, (4.4) the indicator of [-1, 1], (4.5) (1 - x^2)^10, none normalised,
as in the paper. Particles sit at the grid points jh of [-1, 1] with masses rho0(jh) h^d; the
grids hold at most :data:`~particle_methods.blob.checks.MAX_PARTICLES` points (1D) or four times
:data:`~particle_methods.blob.checks.MAX_FMM_PARTICLES` nodes around the data (2D; a run then takes the
limit of its kernel).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..jit import njit
from ..validation import finite_values, instance, integer_at_least, one_of, positive
from .checks import MAX_DATA_POWER, MAX_FMM_PARTICLES, MAX_PARTICLES

#: Points are taken in tiles of this many: the recurrence runs one degree at a time over a tile, a loop
#: that LLVM vectorises (1.8x faster than one point at a time, the same operations in the same order).
_TILE = 256


@njit
def power_mass_kernel(x, power, out):
    """int_0^x (1 - s^2)^power ds at each x in [-1, 1], by the recurrence of Data1D.mass_from_origin, into out (also
    the bump kernels of particle_methods.cross.hull). It trusts its caller's checks."""
    factor = np.empty(_TILE)
    base = np.empty(_TILE)
    for start in range(0, x.size, _TILE):
        count = min(_TILE, x.size - start)
        for j in range(count):
            base[j] = 1.0 - x[start + j] * x[start + j]
            factor[j] = 1.0
            out[start + j] = x[start + j]
        for p in range(1, power + 1):
            twice, odd = 2.0 * p, 2.0 * p + 1.0
            for j in range(count):
                factor[j] *= base[j]
                out[start + j] = (x[start + j] * factor[j] + twice * out[start + j]) / odd


@dataclass(frozen=True)
class Data1D:
    """A symmetric density on [-1, 1]: polynomial (1 - x^2)^power, or the indicator (power 0)."""

    name: str
    power: int

    def __post_init__(self):
        instance("name", self.name, str)
        integer_at_least("power", self.power, 0, MAX_DATA_POWER)

    def __call__(self, x):
        """rho0 at the points ``x`` (any shape)."""
        return self._density(finite_values("x", x))

    # The unchecked versions, for float64 arrays of finite positions: the bumps of particle_methods.cross.hull call
    # them on positions they have checked (their root iterations, compiled since, called them thousands of times on a
    # few points, where the checks took a fifth of the time: issue 47). The same operations as the checked ones, so
    # the same numbers.

    def _density(self, x):
        return np.where(np.abs(x) <= 1.0, np.clip(1.0 - x * x, 0.0, None) ** self.power, 0.0)

    @property
    def maximum(self) -> float:
        return 1.0

    @property
    def mass(self) -> float:
        """Total mass M = 2 m(1)."""
        return 2.0 * float(self.mass_from_origin(1.0))

    def mass_from_origin(self, x):
        """m(x) = int_0^x rho0 (odd in x), exactly, by the recurrence of I_p(x) = int_0^x (1 - s^2)^p ds,

            (2p + 1) I_p = x (1 - x^2)^p + 2p I_{p-1},    I_0 = x,

        whose factor 2p/(2p + 1) < 1 damps rounding errors (the expanded polynomial of (4.3) has
        coefficients up to 10^5 and loses six digits to cancellation near |x| = 1).
        """
        return self._mass_from_origin(finite_values("x", x))

    def _mass_from_origin(self, x):
        x = np.clip(x, -1.0, 1.0)
        out = np.empty(x.size)
        power_mass_kernel(np.ascontiguousarray(x).ravel(), self.power, out)
        return out.reshape(x.shape)

    def moment_from_left(self, x):
        """int_{-1}^x s rho0(s) ds = -(1 - x^2)_+^{p+1} / (2(p + 1)) (zero outside [-1, 1])."""
        return self._moment_from_left(finite_values("x", x))

    def _moment_from_left(self, x):
        return -np.clip(1.0 - x * x, 0.0, None) ** (self.power + 1) / (2.0 * (self.power + 1))


DATA_1D = {"smooth20": Data1D("(1 - x^2)^20 (4.3)", 20), "indicator": Data1D("indicator of [-1, 1] (4.4)", 0),
           "smooth10": Data1D("(1 - x^2)^10 (4.5)", 10)}


def data_1d(name: str) -> Data1D:
    """Initial data 'smooth20' (4.3), 'indicator' (4.4) or 'smooth10' (4.5)."""
    return one_of("initial data", name, DATA_1D)


def as_data_1d(data) -> Data1D:
    """``data`` itself or the data named by it (see :func:`data_1d`)."""
    return data_1d(data) if isinstance(data, str) else instance("data", data, Data1D)


def grid_1d(h: float) -> np.ndarray:
    """Grid points jh of [-1, 1], as a column (N, 1); h must divide 1 for the ends to be nodes."""
    h = positive("h", h)
    if 2.0 / h + 1.0 > MAX_PARTICLES:
        raise ValueError(f"h = {h} puts {2.0 / h + 1.0:.4g} particles on [-1, 1], more than MAX_PARTICLES = "
                         f"{MAX_PARTICLES} (a limit on the work of one run)")
    half = int(round(1.0 / h))
    if abs(half * h - 1.0) > 1e-9:
        raise ValueError(f"h = {h} must divide 1 so that the grid hZ contains the ends of [-1, 1]")
    return (h * np.arange(-half, half + 1))[:, None]


_NAMES_2D = ("regular", "disk", "quartic", "bump", "star")


@dataclass(frozen=True)
class Data2D:
    """2D initial data of section 4.4, with its radial mass function m(r) = int_0^r s rho0(s) ds."""

    name: str
    radius: float

    def __post_init__(self):
        one_of("2D data", self.name, dict.fromkeys(_NAMES_2D))
        positive("radius", self.radius)

    def __call__(self, points):
        """rho0 at ``points`` (..., 2)."""
        points = finite_values("points", points)
        if points.ndim == 0 or points.shape[-1] != 2:
            raise ValueError(f"points must have shape (..., 2), got {points.shape}")
        r2 = (points**2).sum(axis=-1)
        if self.name == "regular":          # (1 - |x|^2)_+^2
            return np.clip(1.0 - r2, 0.0, None) ** 2
        if self.name == "disk":             # indicator of the closed unit disk
            return np.where(r2 <= 1.0, 1.0, 0.0)
        if self.name == "quartic":          # (4.7): C (1 - |x|^2)^2 with unit mass, C = 3/pi
            return 3.0 / np.pi * np.clip(1.0 - r2, 0.0, None) ** 2
        if self.name == "bump":             # exp(1/(|x|^2 - 1)) with unit mass
            inside = r2 < 1.0
            return np.where(inside, np.exp(1.0 / np.where(inside, r2 - 1.0, -1.0)), 0.0) / _BUMP_MASS
        # star, (4.6): 1 for r < (sin^2(5 theta/2) + 1/2)/4
        theta = np.arctan2(points[..., 1], points[..., 0])
        return np.where(np.sqrt(r2) < (np.sin(2.5 * theta) ** 2 + 0.5) / 4.0, 1.0, 0.0)

    def mass_from_origin(self, r):
        """m(r) = int_0^r s rho0(s) ds for the radial data with exact solutions (regular, disk)."""
        r = np.clip(finite_values("r", r), 0.0, 1.0)
        if self.name == "regular":
            return (1.0 - (1.0 - r**2) ** 3) / 6.0
        if self.name == "disk":
            return r**2 / 2.0
        raise ValueError(f"no radial mass function for {self.name!r}")


def _bump_mass() -> float:
    from scipy import integrate

    return integrate.quad(lambda r: 2 * np.pi * r * np.exp(1.0 / (r * r - 1.0)), 0.0, 1.0, epsabs=1e-15)[0]


_BUMP_MASS = _bump_mass()
DATA_2D = {name: Data2D(name, 0.375 if name == "star" else 1.0) for name in _NAMES_2D}


def data_2d(name: str) -> Data2D:
    """2D data: 'regular' (1 - |x|^2)_+^2, 'disk' (indicator), 'bump' exp(1/(|x|^2 - 1)) with unit mass,
    'quartic' (4.7) and 'star' (4.6)."""
    return one_of("2D data", name, DATA_2D)


def as_data_2d(data) -> Data2D:
    """``data`` itself or the data named by it (see :func:`data_2d`)."""
    return data_2d(data) if isinstance(data, str) else instance("data", data, Data2D)


def grid_2d(h: float, data: Data2D) -> np.ndarray:
    """Points of hZ^2 where rho0 > 0, shape (N, 2); ``data`` or its name, 0 < h <= its radius."""
    data = as_data_2d(data)
    h = positive("h", h)
    if h > data.radius:
        raise ValueError(f"h = {h} must not exceed the radius {data.radius} of the data {data.name!r}")
    side = 2.0 * np.ceil(data.radius / h) + 3.0  # nodes on a side of the grid's box
    if side > 2.0 * np.sqrt(MAX_FMM_PARTICLES):
        raise ValueError(f"h = {h} gives {side:.4g}^2 grid nodes around the data, more than 4 MAX_FMM_PARTICLES = "
                         f"{4 * MAX_FMM_PARTICLES} (a limit on the work of one run)")
    half = int(np.ceil(data.radius / h)) + 1
    axis = h * np.arange(-half, half + 1)
    points = np.stack(np.meshgrid(axis, axis, indexing="ij"), axis=-1).reshape(-1, 2)
    return points[data(points) > 0]
