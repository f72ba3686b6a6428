"""The rules generated from the registry (particle_replication.registry): one data rule per result
file that has a job, named data_<paper>_<file>, one plot rule per plot job, named
plot_<paper>_<figures>, drawing the registered figures with their captions and titles, and each
paper's claims rule, <paper>_claims, measuring every registered result file of the paper."""

# What the report says of a figure of our own studies, not of the paper (the registry's `ours`).
OURS = "our own study, not a figure of the paper"


def plot_outputs(paper, plot):
    """PDF and PNG of each figure of a plot job (``pdf``/``png``, or ``<figure>_pdf``/``<figure>_png``
    for a job that draws several); each PNG goes to the Snakemake report with its caption, under its
    paper's figures, labelled as the PDF report labels it (the registry's ``Paper.label``: Figure Blob 7,
    and ours numbered apart, Figure Blob A1)."""
    outputs = {}
    for entry in plot.figures:
        prefix = "" if len(plot.figures) == 1 else f"{entry.name}_"
        path = f"figures/{paper.id}/{entry.name}"
        outputs[f"{prefix}pdf"] = f"{path}.pdf"
        outputs[f"{prefix}png"] = report(
            f"{path}.png",
            caption=CAPTION,
            category=f"Figures ({paper.id})",
            subcategory=paper.label(entry.name),
        )
    return outputs


def plot_parameters(paper, plot):
    """The plot job's params: the captions (for the report, each led by the figure's label, ours saying
    so), the figure's name and title when it draws one figure, and the job's own parameters from the
    paper's section of the config."""
    section = config[paper.id]
    captions = [
        f"{paper.label(entry.name)}"
        + (f" ({OURS})" if entry.ours else "")
        + f". {entry.caption(section)}"
        for entry in plot.figures
    ]
    parameters = {"caption": " ".join(captions)}
    if len(plot.figures) == 1:
        parameters["figure"] = plot.figures[0].name
        if plot.figures[0].title is not None:
            parameters["title"] = plot.figures[0].title(section)
    return {**parameters, **plot.params(section)}


for paper in registry.PAPERS.values():
    for entry in paper.results:
        if entry.job is None:
            continue

        rule:
            name:
                entry.rule
            input:
                **entry.job.inputs,
                code=imports(f"{paper.id}/{entry.writer}"),
            output:
                entry.path,
            log:
                f"logs/{paper.id}/{entry.rule.removeprefix(f'data_{paper.id}_')}_data.log",
            benchmark:
                f"logs/benchmarks/{entry.rule}.tsv"
            conda:
                ENVIRONMENT
            threads: workflow.cores if entry.job.threads == "all" else entry.job.threads
            params:
                **entry.job.params(config[paper.id]),
                nudge=config["nudge"],
                script=f"{paper.id}/{entry.writer}",
            script:
                # Formatted when the job runs (a loop variable here would be the loop's last value then).
                "../scripts/{params.script}"

    for plot in paper.plots:

        rule:
            name:
                plot.rule(paper.id)
            input:
                **plot.data,
                code=imports(f"{paper.id}/{plot.script}"),
            output:
                **plot_outputs(paper, plot),
            log:
                f"logs/{paper.id}/{'_'.join(plot.names)}_plot.log",
            benchmark:
                f"logs/benchmarks/{plot.rule(paper.id)}.tsv"
            conda:
                ENVIRONMENT
            threads: 1
            params:
                **plot_parameters(paper, plot),
                script=f"{paper.id}/{plot.script}",
            script:
                # Formatted when the job runs (a loop variable here would be the loop's last value then).
                "../scripts/{params.script}"

    rule:
        name:
            f"{paper.id}_claims"
        input:
            **paper.claim_inputs(),
            code=imports(f"{paper.id}/claims.py"),
        output:
            claims=f"results/{paper.id}/claims.csv",
            rates=f"results/{paper.id}/rates.json",
        log:
            f"logs/{paper.id}/claims.log",
        benchmark:
            f"logs/benchmarks/{paper.id}_claims.tsv"
        conda:
            ENVIRONMENT
        threads: 1
        params:
            cfg=config[paper.id],
            script=f"{paper.id}/claims.py",
        script:
            "../scripts/{params.script}"
