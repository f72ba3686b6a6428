"""Layout rules that keep the code base extensible: no shipped module (packages, pipeline scripts, benchmarks,
notebooks) reaches into another's private names (tests may: they check a module's internals), and the
numerics load none of the pipeline's software."""

import ast
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = [path for folder in ("src", "scripts", "benchmarks", "notebooks") for path in (ROOT / folder).rglob("*.py")]
PACKAGES = ("particle_methods", "particle_replication")


def private_imports(path: Path) -> list[str]:
    """`from particle_methods... import _name`, and `module._name` on a module imported from the packages."""
    tree = ast.parse(path.read_text())
    found, modules = [], set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            package = node.level > 0 or (node.module or "").startswith(PACKAGES)
            for alias in node.names:
                if package and alias.name.startswith("_") and not alias.name.startswith("__"):
                    found.append(f"{path.relative_to(ROOT)}:{node.lineno} imports {alias.name}")
                elif package:
                    modules.add(alias.asname or alias.name)
        elif isinstance(node, ast.Import):
            modules.update(alias.asname or alias.name for alias in node.names
                           if alias.name.startswith(PACKAGES))
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__")
                and isinstance(node.value, ast.Name) and node.value.id in modules):
            found.append(f"{path.relative_to(ROOT)}:{node.lineno} reads {node.value.id}.{node.attr}")
    return found


def test_no_module_uses_a_private_name_of_another():
    problems = [problem for path in SOURCES for problem in private_imports(path)]
    assert not problems, "\n".join(problems)


def test_the_rule_sees_both_forms(tmp_path):
    sample = tmp_path / "sample.py"
    sample.write_text("from particle_methods.sticky.spd import _secret\nfrom particle_methods import jit\njit._x\n")
    global ROOT
    root, ROOT = ROOT, tmp_path
    try:
        assert len(private_imports(sample)) == 2
    finally:
        ROOT = root


#: What the numerics must not load: the pipeline's software and the replication package itself.
PIPELINE_SOFTWARE = ("snakemake", "IPython", "jupytext", "nbclient", "matplotlib", "yaml", "particle_replication")


def test_the_numerics_load_none_of_the_pipelines_software():
    """Every module of particle_methods imported in a fresh interpreter: none of the pipeline's software loads
    (numba, imported first, loads yaml itself when it is installed, to read an optional .numba_config.yaml)."""
    code = ("import importlib, pkgutil, sys\n"
            "import numba\n"
            "before = set(sys.modules)\n"
            "import particle_methods\n"
            "for module in pkgutil.walk_packages(particle_methods.__path__, 'particle_methods.'):\n"
            "    importlib.import_module(module.name)\n"
            "loaded = {name.split('.')[0] for name in set(sys.modules) - before}\n"
            f"print(sorted(loaded & set({PIPELINE_SOFTWARE!r})))\n")
    loaded = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "[]"


def third_party_imports(package: Path) -> set[str]:
    """Top-level names of the modules outside the standard library and ``package`` that its modules import."""
    names = set()
    for path in package.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Import):
                names.update(alias.name.split(".")[0] for alias in node.names)
            elif isinstance(node, ast.ImportFrom) and not node.level:
                names.add(node.module.split(".")[0])
    return names - set(sys.stdlib_module_names) - {package.name, "__future__"}


def test_the_numerics_install_alone():
    """`pip install particle-methods` installs what the numerics import and nothing else; the pipeline's software
    comes with the `pipeline` extra, which the test extra includes (.ci/run installs both ways)."""
    import re
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    name = lambda requirement: re.match(r"[A-Za-z0-9_.-]+", requirement).group().lower()  # noqa: E731
    numerics = {name(requirement) for requirement in project["dependencies"]}
    assert numerics == third_party_imports(ROOT / "src" / "particle_methods")
    pipeline = {name(requirement) for requirement in project["optional-dependencies"]["pipeline"]}
    assert {"snakemake", "matplotlib", "jupytext", "nbclient", "ipykernel", "pyyaml"} <= pipeline
    assert not pipeline & numerics
    assert "particle-methods[pipeline]" in project["optional-dependencies"]["test"]


def test_plot_scripts_give_text_sizes_relative_to_the_printed_style():
    """Sizes in points would not follow plotting.new_figure's scaling to the printed width (a 16 in figure
    printed its 7 pt legends at 2.8 pt): scripts say "small", "x-small", never a number."""
    import re

    pattern = re.compile(r"\b(?:fontsize|labelsize)\s*=\s*[0-9]")
    found = [f"{path.relative_to(ROOT)}:{number}" for path in (ROOT / "scripts").rglob("*.py")
             for number, line in enumerate(path.read_text().splitlines(), 1) if pattern.search(line)]
    assert not found, found


def package_imports(path: Path) -> set[str]:
    """The modules of particle_replication that ``path`` (a module of it) imports, anywhere in its body."""
    package = path.relative_to(ROOT / "src").with_suffix("").parts[:-1]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            base = list(package[:len(package) - node.level + 1]) if node.level else []
            module = [*base, *(node.module.split(".") if node.module else [])]
            found.update(".".join([*module, alias.name]) for alias in node.names)
            found.add(".".join(module))
        elif isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
    return found


def test_no_two_modules_of_the_pipeline_import_each_other():
    modules = {".".join(path.relative_to(ROOT / "src").with_suffix("").parts): path
               for path in (ROOT / "src" / "particle_replication").rglob("*.py") if path.name != "__init__.py"}
    imports = {name: package_imports(path) & set(modules) for name, path in modules.items()}
    circles = sorted(f"{a} <-> {b}" for a in imports for b in imports[a] if a < b and a in imports.get(b, ()))
    assert not circles, "\n".join(circles)


def test_every_claim_is_written_with_keywords():
    """claim(c.<comparison>, <name>, kind=..., source=..., figure=..., text=..., published=..., measured=...,
    tolerance=...): nothing positional after the comparison and the name (CONTRIBUTING, Extending, 4)."""
    positional = []
    for path in sorted((ROOT / "src" / "particle_replication" / "verdicts").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "claim"
                    and node.args and isinstance(node.args[0], ast.Attribute) and len(node.args) > 2):
                positional.append(f"{path.name}:{node.lineno}")
    assert not positional, positional
