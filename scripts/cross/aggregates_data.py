"""Aggregates that move and merge: the asymmetric data two_bumps (particle_methods.cross.hull) by the SPD (equal
masses and grid weights), the particle method and LTP (before the first blow-up), the blob method, Godunov and SP,
against the exact solution by the continuous hull.

- exact: the aggregates (positions, masses) at every time of the grid, the blow-up times 1/peak of each bump, the
  merger time (bisection on the number of aggregates);
- every method and size: W1 to the exact solution at every time of the grid (its largest value is the error
  uniformly in time), and, at every time, the centre of each exact aggregate's levels in the method's output
  (particle_methods.cross.aggregates: the mean of its quantile over those levels);
- the merger time: the SPD's when its two heavy clusters become one; the blob's, SP's and Godunov's when the centres
  of the two exact aggregates' levels come within delta, eps or one cell (on every sample of their runs over the
  merger bracket, interpolated: the blob's fine grid, SP's and Godunov's steps); NaN for LTP and the particle
  method, which stop at the first blow-up;
- the particle method: its largest distance to the grid SPD of the same particles (NaN for the other methods).
"""

import numpy as np

from particle_methods.cross import HullSolution, merger_time
from particle_methods.cross import aggregates as agg
from particle_methods.cross import methods as m
from particle_methods.cross.distances import w1_atoms, w1_cells, w1_particles
from particle_methods.sticky.spd import spd_positions
from particle_replication.workflow import logged, progress, save_results

DATA = "two_bumps"


def grid_times(p):
    """The time grid: `steps` equal steps up to t_end, with the fixed times added."""
    return np.union1d(np.linspace(0.0, p["t_end"], p["steps"] + 1), p["fixed_times"])


#: Heavy clusters of the smallest SPD kept per time for the figure (two aggregates at most, and room to spare).
CLUSTER_SLOTS = 4


def padded(values, slots):
    """``values`` as floats, padded with NaN to ``slots`` entries (times with fewer aggregates than others)."""
    values = np.asarray(values, dtype=float)
    return np.pad(values, (0, slots - values.size), constant_values=np.nan)


def atoms(name, out, mass):
    """A method's output as (positions, masses) of point masses (see particle_methods.cross.aggregates)."""
    if name.startswith("Godunov"):
        return agg.cell_atoms(*out, mass)
    if name in ("LTP", "SP"):
        return out.centres, out.weights
    return out


def path_merger(times, positions, masses, low, length):
    """Merger from a run sampled at ``times``: the first time from ``low`` on at which the centres of the two exact
    aggregates' levels at ``low`` come within ``length``."""
    after = times >= low
    ranges = agg.level_ranges(HullSolution(DATA, low))
    return agg.first_within(times[after], agg.gap_path(positions[after], masses, ranges), length)


def merger_or_nan(measure, *args, **kwargs):
    """A method's merger time, NaN (logged) where it does not merge within the bracket: its claim then fails."""
    try:
        return measure(*args, **kwargs)
    except ValueError as error:
        progress(f"no merger: {error}")
        return np.nan


