"""One equation, every method: W1 errors and wall times on the 1D aggregation equation with K = |x|/2.

For each data and time of the config, every method runs at each of its sizes. Two jobs run this script:

- ``part: errors`` (one core): each run once; the W1 distance of its output to the exact solution
  (:mod:`particle_methods.cross.exact`), computed on the method's own output, and the diagnostics;
- ``part: times`` (every core, so that no other job disturbs it): the same runs timed, initial
  discretisation plus evolution, after warm-up runs that compile every kernel (the smallest size, and
  once per method the largest, which takes the parallel variants), the best of ``repeats`` rounds
  over all the runs when a run is short (interleaved), with the CPU and a load guard recorded beside
  them; merged with the errors into the study's results.
"""

import numpy as np

from particle_methods.cross import distances, methods
from particle_methods.cross.exact import AggregationSolution
from particle_replication.environment import cpu
from particle_replication.workflow import LoadGuard, interleaved, load_results, logged, progress, save_results


def count(output) -> int:
    """Particles or cells of a method's output."""
    if isinstance(output, tuple):
        return output[0].size if output[0].size == output[1].size else output[1].size
    return output.centres.size


def dirac_width(solution, output) -> float:
    """Largest |x| of the point masses whose levels lie in the exact Dirac mass (NaN without one, or
    for an output that is not point masses): how far the method is from forming the Dirac mass."""
    if not isinstance(output, tuple) or output[0].size != output[1].size or solution.dirac_mass == 0:
        return np.nan
    positions, masses = output
    order = np.argsort(positions, kind="stable")
    levels = np.cumsum(masses[order]) - 0.5 * masses[order]
    inside = (levels > solution.level) & (levels < solution.mass - solution.level)
    return float(np.max(np.abs(positions[order][inside]))) if np.any(inside) else np.nan


def spd_difference(name, data, size, t, output) -> float:
    """Largest |x - x_SPD| between the particle method's output and the weighted SPD from the same grid
    (NaN for the other methods)."""
    if name != "particle method":
        return np.nan
    positions, _ = methods.spd_grid(data, 1.0 / size, t)
    return float(np.max(np.abs(output[0] - positions)))


def method_table(p):
    """name -> (times at which it runs, sizes (n, 1/h or cells; or a dict time -> sizes), run(data, size, t),
    W1(solution, output))."""
    blob, ltp, fv = p["blob"], p["ltp"], p["godunov"]
    spd_times = [0.0, *p["times"]]  # at t = 0 too, for the contraction claim
    atoms = distances.w1_atoms

    table = {
        "SPD, equal masses": (spd_times, p["spd_n"], lambda d, n, t: methods.spd_equal(d, n, t),
                              lambda s, out: atoms(s, *out)),
        "SPD, grid weights": (spd_times, p["grid_inverse_h"], lambda d, k, t: methods.spd_grid(d, 1.0 / k, t),
                              lambda s, out: atoms(s, *out)),
        "particle method": (p["particle_times"], p["particle_inverse_h"],
                            lambda d, k, t: methods.particle_method(d, 1.0 / k, t), lambda s, out: atoms(s, *out)),
        "Godunov for F": (p["times"], fv["cells"],
                          lambda d, n, t: methods.godunov_mass(d, n, t, cfl=fv["cfl"]),
                          lambda s, out: distances.w1_cells(s, *out)),
    }
    for order in blob["orders"]:
        table[f"blob, m = {order}"] = (
            p["times"], {t: blob["inverse_h"] if t < 1.0 else blob["after_inverse_h"] for t in p["times"]},
            lambda d, k, t, order=order: methods.blob_method(d, 1.0 / k, t, order=order, q=blob["q"]),
            lambda s, out: atoms(s, *out))
    table["LTP"] = (ltp["times"], ltp["inverse_h"],
                    lambda d, k, t: methods.ltp_method(d, 1.0 / k, ltp["dt_over_h"] / k, t), distances.w1_particles)
    # After the blow-up SP costs about twice as much per run (more steps): its sizes stop earlier.
    sp_sizes = {t: ltp["inverse_h"] if t < 1.0 else ltp["sp_after_inverse_h"] for t in ltp["sp_times"]}
    table["SP"] = (ltp["sp_times"], sp_sizes,
                   lambda d, k, t: methods.ltp_method(d, 1.0 / k, ltp["dt_over_h"] / k, t, method="sp",
                                                      eps=ltp["sp_eps_over_h"] / k), distances.w1_particles)
    return table


