"""The time of a pipeline run from Snakemake's benchmark files: each job's wall time, their sum, the critical path,
the lower bound on the run's wall time, the span of the run and whether it compiled its kernels itself.

Every rule writes ``logs/benchmarks/<rule>[_<wildcard values, sorted by wildcard name>].tsv`` under the run's output
root; the first column ``s`` of such a file is the job's wall time in seconds (the mean when a rule benchmarks
several repeats), and Snakemake writes it when the job ends. The job graph comes from a dry run,
``snakemake -n --forceall [--configfile ...]`` in the repository root, which computes nothing: it prints every job
with its rule, wildcards, input and output files, and a job depends on the jobs that write its input files.
``benchmarks/pipeline_times.py`` prints the table; :mod:`particle_replication.readme` puts the summary
(:func:`run_times`) into the README.
"""

from __future__ import annotations

import re
import subprocess
import sys
from collections import deque
from dataclasses import dataclass
from pathlib import Path

from .environment import CPU_NOT_RECORDED, recorded_cpu
from .paths import REPOSITORY

JOB_HEADER = re.compile(r"^(?:local)?(?:rule|checkpoint) (\w+):$")
JOB_FIELD = re.compile(r"^    (\w+): (.*)$")


def read_benchmarks(directory) -> dict[str, float]:
    """{file name without .tsv: wall seconds} for every Snakemake benchmark file in ``directory``."""
    seconds = {}
    for path in sorted(Path(directory).glob("*.tsv")):
        header, *rows = [line.split("\t") for line in path.read_text().splitlines() if line.strip()]
        if rows:
            column = header.index("s")
            seconds[path.stem] = sum(float(row[column]) for row in rows) / len(rows)
    return seconds


def run_cpu(root) -> str:
    """The CPU the run under ``root`` was measured on, as its ``results/versions.md`` records it (the run's
    machine, not this one), or "CPU not recorded" when the run has no such record."""
    path = Path(root) / "results" / "versions.md"
    return recorded_cpu(path.read_text()) if path.is_file() else CPU_NOT_RECORDED


def benchmark_name(rule, wildcards) -> str:
    """The benchmark file name (without .tsv) of a job: the rule and its wildcard values by sorted name."""
    return "_".join([rule, *(str(wildcards[key]) for key in sorted(wildcards))])


def parse_dry_run(text):
    """Jobs {jobid: (rule, wildcards)}, edges [(producer, consumer)] and threads {jobid: threads} from
    `snakemake -n` output (a job prints its threads when it has more than one)."""
    blocks, fields = [], None
    for line in text.splitlines():
        header = JOB_HEADER.match(line)
        if header:
            fields = {"rule": header.group(1)}
            blocks.append(fields)
        elif fields is not None and (field := JOB_FIELD.match(line)):
            fields[field.group(1)] = field.group(2)
        else:
            fields = None
    jobs, producer, threads = {}, {}, {}
    for fields in blocks:
        jobid = int(fields["jobid"])
        threads[jobid] = int(fields.get("threads", 1))
        wildcards = dict(item.split("=", 1) for item in fields.get("wildcards", "").split(", ") if item)
        jobs[jobid] = (fields["rule"], wildcards)
        for path in fields.get("output", "").split(", "):
            producer[path] = jobid
    edges = sorted({(producer[path], int(fields["jobid"])) for fields in blocks
                    for path in fields.get("input", "").split(", ") if path in producer})
    return jobs, edges, threads


def critical_path(durations, edges) -> tuple[float, list]:
    """(total, jobs) of the longest chain of dependent jobs, weighted by ``durations`` (missing: 0).

    ``edges`` are pairs (before, after); the graph must be acyclic.
    """
    nodes = set(durations) | {node for edge in edges for node in edge}
    successors = {node: [] for node in nodes}
    waiting = dict.fromkeys(nodes, 0)
    for before, after in edges:
        successors[before].append(after)
        waiting[after] += 1
    finish = {node: durations.get(node, 0.0) for node in nodes}  # longest chain ending with the node
    previous = dict.fromkeys(nodes)
    ready = deque(sorted((node for node in nodes if not waiting[node]), key=str))
    done = 0
    while ready:  # topological order: a node's chain is final before its successors are looked at
        node = ready.popleft()
        done += 1
        for after in successors[node]:
            if finish[node] + durations.get(after, 0.0) > finish[after]:
                finish[after], previous[after] = finish[node] + durations.get(after, 0.0), node
            waiting[after] -= 1
            if not waiting[after]:
                ready.append(after)
    if done < len(nodes):
        raise ValueError("the job graph has a cycle")
    if not nodes:
        return 0.0, []
    node = max(sorted(nodes, key=str), key=finish.get)
    total, path = finish[node], []
    while node is not None:
        path.append(node)
        node = previous[node]
    return total, path[::-1]


