"""Campos Pinto, Carrillo, Charles, Choi: linearly transformed particles, Figures 1-8."""

LTP = config["ltp"]
LTP_FIGURES = registry.figure_outputs("ltp")


rule ltp_quadratic_data:
    """Figures 2 and 3: LTP and SP runs for W = x^2 against the exact solution (6.4)."""
    input:
        code=imports("ltp/quadratic_data.py"),
    output:
        "results/ltp/quadratic.npz",
    log:
        "logs/ltp/quadratic.log",
    benchmark:
        "logs/benchmarks/ltp_quadratic_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP["quadratic"],
    script:
        "../scripts/ltp/quadratic_data.py"


rule ltp_fig4_data:
    """Figure 4: LTP and SP with hat and B3 shapes for W = x^2/2."""
    input:
        code=imports("ltp/fig4_data.py"),
    output:
        "results/ltp/fig4.npz",
    log:
        "logs/ltp/fig4_data.log",
    benchmark:
        "logs/benchmarks/ltp_fig4_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP["fig4"],
    script:
        "../scripts/ltp/fig4_data.py"


rule ltp_rows_data:
    """Figures 5 and 6: LTP runs with power and attractive-repulsive potentials."""
    input:
        code=imports("ltp/rows_data.py"),
    output:
        "results/ltp/{figure}.npz",
    log:
        "logs/ltp/{figure}_data.log",
    benchmark:
        "logs/benchmarks/ltp_rows_data_{figure}.tsv"
    wildcard_constraints:
        figure="fig5|fig6",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=lambda wildcards: LTP[wildcards.figure],
        concentration=LTP["concentration"],
    script:
        "../scripts/ltp/rows_data.py"


rule ltp_fig7_data:
    """Figure 7: density snapshots from (6.3)."""
    input:
        code=imports("ltp/fig7_data.py"),
    output:
        "results/ltp/fig7.npz",
    log:
        "logs/ltp/fig7_data.log",
    benchmark:
        "logs/benchmarks/ltp_fig7_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP["fig7"],
        concentration=LTP["concentration"],
    script:
        "../scripts/ltp/fig7_data.py"


rule ltp_fig8_data:
    """Figure 8: SP and LTP end states."""
    input:
        code=imports("ltp/fig8_data.py"),
    output:
        "results/ltp/fig8.npz",
    log:
        "logs/ltp/fig8_data.log",
    benchmark:
        "logs/benchmarks/ltp_fig8_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP["fig8"],
    script:
        "../scripts/ltp/fig8_data.py"


rule ltp_nonaffine_data:
    """Convergence on a flow that is not affine; centre of mass on asymmetric data."""
    input:
        code=imports("ltp/nonaffine_data.py"),
    output:
        "results/ltp/nonaffine.npz",
    log:
        "logs/ltp/nonaffine_data.log",
    benchmark:
        "logs/benchmarks/ltp_nonaffine_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP["nonaffine"],
    script:
        "../scripts/ltp/nonaffine_data.py"


rule ltp_claims:
    """Measure every LTP claim from the cached results; record every fitted rate."""
    input:
        quadratic="results/ltp/quadratic.npz",
        fig4="results/ltp/fig4.npz",
        fig5="results/ltp/fig5.npz",
        fig6="results/ltp/fig6.npz",
        fig7="results/ltp/fig7.npz",
        fig8="results/ltp/fig8.npz",
        nonaffine="results/ltp/nonaffine.npz",
        code=imports("ltp/claims.py"),
    output:
        claims="results/ltp/claims.csv",
        rates="results/ltp/rates.json",
    log:
        "logs/ltp/claims.log",
    benchmark:
        "logs/benchmarks/ltp_claims.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=LTP,
    script:
        "../scripts/ltp/claims.py"
