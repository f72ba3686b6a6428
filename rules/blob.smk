"""Craig and Bertozzi: the blob method for the aggregation equation, Figures 1-4 (1D)."""

BLOB = config["blob"]
BLOB_FIGURES = expand("figures/blob/fig{number}.{ext}", number=range(1, 5), ext=["pdf", "png"])
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
    wildcard_constraints:
        figure="fig1|fig2|fig3",
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
    wildcard_constraints:
        figure="fig1|fig2|fig3",
    params:
        title=lambda wildcards: BLOB_TITLES[wildcards.figure],
    script:
        "../scripts/blob/plot_newtonian.py"


rule blob_fig4_data:
    """Figure 4: particle, m = 4 and m = 6 errors for two kernels."""
    input:
        code=imports("blob/fig4_data.py"),
    output:
        "results/blob/fig4.npz",
    log:
        "logs/blob/fig4_data.log",
    params:
        cfg=BLOB["fig4"],
    script:
        "../scripts/blob/fig4_data.py"


rule blob_fig4:
    """Figure 4 from the cached runs."""
    input:
        data="results/blob/fig4.npz",
        code=imports("blob/plot_fig4.py"),
    output:
        **figure("figures/blob/fig4"),
    log:
        "logs/blob/fig4_plot.log",
    script:
        "../scripts/blob/plot_fig4.py"


rule blob_claims:
    """Measure every blob claim of Figures 1-4 from the cached results."""
    input:
        fig1="results/blob/fig1.npz",
        fig2="results/blob/fig2.npz",
        fig3="results/blob/fig3.npz",
        fig4="results/blob/fig4.npz",
        code=imports("blob/claims.py"),
    output:
        "results/blob/claims.csv",
    log:
        "logs/blob/claims.log",
    script:
        "../scripts/blob/claims.py"
