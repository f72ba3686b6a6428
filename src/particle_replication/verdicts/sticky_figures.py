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
w (fig5.no_shock, fig7.early_shocks, fig7.late_rarefactions). A check that u and v conserve as the
p-system does was tried and dropped: the law for v holds for every configuration (the velocities
(1.8) sum to zero along the rank staircase), and the defect of the law for u stays below any useful
tolerance even in the shock case, where the MSPD's limit is not the conservative solution.
"""

from __future__ import annotations

import functools

import numpy as np

from particle_methods.sticky.spd import cluster_sizes
from particle_methods.systems import MINUS, PLUS

from .. import claims as c

claim = functools.partial(c.claim, "sticky")


def clusters(positions) -> list[tuple[int, int]]:
    """Index ranges [start, stop) of the clusters of at least two particles of sorted ``positions``."""
    stops = np.cumsum(cluster_sizes(positions))
    return [(int(b - size), int(b)) for b, size in zip(stops, np.diff(stops, prepend=0)) if size >= 2]


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


def figure_claims(shocks) -> list:
    """Figure 6: two clusters blown up by one collision (section 5.2.2)."""
    path, field = shocks["trajectories"], shocks["field_path"]
    split, text = blown_up(path)
    field_text = blown_up(field)[1]
    return [
        claim(
            c.at_least, "fig6.two_clusters_blow_up", kind="paper", source="section 5.2.2 (on Figure 6)", figure="6",
            text=f"a - cluster and the + cluster cross each other and both break up under the effect of it: largest "
                 f"number of the two colliding clusters (each of two particles or more) no longer at one position in "
                 f"the iterated TSPD step after the crossing, over the collisions of the run of Figure 6 "
                 f"({path.shape[-1]} per type: {text}; the run of Figure 7, {field.shape[-1]} per type: {field_text})",
            tolerance=2.0, measured=split, published="two clusters"),
    ]
