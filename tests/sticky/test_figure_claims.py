"""The claim of Figure 6 added by particle_replication.verdicts.sticky_figures can fail: two clusters
that do not both break up after their collision."""

import numpy as np
import pytest

from particle_methods.systems import MINUS, PLUS
from particle_replication.verdicts import sticky_figures as f


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"sticky.{name}"]


def collision(minus_split=1, plus_split=1, minus_cluster=True):
    """Four particles per type, steps of 0.1: the + particles sit as one cluster at 0; two - particles
    (one cluster, or 0.01 apart) cross it in the step from 2 to 3; each cluster spreads from
    ``*_split`` steps after step 3 on."""
    steps = 7
    path = np.empty((steps + 1, 2, 4))
    for k in range(steps + 1):
        x = -0.75 + 0.3 * k  # left of 0 at step 2, right of it at step 3
        spread = 0.1 * max(k - 3 - minus_split + 1, 0) + (0.0 if minus_cluster else 0.01)
        path[k, MINUS] = [-5.0, -4.0, x, x + spread]
        path[k, PLUS] = -0.03 * max(k - 3 - plus_split + 1, 0) * np.array([3.0, 2.0, 1.0, 0.0])
    return {"trajectories": path, "field_path": path}


def test_both_clusters_break_up_after_their_collision():
    assert f.collisions(collision()["trajectories"]) == [(3, 2, 4, 2)]
    assert status(f.figure_claims(collision()), "fig6.two_clusters_blow_up") == "pass"


@pytest.mark.parametrize("wrong", [
    dict(minus_split=99),                 # the - cluster goes through the + cluster intact (99: past the run)
    dict(plus_split=99),                  # the + cluster holds
    dict(minus_split=2, plus_split=2),    # both split, but a step later than the new ranks act
    dict(minus_cluster=False),            # lone - particles cross: no collision of two clusters
])
def test_fig6_two_clusters_blow_up_fails_without_it(wrong):
    assert status(f.figure_claims(collision(**wrong)), "fig6.two_clusters_blow_up") == "fail"
