"""The registry (particle_replication.registry) is the one list of figures and result files: the
README's figure map, the report, the notebooks and the scripts agree with it, and the result
files' keys are checked against it when written and read."""

import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from particle_replication import registry
from particle_replication.paths import read_yaml
from particle_replication.report import further_figures, placed_figures
from particle_replication.workflow import code_inputs, load_results, module_dependencies, save_results

ROOT = Path(__file__).resolve().parents[1]
CONFIG = read_yaml(ROOT / "config" / "config.yaml")


def test_readme_figure_map_is_the_generated_one():
    readme = (ROOT / "README.md").read_text()
    found = re.search(r"<!-- figure map:.*?-->\n(.*?)\n<!-- end of the figure map -->", readme, flags=re.DOTALL)
    assert found, "README.md has lost the markers of its figure map"
    assert found.group(1) == registry.figure_map(), "run `python -m particle_replication.registry --write`"
    assert "| blob | A1 (`repulsive`) |" in found.group(1)


def printed_labels(source: str) -> list[tuple[str, str]]:
    """(label, figure) of every figure of a LaTeX source, as LaTeX numbers them (paper/preamble.tex): after
    \\paperfigures{Blob} the k-th \\fig prints Figure Blob k (a counter), \\ourfig{k} prints Figure Blob Ak."""
    labels, name, counter = [], None, 0
    pattern = r"\\paperfigures\{(\w+)\}|\\(fig|ourfig)(?:\[[0-9.]+\])?(?:\{(\d+)\})?\{([a-z]+/[a-z0-9_]+)\.pdf\}"
    for match in re.finditer(pattern, source):
        if match.group(1):
            name, counter = match.group(1), 0
        elif match.group(2) == "fig":
            counter += 1
            labels.append((f"Figure {name} {counter}", match.group(4)))
        else:
            labels.append((f"Figure {name} A{match.group(3)}", match.group(4)))
    return labels


def test_report_labels_every_registered_figure_as_the_registry_does():
    """Every registered figure printed once, the paper's in the report (\\fig), ours in the report or its
    supplement (\\ourfig{k}), each under the registry's label (Paper.label: Figure Blob 7 is the paper's Figure 7,
    ours numbered apart, Figure Blob A1, in registry order), which the README's figure map, the HTML report and the
    notebooks show."""
    report_source, supplement_source = ((ROOT / "paper" / name).read_text() for name in ("ms.tex", "supplement.tex"))
    report = printed_labels(report_source)
    # the figures of ours no document places by hand go to the supplement's generated section
    supplement = printed_labels(supplement_source + further_figures(CONFIG, placed_figures(report_source,
                                                                                           supplement_source)))
    assert "\\input{../generated/further_figures.tex}" in supplement_source
    names = {paper.name: paper for paper in registry.PAPERS.values()}
    printed = sorted(figure for _, figure in report + supplement)
    assert printed == sorted(f"{paper.id}/{f.name}" for paper in registry.PAPERS.values() for f in paper.figures)
    for label, figure in report + supplement:
        paper_id, name = figure.split("/")
        paper = names[label.split(" ")[1]]
        assert paper.id == paper_id and label == paper.label(name), (label, figure)
    assert all(" A" in label for label, _ in supplement), "the paper's figures belong in the report"


def test_labels_number_ours_apart():
    blob = registry.PAPERS["blob"]
    assert blob.label("fig5") == "Figure Blob 5" and blob.label("repulsive") == "Figure Blob A1"
    assert [blob.numbers[f.name] for f in blob.figures if f.ours] == ["A1", "A2"]
    with pytest.raises(ValueError, match="figure must be one of"):
        blob.label("fig9")
    with pytest.raises(ValueError, match="fig<number>"):
        _ = registry.Paper("x", "X", (registry.Plot("p.py", (registry.Figure("wrong", "w", str),)),), (), ()).numbers


def test_a_figure_of_ours_no_document_places_goes_to_the_supplement():
    config = {paper: CONFIG[paper] for paper in registry.PAPERS}
    placed = {"blob/repulsive"}  # as if the report placed only this figure of ours
    text = further_figures(config, placed)
    assert "\\ourfig{2}{blob/fig4log.pdf}" in text and "blob/repulsive" not in text and "\\paperfigures{Blob}" in text
    assert text.startswith("\\section{Further figures}")
    everything = {f"{paper.id}/{f.name}" for paper in registry.PAPERS.values() for f in paper.figures}
    assert further_figures(config, everything) == ""
    text = "\\fig[0.5]{sticky/fig2.pdf}{c} \\ourfig{3}{cross/x_y.pdf}{c}"
    assert placed_figures(text) == {"sticky/fig2", "cross/x_y"}


