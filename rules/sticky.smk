"""Jourdain and Reygner: sticky particle dynamics (SPD) and multitype SPD, Figures 1-7."""

STICKY = config["sticky"]
STICKY_FIGURES = registry.figure_outputs("sticky")


rule sticky_claims:
    """Measure every sticky claim from the cached results; record every fitted rate."""
    input:
        burgers="results/sticky/fig2.npz",
        concave="results/sticky/fig3.npz",
        rarefaction="results/sticky/psystem_rarefaction.npz",
        shocks="results/sticky/psystem_shocks.npz",
        lemma21="results/sticky/lemma21.npz",
        remark33="results/sticky/remark33.npz",
        tspd="results/sticky/tspd_convergence.npz",
        cost="results/sticky/cost.npz",
        beyond="results/sticky/beyond.npz",
        code=imports("sticky/claims.py"),
    output:
        claims="results/sticky/claims.csv",
        rates="results/sticky/rates.json",
    log:
        "logs/sticky/claims.log",
    benchmark:
        "logs/benchmarks/sticky_claims.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=STICKY,
    script:
        "../scripts/sticky/claims.py"
