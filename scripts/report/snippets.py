"""Write the LaTeX snippets of the report from the claims table, the versions and the run's config."""

from particle_replication.report import write_snippets
from particle_replication.workflow import logged

with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    write_snippets(snakemake.input.claims, snakemake.input.rates, snakemake.input.versions, dict(snakemake.config),  # noqa: F821
                   snakemake.params.outdir)  # noqa: F821
