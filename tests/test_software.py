"""The conda environment of the rules: same dependencies as pyproject.toml, and a post-deploy
script that installs this clone's package into the environment it runs in.

Conda channels cannot be reached where these tests run, so the environment is never created
here; the script is exercised in a virtual environment instead, which is what it sees once conda
has activated the new environment.
"""

import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

from particle_replication.paths import read_yaml

ROOT = Path(__file__).resolve().parents[1]
ENVIRONMENT = ROOT / "envs" / "particle-methods.yaml"
POST_DEPLOY = ROOT / "envs" / "particle-methods.post-deploy.sh"
CONDA_NAMES = {"matplotlib-base": "matplotlib"}
NOT_NEEDED_BY_RULES = {"snakemake"}


def requirement(text):
    name, bound = re.fullmatch(r"([A-Za-z0-9_.-]+)\s*(.*)", text).groups()
    return CONDA_NAMES.get(name, name).lower(), bound.replace(" ", "")


def test_environment_lists_the_runtime_dependencies_of_pyproject():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    # the rules run the numerics and the replication layer: the dependencies and the pipeline extra's
    wanted = dict(map(requirement, project["dependencies"] + project["optional-dependencies"]["pipeline"]))
    for name in NOT_NEEDED_BY_RULES:
        wanted.pop(name)
    listed = dict(map(requirement, read_yaml(ENVIRONMENT)["dependencies"]))
    assert listed.pop("python") == "=3.11"
    assert listed.pop("pip") == ""
    assert listed == wanted


def run_post_deploy(tmp_path, source):
    environment = tmp_path / "env"
    # Without a pip of its own (ensurepip took 3 s): the system's, seen through the system site-packages, installs
    # into the environment whose Python runs it.
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", str(environment)],
                   check=True)
    variables = {**os.environ, "PATH": f"{environment / 'bin'}{os.pathsep}{os.environ['PATH']}"}
    variables.pop("PARTICLE_METHODS_SOURCE", None)
    if source is not None:
        variables["PARTICLE_METHODS_SOURCE"] = str(source)
    result = subprocess.run(["bash", str(POST_DEPLOY)], env=variables, capture_output=True, text=True,
                            timeout=300, cwd=tmp_path)
    return environment, result


def test_post_deploy_installs_this_clone_into_the_active_environment(tmp_path):
    environment, result = run_post_deploy(tmp_path, ROOT)
    assert result.returncode == 0, result.stderr[-2000:]
    located = subprocess.run([str(environment / "bin" / "python"), "-c",
                              "import particle_methods, sys; print(particle_methods.__file__); print(sys.prefix)"],
                             capture_output=True, text=True, check=True, cwd=tmp_path).stdout.split()
    assert Path(located[0]).is_relative_to(ROOT / "src")
    assert Path(located[1]) == environment
    assert list((environment / "lib").glob("python3*/site-packages/__editable__.particle_methods*"))


def test_post_deploy_without_the_source_variable_names_it(tmp_path):
    _, result = run_post_deploy(tmp_path, None)
    assert result.returncode != 0
    assert "PARTICLE_METHODS_SOURCE" in result.stderr
