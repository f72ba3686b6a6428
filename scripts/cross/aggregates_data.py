"""Aggregates that move and merge, on bump data (particle_methods.cross.hull): the SPD (equal masses and grid
weights), the particle method and LTP (before the first blow-up), the blob method, Godunov and SP, against the exact
solution by the continuous hull.

- exact: the aggregates (positions, masses, levels) at every time of the grid, the blow-up times 1/peak of each bump,
  the merger time (bisection on the number of aggregates), and for each aggregate whether its position is a
  centre-of-mass identity (:func:`identities`);
- every method and size: W1 to the exact solution at every time of the grid, and at the times of a window around the
  merger (SP: its steps nearest to them); at every time, the centre of each exact aggregate's levels in the method's
  output and the mean distance of those levels from the aggregate (particle_methods.cross.aggregates);
- the equal-mass SPD's merger (its two heavy clusters become one) at every n of a block of consecutive sizes above
  each configured n, and the grid SPD's at each size; the blob's gap at the exact merger (the centres of the two
  exact aggregates' levels just before it) over delta;
- the particle method: its largest distance to the grid SPD of the same particles (NaN for the other methods).

Two jobs per case (issue 47: one job took up to 110 s): part ``godunov_ltp`` finds the exact merger and the time grid
and runs Godunov, LTP and SP with their rows (about 45 % of the work); part ``rest`` reads them, runs every other
method and writes the case's result, with every method's rows in the order of :data:`METHOD_ORDER`.
"""

from fractions import Fraction

import numpy as np

from particle_methods.cross import HullSolution, merger_time
from particle_methods.cross import aggregates as agg
from particle_methods.cross import methods as m
from particle_methods.cross.distances import w1_atoms, w1_cells, w1_particles
from particle_methods.cross.hull import bump_data
from particle_methods.sticky.spd import spd_positions
from particle_replication.workflow import load_results, logged, progress, save_results

#: Heavy clusters of the smallest SPD kept per time for the figure (two aggregates at most, and room to spare).
CLUSTER_SLOTS = 4


def grid_times(p):
    """The time grid: `steps` equal steps up to t_end, with the fixed times added."""
    return np.union1d(np.linspace(0.0, p["t_end"], p["steps"] + 1), p["fixed_times"])


def padded(values, slots):
    """``values`` as floats, padded with NaN to ``slots`` entries (times with fewer aggregates than others)."""
    values = np.asarray(values, dtype=float)
    return np.pad(values, (0, slots - values.size), constant_values=np.nan)


def identities(solution, tolerance=1e-9):
    """For each aggregate of ``solution``: True where its position is the centre of mass of its levels by symmetry
    alone, so that any method whose pair forces are odd gets it: its levels are whole bumps, or lie in one symmetric
    bump symmetrically about the bump's middle level."""
    data = solution.data
    masses = np.array([b.mass for b in data.bumps])
    starts = np.concatenate(([0.0], np.cumsum(masses)[:-1]))
    ends = starts + masses
    scale = tolerance * data.mass
    out = []
    for mass, lower in zip(*solution.aggregates[1:]):
        upper = lower + mass
        whole = np.any(np.abs(starts - lower) <= scale) and np.any(np.abs(ends - upper) <= scale)
        symmetric = any(symmetric_bump(b) and lower >= s - scale and upper <= e + scale
                        and abs(lower + upper - s - e) <= 2 * scale for b, s, e in zip(data.bumps, starts, ends))
        out.append(bool(whole or symmetric))
    return np.array(out, dtype=bool)


def symmetric_bump(bump):
    """True for a bump symmetric about its centre."""
    return getattr(bump, "right_radius", bump.radius) == bump.radius


