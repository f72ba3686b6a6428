"""Sections 3 and 4 beyond the figures: Proposition 3.2 and (3.3) on scalar laws, Lemma 4.2, Remark 4.3,
(4.5) and (4.1) on the iterated TSPD of the p-system, the constants of (4.6), Corollary 4.6 on random
configurations and the time dependence of section 5.2.

Every distance is exact: W1 between empirical measures, or between an empirical measure and an entropy
solution given in closed form (Burgers from atoms, the cubic flux from delta_0). The p-system references
are exact MSPD runs from (1.9), each also run with half its particles to measure its own error.
"""

import numpy as np

from particle_methods.finite_volume.fluxes import burgers_flux, concave_flux
from particle_methods.norms import w1_to_measure
from particle_methods.sticky.cases import (
    SCALAR_CASES,
    configuration_distance,
    psystem_initial_configuration,
    psystem_initial_measures,
)
from particle_methods.sticky.exact import BurgersSolution
from particle_methods.sticky.measures import Laplace, median_quantiles
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.sticky.spd import spd_positions, velocities_from_flux
from particle_methods.sticky.theory import (
    CUBIC_LIPSCHITZ,
    CubicDiracSolution,
    collision_record,
    cubic_flux,
    doubling_distance,
    empirical_atoms,
    psystem_constants,
    sampled_configuration,
)
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results

PSYSTEM_CASES = ("rarefaction", "shocks")
#: The scalar fluxes, their L_LC and the configuration (2.1) of their case: Figure 2's two atoms, Figure 3's
#: Laplace law, delta_0 for the cubic flux (n particles at 0).
SCALAR_FLUXES = {
    "burgers": (burgers_flux, SCALAR_CASES["burgers_two_atoms"].flux_lipschitz,
                lambda n: median_quantiles(SCALAR_CASES["burgers_two_atoms"].initial, n)),
    "concave": (concave_flux, SCALAR_CASES["concave_laplace"].flux_lipschitz,
                lambda n: median_quantiles(SCALAR_CASES["concave_laplace"].initial, n)),
    "cubic": (cubic_flux, CUBIC_LIPSCHITZ, lambda n: np.zeros(n)),
}


def scalar_study(p):
    """(3.3) for every flux and configuration, Proposition 3.2 where u_inf[x] is exact."""
    n_values, times, seeds = np.asarray(p["n_values"]), np.asarray(p["times"], dtype=float), p["seeds"]
    configurations = ["case", *(f"seed {seed}" for seed in seeds)]
    doubling = np.empty((len(SCALAR_FLUXES), len(configurations), n_values.size, times.size))
    burgers_prop32 = np.empty((len(configurations), n_values.size, times.size))
    cubic_prop32 = np.empty((n_values.size, times.size))
    for j, n in enumerate(n_values):
        drawn = [sampled_configuration([Laplace(0.0)], int(n), np.random.default_rng(seed))[0] for seed in seeds]
        for f, (name, (flux, _, case)) in enumerate(SCALAR_FLUXES.items()):
            for c, x in enumerate([case(int(n)), *drawn]):
                doubling[f, c, j] = [doubling_distance(flux, x, t) for t in times]
                if name == "burgers":  # u_inf[x]: a fan from every atom of mu_0[x]
                    v = velocities_from_flux(flux, int(n))
                    burgers_prop32[c, j] = [w1_to_measure(BurgersSolution(empirical_atoms(x), t),
                                                          spd_positions(x, v, t)) for t in times]
        v = velocities_from_flux(cubic_flux, int(n))
        cubic_prop32[j] = [w1_to_measure(CubicDiracSolution(0.0, t), spd_positions(np.zeros(int(n)), v, t))
                           for t in times]
    return {"scalar_fluxes": np.array(list(SCALAR_FLUXES)), "scalar_configurations": np.array(configurations),
            "scalar_lipschitz": np.array([value[1] for value in SCALAR_FLUXES.values()]),
            "scalar_n": n_values, "scalar_times": times, "doubling": doubling, "burgers_prop32": burgers_prop32,
            "cubic_prop32": cubic_prop32}


