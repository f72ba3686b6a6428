"""The quadrature part of the repulsive blob density error predicted without fitted parameters
(particle_methods.blob.aliasing): its closed-form time integral, its mollifier dependence, its agreement with a
direct computation of the quadrature part, and its input checks."""

import numpy as np
import pytest

from particle_methods.blob.aliasing import quadrature_prediction, saddle_ratio
from particle_methods.blob.exact import newtonian_exact
from particle_methods.blob.initial import data_1d

DATA = data_1d("smooth10")
Q, T = 0.9, 0.5


def test_the_closed_form_is_the_time_integral_of_the_first_alias():
    """h sum_i rho(X_i, T) int_0^T 2 w (rho0_i / J_i) exp(-c / J_i^2) dt by a 40-point Gauss rule."""
    h = 1.0 / 80
    alpha = np.linspace(-1.0, 1.0, 161)
    rho0, c = DATA(alpha), (np.pi * h ** (Q - 1.0)) ** 2
    nodes, weights = np.polynomial.legendre.leggauss(40)
    times, weights = 0.5 * T * (nodes + 1.0), 0.5 * T * weights
    jacobian = 1.0 + times[:, None] * rho0
    rate = 2.0 * (4.0 / 3.0) * rho0 / jacobian * np.exp(-c / jacobian**2)
    direct = h * np.sum(rho0 / (1.0 + T * rho0) * (weights @ rate))
    assert quadrature_prediction(DATA, h, Q, T) == pytest.approx(direct, rel=1e-12)


def test_m6_over_m4_is_the_ratio_of_their_narrowest_weights():
    ratio = quadrature_prediction("smooth10", 0.0125, Q, T, order=6) / quadrature_prediction("smooth10", 0.0125, Q, T)
    assert ratio == pytest.approx((64 / 45) / (4 / 3), rel=1e-14)


def test_no_time_no_quadrature_part():
    assert quadrature_prediction(DATA, 0.05, Q, 0.0) == 0.0


def test_the_prediction_matches_the_quadrature_part_computed_directly():
    """At h = 1/160 (saddle ratio 0.24): the particle sum against a trapezoid rule 8 times finer, along the
    exact flow, integrated in time by 8 Gauss points and weighted by rho(X_i, T), as scripts/blob/repulsive_data.py
    measures it (m = 4): within 1 % (the neglected terms are second order in the saddle ratio)."""
    n, fine_factor = 160, 8
    h = 1.0 / n
    delta = h**Q
    alpha, fine = np.linspace(-1.0, 1.0, 2 * n + 1), np.linspace(-1.0, 1.0, 2 * n * fine_factor + 1)
    masses, fine_masses = DATA(alpha) * h, DATA(fine) * (h / fine_factor)
    nodes, weights = np.polynomial.legendre.leggauss(8)
    part = np.zeros(alpha.size)
    for t, w in zip(0.5 * T * (nodes + 1.0), 0.5 * T * weights):
        x = newtonian_exact(DATA, "newtonian_repulsive", alpha, t)[0]
        x_fine = newtonian_exact(DATA, "newtonian_repulsive", fine, t)[0]
        for sources, source_masses in ((x, masses), (x_fine, -fine_masses)):
            r2 = (x[:, None] - sources[None, :]) ** 2
            psi = (4 / 3 * np.exp(-r2 / delta**2) - 1 / 6 * np.exp(-r2 / (4 * delta**2))) / (np.sqrt(np.pi) * delta)
            part += w * (psi @ source_masses)
    measured = h * np.sum(np.abs(newtonian_exact(DATA, "newtonian_repulsive", alpha, T)[1] * part))
    assert saddle_ratio(DATA, h, Q) < 0.25
    assert quadrature_prediction(DATA, h, Q, T) == pytest.approx(measured, rel=0.01)


def test_the_saddle_ratio_falls_below_one_between_h_1_20_and_1_40():
    assert saddle_ratio(DATA, 0.05, Q) > 1.0 > saddle_ratio(DATA, 0.025, Q)


@pytest.mark.parametrize(("arguments", "message"), [
    (("indicator", 0.05, Q, T), "vanish at the ends"),
    ((DATA, 0.3, Q, T), "must divide 1"),
    ((DATA, 0.05, 1.0, T), "q must lie"),
    ((DATA, 0.05, 0.5, T), "q must lie"),
    ((DATA, 0.05, Q, -1.0), "t must be non-negative"),
    ((DATA, 0.05, Q, T, 5), "no mollifier of order"),
])
def test_bad_inputs_are_refused(arguments, message):
    with pytest.raises(ValueError, match=message):
        quadrature_prediction(*arguments)
