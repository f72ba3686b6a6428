"""Beyond the paper (section 5.2): one exact MSPD run of the cost study's reference for one p-system case.

The exact MSPD at the study's time with ``reference_n`` particles per type (part ``full``) or half as many (part
``half``), one job each, so that the two run side by side with the rest of the pipeline and the longest job is the
full run alone (issue 47). The cost study (``beyond_data.py``) takes the full run's W1^(d) distance to the half run
as its own error, and measures its errors against it or against the upwind scheme on its reference grid, whichever is
more accurate. Computed by ``mspd_exact_at``: over the grid of crossings where no two particles of one type meet (the
rarefaction case: seconds instead of minutes, the same configuration bit for bit), else by the event loop; the log
names which.
"""

import numpy as np

from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.multitype_events import mspd_exact_at
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results


def run(system_params, x0, case, part, n, p, output):
    """One part of the reference: ``n`` particles per type (the registry's PART_DIVISORS of reference_n)."""
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    n = int(n)
    mspd, method = mspd_exact_at(psystem_initial_configuration(case, x0, n), system, p["t"], return_method=True)
    progress(f"{case}: exact MSPD with n = {n} per type at t = {p['t']} ({part} part of the reference), by the "
             f"{'grid of crossings' if method == 'grid' else 'event loop'}")
    save_results(output, case=np.array(case), part=np.array(part), n=n, mspd=mspd)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.x0, snakemake.params.case, snakemake.params.part,  # noqa: F821
        snakemake.params.size, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
