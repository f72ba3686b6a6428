"""The plot jobs of a batch (rules/registry.smk: a paper's figures, or ours of it) run in one process. Its own module,
imported by the batch's script alone: an edit here reruns the plots, not the computations, which import
:mod:`.workflow`."""

from __future__ import annotations

import runpy
from collections.abc import Mapping
from types import SimpleNamespace

import matplotlib
import matplotlib.pyplot as plt
from snakemake.iocontainers import Namedlist


def run_plot_batch(job) -> None:
    """Run the plot jobs of one batch (rules/registry.smk: a paper's figures, or ours of it) one after another in
    this process, each as Snakemake runs a script alone: its script from ``scripts/``, with a ``snakemake`` object of
    its own inputs, outputs, params, log and one thread, in a matplotlib style context of its own, its figures closed
    after it. ``job`` is the batch job's ``snakemake`` object; for each plot job ``key`` its params hold
    ``plots[key]`` = {"data", "figures", "params"}, its inputs ``<key>__script`` and ``<key>__<name>`` for
    each data file, its log ``<key>``, and its outputs ``<figure>_pdf`` and ``<figure>_png`` (handed to the script as
    ``pdf`` and ``png`` when it draws one figure). One process per batch: a process per plot job spent about 2.6 s
    starting, importing and warming matplotlib, half of a quick run's plotting (benchmarks/README.md)."""
    plots = getattr(getattr(job, "params", None), "plots", None)
    if not isinstance(plots, Mapping) or not plots:
        raise TypeError(f"job.params.plots must be a non-empty mapping of plot jobs, got {plots!r}")
    for key, plot in plots.items():
        figures = plot["figures"]
        outputs = {f"{figure}_{kind}": job.output[f"{figure}_{kind}"] for figure in figures for kind in ("pdf", "png")}
        if len(figures) == 1:
            outputs = {kind: outputs[f"{figures[0]}_{kind}"] for kind in ("pdf", "png")}
        alone = SimpleNamespace(input=Namedlist(fromdict={name: job.input[f"{key}__{name}"] for name in plot["data"]}),
                                output=Namedlist(fromdict=outputs), params=Namedlist(fromdict=plot["params"]),
                                log=Namedlist([job.log[key]]), threads=1)
        with matplotlib.rc_context():
            runpy.run_path(job.input[f"{key}__script"], init_globals={"snakemake": alone}, run_name="__main__")
        plt.close("all")
