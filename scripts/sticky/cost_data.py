"""Sections 5.1.1 and 5.2.1: the work of the compiled kernels against the problem size, counted as they make
it, and its wall time, in ``processes`` processes one after another
(:mod:`particle_replication.cost_timing`): the counts decide the cost claims, the times of the separate
processes only the wall-time check, the load guards' readings say whether each had a core to itself, and the
CPU is recorded beside the times."""

import numpy as np

from particle_replication.cost_timing import SERIES, replicated
from particle_replication.environment import cpu
from particle_replication.workflow import logged, progress, save_results


def run(p, nudge, output):
    made = replicated(p, p["processes"], nudge["ulps"], nudge["seed"])
    for k, process in enumerate(made):
        progress(f"process {k + 1} of {len(made)}: heap-only allocator "
                 + ("yes" if process["allocator"] else "no (not glibc): timings include page faults"))
        for name in SERIES:
            progress(f"  {name}: best times {np.round(process['times'][name], 5).tolist()} s")
        readings = process["readings"]
        progress(f"  the timed kernels got {readings['cpu_share']:.2f} of a core, {readings['load']:.2g} other "
                 "processes runnable on average")
    operations = {name: np.array(made[0]["operations"][name], dtype=np.int64) for name in SERIES}
    for name in SERIES:
        progress(f"{name}: operations {operations[name].tolist()}")
    progress(f"CPU {cpu()}")
    # one row per process; the guard's readings of the most disturbed process
    times = {name: np.array([process["times"][name] for process in made]) for name in SERIES}
    readings = [process["readings"] for process in made]
    guard = {"cpu_share": min(r["cpu_share"] for r in readings), "load": max(r["load"] for r in readings),
             "cores": readings[0]["cores"], "threads": readings[0]["threads"]}
    save_results(output, hull_n=np.asarray(p["hull_n"]), hull_operations=operations["hull"],
                 hull_free_operations=operations["hull_free"], hull_times=times["hull"],
                 hull_free_times=times["hull_free"], rank_n=np.asarray(p["rank_n"]), rank_operations=operations["rank"],
                 rank_times=times["rank"], tspd_n=np.asarray(p["tspd_n"]), tspd_operations=operations["tspd"],
                 tspd_times=times["tspd"], tspd_steps=p["tspd_steps"], steps_values=np.asarray(p["steps_values"]),
                 steps_operations=operations["steps"], steps_times=times["steps"], steps_n=p["steps_n"], cpu=cpu(),
                 **guard)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.params.nudge, snakemake.output[0])  # noqa: F821
