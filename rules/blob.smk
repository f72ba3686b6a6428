"""Craig and Bertozzi: the blob method for the aggregation equation, Figures 1-4 (1D) and 5-8 (2D)."""

BLOB = config["blob"]
BLOB_CAPTIONS = {
    "fig1": (
        f"Blob method, m = {BLOB['fig1']['order']}, delta = h^{BLOB['fig1']['q']}, K = |x|/2, data (4.3): trajectories, densities at t = {listing(BLOB['fig1']['density_times'])}, zoom near t = 1, and L1_h errors against h at t = {BLOB['fig1']['error_t']}."
    ),
    "fig2": (
        "Particle method (grad K(0) = 0), same data: trajectories (straight lines), zoom, and trajectory errors against h."
    ),
    "fig3": (
        "Blob method for the discontinuous data (4.4): trajectories, rounded densities, zoom and slower convergence."
    ),
    "fig4": (
        f"L1_h errors at t = {BLOB['fig4']['t']} for data (4.5): K = -|x|/2 and |x|^3/3; particle method, m = 4 and m = 6."
    ),
    "fig4log": (
        f"Figure 4's first row read as its label writes it, K = -log|x|/(2 pi) (its caption and text say (-Delta)^(-1)): L1_h errors at t = {BLOB['fig4']['t']} against an m = 6 reference on a grid {BLOB['fig4']['log_reading']['reference_factor']} times finer."
    ),
    "fig5": (
        f"2D, K = log|x|/(2 pi): L1_h errors at t = {BLOB['fig5']['t']} for the blob method with regular data, the particle method, and the blob method with the indicator of the disk."
    ),
    "fig6": (
        f"2D blob method for log|x|/(2 pi), |x|^2/2, |x|^3/3: {BLOB['fig6']['top']['trajectories']} trajectories and the density at t = {BLOB['fig6']['top']['t_density']} (bump data), star patch density at t = {BLOB['fig6']['bottom']['t']} from the side and from above."
    ),
    "fig7": (
        f"2D particle (top) and blob (bottom, delta = {BLOB['fig7']['delta']}) end states for |x|^4/4 - log|x|/(2 pi), |x|^4/4 - |x|^1.5/1.5 and |x|^7/7 - |x|^1.5/1.5."
    ),
    "fig8": (
        f"2D particle (top) and blob (bottom, delta = {BLOB['fig8']['delta']}) end states for the Morse kernels e^-|x| - 2e^-|x|/2 and 2e^-|x| - 2e^-|x|/2, data (4.7) and the star patch."
    ),
    "repulsive": (
        f"K = -|x|/2, data (4.5), t = {BLOB['fig4']['t']}, q = {BLOB['fig4']['q']}: density error of the blob method (m = 4, 6) split into its quadrature and regularisation parts, with the model of the quadrature part fitted on the paper's h and the runs extended to h = 1/{BLOB['fig4']['repulsive']['extra_inverse_h'][-1]}."
    ),
}

# Figure 4 (fig4) and the reading of its row label, K = -log|x|/(2 pi) (fig4log).
BLOB_FIG4_STUDIES = {
    "fig4": BLOB["fig4"],
    "fig4log": {
        **BLOB["fig4"],
        **BLOB["fig4"]["log_reading"],
        "kernels": ["log_repulsive"],
        "diagnostic_q": None,
    },
}

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

BLOB_FIGURES = expand(
    "figures/blob/{name}.{ext}",
    name=[*(f"fig{number}" for number in range(1, 9)), "fig4log", "repulsive"],
    ext=["pdf", "png"],
)
BLOB_COMPARE_TITLES = {
    "fig7": "Repulsive-attractive power kernels, data (4.7): particle (top) and blob (bottom) methods",
    "fig8": "Morse kernels, data (4.7) and star patch (4.6): particle (top) and blob (bottom) methods",
}
BLOB_TITLES = {
    "fig1": "Blob method (m = 4, delta = h^0.9), K = |x|/2, data (4.3)",
    "fig2": "Particle method (grad K(0) = 0), K = |x|/2, data (4.3)",
    "fig3": "Blob method (m = 4, delta = h^0.9), K = |x|/2, discontinuous data (4.4)",
}


rule blob_newtonian_data:
    """Figures 1-3: blob or particle runs against exact solutions, errors against h."""
    input:
        code=imports("blob/newtonian_data.py"),
    output:
        "results/blob/{figure}.npz",
    log:
        "logs/blob/{figure}_data.log",
    benchmark:
        "logs/benchmarks/blob_newtonian_data_{figure}.tsv"
    wildcard_constraints:
        figure="fig1|fig2|fig3",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=lambda wildcards: BLOB[wildcards.figure],
    script:
        "../scripts/blob/newtonian_data.py"


rule blob_newtonian_figure:
    """Figures 1-3 from the cached runs."""
    input:
        data="results/blob/{figure}.npz",
        code=imports("blob/plot_newtonian.py"),
    output:
        **figure("figures/blob/{figure}"),
    log:
        "logs/blob/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/blob_newtonian_figure_{figure}.tsv"
    wildcard_constraints:
        figure="fig1|fig2|fig3",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS),
        title=lambda wildcards: BLOB_TITLES[wildcards.figure],
    script:
        "../scripts/blob/plot_newtonian.py"


