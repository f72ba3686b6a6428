"""The configuration's sizes, counts and times held to the work limits of the code they feed
(particle_replication.work_limits), in process: each absurd value stops at the check, naming its key."""

import importlib
import re
from fnmatch import fnmatchcase

import pytest

from particle_replication.configuration import check_configuration, overlay, repository_configuration
from particle_replication.paths import read_yaml
from particle_replication.work_limits import (
    CASE_FLUXES,
    LIMITS,
    SCALAR_SPEEDS,
    check_work_limits,
    psystem_peak_speed,
    psystem_type_cell_steps,
    solver_limit,
    walk,
)
from particle_replication.workflow import MAX_REPEATS, interleaved

FULL = repository_configuration("full")

# Size, count and time keys by name; the keys they catch must each be held to a limit or be listed below.
SIZE_NAME = re.compile(r"(^|_)(n|particles|n_values|cells|cells_per_unit|inverse_h|h|h_values|steps|max_steps|"
                       r"steps_values|times|t|t_max|t_long|t_end|t_final|repeats|points|count|atoms|evaluations|dt|"
                       r"dt_values|deltas|delta_n|reference_n|spd_n|tspd_n|exact_n|limit_n|snapshots)$")
NOT_WORK = {
    # fit windows, checked against the lists they fit (configuration.FIT_WINDOWS)
    "ltp.quadratic.order_points", "ltp.quadratic.dt_study.fit_points", "ltp.nonaffine.order_points",
    "ltp.nonaffine.theorem1.fit_points", "blob.fig1.fit_points", "blob.fig2.fit_points", "blob.fig3.fit_points",
    "blob.fig4.fit_points", "blob.fig5.fit_points", "cross.fit_points",
    # times within their run's t_max (configuration.TIMES_WITHIN)
    "blob.fig1.density_times", "blob.fig2.density_times", "blob.fig3.density_times",
    # a ratio, not a size
    "cross.ltp.sp_eps_over_h",
    # times of exact solutions: the SPD computes one hull per time (section 5.1.1) and the exact MSPD at most
    # n^2 + 2 n events whatever the time (their n are held), so their work does not grow with t
    "sticky.fig1.t", "sticky.fig2.t_max", "sticky.fig3.t_max", "sticky.remark33.dirac_times",
    "sticky.remark33.admissibility.times", "sticky.theory.scalar.times", "sticky.theory.random.times",
}
UNCHECKED = {
    # evaluation grids and scans of the LTP scripts: no solver limit of their own (configuration.MAX_COUNT only)
    "ltp.fig1.points", "ltp.quadratic.grid_points", "ltp.fig4.grid_points",
    "ltp.quadratic.eps_scan.count", "ltp.fig4.eps_scan.count",
}


def keys(config):
    return [key for key, _ in walk(config) if key and not key.split(".")[-1].isdigit()]


def test_the_limits_are_the_solvers_own():
    """Each limit read from a module's source is the value the module itself holds."""
    for constant in {limit.constant for limit in LIMITS}:
        module, name = constant.rsplit(".", 1)
        assert solver_limit(constant) == getattr(importlib.import_module(module), name), constant


def test_every_pattern_names_keys_of_the_configuration():
    for limit in LIMITS:
        for pattern in limit.keys:
            assert any(fnmatchcase(key, pattern) for key in keys(FULL)), pattern


def test_every_size_count_and_time_is_held_to_a_limit():
    uncovered = [key for key in keys(FULL) if SIZE_NAME.search(key.split(".")[-1])
                 and not any(limit.matches(key) for limit in LIMITS) and key not in NOT_WORK | UNCHECKED]
    assert uncovered == []


@pytest.mark.parametrize("run", ["full", "quick", "fig5-extended"])
def test_the_repositorys_configurations_pass(run):
    check_configuration(repository_configuration(run))


def nested(dotted, value):
    node = value
    for key in reversed(dotted.split(".")):
        node = {key: node}
    return node