def centre_of_mass_offsets(solution):
    """For each aggregate of ``solution``: its distance from the centre of mass of the bump that holds its middle level,
    which moves at M/2 - (mass before the bump) - (the bump's mass)/2 (the mean of the levels' speeds M/2 - w)."""
    data, t = solution.data, solution.t
    masses = np.array([b.mass for b in data.bumps])
    starts = np.concatenate(([0.0], np.cumsum(masses)[:-1]))
    initial = HullSolution(data, 0.0)
    centres = (initial.quantile_integral(starts + masses) - initial.quantile_integral(starts)) / masses
    paths = centres + t * (0.5 * data.mass - starts - 0.5 * masses)
    positions, aggregate_masses, lowers = solution.aggregates
    bump = np.clip(np.searchsorted(starts, lowers + 0.5 * aggregate_masses, side="right") - 1, 0, len(masses) - 1)
    return np.abs(positions - paths[bump])


def atoms(name, out, mass):
    """A method's output as (positions, masses) of point masses (see particle_methods.cross.aggregates)."""
    if name.startswith("Godunov"):
        return agg.cell_atoms(*out, mass)
    if name in ("LTP", "SP"):
        return out.centres, out.weights
    return out


def w1(name, solution, out):
    if name in ("LTP", "SP"):
        return w1_particles(solution, out)
    if name.startswith("Godunov"):
        return w1_cells(solution, *out)
    return w1_atoms(solution, *out)


def count(name, out):
    """Particles (or cells) of a method's output."""
    if name.startswith("Godunov"):
        return out[1].size
    if name in ("LTP", "SP"):
        return out.centres.size
    return out[1].size


def merger_or_nan(measure, *args, **kwargs):
    """A method's merger time, NaN (logged) where it does not merge within the bracket: its claim then fails."""
    try:
        return measure(*args, **kwargs)
    except ValueError as error:
        progress(f"no merger: {error}")
        return np.nan


#: The per-run rows of a part, in the order of its runs.
ROW_KEYS = ("methods", "size", "count", "error", "centre", "spread")
#: The methods (names or their beginnings) in the order of the result's rows, each by increasing size.
METHOD_ORDER = ("SPD, equal masses", "SPD, grid weights", "blob", "Godunov for F", "particle method", "LTP", "SP")


def method_rank(name):
    """The place of the method ``name`` in :data:`METHOD_ORDER`."""
    return next(rank for rank, method in enumerate(METHOD_ORDER) if name.startswith(method))


def exact_times(p):
    """(merger, window, times): the exact merger time (bisection on the number of aggregates), the window of times
    around it, and the time grid with the window added."""
    data = p["data"]
    merger = merger_time(data, *p["merger_bracket"])
    window = merger + np.asarray(p["merger_window"], float)
    return merger, window, np.union1d(grid_times(p), window)


def exact_solutions(data, times):
    """The exact solutions at ``times`` and the padding to the largest number of aggregates among them."""
    solutions = [HullSolution(data, float(t)) for t in times]
    slots = max(s.aggregates[0].size for s in solutions)
    return solutions, lambda values: padded(values, slots)


def method_rows(data, runs, times, solutions, pad, sp_own):
    """For each (name, size, method) of ``runs``: its name, size, particles (or cells), W1 against the exact solution
    at every time, the centres and spreads of the exact aggregates' levels in its output, and (the particle method)
    its largest distance to the grid SPD of the same particles, as a dict of lists."""
    rows = {key: [] for key in (*ROW_KEYS, "difference")}
    for name, size, method in runs:
        row, centre_row, spread_row, difference, particles = [], [], [], np.nan, np.nan
        own = sp_own.get(size, {}) if name == "SP" else {}
        for t, solution in zip(times, solutions):
            out = method(size, float(t))
            ranges = agg.level_ranges(solution)
            if out is not None and name == "particle method":
                difference = np.nanmax([difference, np.max(np.abs(out[0] - m.spd_grid(data, 1.0 / size, t)[0]))])
            if out is None:  # LTP and the particle method after the first blow-up
                row.append(np.nan)
                centre_row.append(pad([np.nan] * ranges.shape[0]))
                spread_row.append(pad([np.nan] * ranges.shape[0]))
                continue
            particles = count(name, out)
            at = own.get(t, t)  # SP: its own step nearest to t
            exact = solution if at == t else HullSolution(data, float(at))
            row.append(w1(name, exact, out))
            if ranges.size and at == t:
                x, weights = atoms(name, out, solution.mass)
                centre_row.append(pad(agg.level_centres(x, weights, ranges)))
                spread_row.append(pad(agg.level_spreads(x, weights, ranges, solution.aggregates[0])))
            else:
                centre_row.append(pad([np.nan] * ranges.shape[0]))
                spread_row.append(pad([np.nan] * ranges.shape[0]))
        for key, value in zip((*ROW_KEYS, "difference"), (name, size, particles, row, centre_row, spread_row,
                                                           difference)):
            rows[key].append(value)
    return rows