def run(p, output):
    times = grid_times(p)
    solutions = [HullSolution(DATA, float(t)) for t in times]
    slots = max(s.aggregates[0].size for s in solutions)
    pad = lambda values: padded(values, slots)  # noqa: E731
    exact_positions = np.array([pad(s.aggregates[0]) for s in solutions])
    exact_masses = np.array([pad(s.aggregates[1]) for s in solutions])
    # The paths for the figure, on a finer grid: the exact aggregates and the heavy clusters of the smallest SPD.
    path_times = np.linspace(0.0, p["t_end"], p["path_steps"] + 1)
    paths = [HullSolution(DATA, float(t)).aggregates for t in path_times]
    path_slots = max(path[0].size for path in paths)
    path_positions = np.array([padded(path[0], path_slots) for path in paths])
    path_masses = np.array([padded(path[1], path_slots) for path in paths])
    x0, masses0 = m.spd_equal(DATA, p["spd_n"][0], 0.0)
    velocities0 = m.weighted_velocities(masses0)
    cluster_rows = []
    for t in path_times:
        heavy = agg.heavy_clusters(spd_positions(x0, velocities0, float(t), masses=masses0), masses0,
                                   p["cluster_share"])
        cluster_rows.append(padded(heavy[:CLUSTER_SLOTS], CLUSTER_SLOTS))
    merger = merger_time(DATA, *p["merger_bracket"])
    progress(f"exact: merger at t = {merger!r}; blow-ups at 1/peak of each bump")
    blob = p["blob"]
    runs = [("SPD, equal masses", n, lambda n, t: m.spd_equal(DATA, n, t)) for n in p["spd_n"]]
    runs += [("SPD, grid weights", k, lambda k, t: m.spd_grid(DATA, 1.0 / k, t)) for k in p["grid_inverse_h"]]
    # The blob method: one integration per size, through every time of the grid and a fine grid over the merger bracket.
    blob_times = np.union1d(times, np.linspace(*p["merger_bracket"], p["merger_samples"] + 1))
    paths = {k: m.blob_paths(DATA, 1.0 / k, blob_times, order=blob["order"], q=blob["q"]) for k in blob["inverse_h"]}
    runs += [(f"blob, m = {blob['order']}", k,
              lambda k, t: (paths[k][0][int(np.searchsorted(blob_times, t))], paths[k][1])) for k in blob["inverse_h"]]
    # Godunov: one run per size through every time of the grid.
    godunov = {cells: dict(zip(times, m.godunov_paths(DATA, cells, times, cfl=p["cfl"])))
               for cells in p["godunov_cells"]}
    runs += [("Godunov for F", cells, lambda n, t: godunov[n][t]) for cells in p["godunov_cells"]]
    # LTP (refused as the left bump blows up: only the times before it) and SP (eps = h), one run per size.
    ltp = p["ltp"]
    before = times[times < min(1.0 / b.height for b in solutions[0].data.bumps)]
    # The particle method, defined up to its first collision (the left bump's blow-up): the times before it.
    runs += [("particle method", k, lambda k, t: m.particle_method(DATA, 1.0 / k, t) if t in before else None)
             for k in p["particle_inverse_h"]]
    ltp_runs = {("LTP", k): dict(zip(before, m.ltp_paths(DATA, 1.0 / k, ltp["dt_over_h"] / k, before)))
                for k in ltp["inverse_h"]}
    # SP through every time of the grid and every step over the merger bracket.
    sp_times, sp_paths = {}, {}
    for k in ltp["sp_inverse_h"]:
        dt = ltp["dt_over_h"] / k
        low, high = p["merger_bracket"]
        steps = np.arange(np.ceil(low / dt - 1e-9), np.floor(high / dt + 1e-9) + 1)
        sp_times[k] = np.union1d(times, np.round(steps * dt, 12))
        sp_paths[k] = m.ltp_paths(DATA, 1.0 / k, dt, sp_times[k], method="sp", eps=ltp["sp_eps_over_h"] / k)
        ltp_runs["SP", k] = dict(zip(sp_times[k], sp_paths[k]))
    runs += [(name, k, lambda k, t, name=name: ltp_runs[name, k].get(t)) for name, k in ltp_runs]
    low = p["merger_bracket"][0]
    names, sizes, errors, centres, mergers, differences = [], [], [], [], [], []
    for name, size, method in runs:
        row, centre_row, difference = [], [], np.nan
        for t, solution in zip(times, solutions):
            out = method(size, float(t))
            ranges = agg.level_ranges(solution)
            if out is not None and name == "particle method":
                difference = np.nanmax([difference, np.max(np.abs(out[0] - m.spd_grid(DATA, 1.0 / size, t)[0]))])
            if out is None:  # LTP and the particle method after the first blow-up
                row.append(np.nan)
                centre_row.append(pad([np.nan] * ranges.shape[0]))
                continue
            if name in ("LTP", "SP"):
                row.append(w1_particles(solution, out))
            elif name.startswith("Godunov"):
                row.append(w1_cells(solution, *out))
            else:
                row.append(w1_atoms(solution, *out))
            centre_row.append(pad(agg.level_centres(*atoms(name, out, solution.mass), ranges) if ranges.size else []))
        merged = np.nan
        if name.startswith("SPD"):
            if name == "SPD, equal masses":
                x0, masses = m.spd_equal(DATA, size, 0.0)
            else:
                x0, _, masses = m.grid_particles(DATA, 1.0 / size)
            merged = merger_or_nan(agg.spd_merger, x0, m.weighted_velocities(masses), masses, *p["merger_bracket"],
                                   p["cluster_share"])
        elif name.startswith("blob"):
            merged = merger_or_nan(path_merger, blob_times, paths[size][0], paths[size][1], low,
                                   (1.0 / size) ** blob["q"])
        elif name == "SP":
            merged = merger_or_nan(path_merger, sp_times[size], np.array([out.centres for out in sp_paths[size]]),
                                   sp_paths[size][0].weights, low, ltp["sp_eps_over_h"] / size)
        elif name.startswith("Godunov"):
            merged = merger_or_nan(agg.godunov_merger, DATA, size, *p["merger_bracket"], cfl=p["cfl"])
        names.append(name)
        sizes.append(size)
        errors.append(row)
        centres.append(centre_row)
        mergers.append(merged)
        differences.append(difference)
        progress(f"{name:18} size {size:6d}: largest W1 over t {np.nanmax(row):.4g} (t = 0: {row[0]:.4g}); "
                 f"merger {merged!r}")
    save_results(output, times=times, fixed_times=np.array(p["fixed_times"], float), exact_positions=exact_positions,
                 exact_masses=exact_masses, merger=merger, path_times=path_times, path_positions=path_positions,
                 path_masses=path_masses, spd_clusters=np.array(cluster_rows),
                 blowups=np.array([1.0 / b.height for b in HullSolution(DATA, 0.0).data.bumps]),
                 methods=np.array(names), size=np.array(sizes), error=np.array(errors), centre=np.array(centres),
                 method_merger=np.array(mergers), spd_difference=np.array(differences))


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