def lower_bound(total, path_total, cores) -> float:
    """No schedule on ``cores`` cores beats the critical path, nor the total work (core-seconds: a job
    holding several cores counts that many times) spread evenly."""
    return max(path_total, total / cores)


def job_graph(configfiles=(), cores=2):
    """Jobs, edges and threads of the whole workflow, from a dry run in the repository root with ``cores``
    cores (the rules that take all the cores then show how many the run gave them)."""
    command = [sys.executable, "-m", "snakemake", "-n", "--forceall", "--cores", str(cores)]
    if configfiles:
        command += ["--configfile", *(str(Path(path).resolve()) for path in configfiles)]
    result = subprocess.run(command, cwd=REPOSITORY, capture_output=True, text=True)
    if result.returncode:
        raise RuntimeError(f"{' '.join(command)} failed:\n{result.stderr}{result.stdout}")
    return parse_dry_run(result.stdout + result.stderr)


def _durations(jobs, seconds) -> tuple[dict, dict]:
    """({jobid: benchmark name}, {jobid: wall seconds, 0 without a benchmark file})."""
    names = {jobid: benchmark_name(rule, wildcards) for jobid, (rule, wildcards) in jobs.items()}
    return names, {jobid: seconds.get(name, 0.0) for jobid, name in names.items()}


def _totals(durations, edges, threads) -> tuple[float, float, float, list]:
    """(summed job time, core-seconds, critical path's time, its jobs)."""
    work = sum(threads.get(jobid, 1) * time for jobid, time in durations.items())
    return (sum(durations.values()), work, *critical_path(durations, edges))


#: Longest time with no job running that one invocation of Snakemake leaves between its jobs, in seconds: it starts
#: the next job as soon as one ends (a rule's checks at its start take a few seconds).
MAX_IDLE = 30.0


def job_intervals(directory, names=None) -> list[tuple[float, float]]:
    """(start, end) of each job whose benchmark file is in ``directory`` (those of ``names`` only, if given), as
    POSIX times, sorted: Snakemake writes each file when its job ends, so a job started at the file's modification
    time less its wall time."""
    seconds = read_benchmarks(directory)
    ends = {name: (Path(directory) / f"{name}.tsv").stat().st_mtime for name in seconds
            if names is None or name in names}
    return sorted((end - seconds[name], end) for name, end in ends.items())


def one_invocation_span(intervals) -> float | None:
    """The time from the first start to the last end of ``intervals``, or None if they leave a time longer than
    :data:`MAX_IDLE` with no job running (the jobs were run by several invocations: an incremental run)."""
    if not intervals:
        return None
    reached = intervals[0][1]
    for start, end in intervals[1:]:
        if start - reached > MAX_IDLE:
            return None
        reached = max(reached, end)
    return reached - intervals[0][0]


def compiled_during(start: float, package: Path | None = None) -> bool | None:
    """Whether the run that started at ``start`` compiled every numba kernel of ``package`` (default: the
    installed ``particle_methods``) itself: no cache index (``__pycache__/*.nbi``) of the package older than the
    run, as in a fresh clone. None where the package holds no cache (numba keeps it elsewhere when the package
    is read-only)."""
    if package is None:
        import particle_methods

        package = Path(particle_methods.__file__).parent
    indexes = list(Path(package).rglob("__pycache__/*.nbi"))
    if not indexes:
        return None
    return min(path.stat().st_mtime for path in indexes) >= start


