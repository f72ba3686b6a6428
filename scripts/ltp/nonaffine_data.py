"""Convergence in h on flows that are not affine, and the centre of mass on asymmetric data.

(a) W = |x|^a/a with a singular W'' (a < 2) from (6.1): LTP at several h against a run with a
    finer ``reference_h`` at the same dt (so that the time error, common to both, cancels), and
    the reference against a run with twice its h, to show that its own error is small.
(b) W = |x|^a/a - |x|^b/b from (6.1), which is not symmetric: the drift of the centre of mass
    sum_k omega_k x_k over the run, at several h (not conserved by LTP for a non-quadratic W).
(c) Theorem 4 under its own hypotheses: the same W, each run with dt = dt_over_h2 h^2, the L1 and Linf
    errors (p = inf is allowed for alpha = -1/2) against a run with h / reference_factor of the finest h
    at the finest run's dt, largest over the record times; weights (2.14) (shape b3) and (2.16) (hat).
(d) Theorem 3 (any initial measure, grad W in W^{1,inf}): rough data and W = |x|^a/a with a >= 2, each
    run with dt = dt_over_h h, the W1 distance (L1 distance of the CDFs) to a run with h / reference_factor
    of the finest h at its own dt, largest over the record times."""

import numpy as np

from particle_methods.ltp import density_named, potential, simulate
from particle_methods.norms import grid_errors
from particle_replication.workflow import logged, progress, save_results

#: Theorem 4's weights: (2.14) with the B3 shape of the other runs, and (2.16), defined for the hat shape only.
WEIGHTS = {"cell": "b3", "biorthogonal": "hat"}


def records(sim, times):
    """Indices of ``sim``'s records at ``times``, which must be multiples of its dt (and of its record step)."""
    recorded = [int(np.argmin(np.abs(sim.times - t))) for t in times]
    if not np.allclose(sim.times[recorded], times, rtol=0, atol=1e-9):
        raise ValueError("the record times must be multiples of every run's dt")
    return recorded


def theorem4_errors(initial, w, grid, q):
    """Largest L1 and Linf errors over the record times (rows: h, columns: L1, Linf) for each weight rule,
    each run with dt = dt_over_h2 h^2; the reference (h_min / reference_factor, the finest run's dt) and its
    distance to the run with twice its h (its own error)."""
    h_values, times = np.asarray(q["h_values"], float), np.asarray(q["times"], float)
    dt_values = q["dt_over_h2"] * h_values**2

    def densities(h, dt, weights):
        progress(f"Theorem 4: {w.name}, weights {weights}, h = {h:g}, dt = {dt:g}, t = {times[-1]:g}")
        every = int(round(times[0] / dt))
        sim = simulate(initial, w, h, dt, times[-1], shape=WEIGHTS[weights], weights=weights, record_every=every)
        return [sim.at(i).density(grid) for i in records(sim, times)]

    out = {"theorem4_h": h_values, "theorem4_dt": dt_values, "theorem4_times": times,
           "theorem4_weights": np.array(list(WEIGHTS))}
    reference_h = h_values.min() / q["reference_factor"]
    for weights in WEIGHTS:
        reference = densities(reference_h, dt_values[-1], weights)
        twin = densities(2 * reference_h, dt_values[-1], weights)
        runs = [densities(h, dt, weights) for h, dt in zip(h_values, dt_values)]
        out[f"theorem4_{weights}_errors"] = np.array(
            [np.max([grid_errors(a, b, grid) for a, b in zip(run, reference)], axis=0) for run in runs])
        out[f"theorem4_{weights}_reference_gap"] = np.max([grid_errors(a, b, grid) for a, b in zip(twin, reference)],
                                                          axis=0)
    out["theorem4_reference_h"] = reference_h
    return out


def theorem3_distances(q, grid_points):
    """Largest W1 distance over the record times for each h (dt = dt_over_h h) to the reference (h_min /
    reference_factor, its own dt), and the reference's distance to the run with twice its h (its own error)."""
    initial = density_named(q["initial"])
    w = potential("power", a=q["a"])
    grid = np.linspace(initial.lower, initial.upper, grid_points)
    h_values, times = np.asarray(q["h_values"], float), np.asarray(q["times"], float)
    reference_h = h_values.min() / q["reference_factor"]

    def cdfs(h):
        dt = q["dt_over_h"] * h
        progress(f"Theorem 3: {w.name} on {initial.name}, h = {h:g}, dt = {dt:g}, t = {times[-1]:g}")
        sim = simulate(initial, w, h, dt, times[-1], record_every=int(round(times[0] / dt)))
        return [sim.at(i).cumulative_mass(grid) for i in records(sim, times)]

    def distance(a, b):
        return max(grid_errors(x, y, grid)[0] for x, y in zip(a, b))

    reference = cdfs(reference_h)
    return {"theorem3_h": h_values, "theorem3_dt": q["dt_over_h"] * h_values, "theorem3_times": times,
            "theorem3_reference_h": reference_h, "theorem3_label": np.array(f"{w.name} on {initial.name}"),
            "theorem3_distances": np.array([distance(cdfs(h), reference) for h in h_values]),
            "theorem3_reference_gap": distance(cdfs(2 * reference_h), reference)}


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
    theorem4 = theorem4_errors(initial, w, grid, p["theorem4"])
    theorem3 = theorem3_distances(p["theorem3"], p["grid_points"])
    save_results(output, **theorem4, **theorem3, h_values=h_values, errors=errors, reference_h=reference_h,
                 reference_gap=reference_gap, order_points=p["order_points"], label=np.array(w.name), t=p["t"],
                 dt=p["dt"], grid=grid, reference=reference, centre_h=np.asarray(centre["h_values"], float),
                 centre_drift=np.array(drifts), centre_label=np.array(w_centre.name))


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
