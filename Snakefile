"""Rebuild every figure and checked claim of the three papers.

snakemake --cores 2                                     # full resolution
snakemake --cores 2 sticky                              # one part: sticky, ltp, blob or cross
snakemake --cores 2 --configfile config/quick.yaml      # coarse, for tests and CI (in runs/quick)
snakemake verify                                        # fails when a verdict differs from the expected one
snakemake --cores 2 robustness                          # the claims under variants of threads, kernels, data, load
snakemake --report report.zip                           # the browsable report, after a run

A configuration file given with --configfile is laid over config/config.yaml (Snakemake merges it
mapping by mapping; a list replaces the whole list), so it holds only what differs, as
config/quick.yaml does. Each configuration writes under its own `output_root`.
"""

from pathlib import Path


report: "report/workflow.rst"


# Reads config/config.yaml and lays what --configfile and --config give over it, then checks the result.
include: "rules/common.smk"


# Every configuration writes under its own root (relative to this checkout; --directory takes precedence), so
# the quick run never touches the full run's files. Absolute, because a cluster job parses the workflow again
# from a directory already inside the root (the SLURM plugin's job step starts in it) and would apply a relative
# root a second time.
workdir: Path(workflow.basedir) / config["output_root"]


# In the output root: a killed run's locks removed, damaged results and claims tables of results that are gone
# marked for rebuilding (rules/common.smk).
remove_stale_locks()
DAMAGED = rebuild_what_is_not_current()


include: "rules/sticky.smk"
include: "rules/ltp.smk"
include: "rules/blob.smk"
include: "rules/cross.smk"
include: "rules/registry.smk"
include: "rules/report.smk"
include: "rules/robustness.smk"


rule all:
    """Every figure, the claims table, its Markdown summary, the executed notebooks, the PDF and the pages
    of the browsable report (`snakemake --report report.zip`)."""
    default_target: True
    input:
        STICKY_FIGURES,
        LTP_FIGURES,
        BLOB_FIGURES,
        CROSS_FIGURES,
        "results/claims.csv",
        "results/claims.md",
        NOTEBOOKS,
        "results/versions.md",
        MANUSCRIPT,
        REPORT_PAGE_FILES,
        NOTEBOOK_PAGES,
        "results/verdicts.txt",


rule sticky:
    """The sticky paper alone: its figures, claims and notebook."""
    input:
        STICKY_FIGURES,
        "results/sticky/claims.csv",
        "notebooks/executed/sticky.ipynb",


rule ltp:
    """The LTP paper alone: its figures, claims and notebook."""
    input:
        LTP_FIGURES,
        "results/ltp/claims.csv",
        "notebooks/executed/ltp.ipynb",


rule blob:
    """The blob paper alone: its figures, claims and notebook."""
    input:
        BLOB_FIGURES,
        "results/blob/claims.csv",
        "notebooks/executed/blob.ipynb",


rule cross:
    """The cross-method comparison alone: its figures, claims and notebook."""
    input:
        CROSS_FIGURES,
        "results/cross/claims.csv",
        "notebooks/executed/cross.ipynb",


onsuccess:
    if not LATEX:
        print(LATEX_HELP)
