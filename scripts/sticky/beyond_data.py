"""Beyond the paper (section 5.2), part 2: the cost argument measured, and the study merged.

Error (W1 of section 1.1, or W1^(d) (1.10)) against the operations each kernel counts as it runs and
against the best wall time: the SPD and the Godunov scheme on the scalar cases of Figures 2 and 3
against their exact solutions; the iterated TSPD (L = n steps of t/n, the choice of section 5.2), the
exact MSPD and the upwind scheme on the p-system cases against the case's reference, the more
accurate of the exact MSPD with the largest n of the limit sweep and the upwind scheme on the most
cells (both from ``beyond_limits.py``, whose results are copied into this job's output).

Operations: the hull's stack operations (SPD; :func:`particle_methods.sticky.spd.hull_operations`),
rank entries and hull operations over the steps (TSPD), events and velocity updates (exact MSPD),
cell updates times components (finite volumes, the steps counted by the scheme). Every kernel runs
once untimed before its timings, so that no compilation is timed. Only timed runs happen here: the
job holds every core, so that no other job disturbs the timings.
"""

import numpy as np

from particle_methods.finite_volume.fluxes import BURGERS, CONCAVE
from particle_methods.finite_volume.psystem import upwind_diagonal
from particle_methods.finite_volume.scalar import godunov
from particle_methods.norms import cdf_antiderivative, l1_to_step_function, w1_to_measure
from particle_methods.sticky.cases import (
    SCALAR_CASES,
    cells_distance,
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
REFERENCES = ("exact MSPD", "upwind")


def measured(run, repeats, warm_up):
    """(seconds, result) of ``run``, best of ``repeats``, after ``warm_up`` (the same kernel on the
    smallest size, untimed) on the first call of each method."""
    if warm_up is not None:
        warm_up()
    return timed(run, repeats)


def scalar_study(name, p, repeats):
    """SPD (n particles) and Godunov (cells) errors, operations and best times for one scalar case."""
    case, t = SCALAR_CASES[name], p["t"]
    solution = case.solution(t)
    spd = []
    for n in p["spd_n"]:
        x, v = case.initial_state(n)
        run = lambda x=x, v=v: spd_positions(x, v, t, return_operations=True)  # noqa: E731
        seconds, (positions, operations) = measured(run, repeats, run if not spd else None)
        spd.append((w1_to_measure(solution, positions), operations, seconds))
        progress(f"{name}: SPD n = {n}: W1 {spd[-1][0]:.3e}, {seconds:.3g} s")
    fv = []
    for cells in p["cells"]:
        edges = np.linspace(*p["domain"], cells + 1)
        u0 = np.diff(cdf_antiderivative(case.initial, edges)) / np.diff(edges)
        run = lambda u0=u0, edges=edges: godunov(FLUXES[name], u0, edges, t, left=0.0, right=1.0,  # noqa: E731
                                                 return_steps=True)
        seconds, (u, steps) = measured(run, repeats, run if not fv else None)
        fv.append((l1_to_step_function(solution, edges, np.append(u, 1.0)), cells * steps, seconds))
        progress(f"{name}: Godunov {cells} cells, {steps} steps: W1 {fv[-1][0]:.3e}, {seconds:.3g} s")
    return np.array(spd).T, np.array(fv).T


def reference(limits, name, domain):
    """The case's reference: of the exact MSPD (n = limit_n[-1]) and the upwind scheme for (1.7) on
    upwind_reference_cells, which approximate the same MSPD limit, the one with the smaller distance
    to its own half resolution (its error). Returns (index in REFERENCES, that error, distance to a
    configuration, distance to a cell function)."""
    errors = (float(limits[f"{name}_mspd_gap"]), float(limits[f"{name}_upwind_gap"]))
    mspd, w = limits[f"{name}_mspd"], limits[f"{name}_upwind_w"]
    fine = np.linspace(*domain, int(limits["upwind_reference_cells"]) + 1)
    if errors[1] < errors[0]:
        return 1, errors[1], lambda x: distance_to_cells(x, w, fine), lambda v, edges: cells_distance(v, edges, w, fine)
    return 0, errors[0], lambda x: configuration_distance(x, mspd), lambda v, edges: distance_to_cells(mspd, v, edges)


def psystem_study(system, name, x0, p, limits):
    """TSPD, exact MSPD and upwind errors, operations and best times for one p-system case."""
    t, repeats = p["t"], p["repeats"]
    chosen, own_error, to_configuration, to_cells = reference(limits, name, p["domain"])
    tspd, exact_runs, upwind_runs = [], [], []
    for n in p["tspd_n"]:
        x = psystem_initial_configuration(name, x0, n)
        run = lambda x=x, n=n: mspd_positions(x, system, t / n, n, return_operations=True)  # noqa: E731
        seconds, (state, operations) = measured(run, repeats, run if not tspd else None)
        tspd.append((to_configuration(state), operations, seconds))
    for n in p["exact_n"]:
        x = psystem_initial_configuration(name, x0, n)
        run = lambda x=x: mspd_exact(x, system, [t], return_events=True)  # noqa: E731
        seconds, (state, events) = measured(run, repeats, run if not exact_runs else None)
        work = events.merges + events.crossings + events.splits + events.member_updates
        exact_runs.append((to_configuration(state[0]), work, seconds, events.crossings))
    for cells in p["upwind_cells"]:
        edges = np.linspace(*p["domain"], cells + 1)
        w0 = psystem_initial_cells(name, x0, edges)
        run = lambda w0=w0, edges=edges: upwind_diagonal(system, w0, edges, t, p["cfl"], return_steps=True)  # noqa: E731
        seconds, (w, steps) = measured(run, repeats, run if not upwind_runs else None)
        upwind_runs.append((to_cells(w, edges), system.d * cells * steps, seconds))
    progress(f"{name}: reference {REFERENCES[chosen]}, own error {own_error:.3g}")
    for label, runs in (("TSPD", tspd), ("exact MSPD", exact_runs), ("upwind", upwind_runs)):
        progress(f"{name}: {label}: " + "; ".join(f"{r[0]:.3e} in {r[2]:.3g} s" for r in runs))
    return dict(tspd=np.array(tspd).T, exact=np.array(exact_runs).T, upwind=np.array(upwind_runs).T,
                reference=REFERENCES[chosen], reference_error=own_error)


def run(system_params, cases, p, limits, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    limits = load_results(limits)
    results = {name: psystem_study(system, name, cases[name]["x0"], p, limits) for name in PSYSTEM_CASES}
    scalar = {name: scalar_study(name, p["scalar"][name], p["repeats"]) for name in FLUXES}
    save_results(
        output, **limits, tspd_n=np.asarray(p["tspd_n"]), exact_n=np.asarray(p["exact_n"]),
        upwind_cells=np.asarray(p["upwind_cells"]), scalar_cases=np.array(list(FLUXES)),
        **{f"{case}_{key}": np.asarray(value) for case, r in results.items() for key, value in r.items()},
        **{f"{name}_spd": spd for name, (spd, _) in scalar.items()},
        **{f"{name}_godunov": fv for name, (_, fv) in scalar.items()},
        **{f"{name}_spd_n": np.asarray(p["scalar"][name]["spd_n"]) for name in FLUXES},
        **{f"{name}_cells": np.asarray(p["scalar"][name]["cells"]) for name in FLUXES},
    )


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.input.limits,  # noqa: F821
        snakemake.output[0])  # noqa: F821
