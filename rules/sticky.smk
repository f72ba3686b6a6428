"""Jourdain and Reygner: sticky particle dynamics (SPD) and multitype SPD, Figures 1-7."""

STICKY = config["sticky"]
STICKY_FIGURES = registry.figure_outputs("sticky")


rule sticky_scalar_data:
    """Figures 2 and 3: SPD trajectories, u(t, x), profiles and exact L1 errors."""
    input:
        code=imports("sticky/scalar_data.py"),
    output:
        "results/sticky/{figure}.npz",
    log:
        "logs/sticky/{figure}_data.log",
    benchmark:
        "logs/benchmarks/sticky_scalar_data_{figure}.tsv"
    wildcard_constraints:
        figure="fig2|fig3",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=lambda wildcards: STICKY[wildcards.figure],
    script:
        "../scripts/sticky/scalar_data.py"


rule sticky_psystem_data:
    """Figures 4-7: iterated TSPD for the p-system, trajectories and space-time fields."""
    input:
        code=imports("sticky/psystem_data.py"),
    output:
        "results/sticky/psystem_{case}.npz",
    log:
        "logs/sticky/psystem_{case}.log",
    benchmark:
        "logs/benchmarks/sticky_psystem_data_{case}.tsv"
    wildcard_constraints:
        case="rarefaction|shocks",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        system=lambda wildcards: {key: STICKY["psystem"][key] for key in ("nu", "kappa")},
        cfg=lambda wildcards: STICKY["psystem"][wildcards.case],
    script:
        "../scripts/sticky/psystem_data.py"


rule sticky_lemma21:
    """Lemma 2.1 and the tail examples: W1 error of the discretisation (2.1)."""
    input:
        code=imports("sticky/lemma21_data.py"),
    output:
        "results/sticky/lemma21.npz",
    log:
        "logs/sticky/lemma21.log",
    benchmark:
        "logs/benchmarks/sticky_lemma21.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=STICKY["lemma21"],
    script:
        "../scripts/sticky/lemma21_data.py"


rule sticky_remark33:
    """Remark 3.3: exact t/(4n) error from one Dirac mass; SPD vs front tracking."""
    input:
        code=imports("sticky/remark33_data.py"),
    output:
        "results/sticky/remark33.npz",
    log:
        "logs/sticky/remark33.log",
    benchmark:
        "logs/benchmarks/sticky_remark33.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=STICKY["remark33"],
    script:
        "../scripts/sticky/remark33_data.py"


rule sticky_tspd_convergence:
    """Theorem 4.4: iterated TSPD errors, Delta sweep at fixed n and n sweep at small Delta."""
    input:
        code=imports("sticky/tspd_convergence_data.py"),
    output:
        "results/sticky/tspd_convergence.npz",
    log:
        "logs/sticky/tspd_convergence.log",
    benchmark:
        "logs/benchmarks/sticky_tspd_convergence.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        system=lambda wildcards: {key: STICKY["psystem"][key] for key in ("nu", "kappa")},
        cases=lambda wildcards: {
            case: STICKY["psystem"][case] for case in ("rarefaction", "shocks")
        },
        cfg=STICKY["tspd_convergence"],
    script:
        "../scripts/sticky/tspd_convergence_data.py"


rule sticky_cost:
    """Sections 5.1.1 and 5.2.1: time of the compiled kernels against n and the number of steps.
    Runs alone (all cores reserved) so that the timings are not disturbed by other jobs."""
    input:
        code=imports("sticky/cost_data.py"),
    output:
        "results/sticky/cost.npz",
    log:
        "logs/sticky/cost.log",
    benchmark:
        "logs/benchmarks/sticky_cost.tsv"
    conda:
        ENVIRONMENT
    threads: workflow.cores
    params:
        cfg=STICKY["cost"],
    script:
        "../scripts/sticky/cost_data.py"


rule sticky_beyond_limits:
    """Beyond the paper: the exact MSPD against conservative and upwind finite volumes (untimed)."""
    input:
        code=imports("sticky/beyond_limits.py"),
    output:
        "results/sticky/beyond_limits.npz",
    log:
        "logs/sticky/beyond_limits.log",
    benchmark:
        "logs/benchmarks/sticky_beyond_limits.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        system=lambda wildcards: {key: STICKY["psystem"][key] for key in ("nu", "kappa")},
        cases=lambda wildcards: {
            case: STICKY["psystem"][case] for case in ("rarefaction", "shocks")
        },
        cfg=STICKY["beyond"],
    script:
        "../scripts/sticky/beyond_limits.py"


rule sticky_beyond:
    """Beyond the paper: the cost study (timed runs only), merged with the limits. Runs alone (all
    cores reserved) so that its timings are not disturbed by other jobs."""
    input:
        limits="results/sticky/beyond_limits.npz",
        code=imports("sticky/beyond_data.py"),
    output:
        "results/sticky/beyond.npz",
    log:
        "logs/sticky/beyond.log",
    benchmark:
        "logs/benchmarks/sticky_beyond.tsv"
    conda:
        ENVIRONMENT
    threads: workflow.cores
    params:
        system=lambda wildcards: {key: STICKY["psystem"][key] for key in ("nu", "kappa")},
        cases=lambda wildcards: {
            case: STICKY["psystem"][case] for case in ("rarefaction", "shocks")
        },
        cfg=STICKY["beyond"],
    script:
        "../scripts/sticky/beyond_data.py"


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
