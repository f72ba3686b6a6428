"""Claims of Figures 5-7 of the sticky-particle paper (section 5.2.2) beyond those of
:func:`particle_replication.verdicts.sticky.psystem_claims`.

Figure 6: the text of section 5.2.2 observes, in the shock case, two clusters that break up under
the effect of a collision. Read on the trajectory: a cluster of - particles crosses the cluster of
+ particles, and both split right after; :func:`collisions` finds every such crossing.

Panels (c) and (d) of Figures 5 and 7 show u and v, which (5.6) computes pointwise from w- and w+:
v = (w+ + w-)/2 and u a smooth, strictly increasing function of w+ - w- (slope between
nu a / kappa and nu a cosh(a) / kappa, a = asinh(kappa/2)). Both w are non-decreasing in x, so v
jumps exactly where w- or w+ does, and u where their jumps differ: lone particles make jumps of
O(1/n), a cluster of k particles one of O(k/n). The shocks of u and v are therefore the clusters of
the MSPD, as for w (u alone would miss a - cluster and a + cluster of equal mass at one place), and
the statements of section 5.2.2 on the shocks and rarefactions of u and v add no claim to those on
w (fig5.no_shock, fig7.early_shocks, fig7.late_rarefactions). What the w claims leave open is that
the panels form a solution of the p-system, whose two equations are conservation laws:
:func:`conservation_defect` measures them in integral form on u and v.
"""

from __future__ import annotations

import functools

import numpy as np

from particle_methods.sticky.cases import empirical_cdf
from particle_methods.systems import MINUS, PLUS

from .. import claims as c

claim = functools.partial(c.claim, "sticky")


def clusters(positions) -> list[tuple[int, int]]:
    """Index ranges [start, stop) of the clusters of at least two particles of sorted ``positions``."""
    positions = np.asarray(positions)
    starts = np.flatnonzero(np.concatenate(([True], np.diff(positions) > 0)))
    stops = np.append(starts[1:], positions.size)
    return [(int(a), int(b)) for a, b in zip(starts, stops) if b - a >= 2]


def collisions(path) -> list[tuple[int, int, int, int]]:
    """Crossings of a - cluster and a + cluster in an iterated TSPD trajectory, and their effect.

    A collision is seen at step k when a - cluster A and a + cluster B (two particles or more each)
    lie at step k with A to the right of B while, at step k - 1, a member of A lay to the left of a
    member of B. The velocities of a step are frozen at its start, so the new ranks act from step k
    on and their effect shows at step k + 1. Returns, per collision, (k, size of A, size of B, how
    many of A and B no longer sit at one position at step k + 1).
    """
    out = []
    for k in range(1, len(path) - 1):
        for a0, a1 in clusters(path[k, MINUS]):
            for b0, b1 in clusters(path[k, PLUS]):
                met = path[k - 1, MINUS, a0:a1].min() < path[k - 1, PLUS, b0:b1].max()
                if path[k, MINUS, a0] > path[k, PLUS, b0] and met:
                    split = int(np.ptp(path[k + 1, MINUS, a0:a1]) > 0) + int(np.ptp(path[k + 1, PLUS, b0:b1]) > 0)
                    out.append((k, a1 - a0, b1 - b0, split))
    return out


def blown_up(path) -> tuple[float, str]:
    """The largest number of the two colliding clusters that split after one collision, and the
    collision that shows it (0 when no - cluster crosses a + cluster)."""
    found = collisions(path)
    if not found:
        return 0.0, "no - cluster crosses a + cluster"
    k, minus, plus, split = max(found, key=lambda event: event[3])
    return float(split), (f"{len(found)} collision(s), the largest count at step {k}: {minus} - and {plus} + "
                          f"particles, {split} of the two split")


def conservation_defect(path, times, system) -> tuple[float, float, float]:
    """Largest defect over t of the p-system's conservation laws in integral form, on u and v of (5.6).

    u and v are step functions between the positions of the configuration, with u = nu/2 and v = 0
    to the left of every particle, u = nu/2 and v = 1 to the right (w+ = w-). Hence
    d/dt int (u - nu/2) dx = [v] (the jump of v across the line, from u_t = v_x) and
    d/dt int (v - 1{x >= 0}) dx = -[p(u)] (from v_t + p(u)_x = 0): both integrals are computed
    exactly at every time, their drift from these rates taken in absolute value. Returns the largest,
    relative to the last time t_end (the growth of int u over the run: w- and w+ run from 0 to 1, so
    [v] = 1), then [v] and [p(u)].
    """
    ends_u, ends_v = system.physical_variables(np.array([0.0, 1.0]), np.array([0.0, 1.0]))
    jump_v, jump_p = ends_v[1] - ends_v[0], system.pressure(ends_u[1]) - system.pressure(ends_u[0])
    volume, velocity = [], []
    for state in path:
        edges = np.sort(np.append(state.ravel(), 0.0))  # 0: where 1{x >= 0} jumps
        middle, widths = 0.5 * (edges[1:] + edges[:-1]), np.diff(edges)
        u, v = system.physical_variables(empirical_cdf(state[MINUS], middle), empirical_cdf(state[PLUS], middle))
        volume.append(np.sum((u - 0.5 * system.nu) * widths))
        velocity.append(np.sum((v - (middle >= 0)) * widths))
    times = np.asarray(times, dtype=float)
    defects = np.maximum(np.abs(np.array(volume) - volume[0] - times * jump_v),
                         np.abs(np.array(velocity) - velocity[0] + times * jump_p))
    return float(defects.max() / times[-1]), float(jump_v), float(jump_p)


def figure_claims(rarefaction, shocks, system, conservation_tolerance: float) -> list:
    """Figure 6 (two clusters blown up by one collision) and Figure 5 (c), (d) (u and v conserve as
    the p-system does; ``conservation_tolerance``: the largest defect of :func:`conservation_defect`)."""
    path, field = shocks["trajectories"], shocks["field_path"]
    split, text = blown_up(path)
    field_text = blown_up(field)[1]
    defect, jump_v, jump_p = conservation_defect(rarefaction["field_path"], rarefaction["times"], system)
    return [
        claim(c.at_least, "fig6.two_clusters_blow_up", "paper", "section 5.2.2 (on Figure 6)", "6",
              f"a - cluster and the + cluster cross each other and both break up under the effect of it: largest "
              f"number of the two colliding clusters (each of two particles or more) no longer at one position in "
              f"the iterated TSPD step after the crossing, over the collisions of the run of Figure 6 "
              f"({path.shape[-1]} per type: {text}; the run of Figure 7, {field.shape[-1]} per type: {field_text})",
              2.0, split, published="two clusters"),
        claim(c.at_most, "fig5.uv_conservation", "check", "section 5.2.2: the p-system, (5.6), Figure 5 (c), (d)",
              "5",
              f"u and v of panels (c), (d) ({rarefaction['field_path'].shape[-1]} per type) solve the p-system, "
              f"with no shock its conservation laws hold: int (u - nu/2) dx grows at the rate [v] = {jump_v:g} "
              f"and int (v - 1{{x >= 0}}) dx at the rate -[p(u)] = {0.0 - jump_p:g}; exact integrals of the step "
              f"functions, largest defect over t <= {float(rarefaction['times'][-1]):g}, relative to t_end "
              "(the shocks and rarefactions of u and v follow from those of w by (5.6): no claim of their own)",
              conservation_tolerance, defect, published="(our check)"),
    ]
