"""Beyond the paper (section 5.2), part 2: the cost argument measured, and the study merged.

Error (W1 of section 1.1, or W1^(d) (1.10)) against the operations each kernel counts as it runs and
against the best wall time: the SPD and the Godunov scheme on the scalar cases of Figures 2 and 3
against their exact solutions; the iterated TSPD (L = n steps of t/n, the choice of section 5.2), the
exact MSPD and the upwind scheme on the p-system cases against the case's reference, the more
accurate of the exact MSPD with the largest n of the limit sweep and the upwind scheme on the most
cells (both from ``beyond_limits.py``, whose results are copied into this job's output).

Operations: the hull's tests, pops, pushes and writes (SPD; :func:`particle_methods.sticky.spd.hull_positions_kernel`),
rank entries and hull operations over the steps (TSPD), events and velocity updates (exact MSPD),
cell updates times components (finite volumes, the steps counted by the scheme). Every kernel runs
once untimed before its timings, so that no compilation is timed; the runs are then timed together,
interleaved, with the CPU and a load guard recorded beside them, and each run's slowest time and number of
timings (``*_timing``): how far the machine's speed moved between rounds, the wall-time check's uncertainty.
Only timed runs happen here: the job holds every core, so that no other job disturbs the timings.
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
from particle_replication.environment import cpu
from particle_replication.workflow import LoadGuard, interleaved, load_results, logged, progress, save_results

FLUXES = {"burgers_two_atoms": BURGERS, "concave_laplace": CONCAVE}
PSYSTEM_CASES = ("rarefaction", "shocks")
REFERENCES = ("exact MSPD", "upwind")


class Timed:
    """The runs of the study, each with what makes its row from its result; the first run of each method also
    runs once untimed (compilation), and all are then timed together, interleaved
    (:func:`~particle_replication.workflow.interleaved`), under one load guard."""

    def __init__(self):
        self.runs, self.rows, self.methods = [], [], set()

    def add(self, method, run, row):
        if method not in self.methods:
            run()
            self.methods.add(method)
        self.runs.append(run)
        self.rows.append(row)
        return len(self.rows) - 1

    def time(self, repeats):
        with LoadGuard() as guard:
            self.timed = interleaved(self.runs, repeats, guard)
        self.guard = guard
        self.made = [row(result, time) for row, result, time in zip(self.rows, self.timed.results, self.timed.best)]

    def spread(self, indices):
        """The slowest time of each of the runs ``indices`` and how many times it was timed (rows of an array)."""
        return np.array([[self.timed.slowest[i] for i in indices], [self.timed.count[i] for i in indices]])


def scalar_study(name, p, timing):
    """SPD (n particles) and Godunov (cells) errors, operations and best times for one scalar case: the indices
    of its runs in ``timing`` (:class:`Timed`)."""
    case, t = SCALAR_CASES[name], p["t"]
    solution = case.solution(t)
    spd, fv = [], []
    for n in p["spd_n"]:
        x, v = case.initial_state(n)
        spd.append(timing.add("spd", lambda x=x, v=v: spd_positions(x, v, t, return_operations=True),
                              lambda result, seconds: (w1_to_measure(solution, result[0]), result[1], seconds)))
    for cells in p["cells"]:
        edges = np.linspace(*p["domain"], cells + 1)
        u0 = np.diff(cdf_antiderivative(case.initial, edges)) / np.diff(edges)
        fv.append(timing.add(
            "godunov", lambda u0=u0, edges=edges: godunov(FLUXES[name], u0, edges, t, left=0.0, right=1.0,
                                                          return_steps=True),
            lambda result, seconds, edges=edges, cells=cells: (
                l1_to_step_function(solution, edges, np.append(result[0], 1.0)), cells * result[1], seconds)))
    return spd, fv


def reference(limits, exact, name, domain):
    """The case's reference: of the exact MSPD (``exact``: its full and half runs from beyond_reference.py) and the
    upwind scheme for (1.7) on upwind_reference_cells (from ``limits``), which approximate the same MSPD limit, the
    one with the smaller distance to its own half resolution (its error). Returns (index in REFERENCES, its size,
    that error, distance to a configuration, distance to a cell function)."""
    full, half = exact
    if int(full["n"]) != 2 * int(half["n"]):
        raise ValueError(f"{name}: the reference's half run has n = {int(half['n'])}, not half of {int(full['n'])}: "
                         "rerun its rule")
    mspd, w = full["mspd"], limits[f"{name}_upwind_w"]
    errors = (configuration_distance(mspd, half["mspd"]), float(limits[f"{name}_upwind_gap"]))
    cells = int(limits["upwind_reference_cells"])
    fine = np.linspace(*domain, cells + 1)
    if errors[1] < errors[0]:
        return (1, f"{cells} cells", errors[1], lambda x: distance_to_cells(x, w, fine),
                lambda v, edges: cells_distance(v, edges, w, fine))
    return (0, f"n = {int(full['n'])}", errors[0], lambda x: configuration_distance(x, mspd),
            lambda v, edges: distance_to_cells(mspd, v, edges))


def psystem_study(system, name, x0, p, limits, exact, timing):
    """TSPD, exact MSPD and upwind errors, operations and best times for one p-system case: the indices of its
    runs in ``timing`` (:class:`Timed`), and its reference."""
    t = p["t"]
    chosen, size, own_error, to_configuration, to_cells = reference(limits, exact, name, p["domain"])
    tspd, exact_runs, upwind_runs = [], [], []
    for n in p["tspd_n"]:
        x = psystem_initial_configuration(name, x0, n)
        tspd.append(timing.add("tspd", lambda x=x, n=n: mspd_positions(x, system, t / n, n, return_operations=True),
                               lambda result, seconds: (to_configuration(result[0]), result[1], seconds)))

    def exact_row(result, seconds):
        state, events = result
        work = events.merges + events.crossings + events.splits + events.member_updates
        return to_configuration(state[0]), work, seconds, events.crossings

    for n in p["exact_n"]:
        x = psystem_initial_configuration(name, x0, n)
        exact_runs.append(timing.add("exact", lambda x=x: mspd_exact(x, system, [t], return_events=True), exact_row))
    for cells in p["upwind_cells"]:
        edges = np.linspace(*p["domain"], cells + 1)
        w0 = psystem_initial_cells(name, x0, edges)
        upwind_runs.append(timing.add(
            "upwind", lambda w0=w0, edges=edges: upwind_diagonal(system, w0, edges, t, p["cfl"], return_steps=True),
            lambda result, seconds, edges=edges, cells=cells: (to_cells(result[0], edges),
                                                               system.d * cells * result[1], seconds)))
    progress(f"{name}: reference {REFERENCES[chosen]} ({size}), own error {own_error:.3g}")
    return dict(tspd=tspd, exact=exact_runs, upwind=upwind_runs, reference=f"{REFERENCES[chosen]}, {size}",
                reference_error=own_error)


def run(system_params, cases, p, limits, references, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    limits = load_results(limits)
    exact = {name: tuple(load_results(references[f"{name}_{part}"], expect={"case": name, "part": part})
                         for part in ("full", "half")) for name in PSYSTEM_CASES}
    timing = Timed()
    studies = {name: psystem_study(system, name, cases[name]["x0"], p, limits, exact[name], timing)
               for name in PSYSTEM_CASES}
    scalar = {name: scalar_study(name, p["scalar"][name], timing) for name in FLUXES}
    timing.time(p["repeats"])

    def rows(indices):
        return np.array([timing.made[i] for i in indices]).T

    def listed(indices):
        return "; ".join(f"{timing.made[i][0]:.3e} in {timing.made[i][2]:.3g} s" for i in indices)

    for name, study in studies.items():
        for method in ("tspd", "exact", "upwind"):
            progress(f"{name}: {method}: {listed(study[method])}")
    for name, (spd, fv) in scalar.items():
        progress(f"{name}: SPD {listed(spd)}; Godunov {listed(fv)}")
    progress(f"CPU {cpu()}; the timed runs got {timing.guard.cpu_share:.2f} of a core, {timing.guard.load:.2g} other "
             "processes runnable on average")
    save_results(
        output, **limits, tspd_n=np.asarray(p["tspd_n"]), exact_n=np.asarray(p["exact_n"]),
        upwind_cells=np.asarray(p["upwind_cells"]), scalar_cases=np.array(list(FLUXES)),
        **{f"{case}_{method}": rows(study[method]) for case, study in studies.items()
           for method in ("tspd", "exact", "upwind")},
        **{f"{case}_{key}": np.asarray(study[key]) for case, study in studies.items()
           for key in ("reference", "reference_error")},
        **{f"{case}_{method}_timing": timing.spread(study[method]) for case, study in studies.items()
           for method in ("tspd", "exact", "upwind")},
        **{f"{name}_spd": rows(spd) for name, (spd, _) in scalar.items()},
        **{f"{name}_godunov": rows(fv) for name, (_, fv) in scalar.items()},
        **{f"{name}_spd_timing": timing.spread(spd) for name, (spd, _) in scalar.items()},
        **{f"{name}_godunov_timing": timing.spread(fv) for name, (_, fv) in scalar.items()},
        **{f"{name}_spd_n": np.asarray(p["scalar"][name]["spd_n"]) for name in FLUXES},
        **{f"{name}_cells": np.asarray(p["scalar"][name]["cells"]) for name in FLUXES},
        cpu=cpu(), **timing.guard.readings(),
    )


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.input.limits,  # noqa: F821
        {name: snakemake.input[name] for name in snakemake.input.keys() if name != "limits"},  # noqa: F821
        snakemake.output[0])  # noqa: F821
