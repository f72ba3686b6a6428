"""Every claim of sections 3 and 4 beyond the figures (particle_replication.verdicts.sticky_theory) can fail:
each passes on an outcome of the shape the paper states and fails on a plausible wrong one (a bound
exceeded, a pair counted too often, an error that stalls or grows like t^2, a coarse reference)."""

from pathlib import Path

import numpy as np
import pytest

from particle_methods.norms import w1_to_measure
from particle_methods.sticky.spd import spd_positions, velocities_from_flux
from particle_methods.sticky.theory import CubicDiracSolution, cubic_flux
from particle_replication.claims import ROUNDING
from particle_replication.paths import read_yaml
from particle_replication.rates import Recorder
from particle_replication.verdicts import sticky_theory as v

CONFIG = read_yaml(Path(__file__).parents[2] / "config" / "config.yaml")["sticky"]["theory"]
L_C, L_USH, L_LC = 3.0354, 2.2546, 2.5  # the p-system of the config (nu = 0.5, kappa = 5)


def status(claims, name):
    return {claim.id: claim.status for claim in claims}[f"sticky.theory.{name}"]


def quiet():
    return Recorder(log=lambda text: None)


def scalar(burgers=0.25, cubic=0.05, doubling=(0.5, 0.0, 0.125)):
    """The scalar study: distances as the given ratios to their bounds (Burgers' exact 1/4 and 1/2 by default)."""
    n, t = np.array([4.0, 16.0, 64.0]), np.array([0.5, 2.0])
    bound = t[None, :] / n[:, None]
    return {"scalar_n": n, "scalar_times": t, "scalar_fluxes": np.array(["burgers", "concave", "cubic"]),
            "scalar_configurations": np.array(["case", "seed 1"]), "scalar_lipschitz": np.ones(3),
            "doubling": np.array([[ratio * bound / 2] * 2 for ratio in doubling]),
            "burgers_prop32": np.array([burgers * bound] * 2), "cubic_prop32": cubic * bound}


def steps(ratio=0.9, free=0.0, count=1, shrink=1.02, window=0.95, per_delta=0.7):
    """The step study for two cases, n = 20, 50 and Delta = 0.1, 0.05 up to t = 0.2: distances at ``ratio``
    times the bound of Lemma 4.2 (``free`` on the steps without collisions), pairs counted ``count`` times."""
    n, deltas = np.array([20, 50]), np.array([0.1, 0.05])
    collisions = np.full((2, 2, 2, 4), -1)
    collisions[:, :, 0, :2] = [3, 0]
    collisions[:, :, 1, :] = [2, 0, 1, 0]
    bound = 2 * deltas[None, None, :, None] * L_LC * collisions / n[None, :, None, None] ** 2
    distances = np.where(collisions > 0, ratio * bound, np.where(collisions == 0, free, np.nan))
    mspd = np.full((2, 2, 2, 5), np.nan)
    mspd[:, :, 0, :3] = per_delta * 0.1 * np.array([0.0, 0.5, 1.0])
    mspd[:, :, 1, :] = per_delta * 0.05 * np.array([0.0, 0.3, 0.6, 0.9, 1.0])
    histogram = np.zeros((2, 2, 2, 8), dtype=np.int64)
    histogram[..., count] = 5
    return {"cases": np.array(["rarefaction", "shocks"]), "d": np.array(2), "speed_bound": np.array(L_C),
            "hyperbolicity": np.array(L_USH), "lipschitz": np.array(L_LC), "crossings_bound": np.array(3),
            "step_n": n, "step_deltas": deltas, "step_t": np.array(0.2), "collisions": collisions,
            "step_distances": distances, "mspd_distances": mspd, "largest_count": np.full((2, 2, 2), float(count)),
            "count_histogram": histogram, "smallest_shrink": np.full((2, 2, 2), shrink * L_USH) * deltas,
            "largest_collision_gap": np.full((2, 2, 2), window * 2 * L_C) * deltas, "extent": np.full((2, 2, 2), 20.0)}


