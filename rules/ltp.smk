"""Campos Pinto, Carrillo, Charles, Choi: linearly transformed particles, Figures 1-8."""

LTP = config["ltp"]
LTP_CAPTIONS = {
    "fig1": ("The hat shape function (2.12) and its bi-orthogonal kernel (dotted)."),
    "fig2": (
        f"W = x^2 from (6.1), t = {LTP['quadratic']['t']}: exact against LTP densities for several h; LTP L1 and Linf errors against h; SP densities with h = {LTP['quadratic']['sp_h']} and fixed widths eps."
    ),
    "fig3": (
        f"SP against LTP errors, W = x^2: (a) SP errors over eps with the LTP error as reference (h = {LTP['quadratic']['eps_scan']['h']}, dt = {LTP['quadratic']['eps_scan']['dt']}); (b) errors against h with eps = h (dt = {LTP['quadratic']['dt']})."
    ),
    "fig4": (
        f"W = x^2/2 from (6.1), h = {LTP['fig4']['h']}, dt = {LTP['fig4']['dt']}: exact, LTP and SP densities with hat (left) and B3 (right) shapes."
    ),
    "fig5": (
        f"W = |x|^a/a from (6.2), a = {listing(case['a'] for case in LTP['fig5']['cases'])}, h = {LTP['fig5']['h']}, {LTP['fig5']['steps']} steps: potential, density, velocity and particle sizes."
    ),
    "fig6": (
        f"W = |x|^3/3 - |x|^b/b from (6.2), b = {listing(case['b'] for case in LTP['fig6']['cases'])}, h = {LTP['fig6']['h']}, {LTP['fig6']['steps']} steps: potential, density, velocity and particle sizes."
    ),
    "fig7": (
        f"W = {power(LTP['fig7']['a'])} - {power(LTP['fig7']['b'])} from (6.3), {LTP['fig7']['steps']} steps: density snapshots, concentrating on two points."
    ),
    "fig8": (
        f"W = {power(LTP['fig8']['a'])} - {power(LTP['fig8']['b'])} from (6.2), h = {LTP['fig8']['h']}, {LTP['fig8']['steps']} steps up to t = {LTP['fig8']['t']}: SP (eps = {LTP['fig8']['sp_eps']}) and LTP densities at the paper's time and at the SP steady time, and particle sizes."
    ),
    "long_time": (
        f"Long-time measures: the collapse measure of Figure 5, the concentration of Figures 6-7 up to t = {LTP['fig6']['t_long']}, and the peaks of Figure 8 up to t = {LTP['fig8']['t_long']}."
    ),
    "nonaffine": (
        f"W = {power(LTP['nonaffine']['a'])} from (6.1), t = {LTP['nonaffine']['t']}, dt = {LTP['nonaffine']['dt']}: LTP errors against h = {LTP['nonaffine']['reference_h']}; drift of the centre of mass for W = {power(LTP['nonaffine']['centre_of_mass']['a'])} - {power(LTP['nonaffine']['centre_of_mass']['b'])}."
    ),
}

LTP_FIGURES = expand(
    "figures/ltp/{name}.{ext}",
    name=[*(f"fig{number}" for number in range(1, 9)), "long_time", "nonaffine"],
    ext=["pdf", "png"],
)
# Figures 5 and 6 share one layout: rows potential, density, velocity, particle size.
LTP_ROW_TITLES = {
    "fig5": f"LTP, W = |x|^a/a from (6.2), h = {LTP['fig5']['h']}, {LTP['fig5']['steps']} steps",
    "fig6": f"LTP, W = |x|^3/3 - |x|^b/b from (6.2), h = {LTP['fig6']['h']}, {LTP['fig6']['steps']} steps",
}


rule ltp_fig1:
    """Figure 1: the hat shape and its bi-orthogonal kernel."""
    input:
        code=imports("ltp/plot_fig1.py"),
    output:
        **figure("figures/ltp/fig1"),
    log:
        "logs/ltp/fig1.log",
    benchmark:
        "logs/benchmarks/ltp_fig1.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "fig1"),
        cfg=LTP["fig1"],
    script:
        "../scripts/ltp/plot_fig1.py"


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


