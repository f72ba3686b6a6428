"""Aggregates that move and merge: the asymmetric data two_bumps (particle_methods.cross.hull) by the SPD (equal
masses and grid weights), the particle method and LTP (before the first blow-up), the blob method, Godunov and SP,
against the exact solution by the continuous hull.

- exact: the aggregates (positions, masses) at every time of the grid, the blow-up times 1/peak of each bump, the
  merger time (bisection on the number of aggregates);
- every method and size: W1 to the exact solution at every time of the grid (its largest value is the error
  uniformly in time), and, at every time, the centre of mass and the spread of the particles whose levels lie
  in each exact aggregate (the levels k - 1/2 of the cumulative masses; NaN for Godunov, which has no particles);
- the SPD: its merger time, when its two heaviest clusters (particles at one position) become one; the blob method:
  the first time of a fine grid over the merger bracket at which the centres of the particles in the two exact
  aggregates' levels come within delta of each other (any fixed multiple of delta gives the same order in h);
- the particle method: its largest distance to the grid SPD of the same particles (NaN for the other methods).
"""

import numpy as np

from particle_methods.cross import HullSolution, merger_time
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


def level_groups(solution, masses):
    """For each exact aggregate of ``solution``, the mask of the particles (in position order, with ``masses``)
    whose levels, k - 1/2 of the cumulative masses, lie in the aggregate's levels."""
    levels = np.cumsum(masses) - 0.5 * masses
    _, aggregate_masses, lowers = solution.aggregates
    return [(levels > lower) & (levels < lower + mass) for mass, lower in zip(aggregate_masses, lowers)]


def aggregate_centres(solution, positions, masses):
    """(centre, spread) of the particles whose levels lie in each exact aggregate (NaN for an aggregate without
    particles in its levels)."""
    order = np.argsort(positions, kind="stable")
    x, w = positions[order], masses[order]
    centres, spreads = [], []
    for position, inside in zip(solution.aggregates[0], level_groups(solution, w)):
        if not np.any(inside):
            centres.append(np.nan)
            spreads.append(np.nan)
            continue
        centres.append(float(np.sum(w[inside] * x[inside]) / np.sum(w[inside])))
        spreads.append(float(np.max(np.abs(x[inside] - position))))
    return centres, spreads


def clusters(positions, masses, share):
    """Number of clusters (particles at one position) holding at least ``share`` of the mass."""
    values, index = np.unique(positions, return_inverse=True)
    totals = np.bincount(index, weights=masses)
    return int(np.sum(totals >= share * masses.sum()))


def spd_merger(x0, velocities, masses, low, high, share):
    """Time at which the SPD's heavy clusters drop from two to one, by bisection (NaN if [low, high] holds none)."""
    count = lambda t: clusters(spd_positions(x0, velocities, t, masses=masses), masses, share)  # noqa: E731
    if not (count(low) >= 2 and count(high) == 1):
        return np.nan
    while True:
        middle = 0.5 * (low + high)
        if middle in (low, high):
            return high
        low, high = (middle, high) if count(middle) >= 2 else (low, middle)