def step_study(system, cases, p):
    """Lemma 4.2, Remark 4.3, (4.5) and (4.1), step by step, for each case, n and Delta."""
    n_values, deltas = np.asarray(p["n_values"]), np.asarray(p["deltas"], dtype=float)
    steps = np.rint(p["t"] / deltas).astype(np.int64)
    if not np.allclose(steps * deltas, p["t"], rtol=1e-9, atol=0.0):
        raise ValueError(f"every Delta must divide t = {p['t']}")
    shape = (len(PSYSTEM_CASES), n_values.size, deltas.size)
    collisions = np.full((*shape, steps.max()), -1, dtype=np.int64)  # -1 past the last step of a run
    step_distances = np.full((*shape, steps.max()), np.nan)
    mspd_distances = np.full((*shape, steps.max() + 1), np.nan)
    largest_count, shrink, window, extent = (np.empty(shape) for _ in range(4))
    count_histogram = np.zeros((*shape, 8), dtype=np.int64)  # pairs counted 0, 1, ..., 7 times in (4.5)
    for c, case in enumerate(PSYSTEM_CASES):
        for i, n in enumerate(n_values):
            x = psystem_initial_configuration(case, cases[case]["x0"], int(n))
            for j, (delta, count) in enumerate(zip(deltas, steps)):
                progress(f"{case}: n = {n}, Delta = {delta:g}, {count} steps against the exact MSPD")
                record = collision_record(x, system, float(delta), int(count))
                collisions[c, i, j, :count] = record.collisions
                step_distances[c, i, j, :count] = record.step_distances
                mspd_distances[c, i, j, :count + 1] = record.mspd_distances
                largest_count[c, i, j] = record.pair_counts.max()
                count_histogram[c, i, j] = np.bincount(np.minimum(record.pair_counts.ravel(), 7), minlength=8)
                shrink[c, i, j], window[c, i, j] = record.smallest_shrink, record.largest_collision_gap
                extent[c, i, j] = record.extent
    return {"step_n": n_values, "step_deltas": deltas, "step_t": p["t"], "collisions": collisions,
            "step_distances": step_distances, "mspd_distances": mspd_distances, "largest_count": largest_count,
            "count_histogram": count_histogram, "smallest_shrink": shrink, "largest_collision_gap": window,
            "extent": extent}


def random_study(system, cases, p):
    """Corollary 4.6 on random configurations and the iterated TSPD with L = n, at each time, against the
    exact MSPD from (1.9) with reference_n per type (and its distance to half as many particles)."""
    n_values, times, seeds = np.asarray(p["n_values"]), np.asarray(p["times"], dtype=float), p["seeds"]
    shape = (len(PSYSTEM_CASES), times.size)
    reference_gap = np.empty(shape)
    random_errors = np.empty((len(PSYSTEM_CASES), len(seeds), n_values.size, times.size))
    random_initial = np.empty((len(PSYSTEM_CASES), len(seeds), n_values.size))
    tspd_errors = np.empty((*shape, n_values.size))
    for c, case in enumerate(PSYSTEM_CASES):
        x0 = cases[case]["x0"]
        progress(f"{case}: exact MSPD references, n = {p['reference_n']} and {p['reference_n'] // 2}, t = "
                 f"{times.tolist()}")
        reference = mspd_exact(psystem_initial_configuration(case, x0, p["reference_n"]), system, times)
        half = mspd_exact(psystem_initial_configuration(case, x0, p["reference_n"] // 2), system, times)
        reference_gap[c] = [configuration_distance(a, b) for a, b in zip(reference, half)]
        measures = psystem_initial_measures(case, x0)
        for s, seed in enumerate(seeds):
            progress(f"{case}: exact MSPD from random configurations, seed {seed}, n = {n_values.tolist()}")
            rng = np.random.default_rng([seed, c])
            for j, n in enumerate(n_values):
                x = sampled_configuration(measures, int(n), rng)
                random_initial[c, s, j] = sum(w1_to_measure(m, row) for m, row in zip(measures, x))
                random_errors[c, s, j] = [configuration_distance(a, b)
                                          for a, b in zip(mspd_exact(x, system, times), reference)]
        progress(f"{case}: iterated TSPD with L = n steps of t/n from (1.9), n = {n_values.tolist()}")
        for j, n in enumerate(n_values):
            x = psystem_initial_configuration(case, x0, int(n))
            tspd_errors[c, :, j] = [configuration_distance(mspd_positions(x, system, t / n, int(n)), r)
                                    for t, r in zip(times, reference)]
    return {"random_seeds": np.asarray(seeds), "random_n": n_values, "random_times": times,
            "reference_n": p["reference_n"], "reference_gap": reference_gap, "random_errors": random_errors,
            "random_initial": random_initial, "tspd_errors": tspd_errors}


def run(system_params, cases, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    constants = psystem_constants(system)
    save_results(output, cases=np.array(PSYSTEM_CASES), d=constants.d, speed_bound=constants.speed_bound,
                 hyperbolicity=constants.hyperbolicity, lipschitz=constants.lipschitz,
                 crossings_bound=constants.crossings_bound, **scalar_study(p["scalar"]),
                 **step_study(system, cases, p["steps"]), **random_study(system, cases, p["random"]))


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
