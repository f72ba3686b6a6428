"""Write the LaTeX snippets of the report from the claims table, the expected verdicts (the causes of the
failures), the register of rules changed after a failing run, the versions and the run's config."""

from particle_replication.claims import read_changes, read_verdicts
from particle_replication.report import write_snippets
from particle_replication.workflow import logged

with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    expected = read_verdicts(snakemake.input.expected, snakemake.params.run)  # noqa: F821
    changes = read_changes(snakemake.input.changes, expected)  # noqa: F821
    write_snippets(snakemake.input.claims, snakemake.input.rates, snakemake.input.versions, dict(snakemake.config),  # noqa: F821
                   snakemake.params.outdir, expected, changes, snakemake.input.documents)  # noqa: F821