@dataclass(frozen=True)
class RunTimes:
    """A run's times in seconds: ``span`` from its first job's start to its last job's end (None if its jobs were
    run by several invocations: :func:`one_invocation_span`), ``jobs`` the summed
    wall times of its jobs, ``core_seconds`` (a job holding several cores counts that many times), the critical
    path's time ``path`` and the ``bound`` no schedule on ``cores`` cores beats; ``cold`` whether the run
    compiled its kernels itself (:func:`compiled_during`); ``cpu`` the CPU it ran on."""

    span: float | None
    jobs: float
    core_seconds: float
    path: float
    bound: float
    cores: int
    cold: bool | None
    cpu: str


def run_times(root, configfiles=(), cores: int = 2) -> RunTimes:
    """The :class:`RunTimes` of the run under the output root ``root`` (its ``logs/benchmarks``), with the job
    graph of the configuration files it was run with (:func:`job_graph`)."""
    directory = Path(root) / "logs" / "benchmarks"
    jobs, edges, threads = job_graph(configfiles, cores)
    names, durations = _durations(jobs, read_benchmarks(directory))
    intervals = job_intervals(directory, set(names.values()))
    if not intervals:
        raise ValueError(f"root {root}: no benchmark file of a job of the run in {directory}")
    total, work, path_total, _ = _totals(durations, edges, threads)
    return RunTimes(span=one_invocation_span(intervals), jobs=total, core_seconds=work, path=path_total,
                    bound=lower_bound(work, path_total, cores), cores=cores, cold=compiled_during(intervals[0][0]),
                    cpu=run_cpu(root))


def report(jobs, edges, seconds, cores, markdown=False, threads=None, top=None, cpu=CPU_NOT_RECORDED):
    """The CPU the run was measured on (``cpu``: :func:`run_cpu`), the table (the ``top`` longest jobs and those
    on the critical path, when ``top`` is given), sum, core-seconds, critical path and lower bound, as text lines."""
    threads = threads or {}
    names, durations = _durations(jobs, seconds)
    total, work, path_total, path = _totals(durations, edges, threads)
    on_path = set(path)
    order = sorted(jobs, key=lambda jobid: (-durations[jobid], names[jobid]))
    if top is not None:
        order = [jobid for rank, jobid in enumerate(order) if rank < top or jobid in on_path]
    width = max(map(len, names.values()), default=3)
    lines = [f"Measured on {cpu}" if cpu != CPU_NOT_RECORDED else cpu, ""]
    if markdown:
        lines += ["| job | wall time [s] | critical path |", "|---|---:|:---:|"]
        for jobid in order:
            time = f"{durations[jobid]:.1f}" if names[jobid] in seconds else "–"
            cores_held = f" ({threads[jobid]} cores)" if threads.get(jobid, 1) > 1 else ""
            lines.append(f"| `{names[jobid]}`{cores_held} | {time} | {'✓' if jobid in on_path else ''} |")
        if len(order) < len(jobs):
            rest = sum(durations[jobid] for jobid in jobs if jobid not in order)
            lines.append(f"| {len(jobs) - len(order)} other jobs | {rest:.1f} | |")
        lines.append(f"| **sum** | **{total:.1f}** | |")
    else:
        lines.append(f"{'job':<{width}} {'wall [s]':>10}  critical path")
        for jobid in order:
            time = f"{durations[jobid]:10.1f}" if names[jobid] in seconds else f"{'-':>10}"
            cores_held = f"  ({threads[jobid]} cores)" if threads.get(jobid, 1) > 1 else ""
            lines.append(f"{names[jobid]:<{width}} {time}  {'*' if jobid in on_path else ''}{cores_held}".rstrip())
        if len(order) < len(jobs):
            rest = sum(durations[jobid] for jobid in jobs if jobid not in order)
            lines.append(f"{f'{len(jobs) - len(order)} other jobs':<{width}} {rest:10.1f}")
        lines.append(f"{'sum':<{width}} {total:10.1f}")
    lines += ["", f"Critical path ({path_total:.1f} s): {' -> '.join(names[jobid] for jobid in path)}",
              f"Core-seconds (wall time x cores held): {work:.1f}",
              f"Lower bound on {cores} cores: max({path_total:.1f}, {work:.1f} / {cores}) = "
              f"{lower_bound(work, path_total, cores):.1f} s"]
    return lines


