"""The forked Snakemake of the pipeline tests (tests/forked_snakemake.py) runs as `python -m snakemake` does: in the
directory, environment and search path asked for, its output and exit status its own, killed at its timeout."""

import os
import subprocess
import sys

import forked_snakemake
import pytest

# A workflow that shows what its process sees: its directory, the first entries of its search path, a variable of
# its environment and whether its standard input is empty; its one rule fails when asked to.
SNAKEFILE = """
import os, sys
print("cwd", os.getcwd())
print("path", sys.path[:3])
print("variable", os.environ.get("FORKED_SNAKEMAKE_PROBE"))
print("stdin", repr(sys.stdin.read()))

rule fail:
    shell: "exit 3"
"""


def outcome(result):
    """A run's exit status and output, without the lines that differ from run to run (its dates and id)."""
    lines = [line for line in result.stdout.splitlines()
             if not line.lstrip().startswith(("Date:", "Workflow ID:", "[")) or line.startswith("path")]
    return result.returncode, lines, result.stderr


def test_a_forked_run_is_the_run_of_a_new_process(tmp_path):
    (tmp_path / "Snakefile").write_text(SNAKEFILE)
    (tmp_path / "src").mkdir()
    environment = {**os.environ, "PYTHONPATH": str(tmp_path / "src"), "FORKED_SNAKEMAKE_PROBE": "here"}
    arguments = ["--cores", "1", "--dry-run"]
    forked = forked_snakemake.run(arguments, cwd=tmp_path, env=environment, timeout=120)
    alone = subprocess.run([sys.executable, "-m", "snakemake", *arguments], cwd=tmp_path, env=environment,
                           capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=120)
    assert outcome(forked) == outcome(alone)
    assert forked.returncode == 0
    assert f"cwd {tmp_path}" in forked.stdout and "variable here" in forked.stdout and "stdin ''" in forked.stdout
    assert f"path ['{tmp_path}', '{tmp_path / 'src'}'" in forked.stdout
    failed = forked_snakemake.run(["--cores", "1", "fail"], cwd=tmp_path, env=environment, timeout=120)
    assert failed.returncode == 1 and "Error in rule fail" in failed.stderr
    assert forked_snakemake.run(["--version"], timeout=120).stdout.strip().replace(".", "").isdigit()


def test_a_forked_run_past_its_timeout_is_killed(tmp_path):
    (tmp_path / "Snakefile").write_text("rule wait:\n    output: 'done'\n    shell: 'sleep 60 && touch {output}'\n")
    with pytest.raises(subprocess.TimeoutExpired):
        forked_snakemake.run(["--cores", "1"], cwd=tmp_path, timeout=3)
    # the next run is served: the killed one has been waited for
    assert forked_snakemake.run(["--version"], timeout=120).returncode == 0
    assert not (tmp_path / "done").exists()


def test_a_line_already_in_the_pipe_is_not_waited_for():
    """Two lines the server wrote at once (a run that ended before its id was read): the second is read at once, not
    after the timeout, which a buffered read of the first would have swallowed from under select."""
    import time

    writer = subprocess.Popen(["printf", "17\\n0\\n"], stdout=subprocess.PIPE, text=True)
    writer.wait()
    started = time.monotonic()
    assert forked_snakemake.read_line(writer) == "17\n"
    assert forked_snakemake.read_line(writer, timeout=30) == "0\n"
    assert time.monotonic() - started < 10
    with pytest.raises(RuntimeError, match="server ended"):
        forked_snakemake.read_line(writer)