def study(per_delta=0.6):
    """The Delta sweep of the Theorem 4.4 study (tspd_convergence.npz): errors ``per_delta`` times Delta."""
    deltas = 0.1 / 2.0 ** np.arange(4)
    return {"cases": np.array(["rarefaction", "shocks"]), "deltas": deltas,
            "delta_errors": per_delta * np.ones((2, 2, 3, 1)) * deltas}


N = np.array([25.0, 50, 100, 200, 400])
TIMES = np.array([1.0, 2.0, 4.0])


def randoms(random_power=0.5, tspd=lambda n, t: (np.log(n) + t) / n, gap=1e-3):
    """Corollary 4.6 and section 5.2: errors of draws falling like n^-random_power (with some scatter), the
    iterated TSPD's errors ``tspd(n, t)``, the references' distance to half their particles ``gap``."""
    scatter = 1.0 + 0.2 * np.cos(np.arange(N.size))
    random_errors = np.empty((2, 2, N.size, TIMES.size))
    random_errors[:] = (0.8 * scatter * N**-random_power)[None, None, :, None]
    return {"cases": np.array(["rarefaction", "shocks"]), "d": np.array(2), "random_seeds": np.array([1, 2]),
            "random_n": N.astype(np.int64), "random_times": TIMES, "reference_n": np.array(3200),
            "reference_gap": np.full((2, TIMES.size), gap), "random_errors": random_errors,
            "random_initial": np.broadcast_to(scatter * N**-0.5, (2, 2, N.size)),
            "tspd_errors": np.array([[tspd(N, t) for t in TIMES]] * 2)}


def random_claims(data):
    return v.random_claims(data, quiet(), CONFIG["order_min"], CONFIG["t_exponent_max"], CONFIG["reference_share"],
                           CONFIG["resolved_min"])


def test_every_claim_passes_on_the_stated_behaviour():
    data = {**scalar(), **steps(), **randoms()}
    claims = v.claims({"theory": data, "tspd_convergence": study()}, CONFIG, quiet())
    assert all(claim.status == "pass" for claim in claims), [(c.id, c.measured) for c in claims if c.status != "pass"]
    assert len({claim.id for claim in claims}) == len(claims) == 13
    assert all(claim.id.startswith("sticky.theory.") for claim in claims)


def cubic_prop32(positions, n_values=(4, 16, 64), times=(0.5, 2.0)):
    """Proposition 3.2's distances for the cubic flux from delta_0, as the data job measures them, with the SPD
    replaced by ``positions(x, v, t)``."""
    return np.array([[w1_to_measure(CubicDiracSolution(0.0, t),
                                    np.sort(positions(np.zeros(n), velocities_from_flux(cubic_flux, n), t)))
                      for t in times] for n in n_values])


WRONG_CUBIC = {
    "x2 velocities": lambda x, v, t: spd_positions(x, 2 * v, t),
    "at 2t": lambda x, v, t: spd_positions(x, v, 2 * t),
    "free flight": lambda x, v, t: x + t * v,
}


def test_prop32_passes_on_the_cubic_spd():
    data = scalar()
    data["cubic_prop32"] = cubic_prop32(spd_positions)
    assert status(v.scalar_claims(data), "prop32.bound") == "pass"


@pytest.mark.parametrize("name", WRONG_CUBIC)
def test_prop32_fails_on_wrong_cubic_dynamics(name):
    data = scalar()
    data["cubic_prop32"] = cubic_prop32(WRONG_CUBIC[name])
    assert status(v.scalar_claims(data), "prop32.bound") == "fail"


@pytest.mark.parametrize("data, name", [
    (scalar(cubic=1.0 + 1e-6), "prop32.bound"),         # just above the bound, beyond rounding
    (scalar(burgers=1.2), "scalar_identities"),         # a non-entropic error beyond Burgers' identity
    (scalar(doubling=(0.5, 1e-6, 0.125)), "scalar_identities"),  # the concave doubling not the same solution
    (scalar(doubling=(0.5, 0.0, 1.3)), "eq33.bound"),   # the doubled SPD too far from the SPD
])
def test_scalar_bounds_can_fail(data, name):
    assert status(v.scalar_claims(data), name) == "fail"


