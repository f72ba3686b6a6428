"""Theorem 4.4: error of the iterated TSPD, O(t/n + Delta) plus the initial W1 error."""

import math

import numpy as np

from particle_methods.norms import w1_between_samples
from particle_methods.sticky.cases import psystem_initial_configuration
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.sticky.psystem import PSystem
from particle_methods.workflow import logged, progress, save_results


def final_state(case, x0, system, n, t, delta_times_n):
    """Iterated TSPD at time t with n particles per type and Delta close to delta_times_n / n."""
    steps = max(1, math.ceil(n * t / delta_times_n))
    return mspd_positions(psystem_initial_configuration(case, x0, n), system, t / steps, steps), t / steps


def run(system_params, case_params, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    case, x0, t = p["case"], case_params["x0"], p["t"]
    progress(f"reference: n = {p['reference_n']}")
    reference, reference_delta = final_state(case, x0, system, p["reference_n"], t, p["reference_delta_times_n"])
    n_values = np.asarray(p["n_values"], dtype=np.int64)
    errors, deltas = np.empty(n_values.size), np.empty(n_values.size)
    for j, n in enumerate(n_values):
        progress(f"n = {n}")
        state, deltas[j] = final_state(case, x0, system, int(n), t, p["delta_times_n"])
        # W1^(d) of (1.10): the sum over types of the L1 distances between CDFs.
        errors[j] = sum(w1_between_samples(a, b) for a, b in zip(state, reference))
    save_results(output, n_values=n_values, deltas=deltas, errors=errors, reference_n=p["reference_n"],
                 reference_delta=reference_delta, t=t)


with logged(snakemake.log[0]):  # noqa: F821
    run(snakemake.params.system, snakemake.params.case, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