# The eight, then one absurd value of every other size, count and time the limits hold.
ABSURD = [
    ("sticky.beyond.repeats", 100_000_000),
    ("ltp.quadratic.h_values", [0.1, 0.05, 0.025, 0.0125, 0.0001]),
    ("blob.fig1.inverse_h", [20, 40, 80, 160, 320, 100000]),
    ("blob.fig5.inverse_h", [5, 10, 20, 40, 100000]),
    ("cross.godunov.cells", [256, 1024, 4096, 50_000_000]),
    ("ltp.fig6.t_long", 1.0e7),
    ("sticky.psystem.shocks.max_steps", 100_000_000),
    ("sticky.fig2.field_particles", 100_000_000),
    ("sticky.cost.repeats", 1000),
    ("cross.repeats", 1000),
    ("sticky.fig1.particles", 10**9),
    ("sticky.fig2.trajectory_times", 10**7),
    ("sticky.fig3.field_times", 10**7),
    ("sticky.fig2.field_points", 10**7),
    ("sticky.fig3.profile_particles", 10**8),
    ("sticky.fig2.error_p", [1, 2, 40]),
    ("sticky.fig3.rate_p", [18, 19, 60]),
    ("sticky.psystem.rarefaction.steps", 10**7),
    ("sticky.psystem.rarefaction.field_particles", 10**6),
    ("sticky.lemma21.n_values", [16, 64, 10**9]),
    ("sticky.lemma21.heavy_tail.n", 10**9),
    ("sticky.remark33.admissibility.points", 10**6),
    ("sticky.remark33.admissibility.n", [1, 2, 10**8]),
    ("sticky.remark33.cells_per_unit", [50, 10**8]),
    ("sticky.tspd_convergence.reference_delta", 1e-9),
    ("sticky.tspd_convergence.reference_n", 10**8),
    ("sticky.cost.tspd_n", [10**6, 10**8, 10**9]),
    ("sticky.cost.steps_values", [10, 100, 10**8]),
    ("sticky.theory.steps.deltas", [0.1, 0.03, 1e-9]),
    ("sticky.theory.steps.n_values", [20, 10**5]),
    ("sticky.theory.random.reference_n", 10**6),
    ("sticky.beyond.reference_n", 10**6),
    ("sticky.beyond.tspd_n", [25, 50, 10**6]),
    ("sticky.beyond.reference_cells", 10**8),
    ("sticky.beyond.scalar.concave_laplace.cells", [500, 10**8]),
    ("sticky.beyond.scalar.burgers_two_atoms.spd_n", [100, 10**9]),
    ("ltp.quadratic.dt", 1e-9),
    ("ltp.quadratic.eps_scan.fine_dt", 1e-9),
    ("ltp.quadratic.dt_study.dt_values", [0.02, 0.01, 1e-9]),
    ("ltp.fig4.h", 1e-6),
    ("ltp.fig5.steps", 10**7),
    ("ltp.fig7.t_long", 1e8),
    ("ltp.fig8.t_long", 1e8),
    ("ltp.fig8.snapshots", 10**7),
    ("ltp.nonaffine.reference_h", 1e-6),
    ("ltp.nonaffine.theorem1.dt_values", [0.02, 0.01, 1e-9]),
    ("ltp.nonaffine.theorem4.h_values", [0.1, 0.05, 1e-5]),
    ("ltp.nonaffine.theorem3_atomic.atoms", 10**6),
    ("ltp.nonaffine.grid_points", 10**7),
    ("ltp.nonaffine.theorem3_atomic.times", [0.1, 0.2, 1e4]),
    ("ltp.nonaffine.theorem3.reference_factor", 10**5),
    ("blob.fig4.repulsive.extra_inverse_h", [640, 10**6]),
    ("blob.fig4.reference_factor", 10**5),
    ("blob.fig2.t_max", 1e9),
    ("blob.fig3.times", 10**7),
    ("blob.fig6.top.h", 1e-5),
    ("blob.fig7.times", 10**7),
    ("blob.fig8.paper_tables.points", 10**8),
    ("blob.fig7.without_origin.septic_power", 1e9),
    ("cross.spd_n", [256, 10**9]),
    ("cross.grid_inverse_h", [128, 10**9]),
    ("cross.times", [0.5, 1e9]),
    ("cross.ltp.inverse_h", [20, 10**6]),
    ("cross.blob.inverse_h", [20, 10**6]),
    ("cross.behaviour.stall_evaluations", 10**9),
    ("cross.aggregates.t_end", 1e9),
    ("cross.aggregates.path_steps", 10**7),
    ("cross.aggregates.godunov_cells", [256, 10**8]),
    # finite volumes, whose steps grow with the time
    ("sticky.remark33.godunov_times", [1.0, 5.0, 1e6]),
    ("sticky.remark33.convex.t", 1e6),
    ("sticky.remark33.refinement.t", 1e5),
    ("sticky.beyond.scalar.burgers_two_atoms.t", 1e5),
    ("sticky.beyond.scalar.concave_laplace.t", 1e4),
    ("sticky.beyond.t", 1e3),
    ("sticky.psystem.nu", 1e-6),
]


