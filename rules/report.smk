"""The repository-wide claims table and its Markdown summary, the verify target, the notebooks,
the software versions and the LaTeX report."""

import os
import shutil

from particle_replication.configuration import compared_run
from particle_replication.environment import commit

PAPERS = list(registry.PAPERS)
CLAIM_SOURCES = expand("results/{paper}/claims.csv", paper=PAPERS)
RATE_SOURCES = expand("results/{paper}/rates.json", paper=PAPERS)
VERDICTS = source(ROOT / config["verdicts"])
SPREADS = source(ROOT / config["robustness"]["spreads"])
MARGIN_MIN = config["robustness"]["margin_min"]
COMMIT = commit()
# The repository's run whose expected verdicts and spreads apply (None for a configuration of the user's own,
# with the keys in which it differs from the run its verdicts_run names).
COMPARED, DIFFERS = compared_run(config)
# How verify and the verdicts rule are told which verdicts to compare (none for a user's own configuration).
COMPARISON = (
    f"--run {COMPARED}" if COMPARED else "--differs " + " ".join(DIFFERS)
) + f" --margin-min {MARGIN_MIN}"


rule claims_table:
    """Merge every paper's claims into results/claims.csv and results/claims.md (with the failures by
    cause, from the expected verdicts) and every paper's fitted rates into results/rates.json."""
    input:
        sources=CLAIM_SOURCES,
        rates=RATE_SOURCES,
        expected=VERDICTS,
        spreads=SPREADS,
        code=[source(REPLICATION / "claims.py"), source(REPLICATION / "rates.py")],
    output:
        csv="results/claims.csv",
        markdown="results/claims.md",
        rates="results/rates.json",
    log:
        "logs/claims_table.log",
    benchmark:
        "logs/benchmarks/claims_table.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        run=config["verdicts_run"],
        # The spreads were measured on the repository's own runs: none apply to another configuration.
        spreads=f"--spreads {SPREADS}" if COMPARED else "",
        margin=MARGIN_MIN,
    shell:
        "python -m particle_replication.claims merge {input.sources} --rates {input.rates} "
        "--csv {output.csv} --markdown {output.markdown} --rates-output {output.rates} "
        "--expected {input.expected} --run {params.run} {params.spreads} --margin-min {params.margin} "
        "> {log} 2>&1"


rule verify:
    """Exit non-zero when a verdict differs from the expected verdicts of the config's `verdicts`
    file (a claim it does not list is expected to pass) or when a listed claim is missing (run as
    `snakemake verify`); print the paper claims with published and measured values. Refuses a claims table
    not built from the current results (current_claims_table)."""
    input:
        current_claims_table,
        claims="results/claims.csv",
        expected=VERDICTS,
    log:
        "logs/verify.log",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        comparison=COMPARISON,
    shell:
        "python -m particle_replication.claims verify {input.claims} --expected {input.expected} "
        "{params.comparison} 2>&1 "
        "| tee {log}; exit ${{PIPESTATUS[0]}}"


# Each notebook shows its paper's figures and claims, and plots some cached results (the registry's).
NOTEBOOK_INPUTS = {
    paper.id: [*paper.notebook, f"results/{paper.id}/claims.csv"]
    for paper in registry.PAPERS.values()
}
NOTEBOOKS = expand("notebooks/executed/{paper}.ipynb", paper=NOTEBOOK_INPUTS)


rule notebook:
    """Execute a paper's jupytext notebook on the cached results and keep the .ipynb copy."""
    input:
        source=source(ROOT / "notebooks" / "{paper}.py"),
        data=lambda wildcards: NOTEBOOK_INPUTS[wildcards.paper],
        figures=lambda wildcards: registry.figure_outputs(wildcards.paper),
        code=lambda wildcards: code_inputs(ROOT / "notebooks" / f"{wildcards.paper}.py"),
    output:
        "notebooks/executed/{paper}.ipynb",
    log:
        "logs/notebooks/{paper}.log",
    benchmark:
        "logs/benchmarks/notebook_{paper}.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    shell:
        "PARTICLE_METHODS_WORKDIR=$PWD MPLBACKEND=module://matplotlib_inline.backend_inline "
        "jupytext --to ipynb --execute "
        "--output {output} {input.source} > {log} 2>&1"


rule versions:
    """Record the commit, and the versions of Python and of every dependency used by this run
    (rerun when the commit changes)."""
    input:
        code=[source(REPLICATION / "environment.py")],
    output:
        "results/versions.md",
    log:
        "logs/versions.log",
    benchmark:
        "logs/benchmarks/versions.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        commit=COMMIT["hash"],
    shell:
        "python -m particle_replication.environment {output} > {log} 2>&1"


# The browsable report (`snakemake --report report.zip`) carries, besides the figures, the claims table
# and the versions as HTML pages, the executed notebooks as HTML, and the PDFs.
REPORT_PAGES = {
    "claims": "Checked claims",
    "versions": "Software versions",
}
REPORT_PAGE_FILES = expand("results/report/{page}.html", page=REPORT_PAGES)
NOTEBOOK_PAGES = expand("notebooks/executed/{paper}.html", paper=NOTEBOOK_INPUTS)


