"""The claims of Figures 5-7 added by particle_replication.verdicts.sticky_figures can fail: two
clusters that do not both break up after their collision, and u, v that do not solve the p-system."""

from pathlib import Path

import numpy as np
import pytest
import yaml

from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_trajectory
from particle_methods.systems import MINUS, PLUS, PSystem
from particle_replication.verdicts import sticky_figures as f

RULES = yaml.safe_load((Path(__file__).parents[2] / "config" / "config.yaml").read_text())["sticky"]["claims"]
DELTA, STEPS = 0.03, 40  # the Delta of Figure 5; 40 steps: the two waves still interact at t = 1.2


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


@pytest.fixture(scope="module")
def rarefaction():
    """The iterated TSPD of Figures 4 and 5 with 20 particles per type, and the same TSPD moved by
    another pressure law (kappa = 2): particles whose u, computed with kappa = 5, is no p-system's."""
    x0 = psystem_initial_configuration("rarefaction", 0.1, 20)
    times = DELTA * np.arange(STEPS + 1)
    return ({"field_path": mspd_trajectory(x0, PSystem(), DELTA, STEPS), "times": times},
            {"field_path": mspd_trajectory(x0, PSystem(kappa=2.0), DELTA, STEPS), "times": times})


def claims(rarefaction, shocks, system=None):
    return f.figure_claims(rarefaction, shocks, system or PSystem(), RULES["conservation_tolerance"])


def test_both_clusters_break_up_after_their_collision(rarefaction):
    assert f.collisions(collision()["trajectories"]) == [(3, 2, 4, 2)]
    assert status(claims(rarefaction[0], collision()), "fig6.two_clusters_blow_up") == "pass"


@pytest.mark.parametrize("wrong", [
    dict(minus_split=99),                 # the - cluster goes through the + cluster intact (99: past the run)
    dict(plus_split=99),                  # the + cluster holds
    dict(minus_split=2, plus_split=2),    # both split, but a step later than the new ranks act
    dict(minus_cluster=False),            # lone - particles cross: no collision of two clusters
])
def test_fig6_two_clusters_blow_up_fails_without_it(rarefaction, wrong):
    assert status(claims(rarefaction[0], collision(**wrong)), "fig6.two_clusters_blow_up") == "fail"


class WrongVelocity(PSystem):
    """(5.6) with a sign slip in v: v = (w+ - w-)/2."""

    def physical_variables(self, w_minus, w_plus):
        u, v = super().physical_variables(w_minus, w_plus)
        return u, v - w_minus


def test_fig5_uv_conservation_holds_on_the_iterated_tspd(rarefaction):
    assert status(claims(rarefaction[0], collision()), "fig5.uv_conservation") == "pass"


def test_fig5_uv_conservation_fails_for_u_v_of_no_p_system(rarefaction):
    right, other_law = rarefaction
    frozen = {**right, "field_path": right["field_path"].copy()}
    frozen["field_path"][:, PLUS] = right["field_path"][0, PLUS]  # the + particles never move
    for data, system in ((other_law, PSystem()), (frozen, PSystem()), (right, WrongVelocity())):
        assert status(claims(data, collision(), system), "fig5.uv_conservation") == "fail"
