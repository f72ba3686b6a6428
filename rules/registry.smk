"""The rules generated from the registry (particle_replication.registry): one data rule per result
file that has a job, named data_<paper>_<file>; two plot rules per paper, plot_<paper> for the
paper's figures and plot_<paper>_ours for our own, each running its plot jobs in one process
(Paper.plot_batches) and drawing the registered figures with their captions and titles; and each
paper's claims rule, <paper>_claims, measuring every registered result file of the paper."""

# What the report says of a figure of our own studies, not of the paper (the registry's `ours`).
OURS = "our own study, not a figure of the paper"
# The report's caption template (rules/common.smk: CAPTION), made one per figure (caption_template).
CAPTION_TEXT = Path(CAPTION).read_text()


def caption_template(paper, figure):
    """The report's caption of ``figure``: Snakemake's report reads a caption's template from a file, and the batch's
    job holds the captions of all its figures (its ``captions`` param), so each figure has a file of its own, written
    at the workflow's start into the run's .snakemake folder from report/caption.rst with the figure's name in place
    of __FIGURE__; returns its path."""
    text = CAPTION_TEXT.replace("__FIGURE__", figure.name)
    path = Path(".snakemake", "captions", paper.id, f"{figure.name}.rst").resolve()
    if not path.is_file() or path.read_text() != text:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return str(path)


def plot_outputs(paper, plots):
    """PDF and PNG of each figure of a batch of plot jobs (``<figure>_pdf``, ``<figure>_png``); each PNG goes to
    the Snakemake report with its caption, under its paper's figures, labelled as the PDF report labels it (the
    registry's ``Paper.label``: Figure Blob 7, and ours numbered apart, Figure Blob A1)."""
    outputs = {}
    for plot in plots:
        for entry in plot.figures:
            path = f"figures/{paper.id}/{entry.name}"
            outputs[f"{entry.name}_pdf"] = f"{path}.pdf"
            outputs[f"{entry.name}_png"] = report(
                f"{path}.png",
                caption=caption_template(paper, entry),
                category=f"Figures ({paper.id})",
                subcategory=paper.label(entry.name),
            )
    return outputs


def plot_parameters(paper, plot):
    """A plot job's params: the figure's name and title when it draws one figure, and the job's own parameters
    from the paper's section of the config."""
    section = config[paper.id]
    parameters = {}
    if len(plot.figures) == 1:
        parameters["figure"] = plot.figures[0].name
        if plot.figures[0].title is not None:
            parameters["title"] = plot.figures[0].title(section)
    return {**parameters, **plot.params(section)}


def plot_captions(paper, plots):
    """The report's caption of each figure of a batch, led by the figure's label (ours saying so)."""
    section = config[paper.id]
    return {
        entry.name: f"{paper.label(entry.name)}"
        + (f" ({OURS})" if entry.ours else "")
        + f". {entry.caption(section)}"
        for plot in plots
        for entry in plot.figures
    }


def plot_inputs(paper, plots):
    """Each plot job's script and result files, named ``<key>__script`` and ``<key>__<name>``, and the modules its
    script imports (particle_replication.plot_batch.run_plot_batch)."""
    inputs = {}
    for plot in plots:
        inputs[f"{plot.key}__script"] = source(ROOT / "scripts" / paper.id / plot.script)
        inputs |= {f"{plot.key}__{name}": path for name, path in plot.data.items()}
    code = {module for plot in plots for module in imports(f"{paper.id}/{plot.script}")}
    return {**inputs, "code": sorted(code | set(imports("plot_batch.py")))}


def job_threads(job, section):
    """A data job's threads under its paper's section: every core of the run for "all"."""
    threads = job.threads_in(section)
    return workflow.cores if threads == "all" else threads


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
            threads: job_threads(entry.job, config[paper.id])
            params:
                **entry.job.params(config[paper.id]),
                nudge=config["nudge"],
                script=f"{paper.id}/{entry.writer}",
            script:
                # Formatted when the job runs (a loop variable here would be the loop's last value then).
                "../scripts/{params.script}"

    for batch, plots in paper.plot_batches.items():

        rule:
            name:
                batch
            input:
                **plot_inputs(paper, plots),
            output:
                **plot_outputs(paper, plots),
            log:
                **{plot.key: f"logs/{paper.id}/{plot.key}_plot.log" for plot in plots},
            benchmark:
                f"logs/benchmarks/{batch}.tsv"
            conda:
                ENVIRONMENT
            threads: 1
            params:
                plots={
                    plot.key: {
                        "data": list(plot.data),
                        "figures": list(plot.names),
                        "params": plot_parameters(paper, plot),
                    }
                    for plot in plots
                },
                captions=plot_captions(paper, plots),
            script:
                "../scripts/plot_batch.py"

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
