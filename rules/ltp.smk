"""Campos Pinto, Carrillo, Charles, Choi: linearly transformed particles, Figures 1-8."""

LTP = config["ltp"]
LTP_FIGURES = registry.figure_outputs("ltp")


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
