"""The plot jobs of a batch run in one process (particle_replication.plot_batch), each as Snakemake would run its
script alone, and the registry's grouping of a paper's plot jobs into batches."""

from types import SimpleNamespace

import pytest
from snakemake.iocontainers import Namedlist

from particle_replication.plot_batch import run_plot_batch
from particle_replication.registry.records import Figure, Paper, Plot

# A plot script as the pipeline's are written: module-level code reading the `snakemake` object; it records what
# it was given and changes matplotlib's style, which must not reach the next script.
SCRIPT = '''
import json
import matplotlib
from pathlib import Path

seen = {"input": dict(snakemake.input.items()), "output": dict(snakemake.output.items()),
        "params": dict(snakemake.params.items()), "log": list(snakemake.log), "threads": snakemake.threads,
        "linewidth": matplotlib.rcParams["lines.linewidth"]}
matplotlib.rcParams["lines.linewidth"] = 9.0
for path in snakemake.output:
    Path(path).write_text(json.dumps(seen))
'''


def figure(name, ours=False):
    return Figure(name, label=name, caption=lambda section: name, ours=ours)


def batch_job(tmp_path):
    """A batch job's `snakemake` object as rules/registry.smk makes it: two plot jobs, one drawing two figures."""
    (tmp_path / "draw.py").write_text(SCRIPT)
    script = str(tmp_path / "draw.py")
    inputs = {"a__script": script, "a__data": "a.npz", "b_c__script": script, "b_c__first": "b.npz",
              "b_c__second": "c.npz", "code": "module.py"}
    outputs = {f"{name}_{kind}": str(tmp_path / f"{name}.{kind}") for name in "abc" for kind in ("pdf", "png")}
    plots = {"a": {"data": ["data"], "figures": ["a"], "params": {"title": "A", "figure": "a"}},
             "b_c": {"data": ["first", "second"], "figures": ["b", "c"], "params": {"t": 2.0}}}
    return SimpleNamespace(input=Namedlist(fromdict=inputs), output=Namedlist(fromdict=outputs),
                           params=Namedlist(fromdict={"plots": plots, "captions": {}}),
                           log=Namedlist(fromdict={"a": "logs/a.log", "b_c": "logs/b_c.log"}), threads=1)


def test_each_plot_job_of_a_batch_gets_its_own_files_params_and_log_and_a_fresh_style(tmp_path):
    import json

    import matplotlib

    before = matplotlib.rcParams["lines.linewidth"]
    run_plot_batch(batch_job(tmp_path))
    a = json.loads((tmp_path / "a.pdf").read_text())
    assert a["input"] == {"data": "a.npz"} and a["log"] == ["logs/a.log"] and a["threads"] == 1
    assert a["output"] == {"pdf": str(tmp_path / "a.pdf"), "png": str(tmp_path / "a.png")}  # one figure: pdf, png
    assert a["params"] == {"title": "A", "figure": "a"}
    bc = json.loads((tmp_path / "c.png").read_text())
    assert bc["input"] == {"first": "b.npz", "second": "c.npz"} and bc["log"] == ["logs/b_c.log"]
    assert set(bc["output"]) == {"b_pdf", "b_png", "c_pdf", "c_png"} and bc["params"] == {"t": 2.0}
    # the first script's change of style reached neither the second nor this process
    assert bc["linewidth"] == a["linewidth"] == before == matplotlib.rcParams["lines.linewidth"]


def test_a_failing_plot_job_fails_the_batch(tmp_path):
    job = batch_job(tmp_path)
    (tmp_path / "draw.py").write_text("raise RuntimeError('no data')\n")
    with pytest.raises(RuntimeError, match="no data"):
        run_plot_batch(job)


@pytest.mark.parametrize("plots", [None, {}, ["a"]])
def test_a_job_without_plot_jobs_is_refused(tmp_path, plots):
    job = batch_job(tmp_path)
    job.params = Namedlist(fromdict={"plots": plots}) if plots is not None else Namedlist()
    with pytest.raises(TypeError, match="job.params.plots"):
        run_plot_batch(job)


def test_a_paper_draws_its_figures_in_one_batch_and_ours_in_another():
    plots = (Plot("p.py", (figure("fig1"),)), Plot("q.py", (figure("extra", ours=True),)),
             Plot("p.py", (figure("fig2"), figure("fig3"))))
    paper = Paper("demo", "Demo", plots, (), ())
    assert paper.plot_batches == {"plot_demo": (plots[0], plots[2]), "plot_demo_ours": (plots[1],)}
    assert [plot.key for plot in plots] == ["fig1", "extra", "fig2_fig3"]


def test_a_plot_job_drawing_figures_of_the_paper_and_ours_is_refused():
    with pytest.raises(ValueError, match="not both"):
        Plot("p.py", (figure("fig1"), figure("extra", ours=True)))
