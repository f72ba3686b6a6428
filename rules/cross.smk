"""One equation, every method: the 1D aggregation equation with K = |x|/2 solved by the sticky
particles, the particle and blob methods, LTP, SP and Godunov's scheme, against its exact solution.
"""

CROSS = config["cross"]
CROSS_FIGURES = registry.figure_outputs("cross")


rule cross_claims:
    """Measure every claim of the comparison from the cached results; record every fitted rate; write
    the report's table of errors and times."""
    input:
        study="results/cross/study.npz",
        behaviour="results/cross/behaviour.npz",
        code=imports("cross/claims.py"),
    output:
        claims="results/cross/claims.csv",
        rates="results/cross/rates.json",
        table="results/cross/table.tex",
    log:
        "logs/cross/claims.log",
    benchmark:
        "logs/benchmarks/cross_claims.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=CROSS,
    script:
        "../scripts/cross/claims.py"
