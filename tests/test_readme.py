"""The README's Python example runs as written."""

import re
from pathlib import Path


def test_readme_python_example_runs():
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, flags=re.DOTALL)
    assert blocks
    namespace = {}
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)
    assert abs(namespace["error"] - namespace["t"] / (4 * namespace["n"])) < 1e-12
    assert namespace["linf_error"] < 0.2
    assert namespace["exact_x"].shape == namespace["x"][0].shape and namespace["particle"].densities is not None
