"""The plot jobs of one batch of a paper's figures (rules/registry.smk), run in this one process
(particle_replication.plot_batch)."""

from particle_replication.plot_batch import run_plot_batch

run_plot_batch(snakemake)  # noqa: F821
