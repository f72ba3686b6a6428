"""Beyond the paper (section 5.2): the exact MSPD's limit, and the cost argument measured.

Limits. For both p-system cases the exact MSPD with n particles per type is compared, at one time
t, with a conservative HLL solution of the p-system at ``reference_cells`` (mapped to Riemann
invariants) and with the upwind scheme for (1.7) at the same resolution; each reference is also
compared with itself at half its resolution.

Cost. Error (W1 of section 1.1, or W1^(d) (1.10)) against an operation count and the wall time:
the SPD and the Godunov scheme on the scalar cases of Figures 2 and 3 against their exact
solutions; the iterated TSPD (L = n steps of t/n, the choice of section 5.2), the exact MSPD and
the upwind scheme on the p-system cases against the exact MSPD with the largest n of the limit
sweep. Operation counts: particles for one hull pass (SPD), particle moves n d L (TSPD), events and
velocity updates (exact MSPD), cell updates times components (finite volumes).
"""

import numpy as np

from particle_methods.finite_volume import BURGERS, CONCAVE, godunov, l1_between_cell_functions
from particle_methods.norms import cdf_antiderivative, l1_to_step_function, w1_between_samples, w1_to_measure
from particle_methods.sticky.cases import (
    SCALAR_CASES,
    distance_to_cells,
    psystem_initial_cells,
    psystem_initial_configuration,
)
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.sticky.psystem import PSystem
from particle_methods.sticky.psystem_volumes import hll_psystem, invariants_from_conservative, upwind_diagonal
from particle_methods.sticky.spd import spd_positions
from particle_methods.workflow import logged, progress, save_results, timed

FLUXES = {"burgers_two_atoms": BURGERS, "concave_laplace": CONCAVE}
PSYSTEM_CASES = ("rarefaction", "shocks")


def configuration_distance(a, b):
    """W1^(d) between two configurations of equal-mass particles."""
    return sum(w1_between_samples(x, y) for x, y in zip(a, b))


def cell_distance(a, b, edges_a, edges_b):
    return sum(l1_between_cell_functions(x, edges_a, y, edges_b) for x, y in zip(a, b))


def hll_invariants(system, case, x0, edges, t, cfl):
    """Riemann invariants (w-, w+) of the conservative HLL run, shape (2, cells)."""
    u0, v0 = system.physical_variables(*psystem_initial_cells(case, x0, edges))
    return np.array(invariants_from_conservative(system, *hll_psystem(system, u0, v0, edges, t, cfl)))


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


def run(system_params, cases, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    t, cfl, repeats = p["t"], p["cfl"], p["repeats"]
    results = {}
    for name in PSYSTEM_CASES:
        x0 = cases[name]["x0"]
        fine = np.linspace(*p["domain"], p["reference_cells"] + 1)
        coarse = np.linspace(*p["domain"], p["reference_cells"] // 2 + 1)
        hll = hll_invariants(system, name, x0, fine, t, cfl)
        hll_half = hll_invariants(system, name, x0, coarse, t, cfl)
        _, (up, _) = upwind(system, name, x0, fine, t, cfl, 1)
        _, (up_half, _) = upwind(system, name, x0, coarse, t, cfl, 1)
        progress(f"{name}: references on {p['reference_cells']} cells done")
        limit_n = np.asarray(p["limit_n"])
        exact = {}
        for n in limit_n:
            exact[n] = mspd_exact(psystem_initial_configuration(name, x0, int(n)), system, [t])[0]
        to_hll = [distance_to_cells(exact[n], hll, fine) for n in limit_n]
        to_upwind = [distance_to_cells(exact[n], up, fine) for n in limit_n]
        progress(f"{name}: MSPD to HLL {np.array(to_hll)}, to upwind {np.array(to_upwind)}")
        reference = exact[limit_n[-1]]
        results[name] = dict(
            limit_to_hll=to_hll, limit_to_upwind=to_upwind,
            mspd_gap=configuration_distance(reference, exact[limit_n[-2]]),
            hll_gap=cell_distance(hll, hll_half, fine, coarse), upwind_gap=cell_distance(up, up_half, fine, coarse),
            hll_to_upwind=cell_distance(hll, up, fine, fine), hll_w=hll, upwind_w=up, mspd=reference)
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
        results[name].update(tspd=np.array(tspd).T, exact=np.array(exact_runs).T, upwind=np.array(upwind_runs).T)
    scalar = {name: scalar_study(name, p["scalar"][name], repeats) for name in FLUXES}
    save_results(
        output, t=t, cases=np.array(PSYSTEM_CASES), limit_n=np.asarray(p["limit_n"]),
        reference_cells=p["reference_cells"], tspd_n=np.asarray(p["tspd_n"]), exact_n=np.asarray(p["exact_n"]),
        upwind_cells=np.asarray(p["upwind_cells"]), scalar_cases=np.array(list(FLUXES)),
        **{f"{case}_{key}": np.asarray(value) for case, r in results.items() for key, value in r.items()},
        **{f"{name}_spd": spd for name, (spd, _) in scalar.items()},
        **{f"{name}_godunov": fv for name, (_, fv) in scalar.items()},
        **{f"{name}_spd_n": np.asarray(p["scalar"][name]["spd_n"]) for name in FLUXES},
        **{f"{name}_cells": np.asarray(p["scalar"][name]["cells"]) for name in FLUXES},
    )


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
