"""The repository-wide claims table, its Markdown summary and the verify target."""

CLAIM_SOURCES = ["results/sticky/claims.csv", "results/ltp/claims.csv", "results/blob/claims.csv"]


rule claims_table:
    """Merge every paper's claims into results/claims.csv and results/claims.md."""
    input:
        sources=CLAIM_SOURCES,
        code=[str(PACKAGE / "claims.py")],
    output:
        csv="results/claims.csv",
        markdown="results/claims.md",
    log:
        "logs/claims_table.log",
    shell:
        "python -m particle_methods.claims merge {input.sources} "
        "--csv {output.csv} --markdown {output.markdown} > {log} 2>&1"


rule verify:
    """Exit non-zero when any claim of the table fails (run as `snakemake verify`)."""
    input:
        "results/claims.csv",
    log:
        "logs/verify.log",
    shell:
        "python -m particle_methods.claims verify {input} 2>&1 | tee {log}; exit ${{PIPESTATUS[0]}}"


# Each notebook reads the cached results it plots and the paper's claims.
NOTEBOOK_INPUTS = {
    "sticky": ["results/sticky/fig2.npz", "results/sticky/fig3.npz", "results/sticky/claims.csv"],
    "ltp": ["results/ltp/quadratic.npz", "results/ltp/claims.csv"],
    "blob": ["results/blob/fig4.npz", "results/blob/claims.csv"],
}
NOTEBOOKS = expand("notebooks/executed/{paper}.ipynb", paper=NOTEBOOK_INPUTS)


rule notebook:
    """Execute a paper's jupytext notebook on the cached results and keep the .ipynb copy."""
    input:
        source=str(ROOT / "notebooks" / "{paper}.py"),
        data=lambda wildcards: NOTEBOOK_INPUTS[wildcards.paper],
    output:
        "notebooks/executed/{paper}.ipynb",
    log:
        "logs/notebooks/{paper}.log",
    shell:
        "PARTICLE_METHODS_WORKDIR=$PWD MPLBACKEND=Agg jupytext --to ipynb --execute "
        "--output {output} {input.source} > {log} 2>&1"


rule versions:
    """Record the versions of Python and of every dependency used by this run."""
    input:
        code=[str(PACKAGE / "environment.py")],
    output:
        "results/versions.md",
    log:
        "logs/versions.log",
    shell:
        "python -m particle_methods.environment {output} > {log} 2>&1"