@pytest.mark.parametrize("key, value", ABSURD, ids=[key for key, _ in ABSURD])
def test_an_absurd_size_stops_at_the_check_naming_the_key_and_its_limit(key, value):
    named = rf"(^|, ){re.escape(key)} = [^:]*: "
    limit = r".*beyond the limit [A-Z_]+ = \S+ of the code it feeds \(particle_(methods|replication)\.[a-z_.]+\)"
    with pytest.raises(ValueError, match=named + limit):
        check_configuration(overlay(FULL, nested(key, value)))


def test_the_finite_volumes_speeds_are_the_solvers_own():
    """The speeds the limits assume are those of the fluxes and of the p-system the runs use."""
    from particle_methods.finite_volume.fluxes import BURGERS, CONCAVE
    from particle_methods.sticky.cases import SCALAR_CASES
    from particle_methods.systems import PSystem

    assert SCALAR_SPEEDS == {"burgers": BURGERS.max_speed(0.0, 1.0), "concave": CONCAVE.max_speed(0.0, 1.0)}
    fluxes = {"burgers": BURGERS, "concave": CONCAVE}
    assert {name: fluxes[flux].f for name, flux in CASE_FLUXES.items()} == {
        name: SCALAR_CASES[name].flux for name in CASE_FLUXES}
    for nu, kappa in [(0.5, 5.0), (1.0, 1e-3), (2.0, 40.0)]:
        system = PSystem(nu=nu, kappa=kappa)
        assert psystem_peak_speed(nu, kappa) == pytest.approx(system.speed_scale, rel=1e-15)
        assert psystem_peak_speed(nu, kappa) == pytest.approx(float(system.sound_speed(nu / 2)), rel=1e-15)


def test_a_time_under_its_finite_volume_limit_passes_and_one_step_beyond_is_refused():
    """The largest sticky.beyond.t the upwind reference accepts passes; a tenth more is refused naming it."""
    sticky = FULL["sticky"]
    work = psystem_type_cell_steps(sticky, sticky["beyond"]["upwind_reference_cells"])
    largest = sticky["beyond"]["t"] * solver_limit("particle_methods.finite_volume.psystem.MAX_UPWIND_WORK") / work
    check_configuration(overlay(FULL, nested("sticky.beyond.t", 0.95 * largest)))
    with pytest.raises(ValueError, match=r"sticky\.beyond\.t = .*MAX_UPWIND_WORK"):
        check_configuration(overlay(FULL, nested("sticky.beyond.t", 1.1 * largest)))


def test_the_check_refuses_what_is_no_configuration():
    with pytest.raises(TypeError, match="config"):
        check_work_limits([1, 2])


def test_interleaved_refuses_rounds_beyond_its_limit():
    with pytest.raises(ValueError, match="MAX_REPEATS"):
        interleaved([lambda: None], MAX_REPEATS + 1)
    with pytest.raises(ValueError, match="repeats"):
        interleaved([lambda: None], 0)


def test_solver_limit_refuses_what_is_no_constant():
    with pytest.raises(ValueError, match="module.NAME"):
        solver_limit("MAX_STEPS")
    with pytest.raises(ValueError, match="assigns no"):
        solver_limit("particle_methods.ltp.solver.NO_SUCH_LIMIT")


def test_a_constant_of_other_constants_is_read_through_their_names(tmp_path, monkeypatch):
    """``8 * PRIMITIVE_CHUNK`` (particle_methods.systems.PARALLEL_MIN_PRIMITIVES) is the module's own value; a name
    the module does not assign, or one that names itself, is no constant."""
    assert solver_limit("particle_methods.systems.PARALLEL_MIN_PRIMITIVES") == importlib.import_module(
        "particle_methods.systems").PARALLEL_MIN_PRIMITIVES
    package = tmp_path / "limits_of_names"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "values.py").write_text("A = 2\nB = 3 * A + 1\nC = D * 2\nE = E + 1\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    assert solver_limit("limits_of_names.values.B") == 7
    for name in ("C", "E"):
        with pytest.raises(ValueError, match="not a constant expression"):
            solver_limit(f"limits_of_names.values.{name}")


def test_quick_overlay_file_is_laid_over_the_full_configuration():
    quick = read_yaml(importlib.import_module("particle_replication.paths").REPOSITORY / "config" / "quick.yaml")
    check_work_limits(overlay(FULL, quick))
