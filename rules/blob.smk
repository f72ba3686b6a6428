"""Craig and Bertozzi: the blob method for the aggregation equation, Figures 1-4 (1D) and 5-8 (2D). Its
rules are generated from its registry (particle_replication.registry.blob, rules/registry.smk) but for
Figure 5's runs, which this file groups into jobs by grid size."""

BLOB = config["blob"]
BLOB_FIGURES = registry.figure_outputs("blob")

# Figure 5's runs in jobs: 1/h below FIG5_OWN_JOB together (up to 5,000 particles: 2 to 11 s), each finer grid
# alone (20,000 particles and more: tens of seconds to minutes), in the order of the config's inverse_h.
FIG5_OWN_JOB = 80
FIG5_GROUPS = {
    **(
        {"coarse": [n for n in BLOB["fig5"]["inverse_h"] if n < FIG5_OWN_JOB]}
        if min(BLOB["fig5"]["inverse_h"]) < FIG5_OWN_JOB
        else {}
    ),
    **{f"h{n}": [n] for n in BLOB["fig5"]["inverse_h"] if n >= FIG5_OWN_JOB},
}
# What one run reads from the config: a new grid step leaves the other runs alone.
FIG5_RUN = {key: BLOB["fig5"][key] for key in ("kernel", "cases", "t", "q", "rtol", "atol")}


rule blob_fig5_case:
    """Figure 5, one of its cases (blob or particle method, regular or disk data) on a group of grids:
    the coarse ones together, each fine one alone, so that the long runs share the cores with every
    other job."""
    input:
        code=imports("blob/fig5_data.py"),
    output:
        "results/blob/fig5/case{index}_{group}.npz",
    log:
        "logs/blob/fig5_case{index}_{group}.log",
    benchmark:
        "logs/benchmarks/blob_fig5_case_{group}_{index}.tsv"
    wildcard_constraints:
        index=r"\d+",
        group="|".join(FIG5_GROUPS),
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=FIG5_RUN,
        index=lambda wildcards: int(wildcards.index),
        inverse_h=lambda wildcards: FIG5_GROUPS[wildcards.group],
        nudge=config["nudge"],
    script:
        "../scripts/blob/fig5_data.py"


rule blob_fig5_data:
    """Figure 5: the errors of its runs in one result, case by case."""
    input:
        runs=expand(
            "results/blob/fig5/case{index}_{group}.npz",
            index=range(len(BLOB["fig5"]["cases"])),
            group=FIG5_GROUPS,
        ),
        code=imports("blob/fig5_merge.py"),
    output:
        "results/blob/fig5.npz",
    log:
        "logs/blob/fig5_data.log",
    benchmark:
        "logs/benchmarks/blob_fig5_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=BLOB["fig5"],
    script:
        "../scripts/blob/fig5_merge.py"


rule blob_fig5_orders:
    """Figure 5's pairwise orders for the report, with those of the opt-in overlay
    config/fig5-extended.yaml when its results exist (rerun this rule after running the overlay)."""
    input:
        data="results/blob/fig5.npz",
        code=imports("blob/fig5_orders.py"),
    output:
        "results/blob/fig5_orders.tex",
    log:
        "logs/blob/fig5_orders.log",
    benchmark:
        "logs/benchmarks/blob_fig5_orders.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        extended=source(ROOT / "runs" / "fig5-extended" / "results" / "blob" / "fig5.npz"),
        extended_finest=max(
            read_yaml(ROOT / "config" / "fig5-extended.yaml")["blob"]["fig5"]["inverse_h"]
        ),
    script:
        "../scripts/blob/fig5_orders.py"
