"""Convergence in h on flows that are not affine, and the centre of mass on asymmetric data.

(a) W = |x|^a/a with a singular W'' (a < 2) from (6.1): LTP at several h against a run with a
    finer ``reference_h`` at the same dt (so that the time error, common to both, cancels), and
    the reference against a run with twice its h, to show that its own error is small.
(b) W = |x|^a/a - |x|^b/b from (6.1), which is not symmetric: the drift of the centre of mass
    sum_k omega_k x_k over the run, at several h (not conserved by LTP for a non-quadratic W).
(c) Theorems 1, 3 and 4 (particle_methods.ltp.theorems): Theorem 1's time error on a flow that is not affine;
    Theorem 3 on atomic data at a fixed dt, and on the indicator (6.2) with dt proportional to h; Theorem 4 on
    data (6.3), which satisfy its hypotheses, by the distances between runs at h and h/2."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.ltp.theorems import theorem1_time_error, theorem3_atomic, theorem3_rough, theorem4_differences
from particle_methods.norms import grid_errors
from particle_replication.workflow import logged, progress, save_results


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("power", a=p["a"])
    grid = np.linspace(initial.lower, initial.upper, p["grid_points"])
    h_values = np.asarray(p["h_values"], float)
    reference_h = float(p["reference_h"])
    densities = {}
    for h in [*h_values, 2 * reference_h, reference_h]:
        if h not in densities:
            progress(f"{w.name}: h = {h:g}, dt = {p['dt']:g}, t = {p['t']:g}")
            densities[h] = simulate(initial, w, h, p["dt"], p["t"]).at(-1).density(grid)
    reference = densities[reference_h]
    errors = np.array([grid_errors(densities[h], reference, grid) for h in h_values])
    reference_gap = np.array(grid_errors(densities[2 * reference_h], reference, grid))

    centre = p["centre_of_mass"]
    w_centre = potential("attractive_repulsive", a=centre["a"], b=centre["b"])
    drifts = []
    for h in centre["h_values"]:
        sim = simulate(initial, w_centre, h, centre["dt"], p["t"])
        drifts.append(abs(sim.at(-1).centre_of_mass - sim.at(0).centre_of_mass))
        progress(f"{w_centre.name}: h = {h:g}: centre of mass drift {drifts[-1]:.3e}")
    progress("Theorem 1: time error at fixed h")
    theorem1 = theorem1_time_error(p["theorem1"], p["grid_points"])
    progress("Theorem 3: atomic data, fixed dt; the indicator with dt proportional to h")
    theorem3 = {**theorem3_atomic(p["theorem3_atomic"]), **theorem3_rough(p["theorem3"], p["grid_points"])}
    progress("Theorem 4: data (6.3), dt proportional to h^2")
    theorem4 = theorem4_differences(p["theorem4"], p["grid_points"])
    save_results(output, **theorem1, **theorem4, **theorem3, h_values=h_values, errors=errors, reference_h=reference_h,
                 reference_gap=reference_gap, order_points=p["order_points"], label=np.array(w.name), t=p["t"],
                 dt=p["dt"], grid=grid, reference=reference, centre_h=np.asarray(centre["h_values"], float),
                 centre_drift=np.array(drifts), centre_label=np.array(w_centre.name))


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
