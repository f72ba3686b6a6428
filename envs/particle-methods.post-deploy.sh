#!/usr/bin/env bash
# Snakemake runs this inside the new conda environment once it is created: install the
# particle_methods package of this clone (its dependencies come from particle-methods.yaml).
# PARTICLE_METHODS_SOURCE is set by rules/common.smk to the repository root.
set -euo pipefail
python -m pip install --no-deps --editable "${PARTICLE_METHODS_SOURCE:?run through snakemake}"
