"""Snakemake for the pipeline tests, imported once and forked for each run.

A start of ``python -m snakemake`` spends most of a short run (a dry run, a rerun of one job) importing Snakemake
and loading its plugins: 1.67 s for a dry run of the quick configuration on an idle Intel Xeon, of which 0.73 s is
left in a process that has them loaded already (benchmarks/README.md, "The CI"). The pipeline tests start it about
thirty times, one after another, on the CI's longest chain. :func:`run` hands a run to a server process that has
imported Snakemake and loaded its plugins (and nothing of this repository), and forks it: the child runs Snakemake's
own entry point, ``snakemake.cli.main``, as ``python -m snakemake`` does, in the directory and environment asked for,
with ``sys.path`` made from that environment's ``PYTHONPATH`` as a new interpreter's would be, so that a scratch
repository's workflow imports its own sources. The run's jobs are processes of their own, as under
``python -m snakemake``.

The server is started on first use, one per test process, and ends with it. Where ``fork`` is missing (not POSIX),
:func:`run` starts ``python -m snakemake`` instead.
"""

from __future__ import annotations

import atexit
import contextlib
import json
import os
import select
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from pathlib import Path

_SERVER: list[subprocess.Popen] = []


def _server() -> subprocess.Popen:
    if not _SERVER or _SERVER[0].poll() is not None:
        environment = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
        _SERVER[:] = [subprocess.Popen([sys.executable, __file__], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                       env=environment, text=True, start_new_session=True)]
        atexit.register(_SERVER[0].kill)
    return _SERVER[0]


def run(args, *, cwd=None, env=None, timeout: float = 900) -> subprocess.CompletedProcess:
    """``python -m snakemake *args`` in ``cwd`` with environment ``env`` (this process's when None), its output
    captured as text, as ``subprocess.run(..., capture_output=True, text=True, timeout=timeout)`` would return it;
    raises :class:`subprocess.TimeoutExpired` (the run's process group killed) when it takes longer."""
    args = [str(arg) for arg in args]
    command = [sys.executable, "-m", "snakemake", *args]
    if not hasattr(os, "fork"):
        return subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    server = _server()
    with tempfile.TemporaryDirectory() as folder:
        stdout, stderr = Path(folder, "stdout"), Path(folder, "stderr")
        request = {"args": args, "cwd": str(Path(cwd or os.getcwd()).resolve()),
                   "env": dict(os.environ if env is None else env), "stdout": str(stdout), "stderr": str(stderr)}
        server.stdin.write(json.dumps(request) + "\n")
        server.stdin.flush()
        pid = int(read_line(server))
        returncode = read_line(server, timeout)
        if returncode is None:
            with contextlib.suppress(ProcessLookupError):  # it may have ended meanwhile
                os.killpg(pid, signal.SIGKILL)
            read_line(server)
            raise subprocess.TimeoutExpired(command, timeout, stdout.read_text(), stderr.read_text())
        returncode = int(returncode)
        return subprocess.CompletedProcess(command, returncode, stdout.read_text(), stderr.read_text())


def read_line(server, timeout: float | None = None) -> str | None:
    """The next line the server wrote, or None when none has come within ``timeout`` seconds. Read a byte at a time
    from the pipe itself: a buffered read could take the next line too, which ``select`` would then never see."""
    deadline = None if timeout is None else time.monotonic() + timeout
    line = b""
    while not line.endswith(b"\n"):
        left = None if deadline is None else max(0.0, deadline - time.monotonic())
        if left is not None and not select.select([server.stdout], [], [], left)[0]:
            return None
        byte = os.read(server.stdout.fileno(), 1)
        if not byte:
            raise RuntimeError(f"the forked Snakemake's server ended (status {server.wait()})")
        line += byte
    return line.decode()


def _child(request) -> int:
    """The forked run: ``request``'s directory, environment, search path and output, then Snakemake's entry point;
    returns its exit status as the interpreter would."""
    os.setsid()
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    added = [entry for entry in request["env"].get("PYTHONPATH", "").split(os.pathsep) if entry]
    sys.path[:] = [request["cwd"], *added, *sys.path]  # as `python -m` makes it: the directory, then PYTHONPATH
    for descriptor, name, flags in ((0, None, os.O_RDONLY), (1, "stdout", os.O_WRONLY | os.O_CREAT | os.O_TRUNC),
                                    (2, "stderr", os.O_WRONLY | os.O_CREAT | os.O_TRUNC)):
        file = os.open(request[name] if name else os.devnull, flags)  # stdin: not the server's requests
        os.dup2(file, descriptor)
        os.close(file)
    # The one value Snakemake takes from the directory at its import (its log's "Run directory"; Snakemake 9): as a new
    # process would have it. tests/test_forked_snakemake.py compares a forked run's log with a new process's.
    snakemake.workflow.Workflow._rundir = request["cwd"]
    sys.argv = [str(Path(snakemake.__file__).with_name("__main__.py")), *request["args"]]  # as `python -m` sets it
    try:
        snakemake.cli.main(request["args"])
        status = 0
    except SystemExit as end:
        if end.code is None or isinstance(end.code, int):
            status = end.code or 0
        else:
            print(end.code, file=sys.stderr)
            status = 1
    sys.stdout.flush()
    sys.stderr.flush()
    return status


if __name__ == "__main__":
    sys.path.pop(0)  # this file's folder: the tests' helpers are no module of the runs
    import snakemake.cli
    import snakemake.workflow

    snakemake.cli.get_argument_parser()  # loads the plugins
    for line in sys.stdin:
        child = os.fork()
        if child == 0:
            status = 1
            try:
                status = _child(json.loads(line))
            except BaseException:
                traceback.print_exc()
            finally:
                os._exit(status)
        print(child, flush=True)
        print(os.waitstatus_to_exitcode(os.waitpid(child, 0)[1]), flush=True)
