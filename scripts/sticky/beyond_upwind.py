"""Beyond the paper (section 5.2): the upwind reference of the limits study for one p-system case.

The upwind scheme for (1.7) on ``upwind_reference_cells`` cells at the study's time, and its distance to
the same scheme on half as many cells, its own error. ``beyond_limits.py`` measures the exact MSPD against
it (and against the conservative HLL scheme); the cost study (``beyond_data.py``) takes it as one of its two
candidate references. On a machine without AVX-512 NumPy evaluates the primitive of (5.7) by libm's sinh and
arctan (20 to 25 ns a value on these data, three values per face and step: about 90 % of a step on an AMD EPYC
with AVX2), so the two runs take 30 to 45 s of a core per case: one job per case, so that the two run side by
side with the rest of the pipeline (issue 47). Untimed.
"""

import numpy as np

from particle_methods.finite_volume.psystem import upwind_diagonal
from particle_methods.sticky.cases import cells_distance, psystem_initial_cells
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results


def run(system_params, x0, case, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    cells = int(p["upwind_reference_cells"])
    fine, coarse = (np.linspace(*p["domain"], count + 1) for count in (cells, cells // 2))
    up, up_half = (upwind_diagonal(system, psystem_initial_cells(case, x0, edges), edges, p["t"], p["cfl"])
                   for edges in (fine, coarse))
    gap = cells_distance(up, fine, up_half, coarse)
    progress(f"{case}: upwind on {cells} cells, distance to {cells // 2}: {gap:.3g}")
    save_results(output, case=np.array(case), upwind_reference_cells=cells, upwind_w=up, upwind_gap=gap)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.x0, snakemake.params.case, snakemake.params.cfg,  # noqa: F821
        snakemake.output[0])  # noqa: F821
