"""Rebuild every figure and checked claim of the three papers.

snakemake --cores 2                                     # full resolution
snakemake --cores 2 --configfile config/quick.yaml      # coarse, for tests and CI
snakemake verify                                        # fails when a claim fails
"""

from pathlib import Path


configfile: str(Path(workflow.basedir) / "config" / "config.yaml")


report: "report/workflow.rst"


include: "rules/common.smk"
include: "rules/sticky.smk"
include: "rules/ltp.smk"
include: "rules/blob.smk"
include: "rules/report.smk"


rule all:
    """Every figure, the claims table, its Markdown summary and the executed notebooks."""
    default_target: True
    input:
        STICKY_FIGURES,
        LTP_FIGURES,
        BLOB_FIGURES,
        "results/claims.csv",
        "results/claims.md",
        NOTEBOOKS,
        "results/versions.md",
        MANUSCRIPT,


onsuccess:
    if not LATEX:
        print(LATEX_HELP)
