"""Iterated typewise SPD: rank velocities (1.8), invariants, and the scalar special case."""

import numpy as np
import pytest
from scipy import integrate

from particle_methods.finite_volume import burgers_flux
from particle_methods.norms import w1_between_samples
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import ScalarLaw, mspd_positions, mspd_trajectory, rank_velocities, ranks_kernel
from particle_methods.sticky.spd import cluster_sizes, spd_positions, velocities_from_flux
from particle_methods.systems import MINUS, PLUS, PSystem

SYSTEM = PSystem()


def test_one_type_reduces_to_the_scalar_spd(rng):
    x = np.sort(rng.normal(size=(1, 30)), axis=1)
    system = ScalarLaw(burgers_flux)
    np.testing.assert_allclose(rank_velocities(x, system)[0], velocities_from_flux(burgers_flux, 30))
    # With one type the ranks never change, so iterating the SPD is the SPD (flow property).
    expected = spd_positions(x[0], velocities_from_flux(burgers_flux, 30), 0.7)
    np.testing.assert_allclose(mspd_positions(x, system, 0.1, 7)[0], expected, atol=1e-12)


def test_ranks_follow_the_post_collisional_order():
    # Type 0 at 0 and 1; type 1 at 0 and 2. At the tie x = 0 the higher type is counted first.
    counts, operations = ranks_kernel(np.array([[0.0, 1.0], [0.0, 2.0]]))
    assert operations == 2 * 2 * 2 * 2  # d n picks, each examining d heads and writing d entries
    np.testing.assert_array_equal(counts[0, :, 1], [1, 1])  # type 1 at 0 counts for type 0 at 0 (<=)
    np.testing.assert_array_equal(counts[1, :, 0], [0, 2])  # type 0 at 0 does not count for type 1 at 0 (<)
    np.testing.assert_array_equal(counts[0, :, 0], [1, 2])
    np.testing.assert_array_equal(counts[1, :, 1], [1, 2])


def test_rank_velocities_match_quadrature_of_1_8(rng):
    n = 6
    x = np.sort(rng.normal(size=(2, n)), axis=1)
    velocities = rank_velocities(x, SYSTEM)
    for gamma, other in ((MINUS, PLUS), (PLUS, MINUS)):
        for k in range(n):
            strict = gamma > other  # (1.8): strict count towards lower types
            rank = np.sum(x[other] < x[gamma, k]) if strict else np.sum(x[other] <= x[gamma, k])

            def speed(w, gamma=gamma, other=other, rank=rank):
                levels = np.empty(2)
                levels[gamma], levels[other] = w, rank / n
                return float(SYSTEM.speeds(levels[MINUS], levels[PLUS])[gamma])

            expected = n * integrate.quad(speed, k / n, (k + 1) / n, epsabs=1e-13)[0]
            assert velocities[gamma, k] == pytest.approx(expected, rel=1e-10)


def test_mspd_invariants_in_the_rarefaction_case():
    x0 = psystem_initial_configuration("rarefaction", 0.1, 30)
    path = mspd_trajectory(x0, SYSTEM, 0.03, 60)
    assert path.shape == (61, 2, 30)
    assert np.all(np.diff(path, axis=2) >= 0)  # each type stays sorted
    assert np.all(path[:, PLUS] <= path[:, MINUS])  # w+ >= w- is preserved
    assert all(cluster_sizes(row).max() == 1 for state in path[1:] for row in state)  # no same-type collision
    # Within a step each type is an SPD: its centre of mass moves at its mean velocity.
    for step in (0, 30):
        v = rank_velocities(path[step], SYSTEM)
        np.testing.assert_allclose(path[step + 1].mean(axis=1), path[step].mean(axis=1) + 0.03 * v.mean(axis=1))
    # Lower type always faster (USH): type - moves right, type + moves left.
    assert np.all(path[-1, MINUS] > path[0, MINUS]) and np.all(path[-1, PLUS] < path[0, PLUS])


def test_clusters_form_and_break_up_in_the_shock_case():
    x0 = psystem_initial_configuration("shocks", -4.0, 20)
    path = mspd_trajectory(x0, SYSTEM, 0.02, 200)
    assert cluster_sizes(path[10, PLUS]).max() == 20
    assert max(cluster_sizes(row).max() for row in path[-1]) == 1
    np.testing.assert_array_equal(mspd_positions(x0, SYSTEM, 0.02, 200), path[-1])