def blob_merger(positions, masses, delta, path_times, start):
    """First of ``path_times`` >= ``start`` at which the centres of mass of the blob particles in the levels of the two
    exact aggregates at ``start`` are within ``delta`` (NaN if never, or if there are not two aggregates then). The
    particles keep their order (the ODE's field is Lipschitz), so their levels are those of the data."""
    groups = level_groups(HullSolution(DATA, start), masses)
    if len(groups) != 2:
        return np.nan
    centres = [positions[:, group] @ masses[group] / masses[group].sum() for group in groups]
    close = np.flatnonzero((path_times >= start) & (np.abs(centres[1] - centres[0]) <= delta))
    return float(path_times[close[0]]) if close.size else np.nan


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
        x = spd_positions(x0, velocities0, float(t), masses=masses0)
        values, index = np.unique(x, return_inverse=True)
        totals = np.bincount(index, weights=masses0)
        heavy = values[totals >= p["cluster_share"] * masses0.sum()]
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
    runs += [("Godunov for F", cells, lambda n, t: m.godunov_mass(DATA, n, t, cfl=p["cfl"]))
             for cells in p["godunov_cells"]]
    # LTP (refused as the left bump blows up: only the times before it) and SP (eps = h), one run per size.
    ltp = p["ltp"]
    before = times[times < min(1.0 / b.height for b in solutions[0].data.bumps)]
    # The particle method, defined up to its first collision (the left bump's blow-up): the times before it.
    runs += [("particle method", k, lambda k, t: m.particle_method(DATA, 1.0 / k, t) if t in before else None)
             for k in p["particle_inverse_h"]]
    ltp_runs = {("LTP", k): dict(zip(before, m.ltp_paths(DATA, 1.0 / k, ltp["dt_over_h"] / k, before)))
                for k in ltp["inverse_h"]}
    ltp_runs |= {("SP", k): dict(zip(times, m.ltp_paths(DATA, 1.0 / k, ltp["dt_over_h"] / k, times, method="sp",
                                                        eps=ltp["sp_eps_over_h"] / k)))
                 for k in ltp["sp_inverse_h"]}
    runs += [(name, k, lambda k, t, name=name: ltp_runs[name, k].get(t)) for name, k in ltp_runs]
    names, sizes, errors, centres, spreads, mergers, differences = [], [], [], [], [], [], []
    for name, size, method in runs:
        row, centre_row, spread_row, difference = [], [], [], np.nan
        for t, solution in zip(times, solutions):
            out = method(size, float(t))
            if out is not None and name == "particle method":
                difference = np.nanmax([difference, np.max(np.abs(out[0] - m.spd_grid(DATA, 1.0 / size, t)[0]))])
            if out is None:  # LTP and the particle method after the first blow-up
                row.append(np.nan)
                centre, spread = [np.nan] * solution.aggregates[0].size, [np.nan] * solution.aggregates[0].size
            elif name in ("LTP", "SP"):
                row.append(w1_particles(solution, out))
                centre, spread = [np.nan] * solution.aggregates[0].size, [np.nan] * solution.aggregates[0].size
            elif name.startswith("Godunov"):
                row.append(w1_cells(solution, *out))
                centre, spread = [np.nan] * solution.aggregates[0].size, [np.nan] * solution.aggregates[0].size
            else:
                row.append(w1_atoms(solution, *out))
                centre, spread = aggregate_centres(solution, *out)
            centre_row.append(pad(centre))
            spread_row.append(pad(spread))
        merged = np.nan
        if name.startswith("SPD"):
            if name == "SPD, equal masses":
                x0, masses = m.spd_equal(DATA, size, 0.0)
            else:
                x0, _, masses = m.grid_particles(DATA, 1.0 / size)
            merged = spd_merger(x0, m.weighted_velocities(masses), masses, *p["merger_bracket"], p["cluster_share"])
        elif name.startswith("blob"):
            merged = blob_merger(paths[size][0], paths[size][1], (1.0 / size) ** blob["q"], blob_times,
                                 p["merger_bracket"][0])
        names.append(name)
        sizes.append(size)
        errors.append(row)
        centres.append(centre_row)
        spreads.append(spread_row)
        mergers.append(merged)
        differences.append(difference)
        progress(f"{name:18} size {size:6d}: largest W1 over t {np.nanmax(row):.4g} (t = 0: {row[0]:.4g}); "
                 f"merger {merged!r}")
    save_results(output, times=times, fixed_times=np.array(p["fixed_times"], float), exact_positions=exact_positions,
                 exact_masses=exact_masses, merger=merger, path_times=path_times, path_positions=path_positions,
                 path_masses=path_masses, spd_clusters=np.array(cluster_rows),
                 blowups=np.array([1.0 / b.height for b in HullSolution(DATA, 0.0).data.bumps]),
                 methods=np.array(names), size=np.array(sizes), error=np.array(errors), centre=np.array(centres),
                 spread=np.array(spreads), method_merger=np.array(mergers), spd_difference=np.array(differences))


with logged(snakemake.log[0], snakemake.threads):  # noqa: F821
    run(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
