"""Beyond the paper (section 5.2): one run of the upwind reference of the limits study for one p-system case.

The upwind scheme for (1.7) at the study's time on ``upwind_reference_cells`` cells (part ``full``) or half as
many (part ``half``), one job each, so that they run side by side with the rest of the pipeline and no job holds
both (issue 47: the two took 56 to 71 s in one job). ``beyond_limits.py`` takes the full run's distance to the half
run as its own error and measures the exact MSPD against it (and against the conservative HLL scheme); the cost
study (``beyond_data.py``) takes it as one of its two candidate references. On a machine without AVX-512 NumPy
evaluates the primitive of (5.7) by libm's sinh and arctan (20 to 25 ns a value on these data, three values per
face and step: most of a step on an AMD EPYC with AVX2), so the job's threads split that evaluation (the same
result to the last bit on any number; 64,000 cells: 1.13 to 1.35 times faster on 2 threads of the repository's
virtual machine, benchmarks/README.md). Untimed.
"""

import numpy as np

from particle_methods.finite_volume.psystem import upwind_diagonal
from particle_methods.sticky.cases import psystem_initial_cells
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results


def run(system_params, x0, case, part, cells, p, threads, output):
    """One part of the reference: ``cells`` cells (the registry's PART_DIVISORS of upwind_reference_cells), the
    primitive evaluated by ``threads`` threads."""
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    reference_cells, cells = int(p["upwind_reference_cells"]), int(cells)
    edges = np.linspace(*p["domain"], cells + 1)
    up = upwind_diagonal(system, psystem_initial_cells(case, x0, edges), edges, p["t"], p["cfl"], threads=threads)
    progress(f"{case}: upwind on {cells} cells ({part} part of the reference on {reference_cells})")
    save_results(output, case=np.array(case), part=np.array(part), upwind_reference_cells=reference_cells,
                 cells=cells, upwind_w=up)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge) as threads:  # noqa: F821
    run(snakemake.params.system, snakemake.params.x0, snakemake.params.case, snakemake.params.part,  # noqa: F821
        snakemake.params.size, snakemake.params.cfg, threads, snakemake.output[0])  # noqa: F821