rule report_page:
    """A Markdown result of the run (the claims table, the versions) as an HTML page of the report."""
    input:
        source="results/{page}.md",
        code=[source(REPLICATION / "report_pages.py")],
    output:
        report(
            "results/report/{page}.html",
            caption=str(ROOT / "report" / "page.rst"),
            category="Claims and versions",
        ),
    log:
        "logs/report_page_{page}.log",
    wildcard_constraints:
        page="|".join(REPORT_PAGES),
    conda:
        ENVIRONMENT
    threads: 1
    params:
        title=lambda wildcards: REPORT_PAGES[wildcards.page],
    shell:
        "python -m particle_replication.report_pages {input.source} {output} "
        "--title '{params.title}' > {log} 2>&1"


rule notebook_page:
    """An executed notebook as a standalone HTML page, for the report."""
    input:
        "notebooks/executed/{paper}.ipynb",
    output:
        report(
            "notebooks/executed/{paper}.html",
            caption=str(ROOT / "report" / "notebook.rst"),
            category="Notebooks",
        ),
    log:
        "logs/notebooks/{paper}_html.log",
    conda:
        ENVIRONMENT
    threads: 1
    shell:
        "jupyter nbconvert --to html --output-dir notebooks/executed {input} > {log} 2>&1"


SNIPPETS = expand(
    "paper/build/generated/{name}.tex",
    name=[
        "claims_sticky",
        "claims_ltp",
        "claims_blob",
        "claims_cross",
        "paperclaims_sticky",
        "paperclaims_ltp",
        "paperclaims_blob",
        "commit",
        "further_figures",
        "measured",
        "parameters",
        "configuration",
        "failures",
        "changes",
        "windows",
        "rates",
        "summary",
        "versions",
        "fragile",
    ],
)
LATEX = all(shutil.which(tool) for tool in ("latexmk", "pdflatex"))
MANUSCRIPT = ["paper/ms.pdf", "paper/supplement.pdf"] if LATEX else []
LATEX_HELP = (
    "paper/ms.pdf and paper/supplement.pdf were not built: no LaTeX toolchain found. On Debian or Ubuntu install it with\n"
    "    sudo apt-get install latexmk texlive-latex-base texlive-latex-recommended "
    "texlive-latex-extra texlive-fonts-recommended lmodern\n"
    "and run snakemake again; everything else is built."
)


rule report_snippets:
    """LaTeX snippets of the report: claims tables, measured values, parameters, versions."""
    input:
        claims="results/claims.csv",
        rates="results/rates.json",
        versions="results/versions.md",
        expected=VERDICTS,
        changes=source(ROOT / "config" / "changes.yaml"),
        # the figures they place by hand; the registry's other figures of ours go to further_figures.tex
        documents=[source(ROOT / "paper" / f"{name}.tex") for name in ("ms", "supplement")],
        code=imports("report/snippets.py"),
    output:
        SNIPPETS,
    log:
        "logs/report_snippets.log",
    benchmark:
        "logs/benchmarks/report_snippets.tsv"
    conda:
        ENVIRONMENT
    threads: 1
    params:
        outdir=lambda wildcards, output: os.path.dirname(output[0]),
        run=config["verdicts_run"],
    script:
        "../scripts/report/snippets.py"


rule manuscript:
    """Build the report paper/ms.pdf, or its supplement paper/supplement.pdf, with latexmk from its source, the
    shared preamble and the generated snippets."""
    input:
        source=source(ROOT / "paper" / "{document}.tex"),
        preamble=source(ROOT / "paper" / "preamble.tex"),
        snippets=SNIPPETS,
        figures=registry.figure_outputs(),
        tables=["results/cross/table.tex", "results/blob/fig5_orders.tex"],
    output:
        report(
            "paper/{document}.pdf",
            caption=str(ROOT / "report" / "documents.rst"),
            category="Documents",
        ),
    log:
        "logs/{document}.log",
    benchmark:
        "logs/benchmarks/{document}.tsv"
    wildcard_constraints:
        document="ms|supplement",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        epoch=COMMIT["epoch"],
    shell:
        # The commit time as SOURCE_DATE_EPOCH: pdfTeX writes it as the creation date and the file
        # identifier, so two builds from one commit are byte-identical. Each document has its own
        # directory under paper/build, so the two builds never share auxiliary files.
        "export SOURCE_DATE_EPOCH={params.epoch} FORCE_SOURCE_DATE=1 && "
        "mkdir -p paper/build/{wildcards.document} && "
        "cp {input.source} {input.preamble} paper/build/{wildcards.document}/ && "
        "cd paper/build/{wildcards.document} && "
        "latexmk -pdf -interaction=nonstopmode -halt-on-error {wildcards.document}.tex > ../../../{log} 2>&1 && "
        "cp {wildcards.document}.pdf ../../{wildcards.document}.pdf"


rule verdicts:
    """The end of every default run: the verdict summary printed and written to results/verdicts.txt, after
    everything else is built. Fails, loudly and on every later run until it is resolved, when a verdict differs
    from config/verdicts.yaml (as `snakemake verify` does); a configuration of the user's own gets the summary
    and the statement that nothing was compared."""
    input:
        claims="results/claims.csv",
        expected=VERDICTS,
        built=[
            STICKY_FIGURES,
            LTP_FIGURES,
            BLOB_FIGURES,
            CROSS_FIGURES,
            "results/claims.md",
            NOTEBOOKS,
            "results/versions.md",
            MANUSCRIPT,
        ],
    output:
        "results/verdicts.txt",
    log:
        "logs/verdicts.log",
    conda:
        ENVIRONMENT
    threads: 1
    params:
        comparison=COMPARISON,
    shell:
        "python -m particle_replication.claims verify {input.claims} --expected {input.expected} "
        "{params.comparison} --brief --report {output} 2>&1 | tee {log}; exit ${{PIPESTATUS[0]}}"
