"""Figure 8: the SP and LTP methods for |x|^4/4 - |x|^2.5/2.5 from (6.2), followed in time.

Both runs continue past the figure's time ``t`` to ``t_long``; every ``record_every`` steps we
keep the centres, the widths and the number of peaks of the density (sampled on a fine grid and
at every particle centre, so that particles narrower than the grid are seen). The steadiness
criterion of the config (relative change of the centres over a window) gives each method's
steady time; the figure shows both methods at the paper's time and at the SP steady time.

A third run, ``shifted_ltp``, is LTP on the grid offset by ``shifted_offset`` h (centres (k + 1/2) h,
weights (2.14) over the shifted cells): with no particle at x = 0 it tests whether the particle there
is what keeps the regular-grid LTP run from settling."""

import math

import numpy as np

from particle_methods.ltp import Particles, density_named, potential, simulate
from particle_methods.ltp.measures import excess_variation, peak_count
from particle_replication.steady import first_steady_time
from particle_replication.workflow import logged, progress, save_results


def sampled(particles, grid):
    points = np.union1d(grid, particles.centres)
    return points, particles.density(points)


def run(p, output):
    initial = density_named(p["initial"])
    w = potential("attractive_repulsive", a=p["a"], b=p["b"])
    dt = p["t"] / p["steps"]
    steps = int(round(max(p["t"], p["t_long"]) / dt))
    grid = np.linspace(-1.1, 1.1, 8801)
    results = {"grid": grid, "label": np.array(w.name), "h": p["h"], "dt": dt, "steps": p["steps"], "t": p["t"],
               "sp_eps": p["sp_eps"], "shifted_offset": p["shifted_offset"]}
    runs = {}
    for name, method, eps, offset in (("ltp", "ltp", None, 0.0), ("sp", "sp", p["sp_eps"], 0.0),
                                      ("shifted_ltp", "ltp", None, p["shifted_offset"])):
        progress(f"{name}: {steps} steps up to t = {steps * dt:g}, grid (k + {offset:g}) h")
        runs[name] = simulate(initial, w, p["h"], dt, steps * dt, method=method, eps=eps, offset=offset,
                              record_every=p["record_every"])
    times = runs["sp"].times
    for method, sim in runs.items():
        samples = [sampled(sim.at(i), grid) for i in range(times.size)]
        peaks = np.array([peak_count(density, p["prominence"]) for _, density in samples])
        oscillation = np.array([excess_variation(x, density) for x, density in samples])
        steady = first_steady_time(times, sim.centres, p["steady"]["window"], p["steady"]["tolerance"])
        progress(f"{method}: peaks {peaks.tolist()}; excess variation {np.round(oscillation, 3).tolist()}; "
                 f"steady from t = {steady:g}")
        results.update({f"{method}_times": times, f"{method}_peaks": peaks, f"{method}_oscillation": oscillation,
                        f"{method}_steady": steady,
                        f"{method}_centres": sim.centres, f"{method}_widths": sim.widths,
                        f"{method}_weights": sim.weights})
    # Why LTP does not settle: the particle at x = 0 sits where W'' * rho_h < 0 and widens; its share of
    # the velocity of the outermost particles at the end of the run.
    final = runs["ltp"].at(-1)
    wide = int(np.argmax(final.widths))
    alone = Particles(final.centres[[wide]], final.weights[[wide]], final.widths[[wide]], final.shape)
    ends = final.centres[[np.argmin(final.centres), np.argmax(final.centres)]]
    share = np.abs(alone.convolutions(w, ends)[0]) / np.abs(final.convolutions(w, ends)[0])
    results.update(widest_centre=final.centres[wide], widest_width=final.widths[wide],
                   widest_weight=final.weights[wide], widest_share=share.max())
    progress(f"ltp at t = {times[-1]:g}: widest particle at x = {final.centres[wide]:.3g}, width "
             f"{final.widths[wide]:.3g}, share of the outer velocities {share.max():.3g}")
    paper_index = int(np.argmin(np.abs(times - p["t"])))
    steady_sp = results["sp_steady"]
    steady_index = int(np.argmin(np.abs(times - steady_sp))) if math.isfinite(steady_sp) else times.size - 1
    for name, index in (("paper", paper_index), ("steady", steady_index)):
        results[f"{name}_time"] = times[index]
        for method, sim in runs.items():
            points, density = sampled(sim.at(index), grid)
            results[f"{method}_{name}_x"], results[f"{method}_{name}_density"] = points, density
    save_results(output, **results)


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
