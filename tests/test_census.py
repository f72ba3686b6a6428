"""The census of the whole public API (issue 46, :mod:`census`): every public callable of ``particle_methods`` is
called with each argument replaced by bad and extreme values, and none may hang, return NaN or inf silently, raise
another exception than ValueError/TypeError, refuse without naming the parameter, or answer a bad value."""

import pytest
from census import FAILURES, HUGE, census, public_callables
from census_entries import ENTRIES, EXEMPT

#: Failures in the modules issue46-b fixes in parallel (cross, finite_volume, systems, blob.newtonian_fmm,
#: blob.solver.mass_defect, sticky.spd.spd_positions, sticky.multitype_events.mspd_exact): strict, so that each
#: fails once fixed, and the lead removes it at the merge.
AWAITING_ISSUE46B = set()
#: Failures the census found in the sticky modules that issue46-c did not fix in its hour (its report lists them):
#: strict, so that each fails once fixed.
KNOWN_FAILING_ISSUE46C = {
    "particle_methods.finite_volume.fluxes.godunov_flux",
    "particle_methods.finite_volume.grids.l1_between_cell_functions",
    "particle_methods.finite_volume.scalar.cfl_time_step",
    "particle_methods.finite_volume.scalar.godunov",
    "particle_methods.systems.checked_primitive",
    "particle_methods.sticky.admissibility.admissibility_violation",
    "particle_methods.sticky.admissibility.checked_sampling",
    "particle_methods.sticky.admissibility.flux_values",
    "particle_methods.sticky.admissibility.mass_levels",
    "particle_methods.sticky.cases.ScalarCase",
    "particle_methods.sticky.cases.cells_distance",
    "particle_methods.sticky.cases.distance_to_cells",
    "particle_methods.sticky.hull_reference.HullIteration",
    "particle_methods.sticky.mspd.ScalarLaw",
    "particle_methods.sticky.mspd.ScalarLaw.speed_primitive",
    "particle_methods.sticky.spd.check_reach",
    "particle_methods.sticky.spd.checked_masses",
    "particle_methods.sticky.theory.CollisionRecord",
    "particle_methods.sticky.theory.SystemConstants",
}
#: Public callables issue46-c had no time to give an entry (its report lists them): the gap, named. A callable
#: added to the package and not here fails the census at once; one given an entry must leave this list.
NOT_YET_IN_THE_CENSUS = {
    "particle_methods.cross.aggregates.cell_atoms",
    "particle_methods.cross.aggregates.first_within",
    "particle_methods.cross.aggregates.gap_path",
    "particle_methods.cross.aggregates.godunov_merger",
    "particle_methods.cross.aggregates.heavy_clusters",
    "particle_methods.cross.aggregates.level_centres",
    "particle_methods.cross.aggregates.level_ranges",
    "particle_methods.cross.aggregates.level_spreads",
    "particle_methods.cross.aggregates.spd_merger",
    "particle_methods.cross.aggregates.two_body_gap",
    "particle_methods.cross.distances.w1_atoms",
    "particle_methods.cross.distances.w1_cells",
    "particle_methods.cross.distances.w1_particles",
    "particle_methods.cross.distances.w1_smooth",
    "particle_methods.cross.exact.AggregationSolution",
    "particle_methods.cross.exact.AggregationSolution.antiderivative",
    "particle_methods.cross.exact.AggregationSolution.cdf",
    "particle_methods.cross.exact.AggregationSolution.quantile",
    "particle_methods.cross.exact.AggregationSolution.quantile_integral",
    "particle_methods.cross.exact.exact_mass_function",
    "particle_methods.cross.exact.solution",
    "particle_methods.cross.hull.Bump",
    "particle_methods.cross.hull.Bump.dense_interval",
    "particle_methods.cross.hull.Bump.density",
    "particle_methods.cross.hull.Bump.left_integrals",
    "particle_methods.cross.hull.Bump.scaled",
    "particle_methods.cross.hull.BumpData",
    "particle_methods.cross.hull.BumpData.cdf",
    "particle_methods.cross.hull.BumpData.density",
    "particle_methods.cross.hull.BumpData.in_bump",
    "particle_methods.cross.hull.HullSolution",
    "particle_methods.cross.hull.HullSolution.antiderivative",
    "particle_methods.cross.hull.HullSolution.cdf",
    "particle_methods.cross.hull.HullSolution.quantile",
    "particle_methods.cross.hull.HullSolution.quantile_integral",
    "particle_methods.cross.hull.aggregate_paths",
    "particle_methods.cross.hull.bump_data",
    "particle_methods.cross.hull.check_hull_work",
    "particle_methods.cross.hull.merger_time",
    "particle_methods.cross.methods.aggregation_flux",
    "particle_methods.cross.methods.blob_method",
    "particle_methods.cross.methods.blob_paths",
    "particle_methods.cross.methods.godunov_advance",
    "particle_methods.cross.methods.godunov_mass",
    "particle_methods.cross.methods.godunov_paths",
    "particle_methods.cross.methods.godunov_time_step",
    "particle_methods.cross.methods.grid_particles",
    "particle_methods.cross.methods.initial_density",
    "particle_methods.cross.methods.ltp_method",
    "particle_methods.cross.methods.ltp_paths",
    "particle_methods.cross.methods.particle_method",
    "particle_methods.cross.methods.particle_velocities",
    "particle_methods.cross.methods.spd_equal",
    "particle_methods.cross.methods.spd_grid",
    "particle_methods.cross.methods.weighted_velocities",
    "particle_methods.cross.profiles.Profile",
    "particle_methods.cross.profiles.limited",
    "particle_methods.cross.profiles.monotone_root",
    "particle_methods.cross.profiles.profile",
    "particle_methods.finite_volume.fluxes.ScalarFlux",
    "particle_methods.finite_volume.grids.cell_averages_of_step_cdf",
    "particle_methods.finite_volume.grids.check_cell_steps",
    "particle_methods.finite_volume.grids.check_cells_match",
    "particle_methods.finite_volume.grids.checked_time_and_cfl",
    "particle_methods.finite_volume.grids.l1_distance_to_step_cdf",
    "particle_methods.finite_volume.psystem.hll_psystem",
    "particle_methods.finite_volume.psystem.invariants_from_conservative",
    "particle_methods.finite_volume.psystem.upwind_diagonal",
    "particle_methods.finite_volume.riemann.PSystemRiemann",
    "particle_methods.finite_volume.riemann.PSystemRiemann.cell_averages",
    "particle_methods.finite_volume.riemann.PSystemRiemann.state",
    "particle_methods.finite_volume.riemann.Wave",
    "particle_methods.ltp.checks.particle_arrays",
    "particle_methods.ltp.checks.piece_arrays",
    "particle_methods.ltp.checks.power_arrays",
    "particle_methods.ltp.exact.exact_density",
    "particle_methods.ltp.exact.exact_support",
    "particle_methods.ltp.exact.quadratic_rate",
    "particle_methods.ltp.initial.InitialDensity",
    "particle_methods.ltp.initial.atomic",
    "particle_methods.ltp.initial.density_named",
    "particle_methods.ltp.initial.golden_atoms",
    "particle_methods.ltp.initial.grid_particles",
    "particle_methods.ltp.kernels.convolutions",
    "particle_methods.ltp.kernels.cumulative_mass_at",
    "particle_methods.ltp.kernels.density_at",
    "particle_methods.ltp.kernels.far_series",
    "particle_methods.ltp.kernels.takes_pair_sums",
    "particle_methods.ltp.measures.collapse_times",
    "particle_methods.ltp.measures.concentration_series",
    "particle_methods.ltp.measures.excess_variation",
    "particle_methods.ltp.measures.l1_distance",
    "particle_methods.ltp.measures.peak_count",
    "particle_methods.ltp.measures.profile_changes",
    "particle_methods.ltp.measures.shrink_rate_inverse",
    "particle_methods.ltp.measures.shrink_rate_ratios",
    "particle_methods.ltp.measures.side_concentration",
    "particle_methods.ltp.potentials.Potential",
    "particle_methods.ltp.potentials.Potential.__call__",
    "particle_methods.ltp.potentials.Potential.as_arrays",
    "particle_methods.ltp.potentials.Potential.derivative",
    "particle_methods.ltp.potentials.Potential.second_derivative",
    "particle_methods.ltp.potentials.potential",
    "particle_methods.ltp.shapes.B3",
    "particle_methods.ltp.shapes.HAT",
    "particle_methods.ltp.shapes.Shape",
    "particle_methods.ltp.shapes.Shape.__call__",
    "particle_methods.ltp.shapes.shape_named",
    "particle_methods.ltp.solver.Particles",
    "particle_methods.ltp.solver.Particles.convolutions",
    "particle_methods.ltp.solver.Particles.cumulative_mass",
    "particle_methods.ltp.solver.Particles.density",
    "particle_methods.ltp.solver.Simulation",
    "particle_methods.ltp.solver.Simulation.at",
    "particle_methods.ltp.solver.Simulation.densities",
    "particle_methods.ltp.solver.Simulation.peak_densities",
    "particle_methods.ltp.solver.simulate",
    "particle_methods.ltp.theorems.atom_flow",
    "particle_methods.ltp.theorems.records",
    "particle_methods.ltp.theorems.theorem1_time_error",
    "particle_methods.ltp.theorems.theorem3_atomic",
    "particle_methods.ltp.theorems.theorem3_rough",
    "particle_methods.ltp.theorems.theorem4_differences",
    "particle_methods.ltp.theorems.w1_to_atoms",
}


