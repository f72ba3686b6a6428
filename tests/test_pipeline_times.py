"""The times of a pipeline run (particle_replication.pipeline_times, printed by benchmarks/pipeline_times.py):
benchmark files, job graph, critical path, the run's CPU, its span and whether it compiled its kernels; the README's
sentence on them; and every benchmark script's header naming the CPU its times are measured on."""

import ast
import os
from pathlib import Path

import pytest

from particle_replication import pipeline_times
from particle_replication.readme import times_sentence

SCRIPT = Path(__file__).resolve().parent.parent / "benchmarks" / "pipeline_times.py"

HEADER = "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"


def row(seconds):
    return f"{seconds:.2f}\t0:00:00\t120.5\t800.1\t100.0\t110.0\t0.00\t1.20\t95.00\t{seconds:.2f}\n"


def test_read_benchmarks(tmp_path):
    (tmp_path / "blob_newtonian_data_fig2.tsv").write_text(HEADER + row(12.5))
    (tmp_path / "sticky_cost.tsv").write_text(HEADER + row(3.0) + row(5.0))  # benchmark: repeat(..., 2)
    (tmp_path / "empty.tsv").write_text(HEADER)
    (tmp_path / "notes.txt").write_text("not a benchmark")
    assert pipeline_times.read_benchmarks(tmp_path) == {"blob_newtonian_data_fig2": 12.5, "sticky_cost": 4.0}
    assert pipeline_times.read_benchmarks(tmp_path / "missing") == {}


def test_benchmark_name_sorts_wildcards_by_name():
    assert pipeline_times.benchmark_name("all", {}) == "all"
    assert pipeline_times.benchmark_name("rule", {"size": "80", "case": "shocks"}) == "rule_shocks_80"


DRY_RUN = """\
Building DAG of jobs...
[Tue Dec  1 21:18:49 2026]
rule sticky_psystem_data:
    input: ../../src/particle_methods/systems.py
    output: results/sticky/shocks.npz
    log: logs/sticky/shocks_data.log
    jobid: 7
    benchmark: logs/benchmarks/sticky_psystem_data_shocks.tsv
    reason: Forced execution
    wildcards: case=shocks
    resources: tmpdir=/tmp
[Tue Dec  1 21:18:49 2026]
rule sticky_psystem_figure:
    input: results/sticky/shocks.npz, ../../src/particle_replication/plotting.py
    output: figures/sticky/fig6.pdf, figures/sticky/fig6.png
    jobid: 9
    wildcards: case=shocks, figure=fig6
[Tue Dec  1 21:18:49 2026]
localrule all:
    input: figures/sticky/fig6.pdf, figures/sticky/fig6.png, results/sticky/shocks.npz
    jobid: 0
    reason: Forced execution
Job stats:
job                        count
"""


def test_parse_dry_run():
    jobs, edges, _ = pipeline_times.parse_dry_run(DRY_RUN)
    assert jobs == {7: ("sticky_psystem_data", {"case": "shocks"}),
                    9: ("sticky_psystem_figure", {"case": "shocks", "figure": "fig6"}),
                    0: ("all", {})}
    assert edges == [(7, 0), (7, 9), (9, 0)]


def test_critical_path_of_a_diamond_and_a_chain():
    # a -> (b | c) -> d -> e, and the separate chain x -> y: the slow branch b wins, the chain is shorter
    durations = {"a": 1.0, "b": 5.0, "c": 2.0, "d": 1.0, "e": 1.0, "x": 3.0, "y": 4.0}
    edges = [("a", "b"), ("a", "c"), ("b", "d"), ("c", "d"), ("d", "e"), ("x", "y")]
    assert pipeline_times.critical_path(durations, edges) == (8.0, ["a", "b", "d", "e"])
    assert pipeline_times.lower_bound(sum(durations.values()), 8.0, cores=2) == 17.0 / 2
    assert pipeline_times.lower_bound(sum(durations.values()), 8.0, cores=4) == 8.0


def test_critical_path_follows_edges_against_the_order_of_the_durations():
    # Taking jobs in the order given (c before its predecessors), or dropping edges, would give 5 s (a alone).
    durations = {"c": 1.0, "b": 1.0, "a": 5.0}
    assert pipeline_times.critical_path(durations, [("b", "c"), ("a", "b")]) == (7.0, ["a", "b", "c"])


def test_critical_path_counts_jobs_without_benchmark_as_zero():
    assert pipeline_times.critical_path({"data": 2.0, "figure": 3.0}, [("data", "figure"), ("figure", "all")]) == (
        5.0, ["data", "figure", "all"])
    assert pipeline_times.critical_path({}, []) == (0.0, [])


def test_critical_path_rejects_a_cycle():
    with pytest.raises(ValueError, match="cycle"):
        pipeline_times.critical_path({"a": 1.0, "b": 1.0}, [("a", "b"), ("b", "a")])


