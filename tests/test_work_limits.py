"""The configuration's sizes, counts and times held to the work limits of the code they feed
(particle_replication.work_limits), in process: each absurd value stops at the check, naming its key."""

import importlib
import re
from fnmatch import fnmatchcase

import pytest
import yaml

from particle_replication.configuration import check_configuration, overlay, repository_configuration
from particle_replication.work_limits import LIMITS, check_work_limits, solver_limit, walk
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
}
UNCHECKED = {
    # The SPD is exact in time (one hull per time): its work does not grow with t. The Godunov and HLL runs'
    # steps do, at a speed of the flux that the configuration does not give (not yet held to MAX_CELL_STEPS).
    "sticky.fig1.t", "sticky.fig2.t_max", "sticky.fig3.t_max", "sticky.remark33.dirac_times",
    "sticky.remark33.admissibility.times", "sticky.remark33.godunov_times", "sticky.remark33.convex.t",
    "sticky.remark33.refinement.t", "sticky.theory.scalar.times", "sticky.theory.random.times", "sticky.beyond.t",
    "sticky.beyond.scalar.burgers_two_atoms.t", "sticky.beyond.scalar.concave_laplace.t",
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
]


@pytest.mark.parametrize("key, value", ABSURD, ids=[key for key, _ in ABSURD])
def test_an_absurd_size_stops_at_the_check_naming_the_key_and_its_limit(key, value):
    named = rf"(^|, ){re.escape(key)} = [^:]*: "
    limit = r".*beyond the limit [A-Z_]+ = \S+ of the code it feeds \(particle_(methods|replication)\.[a-z_.]+\)"
    with pytest.raises(ValueError, match=named + limit):
        check_configuration(overlay(FULL, nested(key, value)))


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


def test_quick_overlay_file_is_laid_over_the_full_configuration():
    quick = yaml.safe_load((importlib.import_module("particle_replication.paths").REPOSITORY / "config" /
                            "quick.yaml").read_text())
    check_work_limits(overlay(FULL, quick))
