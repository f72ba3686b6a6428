"""The robustness run: every claim recomputed under variants that change results at the level of rounding.

A verdict must be a property of the mathematics, not of the machine that computed it. Each variant of the
configuration's ``robustness.variants`` reruns the whole pipeline up to its claims table, in a Snakemake run of
its own under ``robustness/<variant>/`` of the run's root, with one change that a different machine could make:

- ``env``: environment variables read by the libraries, e.g. one thread (``NUMBA_NUM_THREADS``), another
  family of OpenBLAS kernels (``OPENBLAS_CORETYPE``), NumPy's SIMD dispatch without AVX-512
  (``NPY_DISABLE_CPU_FEATURES``, of which the names this NumPy dispatches are kept: :func:`variant_environment`),
  numba's machine code for another CPU (``NUMBA_CPU_NAME``);
- ``nudge``: every initial datum moved by a few units in the last place (the configuration key ``nudge``,
  :mod:`particle_methods.perturbation`);
- ``load``: a process spinning on each of the run's cores while the variant runs.

:func:`compare` then sets every claim of every variant beside the run's own: a verdict that differs in any
variant is a defect of its measure (never a reason to move a threshold), and the spread of each claim's signed
distance from its threshold over the run and its variants is recorded (:func:`spreads`, written to
``results/robustness/spreads.yaml`` and, once reviewed, copied into ``config/spreads.yaml`` with ``record``), so
that the claims table gives each verdict its margin in units of that spread.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import shlex
import subprocess
import sys
import time
from pathlib import Path

import yaml

from .claims import Spread, margin_of, read_claims
from .paths import read_yaml


def _numpy_cpu() -> tuple[list[str], dict]:
    """(the CPU feature groups this NumPy's SIMD dispatch knows, every feature with whether it is enabled)."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # NumPy 1.x
        from numpy.core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    return list(__cpu_dispatch__), dict(__cpu_features__)


def numpy_dispatch() -> list[str]:
    """The CPU feature groups this NumPy's SIMD dispatch knows (the names ``NPY_DISABLE_CPU_FEATURES`` takes)."""
    return _numpy_cpu()[0]


def effective() -> dict:
    """What the libraries use in this process: numba's threads and CPU, the BLAS kernels, and the NumPy dispatch
    groups enabled."""
    import numba
    from threadpoolctl import threadpool_info

    dispatch, features = _numpy_cpu()
    blas = [info.get("architecture", "?") for info in threadpool_info() if info.get("user_api") == "blas"]
    return {"numba_threads": numba.config.NUMBA_NUM_THREADS, "numba_cpu": numba.config.CPU_NAME or "host",
            "blas": ", ".join(blas), "numpy_dispatch": " ".join(name for name in dispatch if features.get(name))}


def variant_environment(variant: dict, base: dict | None = None) -> dict:
    """The environment of a variant's run: ``base`` (this process's) with the variant's ``env``, of whose
    ``NPY_DISABLE_CPU_FEATURES`` only the names this NumPy dispatches are kept (an older NumPy calls the
    AVX-512 groups by other names, and a name it does not dispatch is not its to disable)."""
    environment = dict(os.environ if base is None else base)
    for key, value in (variant.get("env") or {}).items():
        if key == "NPY_DISABLE_CPU_FEATURES":
            known = set(numpy_dispatch())
            value = " ".join(name for name in value.split() if name in known)
        environment[key] = value
    return environment


def environment_exports(name: str, config_path="config/config.yaml") -> str:
    """Shell lines exporting the environment of the variant ``name`` of the configuration at ``config_path``
    (:func:`variant_environment`), so that a shell runs anything under it, the tests included:
    ``eval "$(python -m particle_replication.robustness environment combined)"``. A variant's nudge and load are
    the pipeline's, not an environment's: they are left out."""
    variants = read_yaml(config_path)["robustness"]["variants"]
    if not isinstance(name, str) or name not in variants:
        raise ValueError(f"variant must be one of {', '.join(variants)}, got {name!r}")
    environment = variant_environment(variants[name], {})
    return "\n".join(f"export {key}={shlex.quote(value)}" for key, value in environment.items())


def variant_configuration(config: dict, variant: dict) -> dict:
    """The configuration of a variant's run: the run's own, with the variant's nudge (or none)."""
    return {**config, "output_root": ".", "nudge": variant.get("nudge") or {"ulps": 0, "seed": 0}}


def probe(environment: dict) -> dict:
    """What the libraries actually use under ``environment``: numba's threads and CPU, the BLAS kernels and the
    NumPy dispatch groups enabled (a variant that asks for what the machine cannot do shows it here)."""
    code = "import json; from particle_replication.robustness import effective; print(json.dumps(effective()))"
    result = subprocess.run([sys.executable, "-c", code], env=environment, capture_output=True, text=True,
                            timeout=300)
    if result.returncode != 0:
        raise RuntimeError(f"the environment probe failed: {result.stderr[-2000:]}")
    return json.loads(result.stdout.strip().splitlines()[-1])


@contextlib.contextmanager
def spinning(count: int):
    """``count`` processes spinning on the cores for the duration of the block (the ``load`` variant)."""
    processes = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(count)]
    try:
        yield
    finally:
        for process in processes:
            process.kill()
        for process in processes:
            process.wait()


