"""The robustness run (`snakemake --cores 2 robustness`): every claim recomputed under the variants of the
config's `robustness.variants` (particle_replication.robustness), each in a Snakemake run of its own under
robustness/<variant>/, then compared with this run's claims: a verdict that differs fails the target.
"""

ROBUSTNESS = config["robustness"]
VARIANTS = ROBUSTNESS["variants"]
# Every source a variant's run may use: a change reruns the variants, whose own runs redo only what it touches.
ROBUSTNESS_CODE = sorted(
    source(path)
    for folder, pattern in [
        (PACKAGE, "*.py"),
        (REPLICATION, "*.py"),
        (ROOT / "scripts", "*.py"),
        (ROOT / "rules", "*.smk"),
    ]
    for path in folder.rglob(pattern)
    if "__pycache__" not in path.parts
) + [source(ROOT / "Snakefile")]


rule robustness_variant:
    """The claims table of one variant, from a Snakemake run of its own in robustness/<variant>/ (on every core,
    alone: the load variant spins on all of them)."""
    input:
        code=ROBUSTNESS_CODE,
    output:
        "robustness/{variant}/results/claims.csv",
    log:
        "logs/robustness/{variant}.log",
    wildcard_constraints:
        variant="|".join(VARIANTS),
    conda:
        ENVIRONMENT
    threads: workflow.cores
    params:
        variant=lambda wildcards: VARIANTS[wildcards.variant],
        config=config,
        snakefile=str(ROOT / "Snakefile"),
        directory=lambda wildcards: f"robustness/{wildcards.variant}",
    script:
        "../scripts/robustness/variant.py"


rule robustness:
    """Every variant's claims beside this run's: results/robustness.md (the variants, the verdicts that moved,
    the fragile ones) and results/robustness/spreads.yaml (each claim's spread, for config/spreads.yaml); fails
    when a verdict differs in any variant (the report is then in the log)."""
    input:
        baseline="results/claims.csv",
        variants=expand("robustness/{variant}/results/claims.csv", variant=VARIANTS),
        code=source(REPLICATION / "robustness.py"),
    output:
        markdown="results/robustness.md",
        spreads="results/robustness/spreads.yaml",
    log:
        "logs/robustness.log",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        variants=" ".join(
            f"--variant {name}=robustness/{name}/results/claims.csv" for name in VARIANTS
        ),
        run=config["verdicts_run"],
        margin=ROBUSTNESS["margin_min"],
    shell:
        "python -m particle_replication.robustness summarize --baseline {input.baseline} {params.variants} "
        "--run {params.run} --margin-min {params.margin} --markdown {output.markdown} "
        "--spreads {output.spreads} > {log} 2>&1"
