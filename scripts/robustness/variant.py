"""One variant of the robustness run: the pipeline up to its claims table, in a Snakemake run of its own."""

from particle_replication.robustness import run_variant

run_variant(snakemake.wildcards.variant, snakemake.params.variant, snakemake.params.config,  # noqa: F821
            snakemake.params.snakefile, snakemake.params.directory, snakemake.threads, snakemake.log[0])  # noqa: F821
