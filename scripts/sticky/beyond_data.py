"""Beyond the paper (section 5.2), part 2: the cost argument measured, and the study merged.

Error (W1 of section 1.1, or W1^(d) (1.10)) against an operation count and the wall time: the SPD
and the Godunov scheme on the scalar cases of Figures 2 and 3 against their exact solutions; the
iterated TSPD (L = n steps of t/n, the choice of section 5.2), the exact MSPD and the upwind scheme
on the p-system cases against the exact MSPD with the largest n of the limit sweep
(``beyond_limits.py``, whose results are copied into this job's output). Operation counts: particles
for one hull pass (SPD), particle moves n d L (TSPD), events and velocity updates (exact MSPD), cell
updates times components (finite volumes). Only timed runs happen here: the job holds every core, so
that no other job disturbs the timings.
"""

import numpy as np

from particle_methods.finite_volume.fluxes import BURGERS, CONCAVE
from particle_methods.finite_volume.psystem import upwind_diagonal
from particle_methods.finite_volume.scalar import godunov
from particle_methods.norms import cdf_antiderivative, l1_to_step_function, w1_to_measure
from particle_methods.sticky.cases import (
    SCALAR_CASES,
    configuration_distance,
    distance_to_cells,
    psystem_initial_cells,
    psystem_initial_configuration,
)
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.sticky.spd import spd_positions
from particle_methods.systems import PSystem
from particle_replication.workflow import load_results, logged, progress, save_results, timed

FLUXES = {"burgers_two_atoms": BURGERS, "concave_laplace": CONCAVE}
PSYSTEM_CASES = ("rarefaction", "shocks")



def upwind(system, case, x0, edges, t, cfl, repeats):
    w0 = psystem_initial_cells(case, x0, edges)
    return timed(lambda: upwind_diagonal(system, w0, edges, t, cfl, return_steps=True), repeats)


def scalar_study(name, p, repeats):
    """SPD (n particles) and Godunov (cells) errors, operation counts and best times for one scalar case."""
    case, t = SCALAR_CASES[name], p["t"]
    solution = case.solution(t)
    spd = []
    for n in p["spd_n"]:
        x, v = case.initial_state(n)
        seconds, positions = timed(lambda x=x, v=v: spd_positions(x, v, t), repeats)
        spd.append((w1_to_measure(solution, positions), n, seconds))
        progress(f"{name}: SPD n = {n}: W1 {spd[-1][0]:.3e}, {seconds:.3g} s")
    fv = []
    for cells in p["cells"]:
        edges = np.linspace(*p["domain"], cells + 1)
        u0 = np.diff(cdf_antiderivative(case.initial, edges)) / np.diff(edges)
        seconds, (u, steps) = timed(lambda u0=u0, edges=edges: godunov(FLUXES[name], u0, edges, t, left=0.0, right=1.0,
                                                                       return_steps=True), repeats)
        fv.append((l1_to_step_function(solution, edges, np.append(u, 1.0)), cells * steps, seconds))
        progress(f"{name}: Godunov {cells} cells, {steps} steps: W1 {fv[-1][0]:.3e}, {seconds:.3g} s")
    return np.array(spd).T, np.array(fv).T


def run(system_params, cases, p, limits, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    t, cfl, repeats = p["t"], p["cfl"], p["repeats"]
    limits = load_results(limits)
    results = {}
    for name in PSYSTEM_CASES:
        x0 = cases[name]["x0"]
        reference = limits[f"{name}_mspd"]
        # Cost: error against the exact MSPD with the largest n.
        tspd, exact_runs, upwind_runs = [], [], []
        for n in p["tspd_n"]:
            x = psystem_initial_configuration(name, x0, n)
            seconds, state = timed(lambda x=x, n=n: mspd_positions(x, system, t / n, n), repeats)
            tspd.append((configuration_distance(state, reference), system.d * n * n, seconds))
        for n in p["exact_n"]:
            x = psystem_initial_configuration(name, x0, n)
            seconds, (state, events) = timed(lambda x=x: mspd_exact(x, system, [t], return_events=True), repeats)
            work = events.merges + events.crossings + events.splits + events.member_updates
            exact_runs.append((configuration_distance(state[0], reference), work, seconds, events.crossings))
        for cells in p["upwind_cells"]:
            edges = np.linspace(*p["domain"], cells + 1)
            seconds, (w, steps) = upwind(system, name, x0, edges, t, cfl, repeats)
            upwind_runs.append((distance_to_cells(reference, w, edges), system.d * cells * steps, seconds))
        for label, runs in (("TSPD", tspd), ("exact MSPD", exact_runs), ("upwind", upwind_runs)):
            progress(f"{name}: {label}: " + "; ".join(f"{r[0]:.3e} in {r[2]:.3g} s" for r in runs))
        results[name] = dict(tspd=np.array(tspd).T, exact=np.array(exact_runs).T, upwind=np.array(upwind_runs).T)
    scalar = {name: scalar_study(name, p["scalar"][name], repeats) for name in FLUXES}
    save_results(
        output, **limits, tspd_n=np.asarray(p["tspd_n"]), exact_n=np.asarray(p["exact_n"]),
        upwind_cells=np.asarray(p["upwind_cells"]), scalar_cases=np.array(list(FLUXES)),
        **{f"{case}_{key}": np.asarray(value) for case, r in results.items() for key, value in r.items()},
        **{f"{name}_spd": spd for name, (spd, _) in scalar.items()},
        **{f"{name}_godunov": fv for name, (_, fv) in scalar.items()},
        **{f"{name}_spd_n": np.asarray(p["scalar"][name]["spd_n"]) for name in FLUXES},
        **{f"{name}_cells": np.asarray(p["scalar"][name]["cells"]) for name in FLUXES},
    )


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.input.limits,  # noqa: F821
        snakemake.output[0])  # noqa: F821
