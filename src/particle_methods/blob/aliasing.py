"""The quadrature error of the blob density for K = -|x|/2 in 1D, predicted without fitted parameters.

For the repulsive Newtonian kernel the blob density obeys d log rho_i/dt = -sum_j m_j psi_delta(X_i - X_j)
(Delta K = -delta_0), and scripts/blob/repulsive_data.py splits that sum, along the exact trajectories
X(alpha, t) = alpha + t m(alpha) of section 4.1 (m(alpha) = int_0^alpha rho0), into a regularisation part
and a quadrature part

    Q_i(t) = h sum_j f_i(jh) - int f_i(alpha) dalpha,    f_i(alpha) = rho0(alpha) psi_delta(X_i - X(alpha)),

whose L1_h norm sum_i h |rho(X_i, T) int_0^T Q_i dt| is the "quadrature part" of the density error at T.

Poisson summation gives Q_i = sum_{k != 0} F_i(2 pi k / h), F_i the Fourier transform of f_i. Near
alpha_i = ih the flow is X(alpha) = X_i + J_i (alpha - alpha_i) with J_i = 1 + t rho0(alpha_i), so the
Gaussian G_s(x) = exp(-x^2/s^2) / (sqrt(pi) s) of width s delta in psi (a mixture of such Gaussians,
(4.1)) becomes a Gaussian of width s delta / J_i in alpha, whose transform at 2 pi k / h is
(rho0_i / J_i) exp(-(pi k s delta / (h J_i))^2) times the phase exp(-2 pi i k alpha_i / h) = 1: at the
particles the aliases add up with the same sign at every time. The first alias (k = +-1) of the
narrowest Gaussian (s = 1, weight 4/3 for m = 4 and 64/45 for m = 6) dominates; the others are smaller by
exp(-3 c / J^2), with c = (pi delta / h)^2 and delta = h^q (below 3e-9 in Figure 4's study: J <= 1.5,
h <= 1/20). With rho0_i / J_i = rho(X_i, t) and u = J_i(t), the time integral is exact:

    int_0^T 2 w (rho0_i / J_i) exp(-c / J_i^2) dt = w [E1(c / J_i(T)^2) - E1(c)],

E1 the exponential integral. The prediction is therefore

    P = h sum_i rho(X_i, T) w [E1(c / J_i(T)^2) - E1(c)],

with nothing fitted: w and the width from (4.1), q, T and rho0 (for Figure 4, (4.5)) from the study.
Neglected: the curvature of the flow and the variation of rho0 over the imaginary displacement
pi s^2 delta^2 / (h J^2) of the saddle point of F_i, measured against the width 1/sqrt(2p) of the data
(1 - x^2)^p at their peak (:func:`saddle_ratio`), and the algebraic aliases of the ends +-1, where
rho0 vanishes to order p and so does the weight rho(X_i, T).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from ..validation import finite_result, nonnegative, positive
from .initial import as_data_1d, grid_1d
from .mollifiers import mollifier


def _checked(data, h: float, q: float, order: int):
    """(data, grid points, q, weight and width of the narrowest Gaussian of the mollifier of ``order``)."""
    data = as_data_1d(data)
    if data.power < 1:
        raise ValueError(f"the prediction needs data that vanish at the ends of [-1, 1], got {data.name} "
                         "(its jumps alias algebraically)")
    alpha = grid_1d(h)[:, 0]
    q = positive("q", q)
    if not 0.5 < q < 1.0:
        raise ValueError(f"q must lie in (1/2, 1) (delta = h^q, Theorem 3.8), got {q}")
    psi = mollifier(order, 1)
    narrowest = int(np.argmin(psi.widths))
    return data, alpha, q, psi.weights[narrowest], psi.widths[narrowest]


def quadrature_prediction_terms(data, h: float, q: float, t: float, order: int = 4) -> np.ndarray:
    """The terms of :func:`quadrature_prediction` particle by particle: the predicted time integral
    w [E1(c / J_i^2) - E1(c)] of the quadrature part Q_i up to ``t``, at the grid points ih of [-1, 1]
    (positive: the aliases add up with one sign). Its L1_h norm weighted by rho(X_i, t) is the prediction P;
    added to the regularisation part particle by particle it predicts the density error itself."""
    data, alpha, q, weight, width = _checked(data, h, q, order)
    t = nonnegative("t", t)
    jacobian = 1.0 + t * data(alpha)
    root_c = math.pi * width * h ** (q - 1.0)  # sqrt(c), so that c / J^2 underflows instead of overflowing
    cause = f"t = {t} is too large"
    return finite_result("the predicted quadrature part", weight * (special.exp1((root_c / jacobian) ** 2)
                                                                     - special.exp1(root_c**2)), cause)


def quadrature_prediction(data, h: float, q: float, t: float, order: int = 4) -> float:
    """Predicted quadrature part (see the module) of the blob density error for K = -|x|/2 at time ``t``:
    h sum_i rho(X_i, t) w [E1(c / J_i^2) - E1(c)], J_i = 1 + t rho0(ih), c = (pi s h^(q - 1))^2, for the
    narrowest Gaussian (weight w, width s delta) of the mollifier (4.1) of ``order``, particles at the grid
    points ih of [-1, 1] (h divides 1). ``data``: a :class:`~particle_methods.blob.initial.Data1D` with
    power >= 1 or its name.

    For m = 6 the prediction is 16/15 times that for m = 4: (4.1) gives
    psi6 = (16/15) psi4(x) - (1/30) psi4(x/2) = (64/45) G_1 - (4/9) G_2 + (1/45) G_4 against
    psi4 = (4/3) G_1 - (1/3) G_2 (G_s the unit Gaussian of width s), the same narrowest Gaussian G_1 with the
    weight (64/45) / (4/3) = 16/15 times m = 4's; the next one, G_2, aliases exp(-3 c / J^2) times less."""
    data = as_data_1d(data)
    alpha = grid_1d(h)[:, 0]
    t = nonnegative("t", t)
    rho0 = data(alpha)
    return float(h * (rho0 / (1.0 + t * rho0) * quadrature_prediction_terms(data, h, q, t, order)).sum())


def saddle_ratio(data, h: float, q: float, order: int = 4) -> float:
    """pi s^2 h^(2q - 1) sqrt(2p): the displacement of the saddle point behind :func:`quadrature_prediction`
    (its largest, J = 1) over the width 1/sqrt(2p) of the data (1 - x^2)^p at its peak. The prediction is
    an expansion in this ratio; above 1 its neglected terms are not small."""
    data, _, q, _, width = _checked(data, h, q, order)
    return math.pi * width**2 * h ** (2.0 * q - 1.0) * math.sqrt(2.0 * data.power)
