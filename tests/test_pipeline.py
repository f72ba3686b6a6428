"""End to end: the quick configuration of the Snakemake pipeline in a scratch directory."""

import csv
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import ci_tools
import forked_snakemake
import pytest
import yaml

from particle_replication import registry
from particle_replication.claims import COLUMNS, KINDS, STATUSES, read_verdicts
from particle_replication.paths import read_yaml
from particle_replication.workflow import damaged as workflow_damaged

ROOT = Path(__file__).resolve().parents[1]
QUICK = ROOT / "config" / "quick.yaml"
# Every figure, from the registry; the notebooks show their paper's.
EXPECTED_FIGURES = registry.figure_outputs()
# Every claim of the quick run, with its expected verdict (`snakemake verify` checks them).
EXPECTED_VERDICTS = read_verdicts(ROOT / "config" / "verdicts.yaml", "quick")
CONFIG = read_yaml(ROOT / "config" / "config.yaml")
# The smallest margin that is not fragile, also the factor of a value's spread that its pin allows.
CONFIG_MARGIN = CONFIG["robustness"]["margin_min"]

# One xdist worker runs this module (its quick run is a module fixture); the unit tests share the other cores.
pytestmark = [pytest.mark.pipeline, pytest.mark.xdist_group("pipeline")]
# The tests that need no quick run: a group of their own (pytest-xdist joins a test's group names), which another
# worker takes while the quick run is made.
WITHOUT_THE_RUN = pytest.mark.xdist_group("without_the_run")


# What a clone holds besides the sources: never copied into the scratch repositories.
GENERATED = shutil.ignore_patterns(".git", ".snakemake", "results", "figures", "logs", "runs", "executed", "build",
                                   "ms.pdf", "supplement.pdf", "__pycache__", "*.nbi", "*.nbc", ".hypothesis",
                                   ".pytest_cache")


def copy_repository(destination):
    """The repository's sources copied to ``destination`` (file times kept), as a fresh clone has them. Their
    ``__pycache__`` folders are links to this checkout's: the sources and their times are the same, so Python's
    and numba's caches (keyed by a source's time and size, numba's also stamped with a digest of every source,
    :mod:`particle_methods.jit`) hold for both, and a kernel is compiled once for the unit tests and the quick
    run, which run side by side under pytest-xdist, rather than once in each."""
    shutil.copytree(ROOT, destination, ignore=GENERATED)
    for folder in {path.parent for path in (ROOT / "src").rglob("*.py")}:
        (folder / "__pycache__").mkdir(exist_ok=True)
        (destination / folder.relative_to(ROOT) / "__pycache__").symlink_to(folder / "__pycache__")
    return destination


def checkout_environment(repository):
    """The environment in which the scratch ``repository`` runs its own code, as a clone installed with
    ``pip install -e`` does: its ``src`` first on the path (the workflow stops on another checkout's)."""
    path = os.pathsep.join(filter(None, [str(Path(repository) / "src"), os.environ.get("PYTHONPATH")]))
    return {**os.environ, "PYTHONPATH": path}


def snakefile_of(workdir):
    """The Snakefile of the scratch repository a run directory belongs to (runs/<name> inside it)."""
    candidate = Path(workdir).parents[1] / "Snakefile"
    return candidate if candidate.is_file() else ROOT / "Snakefile"


def snakemake_arguments(workdir, *args, configs=()):
    """Snakemake's arguments for a run in ``workdir`` of the quick configuration with overlays ``configs``."""
    return ["-s", str(snakefile_of(workdir)), "--directory", str(workdir), "--cores", "2", "--configfile", str(QUICK),
            *map(str, configs), *args]


def snakemake_command(workdir, *args, configs=()):
    """The command of that run as a process of its own (the tests that signal it)."""
    return [sys.executable, "-m", "snakemake", *snakemake_arguments(workdir, *args, configs=configs)]


def snakemake(workdir, *args, configs=()):
    """A run in ``workdir`` (:func:`snakemake_arguments`) in its repository's environment, its output captured; run
    by a forked Snakemake that has its imports done (tests/forked_snakemake.py)."""
    return forked_snakemake.run(snakemake_arguments(workdir, *args, configs=configs), timeout=900,
                                env=checkout_environment(snakefile_of(workdir).parent))


def verify(workdir, *args, configs=()):
    """`snakemake verify` of the quick configuration with overlays ``configs``, as the README writes it: from the
    root of the repository that ``workdir`` (runs/quick) belongs to."""
    repository = workdir.parents[1]
    return forked_snakemake.run(["verify", *args, "--configfile", "config/quick.yaml", *map(str, configs)],
                                cwd=repository, env=checkout_environment(repository), timeout=600)


def planned_rules(result):
    return set(re.findall(r"^rule (\w+):", result.stdout + result.stderr, flags=re.MULTILINE))