def run_godunov_ltp(p, output):
    """Part ``godunov_ltp``: the exact merger and time grid, and the rows of Godunov, LTP (up to the first blow-up) and
    SP."""
    data = p["data"]
    merger, window, times = exact_times(p)
    progress(f"exact ({data}): merger at t = {merger!r}")
    solutions, pad = exact_solutions(data, times)
    godunov = {cells: dict(zip(times, m.godunov_paths(data, cells, times, cfl=p["cfl"])))
               for cells in p["godunov_cells"]}
    first_blowup = float(min(1.0 / b.height for b in bump_data(data).bumps))
    ltp = p["ltp"]
    early = times[times < first_blowup]
    ltp_runs = {("LTP", k): dict(zip(early, m.ltp_paths(data, 1.0 / k, ltp["dt_over_h"] / k, early)))
                for k in ltp["inverse_h"]}
    # SP at the step nearest to each time of the grid (the window around the merger is not on its steps): its W1
    # against the exact solution at that step.
    sp_own = {}
    for k in ltp["sp_inverse_h"]:
        dt = ltp["dt_over_h"] / k
        own = np.round(np.rint(times / dt) * dt, 12)
        steps = np.unique(own)
        states = dict(zip(steps, m.ltp_paths(data, 1.0 / k, dt, steps, method="sp", eps=ltp["sp_eps_over_h"] / k)))
        ltp_runs["SP", k] = {t: states[s] for t, s in zip(times, own)}
        sp_own[k] = dict(zip(times, own))
    runs = [("Godunov for F", cells, lambda n, t: godunov[n][t]) for cells in p["godunov_cells"]]
    runs += [(name, k, lambda k, t, name=name: ltp_runs[name, k].get(t)) for name, k in ltp_runs]
    rows = method_rows(data, runs, times, solutions, pad, sp_own)
    for name, size, row in zip(rows["methods"], rows["size"], rows["error"]):
        progress(f"{name:18} size {size:6d}: largest W1 over t > 0 {np.nanmax(row[1:]):.4g} (t = 0: {row[0]:.4g})")
    save_results(output, merger=merger, window_times=window, times=times,
                 **{key: np.array(rows[key]) for key in ROW_KEYS})


