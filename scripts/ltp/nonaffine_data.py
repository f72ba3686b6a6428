"""Convergence in h on flows that are not affine, and the centre of mass on asymmetric data.

(a) W = |x|^a/a with a singular W'' (a < 2) from (6.1): LTP at several h against a run with a
    finer ``reference_h`` at the same dt (so that the time error, common to both, cancels), and
    the reference against a run with twice its h, to show that its own error is small.
(b) W = |x|^a/a - |x|^b/b from (6.1), which is not symmetric: the drift of the centre of mass
    sum_k omega_k x_k over the run, at several h (not conserved by LTP for a non-quadratic W)."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
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
    save_results(output, h_values=h_values, errors=errors, reference_h=reference_h, reference_gap=reference_gap,
                 order_points=p["order_points"], label=np.array(w.name), t=p["t"], dt=p["dt"],
                 grid=grid, reference=reference, centre_h=np.asarray(centre["h_values"], float),
                 centre_drift=np.array(drifts), centre_label=np.array(w_centre.name))


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
