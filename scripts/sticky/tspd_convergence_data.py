"""Theorem 4.4: the iterated TSPD against references, sweeping Delta at fixed n and n at small Delta.

Errors are W1^(d) of (1.10), the sum over types of the L1 distances between empirical CDFs
(exact for point masses). The Delta sweep compares with the same n and a much smaller Delta (the
C Delta term); the n sweep compares with a large-n run (the O(W1(m, mu_0) + t/n) term). Each
reference is also compared with a run of half its resolution, to show its own error is small.
"""

import numpy as np

from particle_methods.norms import w1_to_measure
from particle_methods.sticky.cases import (
    configuration_distance,
    psystem_initial_configuration,
    psystem_initial_measures,
)
from particle_methods.sticky.mspd import mspd_positions
from particle_methods.systems import PSystem
from particle_replication.workflow import logged, progress, save_results


def snapshots(case, x0, system, n, delta, times):
    """Iterated TSPD with n particles per type and step delta, at each of ``times`` (multiples of delta)."""
    steps = np.rint(np.asarray(times) / delta).astype(np.int64)
    if not np.allclose(steps * delta, times, rtol=1e-9, atol=0.0):
        raise ValueError(f"every time must be a multiple of Delta = {delta}")
    state, done, out = psystem_initial_configuration(case, x0, n), 0, []
    for target in steps:
        state = mspd_positions(state, system, delta, int(target - done))
        done = target
        out.append(state)
    return out



def run(system_params, cases, p, output):
    system = PSystem(nu=system_params["nu"], kappa=system_params["kappa"])
    times, deltas, n_values = (np.asarray(p[key], dtype=float) for key in ("times", "deltas", "n_values"))
    shape = (len(p["cases"]), times.size)
    delta_n = np.asarray(p["delta_n"], dtype=np.int64)
    delta_errors = np.empty((len(p["cases"]), delta_n.size, times.size, deltas.size))
    n_errors, bounds = np.empty((*shape, n_values.size)), np.empty((*shape, n_values.size))
    delta_reference_gap, n_reference_gap = np.empty(shape), np.empty(shape)
    for c, name in enumerate(p["cases"]):
        x0 = cases[name]["x0"]
        gaps = []
        for m, n in enumerate(delta_n):
            progress(f"{name}: Delta sweep, n = {n}, reference Delta = {p['reference_delta']:g}")
            reference = snapshots(name, x0, system, int(n), p["reference_delta"], times)
            coarser = snapshots(name, x0, system, int(n), 2 * p["reference_delta"], times)
            gaps.append([configuration_distance(a, b) for a, b in zip(reference, coarser)])
            for j, delta in enumerate(deltas):
                run_ = snapshots(name, x0, system, int(n), delta, times)
                delta_errors[c, m, :, j] = [configuration_distance(a, b) for a, b in zip(run_, reference)]
        delta_reference_gap[c] = np.max(gaps, axis=0)
        progress(f"{name}: n sweep, Delta = {p['n_delta']:g}, reference n = {p['reference_n']}")
        reference = snapshots(name, x0, system, p["reference_n"], p["n_delta"], times)
        coarser = snapshots(name, x0, system, p["reference_n"] // 2, p["n_delta"], times)
        n_reference_gap[c] = [configuration_distance(a, b) for a, b in zip(reference, coarser)]
        measures = psystem_initial_measures(name, x0)
        for j, n in enumerate(n_values.astype(np.int64)):
            run_ = snapshots(name, x0, system, int(n), p["n_delta"], times)
            n_errors[c, :, j] = [configuration_distance(a, b) for a, b in zip(run_, reference)]
            initial = sum(w1_to_measure(m, x) for m, x in zip(measures, psystem_initial_configuration(name, x0, n)))
            # Theorem 4.4 without its constants: W1^(d)(m, mu_0[x(n)]) + t d L_LC / n.
            bounds[c, :, j] = initial + times * system.d * system.speed_lipschitz / n
    save_results(output, cases=np.array(p["cases"]), times=times, deltas=deltas, delta_n=delta_n,
                 reference_delta=p["reference_delta"], delta_errors=delta_errors,
                 delta_reference_gap=delta_reference_gap, n_values=n_values, n_delta=p["n_delta"],
                 reference_n=p["reference_n"], n_errors=n_errors, bounds=bounds, n_reference_gap=n_reference_gap)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.system, snakemake.params.cases, snakemake.params.cfg, snakemake.output[0])  # noqa: F821