@pytest.mark.parametrize("knobs, name", [
    ({"ratio": 1.1}, "lemma42.bound"),            # more than the collisions can explain
    ({"free": 1e-6}, "lemma42.bound"),            # a step without collisions that moves the MSPD away
    ({"count": 4}, "eq45.count"),                 # a pair counted at more than m = 3 iterates
    ({"shrink": 0.9}, "remark43.shrink"),         # a pair closing slower than L_USH Delta
    ({"window": 1.1}, "remark43.window"),         # a collision from farther than 2 L_C Delta
    ({"per_delta": 16.0}, "prop41.grid_times"),        # the MSPD's distance above C Delta
])
def test_step_claims_can_fail(knobs, name):
    assert status(v.step_claims(steps(**knobs)), name) == "fail"


def test_the_constant_of_4_6_can_fail():
    assert status(v.constant_claims(steps(), study()), "c46.study") == "pass"
    assert status(v.constant_claims(steps(), study(per_delta=16.0)), "c46.study") == "fail"


def test_lemma42_allows_rounding_on_steps_without_collisions():
    assert status(v.step_claims(steps(free=ROUNDING)), "lemma42.bound") == "pass"


@pytest.mark.parametrize("data, name", [
    (randoms(random_power=0.05), "cor46.convergence"),                      # an error that stalls
    (randoms(tspd=lambda n, t: (np.log(n) + 10 * t**2) / n), "t_exponent"),  # an error growing like t^2 / n
    (randoms(gap=0.03), "references"),                                      # a reference as far off as the errors
])
def test_random_claims_can_fail(data, name):
    assert status(random_claims(data), name) == "fail"


def test_one_draw_does_not_decide_the_convergence_the_mean_over_draws_does():
    """One seed whose error happens to stall over these n (a draw, not the dynamics) leaves the order of the mean
    over the seeds near 1/2: it passes, and its own order is listed; every seed stalling fails."""
    data = randoms()
    data["random_errors"][:, 1] = 0.8 * N[-1] ** -0.5  # the second draw: flat at its value at the largest n
    claim = next(c for c in random_claims(data) if c.id == "sticky.theory.cor46.convergence")
    assert claim.status == "pass" and "one draw's own order scatters: 0.00" in claim.claim
    data["random_errors"][:, 0] = 0.8 * N[-1] ** -0.5
    assert status(random_claims(data), "cor46.convergence") == "fail"


def test_the_premise_of_corollary_46_can_fail():
    data = randoms()
    data["random_initial"] = np.ones((2, 2, N.size))  # draws whose W1 to m does not fall
    assert status(random_claims(data), "cor46.premise") == "fail"


def test_runs_the_reference_cannot_resolve_never_enter_the_fits():
    # The two finest TSPD runs of one time sit below five times the reference's own error: left out,
    # the exponent is the same as without them; a time with fewer than two resolvable runs fails.
    data = randoms(gap=1e-3)
    data["tspd_errors"][0][2, 3:] = 1e-3
    claims = random_claims(data)
    assert status(claims, "t_exponent") == "pass" and status(claims, "references") == "pass"
    data["tspd_errors"][0][2, 1:] = 1e-3
    claims = random_claims(data)
    assert status(claims, "t_exponent") == "fail" and status(claims, "references") == "fail"


def test_an_error_the_other_times_never_reach_fails_the_t_exponent():
    # Shock case: at t = 1 every error lies below eps*, so n(eps*) would need extrapolation; the case that
    # has an exponent must not hide it.
    data = randoms(gap=1e-5)
    data["tspd_errors"][1] = [(1.0 if t > 1 else 0.01) * 10 / N for t in TIMES]
    assert status(random_claims(data), "t_exponent") == "fail"
