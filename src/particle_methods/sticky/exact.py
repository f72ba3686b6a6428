"""Exact entropy solutions used by the figures, as measures m_t with u(t, .) = H*m_t.

Each solution is given in Lagrangian form, by the quantile function
X_t(w) = F_t^{-1}(w) of m_t and its antiderivative, so that W1 errors against
particle approximations are integrated exactly (:func:`particle_methods.norms.w1_to_measure`).
"""

from __future__ import annotations

import numpy as np
from scipy import special

from ..validation import nonnegative
from .measures import Laplace, QuantileMeasure, checked_measure


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
            root = special.lambertw(-0.5 * self.t * np.exp(-0.5 * self.t), 0).real
            self.shock_level = float(-root / self.t)

    def _left_cdf(self, x):
        """Level w < w_0(t) whose characteristic sits at x < 0: the root of
        log(2w) + t (1/2 - w) = x, i.e. w = -W_0(-(t/2) e^{x - t/2}) / t."""
        if self.t == 0.0:
            return 0.5 * np.exp(x)
        return -special.lambertw(-0.5 * self.t * np.exp(x - 0.5 * self.t), 0).real / self.t

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