def latex_installed():
    """Whether the LaTeX toolchain of the report's PDFs is installed: asked by each test, since under CI it is
    installed while the quick run is made (tests/ci_tools.py). Without it the run builds neither the PDFs nor
    what only they read."""
    return bool(shutil.which("latexmk") and shutil.which("pdflatex"))


@pytest.fixture(scope="module")
def repository(tmp_path_factory):
    """A scratch copy of the repository where the quick run is made as the README says: from its root. Where CI
    still installs LaTeX (tests/ci_tools.py), a half-installed toolchain must not build the documents: the run
    leaves them out (and what follows them), then the README's command runs again once the install has ended, as
    the run's message tells a user who installs LaTeX later, and builds only those."""
    repository = copy_repository(tmp_path_factory.mktemp("clone") / "particle-methods")
    command = [sys.executable, "-m", "snakemake", "--cores", "2", "--configfile", "config/quick.yaml"]

    def run(*extra):
        result = subprocess.run([*command, *extra], cwd=repository, capture_output=True, text=True, timeout=900,
                                env=checkout_environment(repository))
        assert result.returncode == 0, result.stderr[-4000:]

    if ci_tools.installing():
        run("--omit-from", "manuscript")
        ci_tools.wait()
    run()
    return repository


@pytest.fixture(scope="module")
def workdir(repository):
    return repository / "runs" / "quick"


def test_the_quick_run_writes_under_its_own_root(repository):
    assert (repository / "runs/quick/results/claims.csv").is_file()
    for generated in ("results", "figures", "logs", "paper/ms.pdf", "paper/supplement.pdf", "notebooks/executed"):
        assert not (repository / generated).exists(), f"the quick run wrote {generated} of the full run"


def test_a_copied_repository_with_its_run_has_nothing_to_do(repository, tmp_path):
    """Moving or copying a finished run (with its repository, file times kept) replans nothing."""
    copy = tmp_path / "elsewhere" / "deeper" / "copy"
    # without the caches, which the unit tests may be writing meanwhile (see copy_repository)
    shutil.copytree(repository, copy, ignore=shutil.ignore_patterns("__pycache__"))
    command = ["--dry-run", "--configfile", "config/quick.yaml"]
    result = forked_snakemake.run(command, cwd=copy, timeout=300, env=checkout_environment(copy))
    assert result.returncode == 0, result.stderr[-2000:]
    assert "Nothing to be done" in result.stdout + result.stderr, result.stdout[-2000:]
    # Run in the environment of the repository it was copied from, it would run that one's code: it stops.
    result = forked_snakemake.run(command, cwd=copy, timeout=300, env=checkout_environment(repository))
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert f"particle_methods from {(repository / 'src').resolve()}" in output, output[-2000:]
    assert f"PYTHONPATH={copy / 'src'}" in output, output[-2000:]


@pytest.mark.parametrize("paper", ["sticky", "ltp", "blob"])
def test_one_paper_at_a_time(workdir, paper):
    """`snakemake <paper>` plans that paper's figures, claims and notebook and nothing of the others."""
    result = snakemake(workdir, "--dry-run", "--forceall", paper)
    assert result.returncode == 0, result.stderr[-2000:]
    planned = planned_rules(result)
    others = {"sticky", "ltp", "blob"} - {paper}
    assert f"{paper}_claims" in planned and "notebook" in planned
    foreign = tuple(f"{prefix}{other}_" for other in others for prefix in ("", "plot_"))
    assert not any(rule.startswith(foreign) or rule in {f"plot_{other}" for other in others} for rule in planned)
    assert f"plot_{paper}" in planned


