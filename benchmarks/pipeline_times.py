"""Wall time of each pipeline job from Snakemake's benchmark files, their sum and the critical path.

    python benchmarks/pipeline_times.py                                    # the full run (output root .)
    python benchmarks/pipeline_times.py --configfile config/quick.yaml --root runs/quick
    python benchmarks/pipeline_times.py ... --cores 2 --markdown           # the same as a table (benchmarks/README.md)

Every rule writes `logs/benchmarks/<rule>[_<wildcard values, sorted by wildcard name>].tsv` under the
run's output root; the first column `s` of such a file is the job's wall time in seconds (the mean
when a rule benchmarks several repeats). The job graph comes from a dry run,
`snakemake -n --forceall [--configfile ...]` in the repository root, which computes nothing: it prints
every job with its rule, wildcards, input and output files, and a job depends on the jobs that write
its input files. (`--d3dag` and `--dag` print the same graph, but without all of a job's wildcards.)
Printed: the CPU the run was measured on (the one its `results/versions.md` names, written by the run's
`versions` rule: not the machine reading the logs; "CPU not recorded" without it), each job's wall time,
largest first (`-`: no benchmark file, counted as 0 s, e.g. `all`), their sum, the core-seconds (a job
that holds several cores counts that many times), the critical path (the chain of dependent jobs with the
largest total wall time) and the lower bound max(critical path, core-seconds / cores) on the run's wall time
with --cores cores.
"""

import argparse
import re
import subprocess
import sys
from collections import deque
from pathlib import Path

from particle_replication.environment import CPU_NOT_RECORDED, recorded_cpu

REPOSITORY = Path(__file__).resolve().parent.parent
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
        sys.exit(f"{' '.join(command)} failed:\n{result.stderr}{result.stdout}")
    return parse_dry_run(result.stdout + result.stderr)


def report(jobs, edges, seconds, cores, markdown=False, threads=None, top=None, cpu=CPU_NOT_RECORDED):
    """The CPU the run was measured on (``cpu``: :func:`run_cpu`), the table (the ``top`` longest jobs and those
    on the critical path, when ``top`` is given), sum, core-seconds, critical path and lower bound, as text lines."""
    threads = threads or {}
    names = {jobid: benchmark_name(rule, wildcards) for jobid, (rule, wildcards) in jobs.items()}
    durations = {jobid: seconds.get(name, 0.0) for jobid, name in names.items()}
    total = sum(durations.values())
    work = sum(threads.get(jobid, 1) * time for jobid, time in durations.items())
    path_total, path = critical_path(durations, edges)
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", default=".", help="the run's output root (output_root of its configuration)")
    parser.add_argument("--configfile", nargs="+", default=(),
                        help="the configuration files of the run, as given to snakemake (default: config/config.yaml)")
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    parser.add_argument("--top", type=int, help="list only the TOP longest jobs and those on the critical path")
    args = parser.parse_args()
    directory = Path(args.root) / "logs" / "benchmarks"
    seconds = read_benchmarks(directory)
    jobs, edges, threads = job_graph(args.configfile, args.cores)
    if not seconds:
        print(f"No benchmark files found in {directory}: every job counts as 0 s.\n")
    names = {benchmark_name(rule, wildcards) for rule, wildcards in jobs.values()}
    if unmatched := sorted(set(seconds) - names):
        print(f"Benchmark files of no job in the graph (left out): {', '.join(unmatched)}\n")
    print("\n".join(report(jobs, edges, seconds, args.cores, args.markdown, threads, args.top, run_cpu(args.root))))


if __name__ == "__main__":
    main()