def run_variant(name: str, variant: dict, config: dict, snakefile, directory, cores: int, log) -> None:
    """Run the pipeline up to its claims table under one variant, in ``directory`` (its own Snakemake run,
    which redoes only what changed since its last run), writing its log to ``log``."""
    directory = Path(directory).resolve()
    directory.mkdir(parents=True, exist_ok=True)
    overlay = directory / "variant.yaml"
    overlay.write_text(yaml.safe_dump(variant_configuration(config, variant), sort_keys=False))
    environment = variant_environment(variant)
    effective = probe(environment)
    (directory / "environment.json").write_text(json.dumps({"variant": name, **variant, "effective": effective},
                                                           indent=1) + "\n")
    command = [sys.executable, "-m", "snakemake", "-s", str(Path(snakefile).resolve()), "--directory", str(directory),
               "--configfile", str(overlay), "--cores", str(cores), "--rerun-incomplete", "results/claims.csv"]
    with Path(log).open("w") as handle, spinning(cores if variant.get("load") else 0):
        handle.write(f"variant {name}: {json.dumps(variant)}\neffective: {json.dumps(effective)}\n")
        handle.flush()
        start = time.perf_counter()
        result = subprocess.run(command, env=environment, stdout=handle, stderr=subprocess.STDOUT,
                                cwd=Path(snakefile).resolve().parent)
        handle.write(f"variant {name}: {time.perf_counter() - start:.0f} s, exit code {result.returncode}\n")
    if result.returncode != 0:
        raise RuntimeError(f"the variant {name} failed (exit code {result.returncode}): see {log}")


def _float(text: str) -> float:
    return float(text) if text else math.nan


def _spread(values) -> float:
    """Largest minus smallest of ``values``: 0 when all are equal (infinite ones included), inf when some are
    non-finite and the others differ from them."""
    values = list(values)
    if all(v == values[0] for v in values):
        return 0.0
    if not all(math.isfinite(v) for v in values):
        return math.inf
    return max(values) - min(values)


def spreads(tables: dict) -> dict[str, Spread]:
    """Claim id -> :class:`Spread` of its signed distance and of its measured value over the tables
    (name -> claims), for the claims present in every table (a check that abstained in a table is left out
    of its spread there, as it is of the comparison)."""
    ids = set.intersection(*({claim.id for claim in claims} for claims in tables.values()))
    rows = {name: {claim.id: claim for claim in claims} for name, claims in tables.items()}
    out = {}
    for i in sorted(ids):
        decided = [rows[name][i] for name in rows if rows[name][i].status != "abstain"] or [rows[next(iter(rows))][i]]
        distance = _spread(_float(claim.distance) for claim in decided)
        out[i] = Spread(distance, _spread(_float(claim.value) for claim in decided),
                        min(margin_of(_float(claim.distance), distance) for claim in decided), decided[0].kind)
    return out


def compare(baseline: list, variants: dict) -> list[str]:
    """Every difference of a variant from the baseline: a verdict changed, a claim missing or added (a check
    that abstained, on a loaded machine, is no difference)."""
    base = {claim.id: claim for claim in baseline}
    problems = []
    for name, claims in variants.items():
        rows = {claim.id: claim for claim in claims}
        for i, claim in base.items():
            other = rows.get(i)
            if other is None:
                problems.append(f"{name}: MISSING {i}")
            elif "abstain" not in (claim.status, other.status) and other.status != claim.status:
                problems.append(f"{name}: CHANGED {i}: {claim.status} -> {other.status} (measured {claim.measured} "
                                f"-> {other.measured}, tolerance {claim.tolerance})")
        problems += [f"{name}: NEW {i}" for i in rows if i not in base]
    return problems