def test_the_summary_names_the_cpu_the_run_recorded_not_this_machine(tmp_path):
    (tmp_path / "results").mkdir()
    (tmp_path / "results" / "versions.md").write_text("# Software versions\n\nCommit: 0123abc\n\n"
                                                      "CPU: Intel Xeon (AVX-512, 2 cores)\n\n| package | version |\n")
    jobs, edges, threads = pipeline_times.parse_dry_run(DRY_RUN)
    seconds = {"sticky_psystem_data_shocks": 3.0}
    cpu = pipeline_times.run_cpu(tmp_path)
    assert cpu == "Intel Xeon (AVX-512, 2 cores)"
    for markdown in (False, True):
        lines = pipeline_times.report(jobs, edges, seconds, 2, markdown, threads, cpu=cpu)
        assert lines[0] == "Measured on Intel Xeon (AVX-512, 2 cores)"


def test_a_run_without_a_cpu_record_says_so(tmp_path):
    assert pipeline_times.run_cpu(tmp_path) == "CPU not recorded"
    (tmp_path / "results").mkdir()
    (tmp_path / "results" / "versions.md").write_text("# Software versions\n\nCommit: 0123abc\n")
    assert pipeline_times.run_cpu(tmp_path) == "CPU not recorded"
    jobs, edges, threads = pipeline_times.parse_dry_run(DRY_RUN)
    assert pipeline_times.report(jobs, edges, {}, 2, cpu=pipeline_times.run_cpu(tmp_path))[0] == "CPU not recorded"


def imported_names(path):
    return {(node.module, alias.name) for node in ast.walk(ast.parse(path.read_text()))
            if isinstance(node, ast.ImportFrom) for alias in node.names}


def test_every_benchmark_prints_the_cpu_from_its_one_description():
    """Each timing script calls timing.print_cpu, which prints particle_replication.environment.cpu(); the
    pipeline's summary reads the run's record of it instead (environment.recorded_cpu)."""
    folder = SCRIPT.parent
    assert ("particle_replication.environment", "cpu") in imported_names(folder / "timing.py")
    scripts = sorted(path for path in folder.glob("*.py") if path.name != "timing.py")
    assert len(scripts) >= 10
    for path in scripts:
        expected = (("particle_replication.pipeline_times", "run_cpu") if path == SCRIPT
                    else ("timing", "print_cpu"))
        assert expected in imported_names(path), path.name
        calls = {node.func.id for node in ast.walk(ast.parse(path.read_text()))
                 if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)}
        assert expected[1] in calls, f"{path.name} imports {expected[1]} but never calls it"


def test_a_span_is_measured_only_for_jobs_of_one_invocation(tmp_path):
    """Each job ends at its benchmark file's time; a gap longer than MAX_IDLE with no job running means several
    invocations (an incremental run), whose span says nothing of one run's time."""
    for name, seconds, end in [("a", 10.0, 1010.0), ("b", 20.0, 1025.0), ("c", 5.0, 1040.0)]:
        path = tmp_path / f"{name}.tsv"
        path.write_text(HEADER + row(seconds))
        os.utime(path, (end, end))
    intervals = pipeline_times.job_intervals(tmp_path)
    assert intervals == [(1000.0, 1010.0), (1005.0, 1025.0), (1035.0, 1040.0)]
    assert pipeline_times.one_invocation_span(intervals) == 40.0
    assert pipeline_times.job_intervals(tmp_path, {"a", "c"}) == [(1000.0, 1010.0), (1035.0, 1040.0)]
    late = intervals + [(1040.0 + pipeline_times.MAX_IDLE + 1.0, 1100.0)]
    assert pipeline_times.one_invocation_span(late) is None
    assert pipeline_times.one_invocation_span([]) is None


def test_a_run_is_cold_when_no_kernel_cache_predates_it(tmp_path):
    cache = tmp_path / "sub" / "__pycache__"
    cache.mkdir(parents=True)
    assert pipeline_times.compiled_during(100.0, tmp_path) is None
    index = cache / "kernels.f-10.py311.nbi"
    index.write_text("")
    os.utime(index, (150.0, 150.0))
    assert pipeline_times.compiled_during(100.0, tmp_path) is True
    assert pipeline_times.compiled_during(200.0, tmp_path) is False


def test_the_readme_says_what_the_run_cost_and_how_it_was_run():
    times = pipeline_times.RunTimes(span=804.2, jobs=1488.5, core_seconds=1583.5, path=304.4, bound=791.8, cores=2,
                                    cold=True, cpu="AMD EPYC (AVX2, 2 cores)")
    sentence = times_sentence(times)
    assert "took 804 s on 2 cores" in sentence and "compiling every kernel itself" in sentence
    assert "1488 s together" in sentence and "less than 792 s (the critical path 304 s" in sentence
    warm = times_sentence(pipeline_times.RunTimes(**{**times.__dict__, "cold": False}))
    assert "earlier run had compiled" in warm
    several = times_sentence(pipeline_times.RunTimes(**{**times.__dict__, "span": None}))
    assert "several invocations" in several and "took 1488 s together" in several
