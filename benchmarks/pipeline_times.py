"""Wall time of each pipeline job from Snakemake's benchmark files, their sum and the critical path.

    python benchmarks/pipeline_times.py                                    # the full run (output root .)
    python benchmarks/pipeline_times.py --configfile config/quick.yaml --root runs/quick
    python benchmarks/pipeline_times.py ... --cores 2 --markdown           # the same as a table (benchmarks/README.md)

The functions live in `particle_replication.pipeline_times` (whose docstring says where the times and the job
graph come from). Printed: the CPU the run was measured on (the one its `results/versions.md` names, written by the
run's `versions` rule: not the machine reading the logs; "CPU not recorded" without it), each job's wall time,
largest first (`-`: no benchmark file, counted as 0 s, e.g. `all`), their sum, the core-seconds (a job that holds
several cores counts that many times), the critical path (the chain of dependent jobs with the largest total wall
time) and the lower bound max(critical path, core-seconds / cores) on the run's wall time with --cores cores.
"""

import argparse
from pathlib import Path

from particle_replication.pipeline_times import benchmark_name, job_graph, read_benchmarks, report, run_cpu


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
