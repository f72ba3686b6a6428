"""Absolute roots of the generated folders, so that notebooks and scripts run from anywhere.

The pipeline's working directory holds ``results/`` and ``figures/``; by default that is the
repository containing this package. Set ``PARTICLE_METHODS_WORKDIR`` to read another run
(the tests point it at the quick pipeline's scratch directory).
"""

from __future__ import annotations

import os
from pathlib import Path

REPOSITORY = Path(__file__).resolve().parents[2]
WORKDIR = Path(os.environ.get("PARTICLE_METHODS_WORKDIR", REPOSITORY)).resolve()
RESULTS = WORKDIR / "results"
FIGURES = WORKDIR / "figures"


def read_yaml(path):
    """The YAML file at ``path`` as Python data, through libyaml when PyYAML has it (the same safe loader and
    resolver, about ten times faster: every Snakemake start reads the configuration, its schema and the expected
    verdicts)."""
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    return yaml.load(Path(path).read_text(), Loader=loader)