def run(p, ltp_path, output):
    """Part ``rest``: every other method, and the case's result with the rows of part ``godunov_ltp`` (read from
    ``ltp_path``), every row in the order of :data:`METHOD_ORDER`."""
    data = p["data"]
    bumps = bump_data(data)
    ltp_rows = load_results(ltp_path)
    merger, window, times = float(ltp_rows["merger"]), ltp_rows["window_times"], ltp_rows["times"]
    if not np.array_equal(times, np.union1d(grid_times(p), window)):
        raise ValueError(f"{ltp_path} holds another time grid than this case's configuration: rerun its rule")
    progress(f"exact ({data}): merger at t = {merger!r} (from {ltp_path}); blow-ups at "
             f"{[1.0 / b.height for b in bumps.bumps]}")
    solutions, pad = exact_solutions(data, times)
    exact_positions = np.array([pad(s.aggregates[0]) for s in solutions])
    exact_masses = np.array([pad(s.aggregates[1]) for s in solutions])
    exact_lowers = np.array([pad(s.aggregates[2]) for s in solutions])
    exact_identity = np.array([pad(identities(s)) for s in solutions]) == 1.0
    exact_offsets = np.array([pad(centre_of_mass_offsets(s)) for s in solutions])
    # The two aggregates just before the merger: their levels, for the blob's gap at the merger.
    before = HullSolution(data, merger * (1.0 - 1e-9))
    merging = agg.level_ranges(before)
    # The paths for the figure: the exact aggregates on a finer grid with the blow-ups and the merger, and the heavy
    # clusters of the smallest SPD.
    blowups = np.array([1.0 / b.height for b in bumps.bumps])
    # (each blow-up a thousandth after it: at the blow-up itself the aggregate has no mass yet)
    path_times = np.union1d(np.linspace(0.0, p["t_end"], p["path_steps"] + 1), [*(blowups * (1.0 + 1e-3)), merger])
    paths = [HullSolution(data, float(t)).aggregates for t in path_times]
    path_slots = max(path[0].size for path in paths)
    path_positions = np.array([padded(path[0], path_slots) for path in paths])
    path_masses = np.array([padded(path[1], path_slots) for path in paths])
    x0, masses0 = m.spd_equal(data, p["spd_n"][0], 0.0)
    velocities0 = m.weighted_velocities(masses0)
    cluster_rows = []
    for t in path_times:
        heavy = agg.heavy_clusters(spd_positions(x0, velocities0, float(t), masses=masses0), masses0,
                                   p["cluster_share"])
        cluster_rows.append(padded(heavy[:CLUSTER_SLOTS], CLUSTER_SLOTS))
    blob = p["blob"]
    runs = [("SPD, equal masses", n, lambda n, t: m.spd_equal(data, n, t)) for n in p["spd_n"]]
    runs += [("SPD, grid weights", k, lambda k, t: m.spd_grid(data, 1.0 / k, t)) for k in p["grid_inverse_h"]]
    # The blob method: one integration per size, through every time of the grid and the exact merger.
    blob_times = np.union1d(times, [merger])
    blob_paths = {k: m.blob_paths(data, 1.0 / k, blob_times, order=blob["order"], q=blob["q"])
                  for k in blob["inverse_h"]}
    runs += [(f"blob, m = {blob['order']}", k,
              lambda k, t: (blob_paths[k][0][int(np.searchsorted(blob_times, t))], blob_paths[k][1]))
             for k in blob["inverse_h"]]
    first_blowup = float(blowups.min())
    early = times[times < first_blowup]
    # The particle method, defined up to its first collision (the first blow-up): the times before it.
    runs += [("particle method", k, lambda k, t: m.particle_method(data, 1.0 / k, t) if t in early else None)
             for k in p["particle_inverse_h"]]
    rows = method_rows(data, runs, times, solutions, pad, {})
    mergers, gaps = [], []
    for name, size, row in zip(rows["methods"], rows["size"], rows["error"]):
        merged, gap = np.nan, np.nan
        if name == "SPD, grid weights":
            x0, _, masses = m.grid_particles(data, 1.0 / size)
            merged = merger_or_nan(agg.spd_merger, x0, m.weighted_velocities(masses), masses, *p["merger_bracket"],
                                   p["cluster_share"])
        elif name.startswith("blob"):
            at = int(np.searchsorted(blob_times, merger))
            gap = agg.gap_path(blob_paths[size][0][at], blob_paths[size][1], merging)[0] / (1.0 / size) ** blob["q"]
        mergers.append(merged)
        gaps.append(gap)
        progress(f"{name:18} size {size:6d}: largest W1 over t > 0 {np.nanmax(row[1:]):.4g} (t = 0: {row[0]:.4g}); "
                 f"merger {merged!r}; blob gap at the merger / delta {gap!r}")
    # Godunov, LTP and SP (part godunov_ltp) have no merger, gap or distance to the grid SPD; every row in the order
    # of METHOD_ORDER.
    later = len(ltp_rows["methods"])
    names, sizes, counts, errors, centres, spreads = (np.concatenate([np.array(rows[key]), ltp_rows[key]])
                                                      for key in ROW_KEYS)
    order = np.argsort([method_rank(name) for name in names], kind="stable")
    names, sizes, counts, errors, centres, spreads = (a[order] for a in (names, sizes, counts, errors, centres,
                                                                        spreads))
    mergers, gaps = np.array(mergers + [np.nan] * later)[order], np.array(gaps + [np.nan] * later)[order]
    differences = np.array(rows["difference"] + [np.nan] * later)[order]
    # The equal-mass SPD's merger: the fraction of a particle's mass on either side of the gap between the bumps
    # follows n m_1 / M, so the error changes sign and size from one n to the next: every n of a block above each size.
    period = merger_period(bumps, p["spd_merger_block_max"])
    progress(f"equal-mass SPD: blocks of {period} consecutive n (the period of n m_1/M mod 1)")
    block = np.array([[n + j for j in range(period)] for n in p["spd_n"]])
    spd_mergers = np.array([[merger_or_nan(agg.spd_merger, *spd_start(data, int(n)), *p["merger_bracket"],
                                           p["cluster_share"]) for n in ns] for ns in block])
    progress(f"equal-mass SPD merger errors: largest n |t_n - t*| per block "
             f"{np.nanmax(np.abs(spd_mergers - merger) * block, axis=1)}")
    # Its levels' distance from the exact aggregates at the fixed times, largest over them, at every n of the blocks.
    fixed = [solutions[int(np.argmin(np.abs(times - t)))] for t in p["fixed_times"]]
    fixed = [s for s in fixed if s.aggregates[0].size]
    spd_levels = np.array([[spd_levels_at(data, int(n), fixed) for n in ns] for ns in block])
    save_results(output, data=np.array(data), times=times, fixed_times=np.array(p["fixed_times"], float),
                 window_times=window, exact_positions=exact_positions, exact_masses=exact_masses,
                 exact_lowers=exact_lowers, exact_identity=exact_identity, exact_offsets=exact_offsets,
                 merger=merger, path_times=path_times,
                 path_positions=path_positions, path_masses=path_masses, spd_clusters=np.array(cluster_rows),
                 blowups=blowups, methods=names, size=sizes, count=counts,
                 error=errors, centre=centres, spread=spreads,
                 method_merger=mergers, merger_gap=gaps, spd_merger_n=block,
                 spd_merger=spd_mergers, spd_levels=spd_levels, spd_difference=differences, mass=bumps.mass,
                 support=np.array(bumps.support))