def test_every_public_callable_is_in_the_census():
    listed = set(ENTRIES) | set(EXEMPT)
    kernels = {name for name in public_callables() if name.rsplit(".", 1)[-1].endswith("_kernel")}
    missing = sorted(set(public_callables()) - listed - kernels - NOT_YET_IN_THE_CENSUS)
    assert not missing, f"public callables neither in the census nor exempt (tests/census_entries.py): {missing}"
    stale = sorted(listed - set(public_callables()))
    assert not NOT_YET_IN_THE_CENSUS & listed, "a callable now in the census must leave NOT_YET_IN_THE_CENSUS"
    assert not stale, f"census entries of no public callable: {stale}"


def test_the_census_refuses_a_new_function(monkeypatch):
    import particle_methods.norms as norms

    monkeypatch.setattr(norms, "brand_new", lambda x: x, raising=False)
    norms.brand_new.__module__ = "particle_methods.norms"
    assert "particle_methods.norms.brand_new" in public_callables()


XFAIL = AWAITING_ISSUE46B | KNOWN_FAILING_ISSUE46C


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.xfail(strict=True, reason="known failure"))
                                  if name in XFAIL else name for name in sorted(ENTRIES)])
def test_census(name):
    failures = [f"{outcome}: {parameter} = {value!r:.60}: {detail}"
                for parameter, value, outcome, detail in census(name, ENTRIES[name]) if outcome in FAILURES]
    header = f"{name}: {len(failures)} failing calls (zero-stride arrays of {HUGE} entries included)"
    assert not failures, "\n".join([header, *failures])
