"""The front page and the usage guide: the Python examples run as written, the README stays a front
page, and its table of failing claims is the expected-verdicts file's."""

import re
from pathlib import Path

from particle_replication.claims import cause_counts, read_verdicts
from particle_replication.readme import cause_sentence

ROOT = Path(__file__).resolve().parents[1]


def test_usage_examples_run():
    usage = (ROOT / "docs" / "usage.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", usage, flags=re.DOTALL)
    assert blocks
    namespace = {}
    for block in blocks:
        exec(compile(block, "docs/usage.md", "exec"), namespace)
    assert abs(namespace["error"] - namespace["t"] / (4 * namespace["n"])) < 1e-12
    assert namespace["linf_error"] < 0.2
    assert namespace["exact_x"].shape == namespace["x"][0].shape and namespace["particle"].densities is not None


def test_readme_is_a_front_page_whose_failures_are_the_expected_ones():
    readme = (ROOT / "README.md").read_text()
    assert len(readme.splitlines()) <= 160
    listed = re.findall(r"^\| `([a-z0-9_.]+)` \| (?:paper|derived|check) \| ([a-z-]+) \|", readme, flags=re.MULTILINE)
    verdicts = read_verdicts(ROOT / "config" / "verdicts.yaml")
    expected = {i: verdict.cause for i, verdict in verdicts.items() if verdict.status == "fail"}
    assert dict(listed) == expected and len(listed) == len(expected)
    sentence = " ".join(readme.split("## Results")[1].split("| claim |")[0].split())
    assert cause_sentence(cause_counts(verdicts)) in sentence
    reasons = dict(re.findall(r"^\| `([a-z0-9_.]+)` \| (?:paper|derived|check) \| [a-z-]+ \| (.*) \|$", readme,
                              flags=re.MULTILINE))
    regenerate = "python -m particle_replication.readme --write"
    assert reasons == {i: verdicts[i].reason.replace("|", "\\|") for i in expected}, regenerate
    for path in ("docs/running.md", "docs/robustness.md", "docs/usage.md", "config/README.md", "benchmarks/README.md",
                 "CONTRIBUTING.md", "paper/README.md"):
        assert f"`{path}`" in readme and (ROOT / path).exists()