def test_every_figure_is_built(workdir):
    for name in EXPECTED_FIGURES:
        path = workdir / name
        assert path.is_file() and path.stat().st_size > 1000, name
    assert (workdir / "figures/sticky/fig2.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_figure5_orders_name_the_finest_grid_of_the_overlay_not_run(repository, workdir):
    """Without the overlay's results, the report's table of Figure 5's orders says so, naming the finest h that
    config/fig5-extended.yaml would reach (a rule parameter read from that file, not a number in the script)."""
    if not latex_installed():
        pytest.skip("no LaTeX toolchain: the table of Figure 5's orders is made for the report's PDF alone")
    finest = max(read_yaml(repository / "config" / "fig5-extended.yaml")["blob"]["fig5"]["inverse_h"])
    text = (workdir / "results" / "blob" / "fig5_orders.tex").read_text()
    assert f"(to $h = 1/{finest}$) has not been run in this clone" in text


def test_every_notebook_runs_on_the_quick_results(workdir):
    import json

    for paper in registry.PAPERS.values():
        notebook = json.loads((workdir / "notebooks" / "executed" / f"{paper.id}.ipynb").read_text())
        code = [cell for cell in notebook["cells"] if cell["cell_type"] == "code"]
        assert not any(o.get("output_type") == "error" for cell in code for o in cell["outputs"]), paper.id
        images = [o for cell in code for o in cell["outputs"] if "image/png" in o.get("data", {})]
        plots = [cell for cell in code if "plt.show()" in "".join(cell["source"])]
        # every figure of the paper and of our own studies (the registry's), and every plot
        assert len(images) == len(paper.figures) + len(plots), paper.id
        assert any("text/markdown" in o.get("data", {}) for cell in code for o in cell["outputs"]), paper.id


def test_measured_values_match_the_last_build(workdir):
    """Every claim's measured value within its tolerance of the reference recorded from the last build
    (config/values-quick.yaml): 1e-9 (relative), or ten times the value's spread over the robustness run's
    variants (config/spreads.yaml) where rounding, threads or another CPU move it more. An optimisation that
    changes results beyond that fails here."""
    from particle_replication.claims import VALUES_HEADER, read_claims, read_spreads, value_differences

    spreads = read_spreads(ROOT / "config" / "spreads.yaml", "quick")
    problems = value_differences(read_claims(workdir / "results/claims.csv"), ROOT / "config" / "values-quick.yaml",
                                 spreads=spreads, factor=CONFIG_MARGIN)
    assert not problems, "\n".join(problems) + "\n(a deliberate change: " + VALUES_HEADER.strip("#\n ") + ")"


def test_another_machine_gives_the_same_verdicts(repository, workdir, tmp_path):
    """The LTP paper's claims under the robustness run's `combined` variant, as another machine would compute
    them: one thread, OpenBLAS's AVX2 kernels, NumPy's dispatch without AVX-512, numba's code for an AVX2 CPU
    and every initial datum nudged by a few ulps, at once (config.yaml, robustness.variants). Every verdict must
    be this run's, and every value within its pin's tolerance. One paper, the one whose jobs cost least, keeps
    CI fast: `snakemake robustness` recomputes every claim under every variant. That paper has no wall-clock
    check (whose pins are exempt: one thread on a quiet machine moved the quick cost study's time exponent from
    1.12 to 0.80, across its band's end, and no test may be decided by wall time)."""
    from particle_replication.claims import read_claims, read_spreads, read_values, value_differences
    from particle_replication.robustness import compare, probe, variant_configuration, variant_environment

    variant = CONFIG["robustness"]["variants"]["combined"]
    environment = variant_environment(variant, checkout_environment(repository))
    effective = probe(environment)
    assert effective["numba_threads"] == 1 and effective["numba_cpu"] == "haswell", effective
    # the variant's run as particle_replication.robustness.run_variant makes it, up to the LTP paper's claims
    overlay = tmp_path / "variant.yaml"
    overlay.write_text(yaml.safe_dump(variant_configuration({}, variant)))
    directory = workdir / "robustness" / "combined-ltp"
    command = [sys.executable, "-m", "snakemake", "-s", str(repository / "Snakefile"), "--directory", str(directory),
               "--cores", "2", "--configfile", str(QUICK), str(overlay), "--", "results/ltp/claims.csv"]
    result = subprocess.run(command, env=environment, capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, (result.stdout + result.stderr)[-3000:]
    wall_clock = {i for i, why in read_values(ROOT / "config" / "values-quick.yaml")[1].items() if "wall-clock" in why}
    assert wall_clock >= {"sticky.cost.wall_time", "sticky.beyond.cost.wall_time", "cross.fastest"}, wall_clock
    baseline = read_claims(workdir / "results/ltp/claims.csv")
    assert baseline and not wall_clock & {claim.id for claim in baseline}
    variant_claims = read_claims(directory / "results/ltp/claims.csv")
    assert not compare(baseline, {"combined": variant_claims})  # every claim there, each with this run's verdict
    spreads = read_spreads(ROOT / "config" / "spreads.yaml", "quick")
    problems = [problem for problem in value_differences(variant_claims, ROOT / "config" / "values-quick.yaml",
                                                         spreads=spreads, factor=CONFIG_MARGIN)
                if not problem.startswith("MISSING") or problem.startswith("MISSING ltp.")]  # others: not rerun
    assert not problems, "\n".join(problems)


@WITHOUT_THE_RUN
def test_value_comparison_sees_a_moved_value(tmp_path):
    import dataclasses

    from particle_replication.claims import Claim, Spread, value_differences

    reference = tmp_path / "values.yaml"
    reference.write_text("exempt: {demo.time: wall clock}\nvalues: {demo.order: '3.6', demo.gone: '1.0'}\n")
    claim = Claim("demo.order", "demo", "paper", "Fig. 1", "1", "order", "3.6", "3.6", "+-0.3", "pass", "3.6000001")
    timing = Claim("demo.time", "demo", "check", "timing", "1", "time", "1", "1", "+-1", "pass", "7.0")
    problems = value_differences([claim, timing], reference)
    assert any(p.startswith("MOVED demo.order") for p in problems) and "MISSING demo.gone" in problems
    assert not any("demo.time" in p for p in problems)
    # a value that the variants move by 1e-7 is pinned to ten times that, and no closer
    spreads = {"demo.order": Spread(distance=1e-7, value=1e-7)}
    assert not any("demo.order" in p for p in value_differences([claim], reference, spreads=spreads))
    moved = dataclasses.replace(claim, value="3.600002")
    assert any(p.startswith("MOVED demo.order") for p in value_differences([moved], reference, spreads=spreads))
    # a value not measured (NaN) stays the same outcome when it is still not measured, and moves when measured
    reference.write_text("exempt: {}\nvalues: {demo.order: 'nan'}\n")
    spreads = {"demo.order": Spread(distance=0.0, value=math.inf)}
    assert not value_differences([dataclasses.replace(claim, value="nan")], reference, spreads=spreads)
    assert any(p.startswith("MOVED demo.order") for p in value_differences([claim], reference, spreads=spreads))


def test_claims_table_and_summary(workdir):
    with (workdir / "results/claims.csv").open(newline="") as handle:
        reader = csv.DictReader(handle)
        assert tuple(reader.fieldnames) == COLUMNS
        rows = list(reader)
    ids = [row["id"] for row in rows]
    assert len(ids) == len(set(ids))
    assert set(EXPECTED_VERDICTS) <= set(ids)  # a claim not listed is expected to pass
    assert {row["status"] for row in rows} <= set(STATUSES)
    assert all(row["kind"] == "check" for row in rows if row["status"] == "abstain")
    assert {row["kind"] for row in rows} <= set(KINDS) and all(row["source"].strip() for row in rows)
    assert all(row["measured"] not in ("", "nan") for row in rows)
    summary = (workdir / "results/claims.md").read_text()
    paper = [row for row in rows if row["kind"] == "paper"]
    passing = sum(row["status"] == "pass" for row in paper)
    assert f"Paper claims reproduced: {passing} of {len(paper)}." in summary


def test_second_run_has_nothing_to_do(workdir):
    result = snakemake(workdir, "--dry-run")
    assert result.returncode == 0
    assert "Nothing to be done" in result.stdout + result.stderr


def test_an_interrupted_run_resumes_without_redoing_finished_work(workdir):
    """Ctrl-C while a solver runs, as in a first run cut short: no truncated result is left, and the
    next plain run plans only the unfinished jobs and what depends on them. The unfinished jobs are then run
    (their targets: the claims, notebook and manuscript after them are rebuilt by other tests already, and would add
    about a quarter of a minute to CI's) and, the numbers being the same, the times put back leave nothing to do."""
    import os
    import signal
    import time

    from particle_replication.workflow import load_results

    # one solver's result and its figure, in the smaller of the blob paper's two plot batches (plot_blob_ours: the
    # resumed run redraws the whole batch)
    unfinished = ("results/blob/repulsive.npz", "figures/blob/repulsive.pdf", "figures/blob/repulsive.png")
    times = {path: (stat.st_atime_ns, stat.st_mtime_ns) for folder in ("results", "figures")
             for path in (workdir / folder).rglob("*") if path.is_file() and (stat := path.stat())}
    for name in unfinished:
        (workdir / name).unlink()
    start = time.time()
    # Ctrl-C's default action restored in the run: pytest started in the background (`pytest &`) ignores SIGINT,
    # and so would the run it starts, which would then finish.
    process = subprocess.Popen(snakemake_command(workdir), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True, env=checkout_environment(workdir.parents[1]),
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    log = workdir / "logs" / "blob" / "repulsive_data.log"
    while not (log.exists() and log.stat().st_mtime >= start and log.read_text()):
        assert process.poll() is None and time.time() - start < 300, "the solver never started"
        time.sleep(0.1)
    os.killpg(process.pid, signal.SIGINT)  # what Ctrl-C in a terminal does
    assert process.wait(timeout=300) != 0
    while time.time() - start < 600:  # let every process of the run end before looking
        try:
            os.killpg(process.pid, 0)
        except ProcessLookupError:
            break
        time.sleep(0.1)
    assert not list(workdir.rglob("*.tmp"))
    for path in (workdir / "results").rglob("*.npz"):
        assert load_results(path)  # whatever is on disk is complete
    # Whether the solver job was cut or had just finished depends on timing; either way the resumed
    # run does only the unfinished part of the blob figures and nothing of the other studies.
    plan = planned_rules(snakemake(workdir, "--dry-run"))
    assert "plot_blob_ours" in plan
    assert plan <= {"data_blob_repulsive", "plot_blob_ours", "blob_claims",
                    "claims_table", "report_snippets", "notebook", "manuscript", "verdicts", "report_page",
                    "notebook_page", "all"}
    resumed = snakemake(workdir, "--", *unfinished)
    assert resumed.returncode == 0, resumed.stderr[-2000:]
    ran = set(re.findall(r"^localrule (\w+):", resumed.stdout + resumed.stderr, flags=re.MULTILINE))
    assert "plot_blob_ours" in ran and ran <= {"data_blob_repulsive", "plot_blob_ours"}, ran
    put_back(times)
    resumed = snakemake(workdir, "--dry-run")
    assert "Nothing to be done" in resumed.stdout + resumed.stderr


def result_times(workdir):
    """The times of every file under the run's results, to put back once a test has rebuilt some of them with
    the same content (the start of a run marks a table of a result that is gone for rebuilding, with time 0)."""
    return {path: (stat.st_atime_ns, stat.st_mtime_ns)
            for path in (workdir / "results").rglob("*") if path.is_file() and (stat := path.stat())}


def put_back(times):
    for path, ns in times.items():
        if path.exists():
            os.utime(path, ns=ns)


def test_a_killed_run_resumes_by_running_the_same_command_again(workdir):
    """SIGKILL of Snakemake alone (its jobs go on): running the same command again stops while the killed run's
    job still writes, then removes the killed run's lock, saying so, and redoes the job it left unfinished."""
    import time

    target = workdir / "results/sticky/lemma21.npz"
    times = result_times(workdir)
    target.unlink()
    start = time.time()
    command = snakemake_command(workdir, "--", "results/sticky/lemma21.npz")
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True, env=checkout_environment(workdir.parents[1]))
    log = workdir / "logs" / "sticky" / "lemma21_data.log"
    while not (log.exists() and log.stat().st_mtime >= start and log.read_text()):
        assert process.poll() is None and time.time() - start < 300, "the job never started"
        time.sleep(0.1)
    process.kill()  # Snakemake alone, as the OOM killer does; its job runs on in its process group
    process.wait()
    assert list((workdir / ".snakemake" / "locks").glob("*.lock"))
    again = snakemake(workdir, "--", "results/sticky/lemma21.npz")
    output = again.stdout + again.stderr
    if again.returncode != 0:  # the job was still running
        assert f"kill -- -{process.pid}" in output, output[-3000:]
        while time.time() - start < 300:
            try:
                os.killpg(process.pid, 0)
            except ProcessLookupError:
                break
            time.sleep(0.1)
        again = snakemake(workdir, "--", "results/sticky/lemma21.npz")
        output = again.stdout + again.stderr
    assert again.returncode == 0, output[-3000:]
    assert "the lock of a Snakemake run that was killed" in output
    # whatever the killed run's job wrote, it was marked incomplete: the rerun redid it
    assert re.search(r"^localrule data_sticky_lemma21:", output, flags=re.MULTILINE), output[-3000:]
    assert not list(workdir.rglob("*.tmp")) and not list((workdir / ".snakemake" / "locks").glob("*.lock"))
    put_back(times)  # the job's numbers are the same: the run is left as it was
    assert "Nothing to be done" in (lambda r: r.stdout + r.stderr)(snakemake(workdir, "--dry-run"))


def test_a_damaged_result_is_rebuilt_and_verify_refuses_until_it_is(workdir):
    """A cached result truncated with its time kept is found at the next start and rebuilt; verify refuses a
    claims table whose results are missing or damaged, naming them, and passes once the run has rebuilt them."""
    result, table = workdir / "results/sticky/lemma21.npz", workdir / "results/sticky/claims.csv"
    kept, times = table.read_bytes(), result_times(workdir)
    with result.open("r+b") as handle:
        handle.truncate(1000)
    os.utime(result, ns=times[result])
    table.unlink()  # as a run that failed on the damaged file leaves it
    refused = verify(workdir)
    output = refused.stdout + refused.stderr
    assert refused.returncode != 0 and "0 differences" not in output
    assert "results/sticky/claims.csv is missing" in output and "results/sticky/lemma21.npz is damaged" in output
    plan = snakemake(workdir, "--dry-run", "--", "results/sticky/claims.csv")
    assert "results/sticky/lemma21.npz is damaged" in plan.stderr
    assert {"data_sticky_lemma21", "sticky_claims"} <= planned_rules(plan), plan.stdout[-3000:]
    # rebuilt: the job's numbers are the same, so the table and times put back leave the run as it was
    assert snakemake(workdir, "--", "results/sticky/lemma21.npz").returncode == 0
    assert workflow_damaged(result) == ""
    table.write_bytes(kept)
    put_back(times)
    assert "Nothing to be done" in (lambda r: r.stdout + r.stderr)(snakemake(workdir, "--dry-run"))


def test_changing_one_parameter_reruns_only_its_dependents(workdir, tmp_path):
    override = tmp_path / "override.yaml"
    override.write_text("sticky:\n  lemma21:\n    n_values: [16, 64, 256, 1024, 2048]\n")
    result = snakemake(workdir, "--dry-run", configs=[override])
    assert result.returncode == 0, result.stderr[-2000:]
    expected = {"data_sticky_lemma21", "sticky_claims", "claims_table", "notebook", "verdicts", "report_page",
                "notebook_page", "all"}
    if latex_installed():  # the snippets are made for the report alone
        expected |= {"report_snippets", "manuscript"}
    assert planned_rules(result) == expected


def test_verify_works_as_the_readme_writes_it(workdir):
    """`snakemake verify`, with no --cores (the default profile gives them), passes when every verdict
    is the expected one and prints the paper claims."""
    result = verify(workdir)
    assert result.returncode == 0, (result.stdout + result.stderr)[-3000:]
    assert not (workdir / "runs").exists()
    assert "Paper claims reproduced:" in result.stdout and "0 differences from the expected verdicts" in result.stdout


def changed_verdicts(tmp_path):
    """An expected-verdicts file in which one claim of the quick run that passes is expected to fail (its quick
    section empty: the quick run's verdicts are its own); returns (path, the claim's id)."""
    changed_id = next(i for i, verdict in EXPECTED_VERDICTS.items() if verdict.status == "pass")
    passing = [i for i, verdict in EXPECTED_VERDICTS.items() if verdict.status == "pass" and i != changed_id]
    failing = {i: {"cause": verdict.cause, "reason": verdict.reason}
               for i, verdict in EXPECTED_VERDICTS.items() if verdict.status == "fail"}
    failing[changed_id] = {"cause": "contradicts", "reason": "pretend it used to fail"}
    expected = tmp_path / "verdicts.yaml"
    expected.write_text(yaml.safe_dump({"pass": passing, "fail": failing, "quick": {"pass": [], "fail": {}}}))
    return expected, changed_id


def test_verify_fails_when_a_verdict_changes(workdir, tmp_path):
    expected, changed_id = changed_verdicts(tmp_path)
    result = verify(workdir, "--config", f"verdicts={expected}")
    assert result.returncode != 0
    assert f"CHANGED {changed_id}: expected fail" in result.stdout + result.stderr


def test_the_default_run_ends_loudly_when_a_verdict_changes(workdir, tmp_path):
    """The run's last step prints the verdict summary and fails while a verdict differs from the expected one;
    with the expected verdicts restored it passes again, and only the merged table and that step rerun."""
    expected, changed_id = changed_verdicts(tmp_path)
    result = snakemake(workdir, "--config", f"verdicts={expected}", "--", "results/verdicts.txt")
    assert result.returncode != 0
    assert f"CHANGED {changed_id}: expected fail" in result.stdout + result.stderr
    assert "Paper claims reproduced:" in result.stdout + result.stderr
    plan = planned_rules(snakemake(workdir, "--dry-run", "--", "results/verdicts.txt"))
    # the merged table (its failures' causes come from the expected verdicts) and the verdicts: no data, no claims
    assert "verdicts" in plan and plan <= {"claims_table", "report_snippets", "manuscript", "verdicts"}, plan
    again = snakemake(workdir, "--", "results/verdicts.txt")
    assert again.returncode == 0, again.stderr[-2000:]
    assert "0 differences from the expected verdicts" in (workdir / "results" / "verdicts.txt").read_text()


def test_a_configuration_of_ones_own_is_compared_with_nothing(workdir, tmp_path):
    """An overlay that changes what a claim measures has no expected verdicts: verify prints the summary, names the
    keys in which it differs, compares nothing and passes."""
    override = tmp_path / "mine.yaml"
    override.write_text("sticky:\n  lemma21:\n    n_values: [16, 64, 256, 1024, 2048]\n")
    # mtime triggers only: the quick run's table stands in for the overlay's, which is not recomputed here
    result = verify(workdir, "--rerun-triggers", "mtime", configs=[override])
    assert result.returncode == 0, (result.stdout + result.stderr)[-2000:]
    assert "Nothing compared" in result.stdout and "sticky.lemma21.n_values" in result.stdout


# One bad value for each of the three checks the workflow makes at its start: the schema (an unknown key), the
# configuration's own checks (Snakefile: check_configuration) and a solver's work limit. The other bad values go
# through the same two calls in process (tests/test_config_census.py, which starts no Snakemake).
@WITHOUT_THE_RUN
@pytest.mark.parametrize(
    "override, key",
    [
        ("sticky:\n  fig2:\n    tmax: 3\n", "tmax"),
        ("blob:\n  fig5:\n    inverse_h: [5, 10, 10]\n", "blob.fig5.inverse_h"),
        ("sticky:\n  beyond:\n    repeats: 100000000\n", "sticky.beyond.repeats"),  # held to a solver's limit
    ],
)
def test_bad_configuration_stops_at_start_naming_the_key(tmp_path, override, key):
    path = tmp_path / "bad.yaml"
    path.write_text(override)
    result = snakemake(tmp_path, "--dry-run", configs=[path])
    assert result.returncode != 0
    assert key in result.stdout + result.stderr
    assert not (tmp_path / "results").exists()


@WITHOUT_THE_RUN
def test_a_configuration_file_is_laid_over_the_full_one(tmp_path):
    """A file given with --configfile holds only what differs: a section it leaves out is the full run's
    (here every sticky job is planned from config/config.yaml's sticky section)."""
    quick = read_yaml(QUICK)
    del quick["sticky"]
    path = tmp_path / "overlay.yaml"
    path.write_text(yaml.safe_dump(quick))
    arguments = ["-s", ROOT / "Snakefile", "--directory", tmp_path, "--dry-run", "--configfile", path]
    result = forked_snakemake.run(arguments, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "data_sticky_cost" in planned_rules(result)


def test_a_forced_rerun_gives_an_identical_claims_table(workdir):
    """Every job of the blob paper's claims rerun (its solvers, FMM, radial tables and pair sums: the paper with
    the most compiled machinery, and no timing claim) gives an identical claims table. The other papers' values
    are held to the last build's by test_measured_values_match_the_last_build; rerunning every job here would
    add most of the quick run's cost to CI's."""
    def table():
        with (workdir / "results/blob/claims.csv").open(newline="") as handle:
            return list(csv.DictReader(handle))

    before = table()
    result = snakemake(workdir, "--forceall", "--", "results/blob/claims.csv")
    assert result.returncode == 0, result.stderr[-2000:]
    ran = set(re.findall(r"^localrule (\w+):", result.stdout + result.stderr, flags=re.MULTILINE))
    assert {"data_blob_fig1", "data_blob_fig8", "blob_fig5_case", "blob_claims"} <= ran, ran
    after = table()
    moved = [(old["id"], key, old[key], new[key]) for old, new in zip(before, after) for key in old
             if old[key] != new[key]]
    assert len(after) == len(before) and not moved, moved[:20]


def test_slurm_profile_parses(workdir):
    """A dry run through the cluster profile, where the SLURM executor plugin is installed."""
    pytest.importorskip("snakemake_executor_plugin_slurm")
    result = snakemake(workdir, "--dry-run", "--forceall", "--profile", str(ROOT / "profiles" / "slurm"))
    assert result.returncode == 0, result.stderr[-2000:]
    assert "blob_fig5_case" in result.stdout + result.stderr


def test_report_pdf_is_built_where_latex_is_installed(workdir):
    if not latex_installed():
        pytest.skip("no LaTeX toolchain: the pipeline skips paper/ms.pdf and says how to install it")
    for pdf in (workdir / "paper" / "ms.pdf", workdir / "paper" / "supplement.pdf"):
        assert pdf.read_bytes()[:5] == b"%PDF-" and pdf.stat().st_size > 100_000, pdf.name
    measured = (workdir / "paper" / "build" / "generated" / "measured.tex").read_text()
    assert "measured@sticky.fig2d.order" in measured


def test_no_figure_of_the_built_pdfs_prints_text_below_the_legible_size(workdir):
    """The figure-size check of tests/test_built_report.py on the PDFs this run built (the quick run's figures
    have the full run's layouts): every registered figure is found, none with text below 7 pt as printed."""
    if not latex_installed():
        pytest.skip("no LaTeX toolchain: no PDF was built")
    from test_built_report import figure_text_sizes

    from particle_replication.plotting import MIN_PRINTED_SIZE

    sizes = {}
    for pdf in (workdir / "paper" / "ms.pdf", workdir / "paper" / "supplement.pdf"):
        sizes |= figure_text_sizes(pdf)
    labels = {paper.label(figure.name).removeprefix("Figure ") for paper in registry.PAPERS.values()
              for figure in paper.figures}
    assert set(sizes) == labels, f"figures not found: {sorted(labels - set(sizes))}; unknown: {set(sizes) - labels}"
    small = {label: size for label, size in sizes.items() if size[0] < MIN_PRINTED_SIZE - 0.01}
    assert not small, f"figure text below {MIN_PRINTED_SIZE} pt: {small}"


def test_two_builds_of_the_pdf_are_byte_identical(workdir):
    if not latex_installed():
        pytest.skip("no LaTeX toolchain")
    # up to date first: an earlier test may have rerun the claims (whose timing values change) without the report
    result = snakemake(workdir, "--", "paper/ms.pdf")
    assert result.returncode == 0, result.stderr[-2000:]
    first = (workdir / "paper" / "ms.pdf").read_bytes()
    result = snakemake(workdir, "--forcerun", "manuscript", "--", "paper/ms.pdf")
    assert result.returncode == 0, result.stderr[-2000:]
    assert (workdir / "paper" / "ms.pdf").read_bytes() == first
    if shutil.which("pdfinfo"):
        info = subprocess.run(["pdfinfo", str(workdir / "paper" / "ms.pdf")], capture_output=True, text=True).stdout
        assert "Title:           Particle methods" in info and "Author:" in info


@pytest.fixture(scope="module")
def report(workdir, tmp_path_factory):
    """The browsable report a user gets (`snakemake --report report.zip`), made once for the tests that read it:
    (its archive, the folder it is unpacked in)."""
    import zipfile

    folder = tmp_path_factory.mktemp("report")
    archive = folder / "report.zip"
    result = snakemake(workdir, "--report", str(archive))
    assert result.returncode == 0, result.stderr[-2000:]
    with zipfile.ZipFile(archive) as opened:
        opened.extractall(folder)
    return archive, folder


def test_browsable_report_has_every_figure_with_its_caption(report):
    """Every figure is in the report with its own caption, led by its label: a plot batch draws several figures in one
    job, whose captions are all its params (rules/registry.smk, caption_template)."""
    html = (report[1] / "report" / "report.html").read_text()
    shown = {name for name in EXPECTED_FIGURES if name.endswith(".png") and name in html}
    assert shown == {name for name in EXPECTED_FIGURES if name.endswith(".png")}
    captions = dict(re.findall(r'"(figures/\w+/\w+\.png)": \{[^{}]*?"caption": "((?:[^"\\]|\\.)*)"', html))
    for paper in registry.PAPERS.values():
        for figure in paper.figures:
            caption = captions.get(f"figures/{paper.id}/{figure.name}.png", "")
            lead = f"<p>{paper.label(figure.name)}" + (" (our own study" if figure.ours else ". ")
            assert caption.startswith(lead), (figure.name, caption[:200])
    assert "Morse kernels" in captions["figures/blob/fig8.png"] and "Brenier-Grenier hull" in captions[
        "figures/sticky/fig1.png"]


# Clicks through the browsable report as its reader does: a menu entry by its label, a result's eye button.
NAVIGATION = """
const sleep = ms => new Promise(resolve => setTimeout(resolve, ms));
async function find(pick, what) {
  for (let i = 0; i < 100; i++) { const found = pick(); if (found) return found; await sleep(100); }
  throw new Error('not shown: ' + what);
}
async function menu(label) {
  (await find(() => [...document.querySelectorAll('li > a')].find(a => a.textContent.trim() === label), label)).click();
  await sleep(300);
}
async function view(name) {
  const row = await find(() => [...document.querySelectorAll('tr')].find(
    row => row.cells.length && row.cells[0].textContent.trim().endsWith(name)), name);
  row.querySelector('a').click();
  await sleep(500);
}
"""


def test_browsable_report_shows_the_claims_table_and_a_figure_in_chromium(workdir, report, tmp_path):
    """The report a user gets (report.zip) opened in headless Chromium: the claims table shows every claim as a
    table, and our own figures are marked and shown."""
    import zipfile

    import chromium

    if chromium.executable() is None:
        pytest.skip(chromium.MISSING)
    archive, folder = report
    with zipfile.ZipFile(archive) as opened:
        names = opened.namelist()
    latex = latex_installed()
    for shipped in ("claims.html", "versions.html", "sticky.html", *(["ms.pdf"] if latex else [])):
        assert any(name.endswith(shipped) for name in names), shipped
    page = (folder / "report" / "report.html").as_uri()
    claims = list(csv.DictReader((workdir / "results" / "claims.csv").open()))
    blob = registry.PAPERS["blob"]
    name = next(entry.name for entry in blob.figures if entry.ours)
    ours = blob.label(name)  # Figure Blob A1, as the PDF labels it
    with chromium.Browser() as browser:
        browser.open(page)
        landing = browser.evaluate("document.body.innerText")
        assert "results/claims.md" not in landing and "three papers" in landing and "claims.html" in landing
        browser.evaluate(f"(async () => {{ {NAVIGATION} await menu('Claims and versions'); "
                         "await view('claims.html'); })()")
        width, height = browser.evaluate(
            "(r => [r.width, r.height])(document.querySelector('iframe').getBoundingClientRect())")
        assert width > 500 and height > 500
        (frame,) = browser.frames()
        rows, shown = browser.evaluate(
            "(table => [table.rows.length, table.getBoundingClientRect().height])(document.querySelector('table'))",
            frame=frame["id"])
        assert rows == len(claims) + 1 and shown > 1000  # the heading and one row a claim, laid out
        text = browser.evaluate("document.body.innerText", frame=frame["id"])
        assert claims[0]["id"] in text and "\\|" not in text
        browser.screenshot(tmp_path / "claims.png")
        browser.open(page)
        figure = name + ".png"
        browser.evaluate(f"(async () => {{ {NAVIGATION} await menu('Figures (blob)'); await menu('{ours}'); "
                         f"await view('{figure}'); }})()")
        natural, shown = browser.evaluate(
            f"(image => [image.naturalWidth, image.getBoundingClientRect().width])"
            f"([...document.querySelectorAll('img')].find(image => image.src.endsWith('{figure}')))")
        assert natural > 500 and shown > 300
        browser.screenshot(tmp_path / "figure.png")


def test_versions_are_recorded(workdir):
    versions = (workdir / "results" / "versions.md").read_text()
    assert "| numba |" in versions and "| python |" in versions
