"""Every checked claim of the LTP paper: its registered result files measured by
particle_replication.verdicts.ltp.claims, with the tolerances and windows of the config."""

from particle_replication.claims import measure_paper
from particle_replication.verdicts import ltp
from particle_replication.workflow import logged, progress

with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    measure_paper(snakemake.input, snakemake.params.cfg, snakemake.output, ltp.claims, log=progress)  # noqa: F821
