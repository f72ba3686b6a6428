"""The entropy solution of the discretised data by Hopf's formula: the exact test of Remark 3.3.

The SPD started from atoms x_1 <= ... <= x_n with masses m_k carries the CDF u_n of section 1.1.3.
Its primitive W(t, x) = int_{-inf}^x u(t, z) dz solves the Hamilton-Jacobi equation

    W_t + Lambda(W_x) - Lambda(0) = 0,

whose viscosity solution is the primitive of the entropy solution of (1.1). The initial primitive
W_0(y) = sum_k m_k (y - x_k)^+ is convex, so Hopf's formula holds for any continuous flux:

    W(t, .) = (W_0^* + t (Lambda - Lambda(0)))^*,        * the Legendre transform,

that is, the Legendre transform of W(t, .) is the convex envelope, on the masses p in [0, M], of

    f(p) = W_0^*(p) + t (Lambda(p) - Lambda(0)),      W_0^*(p) = int_0^p X_0(q) dq,

X_0 the quantile function of the atoms (Lax-Oleinik in the dual variable). At the levels
c_k = m_1 + ... + m_k, W_0^*(c_k) = m_1 x_1 + ... + m_k x_k: f is known exactly there, and between
two levels W_0^* is linear, so for a concave flux f is concave on each [c_{k-1}, c_k] and its convex
envelope only ever touches it at levels (the maximisation over p in Hopf's formula is exact over the
n + 1 levels).

A state with positions y_(1) <= ... <= y_(n) (the particles keep their order in the SPD) has the
conjugate primitive G(c_k) = m_1 y_(1) + ... + m_k y_(k), linear between levels and convex. It is the
entropy solution exactly when G is the convex envelope of f, that is when

- G <= f at every level and between levels (a convex minorant), and
- G = f at p = 0, at p = M, and at every level where G has a corner (y_(k) < y_(k+1): two clusters),

because a convex minorant that touches f at each of its corners is the largest one.
:func:`hopf_gap` measures both conditions from the differences G - f, which it sums from the
displacements y_(k) - x_k: a shift of every position by a constant changes neither. A corner of
size delta = y_(k+1) - y_(k) counts with at most M delta (the change of G that would remove it), so
that the measure is continuous in the positions: two clusters apart by rounding decide nothing. Unlike the
Rankine-Hugoniot and Oleinik test of :mod:`.admissibility`, it needs no velocities: a state at the
wrong time, moved by wrong velocities or by particles that cross, fails it. Between levels it
samples ``points`` masses (exact for a concave flux with points = 0; a convex flux needs them: its
upward jumps are rarefactions, which G lies above between levels).
"""

from __future__ import annotations

import numpy as np

from ..validation import finite_array, finite_number, same_length
from .admissibility import checked_sampling, flux_values, mass_levels

#: Masses sampled strictly inside each interval between levels when the caller gives none.
DEFAULT_POINTS = 4


def hopf_gap(initial, positions, t: float, flux, masses=None, points: int = DEFAULT_POINTS) -> float:
    """Violation of Hopf's formula by the state ``positions`` at time ``t`` from the atoms ``initial``.

    Parameters
    ----------
    initial : the atoms x_k of the discretised data (2.1) (or any atoms), in the particles' order.
    positions : positions of the same particles at time t, in any order (the order statistics are
        compared with the sorted atoms: the function u a state carries depends only on where its mass sits).
    t : the time, >= 0.
    flux : the flux Lambda of (1.1), a callable on arrays of states u.
    masses : the mass of each particle, positive, in the order of ``initial``; None for 1/n each.
    points : masses sampled strictly inside each interval between levels, >= 0.

    Returns the largest of (G - f)^+ over the levels and sampled masses, |G - f| at p = M and
    min(|G - f|, M delta) at every level c_k, delta = y_(k+1) - y_(k) the corner of G there, relative
    to the largest term compared (M max |x|, M max |y| and t max |Lambda(c_k) - Lambda(0)|): 0 up to
    rounding (about n eps) exactly when the state's measure is
    the entropy solution of (1.1) from the atoms (module docstring), and of order the relative
    displacement of the wrong mass otherwise.
    """
    x = finite_array("initial", initial)
    y = finite_array("positions", positions)
    n = same_length(initial=x, positions=y)
    t = finite_number("t", t)
    if t < 0:
        raise ValueError(f"t must be >= 0, got {t}")
    points = checked_sampling(n, flux, points, 0)
    order = np.argsort(x, kind="stable")
    x = x[order]
    if masses is None:
        m = np.full(n, 1.0 / n)
        levels = np.arange(n + 1) / n  # exactly the levels of velocities_from_flux
    else:
        m, levels = mass_levels(masses, x, order)
    y = np.sort(y)
    step = m * (y - x)                                     # G - W_0^* gains m_k (y_(k) - x_k) across level k
    base = flux_values(flux, levels[:1])[0]
    rise = t * (flux_values(flux, levels) - base)                # t (Lambda(c_k) - Lambda(0))
    gap = np.concatenate(([0.0], np.cumsum(step))) - rise  # G(c_k) - f(c_k)
    # Contact at every level c_k between two clusters, weighed so that rounding decides nothing: a corner
    # of G of size delta = y_(k+1) - y_(k) counts at most M delta, the change of G that removes it.
    total = levels[-1]
    contact = np.minimum(np.abs(gap[1:-1]), total * np.diff(y))
    violations = [contact.max(initial=0.0), abs(gap[-1]), gap.max()]
    inside = rise[:0]
    if points:
        fractions = np.arange(1, points + 1) / (points + 1)
        masses_inside = levels[:-1, None] + fractions[None, :] * m[:, None]
        inside = t * (flux_values(flux, masses_inside.ravel()) - base)
        between = gap[:-1, None] + rise[:-1, None] + fractions[None, :] * step[:, None] - inside.reshape(n, points)
        violations.append(between.max())
    scale = max(total * float(np.abs(x).max()), total * float(np.abs(y).max()),
                float(np.abs(rise).max()), float(np.abs(inside).max(initial=0.0)))
    if scale == 0.0:  # every atom at 0 and nothing moves: G = f = 0
        return 0.0
    return float(max(0.0, *violations) / scale)

