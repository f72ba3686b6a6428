"""One equation, every method: the 1D aggregation equation with K = |x|/2 solved by the sticky
particles, the particle and blob methods, LTP, SP and Godunov's scheme, against its exact solution.
"""

CROSS = config["cross"]
CROSS_FIGURES = registry.figure_outputs("cross")


rule cross_errors:
    """Every method at every size on both data and times, each run once: W1 errors and diagnostics."""
    input:
        code=imports("cross/study_data.py"),
    output:
        "results/cross/study_errors.npz",
    log:
        "logs/cross/study_errors.log",
    benchmark:
        "logs/benchmarks/cross_errors.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=CROSS,
        part="errors",
    script:
        "../scripts/cross/study_data.py"


rule cross_study:
    """The same runs timed, merged with their errors. It takes every core, so that no other rule runs
    while it times."""
    input:
        errors="results/cross/study_errors.npz",
        code=imports("cross/study_data.py"),
    output:
        "results/cross/study.npz",
    log:
        "logs/cross/study.log",
    benchmark:
        "logs/benchmarks/cross_study.tsv"
    conda:
        ENVIRONMENT
    threads: workflow.cores
    params:
        cfg=CROSS,
        part="times",
    script:
        "../scripts/cross/study_data.py"


rule cross_behaviour:
    """The particle method against the weighted SPD and past its first collision; LTP at the blow-up."""
    input:
        code=imports("cross/behaviour_data.py"),
    output:
        "results/cross/behaviour.npz",
    log:
        "logs/cross/behaviour.log",
    benchmark:
        "logs/benchmarks/cross_behaviour.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=CROSS,
    script:
        "../scripts/cross/behaviour_data.py"


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