def merger_period(bumps, largest):
    """The period of n m_1/M mod 1, m_1 the first bump's mass and M the total: the denominator of m_1/M as a fraction
    with a denominator at most ``largest`` (the closest one, where the ratio is not such a fraction)."""
    return Fraction(bumps.bumps[0].mass / bumps.mass).limit_denominator(largest).denominator


def spd_levels_at(data, n, solutions):
    """The equal-mass SPD with n particles: the largest mean distance of the exact aggregates' levels from them over
    ``solutions`` (exact solutions at times with aggregates)."""
    x0, velocities, masses = spd_start(data, n)
    return max(float(np.max(agg.level_spreads(spd_positions(x0, velocities, s.t), masses, agg.level_ranges(s),
                                              s.aggregates[0]))) for s in solutions)


def spd_start(data, n):
    """(positions, velocities, masses) of the equal-mass SPD with n particles at t = 0."""
    x0, masses = m.spd_equal(data, n, 0.0)
    return x0, m.weighted_velocities(masses), masses


with logged(snakemake.log[0], snakemake.threads, nudge=snakemake.params.nudge):  # noqa: F821
    if snakemake.params.part == "godunov_ltp":  # noqa: F821
        run_godunov_ltp(snakemake.params.cfg, snakemake.output[0])  # noqa: F821
    else:
        run(snakemake.params.cfg, snakemake.input.ltp, snakemake.output[0])  # noqa: F821
