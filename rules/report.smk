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