rule blob_fig4_data:
    """Figure 4: particle, m = 4 and m = 6 errors for two kernels; the same for the row label's kernel."""
    input:
        code=imports("blob/fig4_data.py"),
    output:
        "results/blob/{figure}.npz",
    log:
        "logs/blob/{figure}_data.log",
    benchmark:
        "logs/benchmarks/blob_fig4_data_{figure}.tsv"
    wildcard_constraints:
        figure="fig4|fig4log",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=lambda wildcards: BLOB_FIG4_STUDIES[wildcards.figure],
    script:
        "../scripts/blob/fig4_data.py"


rule blob_repulsive_data:
    """Figure 4, K = -|x|/2: the density error split into quadrature and regularisation parts, and
    the runs extended to finer h."""
    input:
        fig4="results/blob/fig4.npz",
        code=imports("blob/repulsive_data.py"),
    output:
        "results/blob/repulsive.npz",
    log:
        "logs/blob/repulsive_data.log",
    benchmark:
        "logs/benchmarks/blob_repulsive_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg={**BLOB["fig4"], **BLOB["fig4"]["repulsive"]},
    script:
        "../scripts/blob/repulsive_data.py"


rule blob_repulsive:
    """Figure: the two parts of the repulsive density error and the model's prediction."""
    input:
        data="results/blob/repulsive.npz",
        code=imports("blob/plot_repulsive.py"),
    output:
        **figure("figures/blob/repulsive"),
    log:
        "logs/blob/repulsive_plot.log",
    benchmark:
        "logs/benchmarks/blob_repulsive.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS, "repulsive"),
    script:
        "../scripts/blob/plot_repulsive.py"


rule blob_fig4:
    """Figure 4 (and the row label's reading) from the cached runs."""
    input:
        data="results/blob/{figure}.npz",
        code=imports("blob/plot_fig4.py"),
    output:
        **figure("figures/blob/{figure}"),
    log:
        "logs/blob/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/blob_fig4_{figure}.tsv"
    wildcard_constraints:
        figure="fig4|fig4log",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS),
    script:
        "../scripts/blob/plot_fig4.py"


rule blob_claims:
    """Measure every blob claim of Figures 1-8 from the cached results; record every fitted rate."""
    input:
        fig1="results/blob/fig1.npz",
        fig2="results/blob/fig2.npz",
        fig3="results/blob/fig3.npz",
        fig4="results/blob/fig4.npz",
        fig4log="results/blob/fig4log.npz",
        fig5="results/blob/fig5.npz",
        fig6="results/blob/fig6.npz",
        fig7="results/blob/fig7.npz",
        fig8="results/blob/fig8.npz",
        repulsive="results/blob/repulsive.npz",
        code=imports("blob/claims.py"),
    output:
        claims="results/blob/claims.csv",
        rates="results/blob/rates.json",
    log:
        "logs/blob/claims.log",
    benchmark:
        "logs/benchmarks/blob_claims.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=BLOB,
    script:
        "../scripts/blob/claims.py"


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


rule blob_fig5:
    """Figure 5 from the cached runs."""
    input:
        data="results/blob/fig5.npz",
        code=imports("blob/plot_fig5.py"),
    output:
        **figure("figures/blob/fig5"),
    log:
        "logs/blob/fig5_plot.log",
    benchmark:
        "logs/benchmarks/blob_fig5.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS, "fig5"),
    script:
        "../scripts/blob/plot_fig5.py"


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
    script:
        "../scripts/blob/fig5_orders.py"


rule blob_fig6_data:
    """Figure 6: 2D blob runs for the Newtonian, quadratic and cubic kernels."""
    input:
        code=imports("blob/fig6_data.py"),
    output:
        "results/blob/fig6.npz",
    log:
        "logs/blob/fig6_data.log",
    benchmark:
        "logs/benchmarks/blob_fig6_data.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=BLOB["fig6"],
    script:
        "../scripts/blob/fig6_data.py"


rule blob_fig6:
    """Figure 6 from the cached runs."""
    input:
        data="results/blob/fig6.npz",
        code=imports("blob/plot_fig6.py"),
    output:
        **figure("figures/blob/fig6"),
    log:
        "logs/blob/fig6_plot.log",
    benchmark:
        "logs/benchmarks/blob_fig6.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS, "fig6"),
        shown=BLOB["fig6"]["top"]["trajectories"],
    script:
        "../scripts/blob/plot_fig6.py"


rule blob_compare_data:
    """Figures 7 and 8: particle and blob runs for repulsive-attractive kernels in 2D."""
    input:
        code=imports("blob/compare_data.py"),
    output:
        "results/blob/{figure}.npz",
    log:
        "logs/blob/{figure}_data.log",
    benchmark:
        "logs/benchmarks/blob_compare_data_{figure}.tsv"
    wildcard_constraints:
        figure="fig7|fig8",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        cfg=lambda wildcards: BLOB[wildcards.figure],
    script:
        "../scripts/blob/compare_data.py"


rule blob_compare_figure:
    """Figures 7 and 8 from the cached runs."""
    input:
        data="results/blob/{figure}.npz",
        code=imports("blob/plot_compare.py"),
    output:
        **figure("figures/blob/{figure}"),
    log:
        "logs/blob/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/blob_compare_figure_{figure}.tsv"
    wildcard_constraints:
        figure="fig7|fig8",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(BLOB_CAPTIONS),
        title=lambda wildcards: BLOB_COMPARE_TITLES[wildcards.figure],
    script:
        "../scripts/blob/plot_compare.py"