def test_tspd_error_decreases_with_n():
    reference = mspd_positions(psystem_initial_configuration("rarefaction", 0.1, 800), SYSTEM, 1 / 400, 400)
    errors = []
    for n in (25, 50, 100):
        state = mspd_positions(psystem_initial_configuration("rarefaction", 0.1, n), SYSTEM, 1 / (n // 2), n // 2)
        errors.append(sum(w1_between_samples(a, b) for a, b in zip(state, reference)))
    assert errors[0] > errors[1] > errors[2]


@pytest.mark.parametrize(
    "x, delta, steps, message",
    [
        (np.zeros((3, 4)), 0.1, 1, "one row per type"),
        (np.array([[1.0, 0.0], [0.0, 1.0]]), 0.1, 1, "sorted"),
        (np.zeros((2, 3)), 0.0, 1, "Delta must be positive"),
        (np.zeros((2, 3)), 0.1, -1, "steps must be at least 0"),
        (np.zeros((2, 0)), 0.1, 1, "at least 1"),
        (np.zeros(3), 0.1, 1, "2-dimensional"),
    ],
)
def test_bad_input(x, delta, steps, message):
    with pytest.raises(ValueError, match=message):
        mspd_trajectory(x, SYSTEM, delta, steps)


def test_unknown_case():
    with pytest.raises(ValueError, match="unknown p-system case"):
        psystem_initial_configuration("vacuum", 0.0, 4)


class _Delegate:
    """The p-system behind the generic interface: the TSPD takes its checked path."""

    d = 2

    def __init__(self, system):
        self.system = system

    def speed_primitive(self, gamma, levels):
        return self.system.speed_primitive(gamma, levels)


@pytest.mark.parametrize("case", ["rarefaction", "shocks"])
def test_the_p_system_formula_path_gives_the_checked_primitive_bit_for_bit(case):
    system = PSystem(nu=0.5, kappa=5.0)
    x = psystem_initial_configuration(case, -1.0, 60)
    fast, operations = mspd_positions(x, system, 0.05, 40, return_operations=True)
    assert np.array_equal(fast, mspd_positions(x, _Delegate(system), 0.05, 40))
    # Every step: d n picks of d heads examined and d entries written, then per type n pushes, n writes, and
    # between n - 1 tests (no merge) and n - 1 tests, n - 1 merges and n - 1 pops (everything merges).
    assert 40 * (8 * 60 + 2 * (3 * 60 - 1)) <= operations <= 40 * (8 * 60 + 2 * (5 * 60 - 3))


class _PythonPath(PSystem):
    """A PSystem subclass: mspd_positions takes the Python time loop for it (the compiled one is PSystem's own)."""


@pytest.mark.parametrize("case, x0, n, steps", [("rarefaction", 0.1, 40, 40), ("shocks", -4.0, 64, 31),
                                                ("shocks", -4.0, 7, 200)])
def test_compiled_tspd_steps_are_the_python_steps_to_the_bit(case, x0, n, steps):
    """The p-system's compiled steps (mspd._tspd_psystem_kernel) give the Python loop's positions and operation
    counts exactly, for even and odd numbers of steps, through collisions and crossings."""
    x = psystem_initial_configuration(case, x0, n)
    compiled = mspd_positions(x, SYSTEM, 2.0 / steps, steps, return_operations=True)
    python = mspd_positions(x, _PythonPath(), 2.0 / steps, steps, return_operations=True)
    assert np.array_equal(compiled[0], python[0]) and compiled[1] == python[1]


def test_compiled_tspd_refuses_a_reach_that_could_overflow_as_the_python_loop_does():
    x = psystem_initial_configuration("shocks", -4.0, 10)
    for system in (SYSTEM, _PythonPath()):
        with pytest.raises(ValueError, match=r"x0 \+ Delta velocities may overflow"):
            mspd_positions(x, system, 1e306, 2)


def test_a_scalar_law_checks_its_flux_and_names_the_levels_it_refuses():
    """Issue 46 (census): a flux answering NaN was accepted, an overflow named no argument."""
    with pytest.raises(ValueError, match="flux must be finite at u = 0 and 1"):
        ScalarLaw(lambda u: np.full(np.shape(u), np.nan))
    with pytest.raises(ValueError, match="flux refused levels: the Burgers flux"):
        ScalarLaw(burgers_flux).speed_primitive(0, np.array([[0.0], [1e300]]))
