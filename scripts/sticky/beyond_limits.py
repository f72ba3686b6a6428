"""Beyond the paper (section 5.2), part 1: the exact MSPD's limit, untimed.

For both p-system cases the exact MSPD with n particles per type is compared, at one time t, with a
conservative HLL solution of the p-system on ``reference_cells`` cells (mapped to Riemann invariants)
and with the upwind scheme for (1.7) on ``upwind_reference_cells`` (computed by ``beyond_upwind.py``, with
half as many cells in a job of its own: their distance is its own error); the HLL solution is also compared with
itself at half its resolution. The upwind run on its reference grid is one of the cost study's
two candidate references (``beyond_data.py``); the other is the exact MSPD of ``beyond_reference.py``.
Nothing here is timed, so this job holds one core while the timed runs hold them all.
"""

import numpy as np

from particle_methods.finite_volume.psystem import hll_psystem, invariants_from_conservative
from particle_methods.sticky.cases import (
    cells_distance,
    configuration_distance,
    distance_to_cells,
    psystem_initial_cells,
    psystem_initial_configuration,
)
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.systems import PSystem
from particle_replication.workflow import load_results, logged, progress, save_results

PSYSTEM_CASES = ("rarefaction", "shocks")


def hll_invariants(system, case, x0, edges, t, cfl):
    """Riemann invariants (w-, w+) of the conservative HLL run, shape (2, cells)."""
    u0, v0 = system.physical_variables(*psystem_initial_cells(case, x0, edges))
    return np.array(invariants_from_conservative(system, *hll_psystem(system, u0, v0, edges, t, cfl)))


def upwind_reference(paths, case, cells, domain):
    """The upwind runs of ``beyond_upwind.py`` for ``case`` (``paths``: part -> file): (invariants (2, cells),
    their distance to the run on half the cells), each checked to be that case's part of the reference on
    ``cells`` cells."""
    runs = {part: load_results(path, expect={"case": case, "part": part, "upwind_reference_cells": cells})
            for part, path in paths.items()}
    full, half = runs["full"], runs["half"]
    edges = {part: np.linspace(*domain, int(run["cells"]) + 1) for part, run in runs.items()}
    return full["upwind_w"], cells_distance(full["upwind_w"], edges["full"], half["upwind_w"], edges["half"])


def run(system_params, cases, p, upwind, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    t, cfl = p["t"], p["cfl"]
    limit_n = np.asarray(p["limit_n"])
    results = {}
    for name in PSYSTEM_CASES:
        x0 = cases[name]["x0"]
        cells = p["reference_cells"]
        fine, coarse = (np.linspace(*p["domain"], count + 1) for count in (cells, cells // 2))
        hll, hll_half = (hll_invariants(system, name, x0, edges, t, cfl) for edges in (fine, coarse))
        cells = p["upwind_reference_cells"]
        fine_up = np.linspace(*p["domain"], cells + 1)
        up, upwind_gap = upwind_reference(upwind[name], name, cells, p["domain"])
        progress(f"{name}: HLL on {p['reference_cells']} cells done (upwind on {cells} from {upwind[name]})")
        exact = {n: mspd_exact(psystem_initial_configuration(name, x0, int(n)), system, [t])[0] for n in limit_n}
        to_hll = [distance_to_cells(exact[n], hll, fine) for n in limit_n]
        to_upwind = [distance_to_cells(exact[n], up, fine_up) for n in limit_n]
        progress(f"{name}: MSPD to HLL {np.array(to_hll)}, to upwind {np.array(to_upwind)}")
        results[name] = dict(
            limit_to_hll=to_hll, limit_to_upwind=to_upwind,
            mspd_gap=configuration_distance(exact[limit_n[-1]], exact[limit_n[-2]]),
            hll_gap=cells_distance(hll, fine, hll_half, coarse),
            upwind_gap=upwind_gap,
            hll_to_upwind=cells_distance(hll, fine, up, fine_up), hll_w=hll, upwind_w=up, mspd=exact[limit_n[-1]])
    save_results(output, t=t, cases=np.array(PSYSTEM_CASES), limit_n=limit_n, reference_cells=p["reference_cells"],
                 upwind_reference_cells=p["upwind_reference_cells"],
                 **{f"{case}_{key}": np.asarray(value) for case, r in results.items() for key, value in r.items()})


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    upwind_runs = {name: {part: snakemake.input[f"{name}_{part}"] for part in ("full", "half")}  # noqa: F821
                   for name in PSYSTEM_CASES}
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, upwind_runs,  # noqa: F821
        snakemake.output[0])  # noqa: F821