rule ltp_quadratic_figures:
    """Figures 2 and 3 from the cached W = x^2 runs."""
    input:
        data="results/ltp/quadratic.npz",
        code=imports("ltp/plot_quadratic.py"),
    output:
        fig2_pdf="figures/ltp/fig2.pdf",
        fig2_png=report("figures/ltp/fig2.png", caption=CAPTION, category="ltp", subcategory="fig2"),
        fig3_pdf="figures/ltp/fig3.pdf",
        fig3_png=report("figures/ltp/fig3.png", caption=CAPTION, category="ltp", subcategory="fig3"),
    log:
        "logs/ltp/quadratic_plot.log",
    benchmark:
        "logs/benchmarks/ltp_quadratic_figures.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=" ".join(caption(LTP_CAPTIONS, name) for name in ("fig2", "fig3")),
    script:
        "../scripts/ltp/plot_quadratic.py"


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


rule ltp_fig4:
    """Figure 4 from the cached runs."""
    input:
        data="results/ltp/fig4.npz",
        code=imports("ltp/plot_fig4.py"),
    output:
        **figure("figures/ltp/fig4"),
    log:
        "logs/ltp/fig4_plot.log",
    benchmark:
        "logs/benchmarks/ltp_fig4.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "fig4"),
    script:
        "../scripts/ltp/plot_fig4.py"


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


rule ltp_rows_figure:
    """Figures 5 and 6 from the cached runs."""
    input:
        data="results/ltp/{figure}.npz",
        code=imports("ltp/plot_rows.py"),
    output:
        **figure("figures/ltp/{figure}"),
    log:
        "logs/ltp/{figure}_plot.log",
    benchmark:
        "logs/benchmarks/ltp_rows_figure_{figure}.tsv"
    wildcard_constraints:
        figure="fig5|fig6",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS),
        title=lambda wildcards: LTP_ROW_TITLES[wildcards.figure],
    script:
        "../scripts/ltp/plot_rows.py"


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


rule ltp_fig7:
    """Figure 7 from the cached run."""
    input:
        data="results/ltp/fig7.npz",
        code=imports("ltp/plot_fig7.py"),
    output:
        **figure("figures/ltp/fig7"),
    log:
        "logs/ltp/fig7_plot.log",
    benchmark:
        "logs/benchmarks/ltp_fig7.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "fig7"),
    script:
        "../scripts/ltp/plot_fig7.py"


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


rule ltp_fig8:
    """Figure 8 from the cached runs."""
    input:
        data="results/ltp/fig8.npz",
        code=imports("ltp/plot_fig8.py"),
    output:
        **figure("figures/ltp/fig8"),
    log:
        "logs/ltp/fig8_plot.log",
    benchmark:
        "logs/benchmarks/ltp_fig8.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "fig8"),
    script:
        "../scripts/ltp/plot_fig8.py"


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


rule ltp_nonaffine:
    """Figure: errors against h on the non-affine flow, centre-of-mass drift."""
    input:
        data="results/ltp/nonaffine.npz",
        code=imports("ltp/plot_nonaffine.py"),
    output:
        **figure("figures/ltp/nonaffine"),
    log:
        "logs/ltp/nonaffine_plot.log",
    benchmark:
        "logs/benchmarks/ltp_nonaffine.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "nonaffine"),
    script:
        "../scripts/ltp/plot_nonaffine.py"


rule ltp_long_time:
    """Figure: the long-time measures of Figures 5-8."""
    input:
        fig5="results/ltp/fig5.npz",
        fig6="results/ltp/fig6.npz",
        fig7="results/ltp/fig7.npz",
        fig8="results/ltp/fig8.npz",
        code=imports("ltp/plot_long_time.py"),
    output:
        **figure("figures/ltp/long_time"),
    log:
        "logs/ltp/long_time_plot.log",
    benchmark:
        "logs/benchmarks/ltp_long_time.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        caption=caption(LTP_CAPTIONS, "long_time"),
        cfg=LTP,
    script:
        "../scripts/ltp/plot_long_time.py"


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
