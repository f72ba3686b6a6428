"""Jourdain and Reygner: sticky particle dynamics (SPD) and multitype SPD, Figures 1-7."""

STICKY = config["sticky"]
RAREFACTION, SHOCKS = STICKY["psystem"]["rarefaction"], STICKY["psystem"]["shocks"]
STICKY_CAPTIONS = {
    "fig1": (
        "One iteration of the Brenier-Grenier hull algorithm (section 5.1.1): the list L before the iteration, the removal of a concave corner, and L after it."
    ),
    "fig2": (
        f"Burgers equation from (delta_-1 + delta_1)/2: (a) trajectories of {STICKY['fig2']['trajectory_particles']} particles, (b) u(t, x), (c) profiles at t = {listing(STICKY['fig2']['profile_times'])} with the exact fans dashed, (d) log L1 error against p for n = 2^p, t = {listing(STICKY['fig2']['error_times'])}: slope -log 2."
    ),
    "fig3": (
        f"Concave flux u(1-u)/2 from the Laplace law: (a) {STICKY['fig3']['trajectory_particles']} trajectories, (b) u(t, x), (c) profiles at t = {listing(STICKY['fig3']['profile_times'])} with the exact solution, (d) log L1 error against p, t = {listing(STICKY['fig3']['error_times'])}: plateau, then log(n)/n decay."
    ),
    "fig4": (
        f"p-system, w0+ >= w0- (x0 = {RAREFACTION['x0']}): MSPD trajectories by the iterated TSPD (Delta = {RAREFACTION['delta']}), {RAREFACTION['trajectory_particles']} particles per type; no same-type collision."
    ),
    "fig5": (
        f"p-system, w0+ >= w0-: w-, w+, specific volume u and velocity v in the space-time plane (n = {RAREFACTION['field_particles']} per type, Delta = {RAREFACTION['delta']})."
    ),
    "fig6": (
        f"p-system with shocks (x0 = {SHOCKS['x0']}, w0+ = 1{{x >= 0}}): trajectories, {SHOCKS['trajectory_particles']} per type (Delta = {SHOCKS['delta']}); the + cluster forms, then breaks up after crossing."
    ),
    "fig7": (
        f"p-system with shocks: w-, w+, u and v in the space-time plane (n = {SHOCKS['field_particles']} per type, Delta = {SHOCKS['delta']})."
    ),
    "beyond_limits": (
        f"Beyond the paper, p-system at t = {STICKY['beyond']['t']}: (a, b) w- and w+ of the exact MSPD (n = {STICKY['beyond']['limit_n'][-1]} per type), the conservative HLL scheme and the upwind scheme for (1.7) ({STICKY['beyond']['reference_cells']} cells), rarefaction and shock cases; (c) W1 distance of the exact MSPD to both schemes against n, with each reference's distance to its half-resolution run."
    ),
    "beyond_cost": (
        "Beyond the paper, the cost argument of section 5.2: error against operation count (top) and wall time (bottom); SPD and Godunov on the scalar cases of Figures 2 and 3, iterated TSPD (L = n), exact MSPD and upwind scheme for (1.7) on the two p-system cases. Dotted: error proportional to work^-1 (steep) and work^-1/2."
    ),
}


# Figures 4-7 show two p-system runs: figure -> (case, panel kind).
PSYSTEM_FIGURES = {
    "fig4": ("rarefaction", "trajectories"),
    "fig5": ("rarefaction", "fields"),
    "fig6": ("shocks", "trajectories"),
    "fig7": ("shocks", "fields"),
}
STICKY_FIGURES = expand(
    "figures/sticky/{name}.{ext}",
    name=[f"fig{number}" for number in range(1, 8)] + ["beyond_limits", "beyond_cost"],
    ext=["pdf", "png"],
)


rule sticky_fig1:
    """Figure 1: one iteration of the hull algorithm on a small random example."""
    input:
        code=imports("sticky/plot_fig1.py"),
    output:
        **figure("figures/sticky/fig1"),
    log:
        "logs/sticky/fig1.log",
    benchmark:
        "logs/benchmarks/sticky_fig1.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(STICKY_CAPTIONS, "fig1"),
        cfg=STICKY["fig1"],
    script:
        "../scripts/sticky/plot_fig1.py"


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


rule sticky_scalar_figure:
    """Figures 2 and 3: plot panels (a)-(d) from the cached results."""
    input:
        data="results/sticky/{figure}.npz",
        code=imports("sticky/plot_scalar.py"),
    output:
        **figure("figures/sticky/{figure}"),
    log:
        "logs/sticky/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/sticky_scalar_figure_{figure}.tsv"
    wildcard_constraints:
        figure="fig2|fig3",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(STICKY_CAPTIONS),
        case=lambda wildcards: STICKY[wildcards.figure]["case"],
    script:
        "../scripts/sticky/plot_scalar.py"


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


rule sticky_psystem_figure:
    """Figures 4 and 6 (trajectories), 5 and 7 (w-, w+, u, v) from the cached runs."""
    input:
        data=lambda wildcards: f"results/sticky/psystem_{PSYSTEM_FIGURES[wildcards.figure][0]}.npz",
        code=imports("sticky/plot_psystem.py"),
    output:
        **figure("figures/sticky/{figure}"),
    log:
        "logs/sticky/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/sticky_psystem_figure_{figure}.tsv"
    wildcard_constraints:
        figure="fig4|fig5|fig6|fig7",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(STICKY_CAPTIONS),
        case=lambda wildcards: PSYSTEM_FIGURES[wildcards.figure][0],
        kind=lambda wildcards: PSYSTEM_FIGURES[wildcards.figure][1],
        x0=lambda wildcards: STICKY["psystem"][PSYSTEM_FIGURES[wildcards.figure][0]]["x0"],
    script:
        "../scripts/sticky/plot_psystem.py"


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


rule sticky_beyond_figure:
    """Beyond the paper: the limits and the work-precision diagrams from the cached study."""
    input:
        data="results/sticky/beyond.npz",
        code=imports("sticky/plot_beyond.py"),
    output:
        **figure("figures/sticky/{figure}"),
    log:
        "logs/sticky/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/sticky_beyond_figure_{figure}.tsv"
    wildcard_constraints:
        figure="beyond_limits|beyond_cost",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(STICKY_CAPTIONS),
        cfg=STICKY["beyond"],
    script:
        "../scripts/sticky/plot_beyond.py"


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
