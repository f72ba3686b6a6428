"""One equation, every method: the 1D aggregation equation with K = |x|/2 solved by the sticky
particles, the particle and blob methods, LTP, SP and Godunov's scheme, against its exact solution.
Its rules are generated from its registry (particle_replication.registry.cross, rules/registry.smk)
but for the report's table, written here.
"""

CROSS = config["cross"]
CROSS_FIGURES = registry.figure_outputs("cross")


rule cross_table:
    """The report's table of errors at the largest size and wall times to the target error."""
    input:
        study="results/cross/study.npz",
        code=imports("cross/table.py"),
    output:
        "results/cross/table.tex",
    log:
        "logs/cross/table.log",
    benchmark:
        "logs/benchmarks/cross_table.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=CROSS,
    script:
        "../scripts/cross/table.py"