def test_every_notebook_shows_its_papers_figures(monkeypatch):
    """Each notebook ends with show_remaining_figures, which shows every registered figure the tour did not: a new
    figure needs no edit of the notebook."""
    from particle_replication import tour

    for paper in registry.PAPERS.values():
        notebook = (ROOT / "notebooks" / f"{paper.id}.py").read_text()
        assert f'show_remaining_figures("{paper.id}")' in notebook, paper.id
    shown = []
    monkeypatch.setattr(tour, "display", lambda item: shown.append(getattr(item, "filename", None)))
    monkeypatch.setattr(tour, "Image", lambda filename: SimpleNamespace(filename=filename))
    monkeypatch.setattr(tour, "paper_claims", lambda paper: [])
    monkeypatch.setattr(tour, "SHOWN", {})
    tour.show_figure("blob", 1)
    tour.show_figure("blob", "repulsive")
    tour.show_remaining_figures("blob")
    names = [Path(name).stem for name in shown if name]
    assert sorted(names) == sorted(f.name for f in registry.PAPERS["blob"].figures)
    assert names[:2] == ["fig1", "repulsive"] and len(set(names)) == len(names)
    with pytest.raises(ValueError, match="paper must be one of"):
        tour.show_remaining_figures("nope")


def test_scripts_captions_and_titles_exist_for_every_figure():
    names = [(paper.id, figure.name) for paper in registry.PAPERS.values() for figure in paper.figures]
    assert len(names) == len(set(names))
    for paper in registry.PAPERS.values():
        section = CONFIG[paper.id]
        for plot in paper.plots:
            assert (ROOT / "scripts" / paper.id / plot.script).is_file(), plot.script
            assert set(plot.params(section)).isdisjoint({"caption", "figure", "title"})
            for path in plot.data.values():
                assert registry.result(path) is not None and registry.result(path).path == path, path
            for figure in plot.figures:
                assert figure.caption(section).endswith(".") and figure.describe(section)
                assert figure.title is None or figure.title(section)
    for paper in registry.PAPERS.values():
        produced = {entry.path for entry in paper.results}
        for entry in paper.results:
            assert entry.path.startswith(f"results/{paper.id}/"), entry.path
            assert (ROOT / "scripts" / paper.id / entry.writer).is_file(), entry.writer
            if entry.job is None:  # computed by a rule written by hand, which the README's figure map names
                assert f"\nrule {entry.rule}:\n" in (ROOT / "rules" / f"{paper.id}.smk").read_text(), entry.rule
            else:
                assert entry.job.about and entry.job.threads_in(CONFIG[paper.id]) in (1, "all")
                assert set(entry.job.inputs.values()) <= produced, entry.path
                assert "script" not in entry.job.params(CONFIG[paper.id])
    for paper in registry.PAPERS.values():  # the claims read every result file, by its stem
        inputs = paper.claim_inputs()
        assert set(inputs.values()) == {entry.path for entry in paper.results if "*" not in entry.path}
        assert len(inputs) == len({entry.path for entry in paper.results if "*" not in entry.path})
    rules = [entry.rule for entry in registry.RESULTS if entry.job] + [
        batch for paper in registry.PAPERS.values() for batch in paper.plot_batches]
    assert len(rules) == len(set(rules))
    for paper in registry.PAPERS.values():  # each plot job in one batch, named apart from the others of its paper
        batched = [plot.key for plots in paper.plot_batches.values() for plot in plots]
        assert sorted(batched) == sorted(plot.key for plot in paper.plots) and len(set(batched)) == len(batched)


