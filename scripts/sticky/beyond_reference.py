"""Beyond the paper (section 5.2): the exact MSPD reference of the cost study for one p-system case.

The exact MSPD with ``reference_n`` particles per type at the study's time, and its W1^(d) distance to
the run with half as many, its own error. The cost study (``beyond_data.py``) measures its errors
against it or against the upwind scheme on its reference grid, whichever is more accurate. One job per
case, so that the two run side by side with the rest of the pipeline.
"""

import numpy as np

from particle_methods.sticky.cases import configuration_distance, psystem_initial_configuration
from particle_methods.sticky.multitype_events import mspd_exact
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results


def run(system_params, x0, case, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    n = int(p["reference_n"])
    reference, half = (mspd_exact(psystem_initial_configuration(case, x0, size), system, [p["t"]])[0]
                       for size in (n, n // 2))
    gap = configuration_distance(reference, half)
    progress(f"{case}: exact MSPD with n = {n} per type, distance to n = {n // 2}: {gap:.3g}")
    save_results(output, case=np.array(case), reference_n=n, reference_mspd=reference, reference_gap=gap)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.x0, snakemake.params.case, snakemake.params.cfg,  # noqa: F821
        snakemake.output[0])  # noqa: F821
