"""Exact entropy solutions used by the figures, as measures m_t with u(t, .) = H*m_t.

Each solution is given in Lagrangian form, by the quantile function
X_t(w) = F_t^{-1}(w) of m_t and its antiderivative, so that W1 errors against
particle approximations are integrated exactly (:func:`particle_methods.norms.w1_to_measure`).
"""

from __future__ import annotations

import math

import numpy as np

from ..jit import njit
from ..validation import finite_values, nonnegative
from .measures import Atoms, Laplace, QuantileMeasure, checked_measure


@njit
def _lambert_w0_kernel(z, out):
    """W_0(z), the principal branch of Lambert's function (w e^w = z, w >= -1), for -1/e <= z <= 0:
    Halley's iteration from the branch-point series -1 + p - p^2/3 + 11 p^3/72, p = sqrt(2 (e z + 1)),
    below z = -1/4 and from z - z^2 + 3 z^3/2 above, until a step is below one ulp (within 1e-14 of
    scipy.special.lambertw away from the branch point, where both lose digits to the conditioning)."""
    for i in range(z.size):
        x = z[i]
        q = 2.0 * (math.e * x + 1.0)
        if x == 0.0 or q <= 0.0:
            out[i] = 0.0 if x == 0.0 else -1.0
            continue
        if x < -0.25:
            p = math.sqrt(q)
            w = -1.0 + p * (1.0 + p * (-1.0 / 3.0 + p * 11.0 / 72.0))
        else:
            w = x * (1.0 - x * (1.0 - 1.5 * x))
        for _ in range(50):
            e = math.exp(w)
            f = w * e - x
            if f == 0.0:
                break
            step = f / (e * (w + 1.0) - (w + 2.0) * f / (2.0 * (w + 1.0)))
            w -= step
            if abs(step) <= 2.2e-16 * abs(w):
                break
        out[i] = w


def lambert_w0(z):
    """W_0 at every z (any shape) in [-1/e, 0]; values below -1/e by rounding only (1e-15 relative) are
    taken at -1/e, others outside the interval refused."""
    z = finite_values("z", z)
    if np.any(z > 0.0) or np.any(z < -(1.0 + 1e-15) / math.e):
        raise ValueError("z must lie in [-1/e, 0], the real domain of the principal branch taken here")
    out = np.empty(z.size)
    _lambert_w0_kernel(np.clip(z, -1.0 / math.e, 0.0).ravel(), out)
    return out.reshape(z.shape)


class BurgersSolution(QuantileMeasure):
    """Entropy solution of Burgers' equation (5.1) from any initial measure m_0.

    The speed lambda(w) = w is increasing, so X_t(w) = F_0^{-1}(w) + t w is
    non-decreasing for every t: characteristics never cross and every atom of m_0
    opens into a rarefaction fan. From delta_0 this is the uniform law on [0, t]
    (Remark 3.3); from (delta_{-1} + delta_1)/2 it is the pair of fans on
    [-1, -1 + t/2] and [1 + t/2, 1 + t] of section 5.1.2.
    """

    def __init__(self, initial: QuantileMeasure, t: float):
        self.initial = checked_measure("initial", initial)
        self.t = nonnegative("t", t)

    def _quantile(self, w):
        return self.initial._quantile(w) + self.t * w

    def _quantile_integral(self, w):
        return self.initial._quantile_integral(w) + 0.5 * self.t * w**2

    def _cdf(self, x):
        """From atoms a_j with levels (L_{j-1}, L_j], in closed form: the fan of atom j covers
        [a_j + t L_{j-1}, a_j + t L_j], on which F(x) = (x - a_j)/t; F is constant between fans.
        Other initial measures (or t = 0): by bisection on the quantile."""
        if not isinstance(self.initial, Atoms) or self.t == 0.0:
            return super()._cdf(x)
        atoms = self.initial
        j = np.searchsorted(atoms.positions + self.t * atoms.level_starts, x, side="right") - 1
        inside = (x - atoms.positions[np.maximum(j, 0)]) / self.t
        return np.where(j >= 0, np.minimum(atoms.levels[np.maximum(j, 0)], inside), 0.0)


class ConcaveLaplaceSolution(QuantileMeasure):
    """Entropy solution of (5.3) from the Laplace law (5.4), section 5.1.3.

    Characteristics X(w, t) = log(2w) + t (1/2 - w) for w < 1/2 (and their mirror
    images for w > 1/2) run into x = 0, where a stationary shock (the flux is
    symmetric about u = 1/2) absorbs them. For t <= 2 none has arrived. For t > 2
    the characteristic of level w reaches 0 when log(2w) = t (w - 1/2); the
    smaller root is w_0(t) = -W_0(-(t/2) e^{-t/2}) / t with W_0 the principal
    Lambert function, and the shock then carries mass 1 - 2 w_0(t).
    """

    def __init__(self, t: float):
        self.t = nonnegative("t", t)
        if 0.0 < self.t < np.finfo(np.float64).tiny:
            # (t/2) e^{x - t/2} would keep only the few bits of a subnormal t: F_t off by up to 1/2.
            raise ValueError(f"t must be 0 or at least {np.finfo(np.float64).tiny:.3g} (a normal double), got {self.t}")
        self._laplace = Laplace(0.0)
        if self.t <= 2.0:
            self.shock_level = 0.5
        else:
            root = lambert_w0(-0.5 * self.t * np.exp(-0.5 * self.t))
            self.shock_level = float(-root / self.t)

    def _left_cdf(self, x):
        """Level w < w_0(t) whose characteristic sits at x < 0: the root of
        log(2w) + t (1/2 - w) = x, i.e. w = -W_0(-(t/2) e^{x - t/2}) / t."""
        if self.t == 0.0:
            return 0.5 * np.exp(x)
        return -lambert_w0(-0.5 * self.t * np.exp(x - 0.5 * self.t)) / self.t

    def _cdf(self, x):
        """F_t(x): characteristics on each side, the atom of mass 1 - 2 w_0(t) at 0."""
        left = self._left_cdf(-np.abs(x))
        return np.where(x < 0, left, np.where(x > 0, 1.0 - left, 1.0 - self.shock_level))

    def _left_quantile(self, w):
        return self._laplace._quantile(w) + self.t * (0.5 - w)

    def _left_integral(self, w):
        return self._laplace._quantile_integral(w) + 0.5 * self.t * (w - w**2)

    def _quantile(self, w):
        lower = np.minimum(w, 1.0 - w)
        value = np.where(lower < self.shock_level, self._left_quantile(np.maximum(lower, 1e-300)), 0.0)
        return np.where(w < 0.5, value, -value)

    def _quantile_integral(self, w):
        # By the symmetry X_t(w) = -X_t(1 - w), int_0^w X_t = int_0^{1-w} X_t for w > 1/2.
        lower = np.minimum(w, 1.0 - w)
        return self._left_integral(np.minimum(lower, self.shock_level))