def runs(p):
    """(data index, data, time index, time, method index, method name, sizes, method, W1) of every
    method at every data and time where it runs, in the order of the results."""
    table = method_table(p)
    times = sorted({t for entry in table.values() for t in entry[0]})
    for d_index, data in enumerate(p["data"]):
        for t_index, t in enumerate(times):
            for m_index, (name, (method_times, sizes, method, w1)) in enumerate(table.items()):
                if t in method_times:
                    yield d_index, data, t_index, t, m_index, name, sizes[t] if isinstance(sizes, dict) else sizes, \
                        method, w1


def errors(p, output):
    """Every run once: W1 errors and diagnostics (untimed)."""
    table = method_table(p)
    times = sorted({t for entry in table.values() for t in entry[0]})
    cases, solutions = [], {}
    for data in p["data"]:
        for t in times:
            solution = solutions[data, t] = AggregationSolution(data, t)
            cases.append((data, t, solution.mass, solution.dirac_mass))
            progress(f"{data}, t = {t:g}: mass {solution.mass:.6g}, Dirac mass {solution.dirac_mass:.6g}")
    rows = []
    for d_index, data, t_index, t, m_index, name, sizes, method, w1 in runs(p):
        solution = solutions[data, t]
        for size in sizes:
            out = method(data, size, t)
            error = w1(solution, out)
            rows.append((d_index, t_index, m_index, size, count(out), error, dirac_width(solution, out),
                         spd_difference(name, data, size, t, out)))
            progress(f"  {data}, t = {t:g}, {name:18} size {size:7d} ({count(out)}): W1 {error:.4g}")
    rows = np.array(rows)
    case_data, case_times, case_mass, case_dirac = zip(*cases)
    save_results(output, data=np.array(p["data"]), times=np.array(times, dtype=float),
                 methods=np.array(list(table)), data_index=rows[:, 0].astype(int),
                 time_index=rows[:, 1].astype(int), method_index=rows[:, 2].astype(int),
                 size=rows[:, 3].astype(int), count=rows[:, 4].astype(int), error=rows[:, 5],
                 dirac_width=rows[:, 6], spd_difference=rows[:, 7],
                 case_data=np.array(case_data), case_times=np.array(case_times), case_mass=np.array(case_mass),
                 case_dirac=np.array(case_dirac))


def times(p, errors_path, output, threads):
    """Every run timed (after a warm-up per method, data and time; interleaved, under a load guard), merged with
    the errors."""
    results = load_results(errors_path)
    timed, labels, warmed = [], [], set()
    for _, data, _, t, _, name, sizes, method, _ in runs(p):
        method(data, sizes[0], t)  # warm-up: compile and fill caches
        if name not in warmed:
            # Once per method, its largest size too: the kernels' parallel variants (from
            # PARALLEL_MIN_PARTICLES particles) compile on their first call, which a cold run
            # otherwise timed (the particle method at 1/h = 320: 1.8 s instead of 0.015 s).
            method(data, sizes[-1], t)
            warmed.add(name)
        for size in sizes:
            timed.append(lambda m=method, d=data, s=size, t=t: m(d, s, t))
            labels.append(f"{data}, t = {t:g}, {name:18} size {size:7d}")
    if len(timed) != results["size"].size:
        raise RuntimeError(f"{len(timed)} timed runs for {results['size'].size} measured ones: the errors are stale")
    with LoadGuard(threads) as guard:
        seconds = interleaved(timed, p["repeats"], guard).best
    for label, best in zip(labels, seconds):
        progress(f"  {label}: {best:.4g} s")
    progress(f"CPU {cpu()}; {guard.load:.2g} other processes runnable on average")
    save_results(output, **results, seconds=np.array(seconds), cpu=cpu(), **guard.readings())


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    if snakemake.params.part == "errors":  # noqa: F821
        errors(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
    else:
        times(snakemake.params.cfg, snakemake.input.errors, snakemake.output[0], snakemake.threads)  # noqa: F821
