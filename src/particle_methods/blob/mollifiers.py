"""Mollifiers (4.1) and (4.2) as mixtures of Gaussians.

With G_s(x) = exp(-|x|^2/s^2) / (sqrt(pi) s)^d, the unit-mass Gaussian of width s in
d dimensions, the paper's mollifiers are

    1D, m = 4:  psi4(x)       = 4/3 G_1 - 1/3 G_2                            (4.1)
    1D, m = 6:  psi6(x)       = 16/15 psi4(x) - 1/30 psi4(x/2)
                              = 64/45 G_1 - 20/45 G_2 + 1/45 G_4
    2D, m = 4:  psi4(x)       = 2 G_1 - G_sqrt2                              (4.2)

and psi_delta(x) = delta^{-d} psi(x/delta) is the same mixture with every width times
delta. Writing them this way makes every mollified kernel a sum of Gaussian
convolutions, which have closed forms (:mod:`particle_methods.blob.kernels`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import prange

from ..jit import njit_threaded
from ..threads import threads_for
from ..validation import finite_array, finite_result, finite_values, integer_at_least, positive, same_length


@dataclass(frozen=True)
class Mollifier:
    """psi = sum_i weights[i] G_{widths[i]} in ``dimension`` dimensions, of order ``order``."""

    order: int
    dimension: int
    weights: tuple[float, ...]
    widths: tuple[float, ...]

    def __post_init__(self):
        order = integer_at_least("order", self.order, 1)
        integer_at_least("dimension", self.dimension, 1, 3)
        weights, widths = finite_array("weights", self.weights), finite_array("widths", self.widths)
        if same_length(weights=weights, widths=widths) == 0 or np.any(widths <= 0):
            raise ValueError(f"a mollifier needs at least one Gaussian and positive widths, got {self.widths}")
        if order > 2 * widths.size:  # k Gaussians meet at most k moment conditions: the mass, moments 2, ..., 2k - 2
            raise ValueError(f"order = {order} exceeds twice the number of Gaussians (widths), {2 * widths.size}")
        # Tuples of floats: the mollifier is a key of the radial tables' cache.
        object.__setattr__(self, "weights", tuple(float(w) for w in weights))
        object.__setattr__(self, "widths", tuple(float(s) for s in widths))

    def scaled_widths(self, delta: float) -> np.ndarray:
        """Widths of the Gaussians of psi_delta."""
        widths = np.asarray(self.widths) * positive("delta", delta)
        return finite_result("the widths of psi_delta", widths, f"delta = {delta} is too large")

    def __call__(self, r, delta: float = 1.0):
        """psi_delta at distance r from the origin (any shape)."""
        r = finite_values("r", r)
        total = np.zeros_like(r)
        for weight, width in zip(self.weights, self.scaled_widths(delta)):
            total += weight * np.exp(-(r / width) ** 2) / (np.sqrt(np.pi) * width) ** self.dimension
        return finite_result("psi_delta", total, f"delta = {delta} is too small for double precision")

    def sums_1d(self, targets, sources, weights, delta: float) -> np.ndarray:
        """sum_j weights_j psi_delta(targets_i - sources_j) in 1D, over the sources within :data:`REACH` widths
        of the widest Gaussian of each target (the others add less than e^{-72} = 5e-32 of a Gaussian's
        peak each): a window of the sorted sources, O((T + S) log S + T w) instead of T x S."""
        if self.dimension != 1:
            raise ValueError("sums_1d needs a 1D mollifier")
        targets = np.ascontiguousarray(finite_array("targets", targets))
        sources, weights = finite_array("sources", sources), finite_array("weights", weights)
        same_length(sources=sources, weights=weights)
        order = np.argsort(sources, kind="stable")
        widths = self.scaled_widths(delta)
        with threads_for(targets.size, PARALLEL_MIN_TARGETS):
            sums = _windowed_sums(targets, np.ascontiguousarray(sources[order]), np.ascontiguousarray(weights[order]),
                                  np.asarray(self.weights) / (np.sqrt(np.pi) * widths), 1.0 / widths**2,
                                  REACH * widths.max())
        return finite_result("the mollified sums", sums, f"the weights are too large or delta = {delta} is too small "
                             "for double precision")


#: Half-width of the window of :meth:`Mollifier.sums_1d`, in widths of the widest Gaussian.
REACH = 8.5
#: Below this many targets :meth:`Mollifier.sums_1d` runs on one thread (the threshold of the LTP sums, whose
#: cost per target is alike; not measured separately).
PARALLEL_MIN_TARGETS = 1000


@njit_threaded
def _windowed_sums(targets, sources, weights, scales, inverse, reach):
    """sum over the sorted sources within ``reach`` of each target of weights_j sum_k scales_k e^{-inverse_k r^2}."""
    out = np.zeros(targets.size)
    for i in prange(targets.size):
        lo = np.searchsorted(sources, targets[i] - reach)
        hi = np.searchsorted(sources, targets[i] + reach, side="right")
        total = 0.0
        for j in range(lo, hi):
            r2 = (targets[i] - sources[j]) ** 2
            value = 0.0
            for k in range(scales.size):
                value += scales[k] * np.exp(-inverse[k] * r2)
            total += weights[j] * value
        out[i] = total
    return out


MOLLIFIERS = {
    (1, 4): Mollifier(4, 1, (4 / 3, -1 / 3), (1.0, 2.0)),
    (1, 6): Mollifier(6, 1, (64 / 45, -20 / 45, 1 / 45), (1.0, 2.0, 4.0)),
    (2, 4): Mollifier(4, 2, (2.0, -1.0), (1.0, np.sqrt(2.0))),
}


def mollifier(order: int, dimension: int = 1) -> Mollifier:
    """The paper's mollifier of ``order`` m in ``dimension`` d: (4.1) for d = 1, (4.2) for d = 2."""
    integer_at_least("mollifier order m", order, 1)
    integer_at_least("dimension d", dimension, 1)
    try:
        return MOLLIFIERS[(dimension, order)]
    except KeyError:
        available = ", ".join(f"m = {m} in {d}D" for d, m in MOLLIFIERS)
        raise ValueError(f"no mollifier of order m = {order} in dimension d = {dimension}: available "
                         f"{available}") from None