def test_the_upwind_references_hold_every_core_only_where_their_grid_splits_the_primitive():
    """The full run's grids (3 (cells + 1) primitive values a step from systems.PARALLEL_MIN_PRIMITIVES on) use
    every core; the quick run's, under it, one: held on two cores they ran on one. A job's threads are refused
    unless a positive integer or "all"."""
    from particle_methods.systems import PARALLEL_MIN_PRIMITIVES

    quick = read_yaml(ROOT / "config" / "quick.yaml")["sticky"]["beyond"]["upwind_reference_cells"]
    jobs = {entry.path: entry.job for entry in registry.PAPERS["sticky"].results if "beyond_upwind_" in entry.path}
    assert len(jobs) == 4
    def with_cells(reference_cells):
        return {**CONFIG["sticky"], "beyond": {**CONFIG["sticky"]["beyond"], "upwind_reference_cells": reference_cells}}

    for path, job in jobs.items():
        divisor = 2 if path.endswith("_half.npz") else 1
        cells = CONFIG["sticky"]["beyond"]["upwind_reference_cells"] // divisor
        assert 3 * (cells + 1) >= PARALLEL_MIN_PRIMITIVES and job.threads_in(CONFIG["sticky"]) == "all", path
        assert job.threads_in(with_cells(quick)) == 1, path
        # 21,845 cells: 65,538 values a step, at the threshold (65,536); 21,844 cells: 65,535, one short
        edge = PARALLEL_MIN_PRIMITIVES // 3
        assert job.threads_in(with_cells(edge * divisor)) == "all", path
        assert job.threads_in(with_cells((edge - 1) * divisor)) == 1, path
    for bad in (0, -1, True, 1.5, "some"):
        with pytest.raises(ValueError, match="threads must be"):
            registry.records.Job("a job", lambda s: {}, threads=bad).threads_in({})


def test_the_registry_is_not_a_code_input_of_the_jobs():
    """Its captions and parameters reach the jobs as params, which Snakemake tracks: editing a
    caption must not rerun a computation, though every script imports the registry (through the
    key checks of workflow.save_results)."""
    packages = [ROOT / "src" / "particle_methods", ROOT / "src" / "particle_replication"]
    script = ROOT / "scripts" / "blob" / "fig6_data.py"
    everything = module_dependencies(script, packages)
    inputs = code_inputs(script, packages)
    registry_dir = ROOT / "src" / "particle_replication" / "registry"
    assert any(Path(path).is_relative_to(registry_dir) for path in everything)
    assert not any(Path(path).is_relative_to(registry_dir) for path in inputs)
    assert set(inputs) == {path for path in everything if not Path(path).is_relative_to(registry_dir)}
    assert str(ROOT / "src" / "particle_replication" / "workflow.py") in inputs
    assert "workflow_code_inputs(path, PACKAGES)" in (ROOT / "rules" / "common.smk").read_text()


def test_a_copy_leaves_out_its_own_registry(tmp_path):
    """The sources copied elsewhere, the imported package still this checkout's: the copy's registry is left
    out, as the workflow's own (a copied repository run with another's package listed it and replanned
    every job)."""
    import shutil

    copy = tmp_path / "copy"
    shutil.copytree(ROOT / "src", copy / "src", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "scripts" / "blob", copy / "scripts" / "blob", ignore=shutil.ignore_patterns("__pycache__"))
    packages = [copy / "src" / "particle_methods", copy / "src" / "particle_replication"]
    inputs = code_inputs(copy / "scripts" / "blob" / "fig6_data.py", packages)
    assert str((copy / "src" / "particle_replication" / "workflow.py").resolve()) in inputs
    assert not any("registry" in Path(path).parts for path in inputs), inputs


def test_result_keys_are_checked_when_written_and_read(tmp_path):
    entry = registry.result("results/ltp/fig7.npz")
    arrays = {key: np.zeros(1) for key in entry.keys}
    path = tmp_path / "results" / "ltp" / "fig7.npz"
    save_results(path, **arrays)
    assert set(load_results(path)) == set(entry.keys)
    with pytest.raises(KeyError, match="declared keys missing \\['weights'\\]"):
        save_results(path, **{key: value for key, value in arrays.items() if key != "weights"})
    with pytest.raises(KeyError, match="not declared in the registry \\['spare'\\]"):
        save_results(path, **arrays, spare=np.zeros(1))
    np.savez(path, **{key: value for key, value in arrays.items() if key != "grid"})  # a file of older code
    with pytest.raises(KeyError, match="grid"):
        load_results(path)
    save_results(tmp_path / "scratch.npz", anything=np.zeros(1))  # files the registry does not know: unchecked


def test_patterns_need_a_match():
    entry = registry.result("results/blob/fig5.npz")
    arrays = {key.replace("*", "0"): np.zeros(1) for key in entry.keys}
    entry.check_keys(arrays)
    with pytest.raises(KeyError, match="case\\*_density"):
        entry.check_keys({key: value for key, value in arrays.items() if key != "case0_density"})


def test_figure_outputs():
    assert registry.figure_outputs("ltp")[:2] == ["figures/ltp/fig1.pdf", "figures/ltp/fig1.png"]
    assert len(registry.figure_outputs()) == 2 * sum(len(p.figures) for p in registry.PAPERS.values())
    with pytest.raises(ValueError, match="paper"):
        registry.figure_outputs("nope")
