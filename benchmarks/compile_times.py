"""Numba compile time of one pipeline job, kernel by kernel, from an empty cache.

    snakemake --cores 1 --forcerun <rule> --skip-script-cleanup <its output>  # keeps .snakemake/scripts/*.py
    python benchmarks/compile_times.py .snakemake/scripts/<tmp>.<script>.py [--top 15]

The job's script (the copy Snakemake writes, with its `snakemake` object) runs once in this process with
NUMBA_CACHE_DIR pointing to an empty directory, so every kernel it calls is compiled. numba reports each
compilation as a "numba:compile" event (numba.core.event); a kernel's compilation includes those of the
kernels and library overloads it calls, so each kernel's time is printed exclusive of them. Printed: the
job's wall time, the sum of the outermost compilations, the kernels by exclusive time and the library
overloads (numba's own implementations, e.g. the error messages of an array copy) with the kernel that
pulled them in. Used to find the compile costs of issue 25 (a cold run spends about 90 of its 535
core-seconds compiling; benchmarks/README.md).
"""

import argparse
import collections
import os
import sys
import tempfile
import time

from timing import print_cpu


def exclusive_times(events):
    """(kernel -> exclusive seconds, (kernel <- overload) -> inclusive seconds, outermost total) from the
    recorded (timestamp, event) pairs of "numba:compile"."""
    stack, exclusive, overloads, outermost = [], collections.Counter(), collections.Counter(), 0.0
    for timestamp, event in events:
        function = event.data["dispatcher"].py_func
        name = f"{function.__module__}.{function.__qualname__.split('.<locals>')[0]}"
        ours = not function.__module__.startswith("numba.")
        if event.is_start:
            stack.append([name, timestamp, 0.0, ours])
            continue
        name, started, inner, ours = stack.pop()
        duration = timestamp - started
        exclusive[name] += duration - inner
        if not ours and (not stack or stack[-1][3]):
            overloads[f"{stack[-1][0] if stack else '?'} <- {name}"] += duration
        if stack:
            stack[-1][2] += duration
        else:
            outermost += duration
    return exclusive, overloads, outermost


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("script", help="a job script kept by snakemake --skip-script-cleanup")
    parser.add_argument("--top", type=int, default=15, help="rows of each table")
    args = parser.parse_args(argv)
    os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="numba-cold-")  # before numba is imported
    import numba.core.event as event

    recorder = event.RecordingListener()
    event.register("numba:compile", recorder)
    code = compile(open(args.script).read(), args.script, "exec")
    stdout = sys.stdout
    print_cpu(stdout)
    start = time.perf_counter()
    sys.argv = [args.script]
    exec(code, {"__name__": "__main__", "__file__": args.script})  # the job redirects stdout to its log
    wall = time.perf_counter() - start
    exclusive, overloads, outermost = exclusive_times(recorder.buffer)
    print(f"{args.script}: {wall:.1f} s, of which compiling {outermost:.1f} s", file=stdout)
    print("kernels, exclusive seconds:", file=stdout)
    for name, seconds in exclusive.most_common(args.top):
        print(f"  {seconds:6.2f}  {name}", file=stdout)
    print("library overloads compiled for a kernel, seconds:", file=stdout)
    for name, seconds in overloads.most_common(args.top):
        print(f"  {seconds:6.2f}  {name}", file=stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