def report(variants: dict, environments: dict, problems: list[str], spread: dict[str, Spread], margin_min: float,
           run: str) -> str:
    """Markdown: the variants (what each changed, what the libraries then used, how many verdicts moved:
    ``problems``, from :func:`compare`), then every claim whose margin (``spread``, from :func:`spreads`) is below
    ``margin_min`` spreads."""
    lines = [f"# Robustness of the {run} run's verdicts", "",
             f"{len(variants)} variants beside the run itself; {len(problems)} verdicts differ.", "",
             "| variant | change | BLAS kernels | NumPy dispatch | numba CPU, threads | verdicts changed | "
             "abstained |", "|---|---|---|---|---|---|---|"]
    for name, claims in variants.items():
        info = environments.get(name, {})
        changes = [f"{k}={v}" for k, v in (info.get("env") or {}).items()]  # every change the variant makes
        if info.get("nudge"):
            changes.append(f"initial data nudged by up to {info['nudge']['ulps']} ulps (seed {info['nudge']['seed']})")
        if info.get("load"):
            changes.append("a spinning process on every core")
        change = "; ".join(changes)
        effective = info.get("effective", {})
        changed = sum(problem.startswith(f"{name}: ") for problem in problems)
        lines.append(f"| {name} | {change} | {effective.get('blas', '?')} | {effective.get('numpy_dispatch', '?')} | "
                     f"{effective.get('numba_cpu', '?')}, {effective.get('numba_threads', '?')} | {changed} | "
                     f"{sum(claim.status == 'abstain' for claim in claims)} |")
    lines += ["", *(f"- {problem}" for problem in problems)] if problems else []
    shaky = sorted((s.margin, i) for i, s in spread.items() if s.margin < margin_min)
    lines += ["", f"## Fragile verdicts: {len(shaky)} within {margin_min:g} spreads of their threshold (the smallest "
              "margin over the run and its variants)", ""]
    if shaky:
        lines += ["| claim | kind | margin (spreads) | distance spread | value spread |", "|---|---|---|---|---|"]
        lines += [f"| `{i}` | {spread[i].kind} | {m:.3g} | {spread[i].distance:.3g} | {spread[i].value:.3g} |"
                  for m, i in shaky]
    exact = sum(s.distance == 0 for s in spread.values())
    lines += ["", f"{exact} of {len(spread)} claims have the same distance from their threshold in every variant."]
    return "\n".join(lines) + "\n"


def write_spreads(path, run: str, spread: dict[str, Spread]) -> None:
    """The spreads of one run as a spreads file (``{run: {id: {distance, value}}}``)."""
    section = {i: {"distance": float(s.distance), "value": float(s.value), "margin": float(s.margin), "kind": s.kind}
               for i, s in spread.items()}
    Path(path).write_text(yaml.safe_dump({run: section}, sort_keys=False, width=120))


def record(source, target) -> None:
    """Copy the sections of a robustness run's spreads file into the committed one (``config/spreads.yaml``),
    replacing those runs' sections and keeping the others."""
    new = read_yaml(source) or {}
    target = Path(target)
    old = read_yaml(target) if target.exists() else {}
    header = ("# The spread of every claim's distance from its threshold, and of its measured value, over the\n"
              "# variants of the robustness run (snakemake --cores 2 robustness; docs/robustness.md), per run.\n"
              "# Written by `python -m particle_replication.robustness record <root>/results/robustness/spreads.yaml`\n"
              "# after a robustness run; the claims table's margins and the quick run's value tests read it.\n")
    target.write_text(header + yaml.safe_dump({**(old or {}), **new}, sort_keys=False, width=120))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m particle_replication.robustness", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    summary = sub.add_parser("summarize", help="compare the variants' claims with the run's; exit 1 on a change")
    summary.add_argument("--baseline", required=True, help="the run's own claims table")
    summary.add_argument("--variant", action="append", default=[], metavar="NAME=CLAIMS",
                         help="a variant's claims table (its environment.json beside its results/)")
    summary.add_argument("--run", required=True, help="the run's name in the spreads file (full, quick)")
    summary.add_argument("--margin-min", type=float, default=10.0)
    summary.add_argument("--markdown", required=True)
    summary.add_argument("--spreads", required=True)
    recorder = sub.add_parser("record", help="copy a robustness run's spreads into the committed spreads file")
    recorder.add_argument("source")
    recorder.add_argument("--into", default="config/spreads.yaml")
    exports = sub.add_parser("environment", help="print shell lines exporting a variant's environment variables")
    exports.add_argument("variant")
    exports.add_argument("--config", default="config/config.yaml")
    args = parser.parse_args(argv)
    if args.command == "environment":
        print(environment_exports(args.variant, args.config))
        return 0
    if args.command == "record":
        record(args.source, args.into)
        return 0
    baseline = read_claims(args.baseline)
    variants, environments = {}, {}
    for item in args.variant:
        name, _, path = item.partition("=")
        variants[name] = read_claims(path)
        info = Path(path).parents[1] / "environment.json"
        environments[name] = json.loads(info.read_text()) if info.exists() else {}
    problems = compare(baseline, variants)
    spread = spreads({"run": baseline, **variants})
    text = report(variants, environments, problems, spread, args.margin_min, args.run)
    Path(args.markdown).write_text(text)
    write_spreads(args.spreads, args.run, spread)
    print(text)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
