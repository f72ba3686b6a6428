"""Every claim of the cross-method comparison (kind ``derived``), measured from the cached results.

The study result (scripts/cross/study_data.py) holds one row per method, data, time and size:
W1 error and wall time; the behaviour result (scripts/cross/behaviour_data.py) holds what the
methods do at the blow-up. tests/cross/test_cross_verdicts.py feeds these functions wrong outcomes.

Orders are slopes of log W1 against log size (n, 1/h or cells) on the ``fit_points`` largest
sizes; identities that hold in exact arithmetic get the shared rounding tolerance
:data:`particle_replication.claims.ROUNDING` times the scale of the quantity compared (:data:`LENGTH`
for positions and W1 per unit mass, the mass, :data:`TIME` for event times; 1 for ratios).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .. import claims as c
from ..rates import Recorder, order
from ..registry.cross import aggregate_settings
from ..workflow import disturbance

PAPER = "cross"
#: Length scale of the positions: the data (4.3) and (4.4) lie in [-1, 1].
LENGTH = 1.0
#: Time scale: both data blow up at t = 1.
TIME = 1.0
SOURCE_IDENTITY = "blob paper Definition 2.2 (grad K(0) = 0); sticky paper section 1.1.3 and Remark 3.3"
SOURCE_SPD = "sticky paper Remark 3.3 (SPD exact for discretised data) and the L1 contraction of entropy solutions"
SPD_METHODS = ("SPD, equal masses", "SPD, grid weights")


claim = functools.partial(c.claim, PAPER)


def series(d, data: str, t: float, method: str, keys=("size", "count", "error", "seconds")):
    """The columns ``keys`` (default: sizes, particle or cell counts, W1 errors, seconds) of one method
    on one case, by size."""
    names, times, methods = list(d["data"]), list(d["times"]), list(d["methods"])
    rows = (
        (d["data_index"] == names.index(data))
        & (d["time_index"] == times.index(t))
        & (d["method_index"] == methods.index(method))
    )
    order_ = np.argsort(d["size"][rows], kind="stable")
    return tuple(d[key][rows][order_] for key in keys)


def cases(d):
    """(data, t, method) of every series in the study."""
    seen = sorted(set(zip(d["data_index"], d["time_index"], d["method_index"])))
    return [(str(d["data"][i]), float(d["times"][j]), str(d["methods"][k])) for i, j, k in seen]


def orders(d, rates: Recorder, methods, times, window: int, skip_collapsed: dict | None = None):
    """Fitted W1 orders of ``methods`` at ``times`` for every data, recorded; the cases whose exact
    solution is a single Dirac mass (``skip_collapsed[(data, t)]`` true) are left out."""
    found = []
    for data, t, method in cases(d):
        if method not in methods or t not in times or (skip_collapsed or {}).get((data, t), False):
            continue
        sizes, _, errors, _ = series(d, data, t, method)
        fit = order(f"{PAPER}.order", "size", sizes, np.maximum(errors, 1e-300), window, f"{method}, {data}, t = {t:g}")
        found.append(-rates.add(fit))
    return found


def collapsed(d, masses) -> dict:
    """(data, t) -> whether the exact solution at t is a single Dirac mass (masses[(data, t)] =
    (mass, Dirac mass))."""
    return {key: abs(value[0] - value[1]) <= c.ROUNDING * value[0] for key, value in masses.items()}


def time_to_error(errors, seconds, target: float, min_seconds: float = 0.0) -> tuple[float, bool]:
    """(wall time at which the work-precision line reaches W1 = target, whether extrapolated).

    Interpolated log-linearly between the two runs bracketing the target; from the smallest
    run if it is already below; extrapolated from the two largest runs (their local slope of log
    time against log error) if no run reaches it, and then NaN (not measured) unless the largest
    took at least ``min_seconds`` and longer than the other (shorter runs time overheads, not the
    method's growth; a fixed overhead left in the smaller run flattens the slope, so the
    extrapolated time is then too small, which favours the method); infinite if those do not
    decrease the error.
    """
    errors, seconds = np.asarray(errors, dtype=float), np.asarray(seconds, dtype=float)
    below = np.flatnonzero(errors <= target)
    if below.size and below[0] == 0:
        return float(seconds[0]), False
    if below.size:
        j = below[0]
        i = j - 1
        extrapolated = False
    else:
        i, j = errors.size - 2, errors.size - 1
        extrapolated = True
        if not errors[j] < errors[i]:
            return math.inf, True
        if seconds[j] < min_seconds or not seconds[j] > seconds[i]:
            return math.nan, True  # the growth of the cost is not measured
    slope = math.log(seconds[j] / seconds[i]) / math.log(errors[j] / errors[i])
    return float(seconds[i] * (target / errors[i]) ** slope), extrapolated


def fastest_table(d, target: float, min_seconds: float = 0.0):
    """{(data, t): {method: (time to target, extrapolated)}} (see :func:`time_to_error`)."""
    table = {}
    for data, t, method in cases(d):
        if t == 0.0:
            continue
        _, _, errors, seconds = series(d, data, t, method)
        table.setdefault((data, t), {})[method] = time_to_error(errors, seconds, target, min_seconds)
    return table


def speed_ratio(d) -> float:
    """Smallest (time of a run of another method) / (time of the best SPD at the same W1 error), over
    every run of the other methods whose error the SPD runs bracket (interpolated, never extrapolated);
    NaN if there is no such run."""
    ratios = []
    every = cases(d)
    for data, t, method in every:
        if method in SPD_METHODS or t == 0.0:
            continue
        errors, seconds = series(d, data, t, method, ("error", "seconds"))
        spd_lines = [series(d, data, t, spd, ("error", "seconds")) for spd in SPD_METHODS if (data, t, spd) in every]
        for error, time in zip(errors, seconds):
            spd_times = []
            for spd_errors, spd_seconds in spd_lines:
                spd_time, extrapolated = time_to_error(spd_errors, spd_seconds, max(error, 0.0))
                if not extrapolated:
                    spd_times.append(spd_time)
            if spd_times:
                ratios.append(time / min(spd_times))
    return float(min(ratios)) if ratios else math.nan


def _sp_dirac_spread(d, masses, after, p):
    """SP after the blow-up: W1 against M_D eps int |s| phi(s) ds, the distance from the Dirac mass M_D to the same
    mass spread over one particle of width eps (its particles gather at 0 at a rate of order 1/eps, and the smooth
    part is O(h^2) from the exact one); the ratio at the largest 1/h farthest from 1 over the data, the ratios at
    every 1/h listed."""
    from particle_methods.cross.methods import SHAPE
    from particle_methods.ltp.shapes import shape_named

    spread, band = shape_named(SHAPE).absolute_moment, p["claims"]["sp_dirac_spread"]
    finest, shown = [], []
    for data, t, method in cases(d):
        if method == "SP" and t in after:
            sizes, _, errors, _ = series(d, data, t, method)
            ratios = errors / (masses[(data, t)][1] * spread * p["ltp"]["sp_eps_over_h"] / sizes)
            finest.append(float(ratios[-1]))
            shown.append(f"{data}, t = {t:g} (M_D = {masses[(data, t)][1]:.4g}): "
                         + ", ".join(f"{r:.3f} at 1/h = {n}" for r, n in zip(ratios, sizes)))
    return claim(
        c.between, "sp_after.dirac_spread", kind="derived",
        source="LTP paper section 2.1 (SP: particles of fixed width eps); the exact solution's Dirac mass",
        figure="cross",
        text=f"SP after the blow-up (eps = {p['ltp']['sp_eps_over_h']:g} h): W1 over the prediction with no fitted "
             f"parameter M_D eps int |s| phi(s) ds ({SHAPE}: {spread:.4g}), the Dirac mass spread over one particle; "
             f"ratios {'; '.join(shown)}; at the largest 1/h, farthest from 1",
        tolerance=band, measured=c.farthest_from_centre(finest, band))


def study_claims(d, rates: Recorder, p):
    """Orders of every method before and after the blow-up, the SPD's contraction and exactness,
    and which method reaches the target W1 first."""
    window, rules = p["fit_points"], p["claims"]
    masses = {
        (str(data), float(t)): (float(m), float(dirac))
        for data, t, m, dirac in zip(d["case_data"], d["case_times"], d["case_mass"], d["case_dirac"])
    }
    single = collapsed(d, masses)
    before, after = [t for t in p["times"] if t < 1.0], [t for t in p["times"] if t > 1.0]
    rows = []

    late = max(p["times"])
    share = masses[(str(p["data"][0]), late)][1] / masses[(str(p["data"][0]), late)][0]
    rows.append(
        claim(
            c.between, "exact.dirac_share", kind="check",
            source="a0 = t m(a0) (this section), against the issue's independent figure", figure="cross",
            text=f"share of the mass in the Dirac mass of the exact solution "
                 f"from {p['data'][0]} at t = {late:g} (issue 15: about 57 % for (4.3) at t = 1.1)",
            tolerance=rules["dirac_share"], measured=float(share))
    )

    spd = orders(d, rates, SPD_METHODS, p["times"], window, single)
    rows.append(
        claim(
            c.between, "order.spd", kind="derived", source=SOURCE_SPD, figure="cross",
            text="W1 order of both SPDs (n or 1/h), every data, before and after the "
                 "blow-up (cases with a single Dirac mass left out): the discretised data are O(1/n) from the "
                 "data, and the SPD is their exact entropy solution; worst fit",
            tolerance=rules["spd_order"], measured=c.farthest_from_centre(spd, rules["spd_order"]))
    )

    ratios, exact = [], []
    for data, t, method in cases(d):
        if method not in SPD_METHODS or t == 0.0:
            continue
        _, _, errors, _ = series(d, data, t, method)
        _, _, initial, _ = series(d, data, 0.0, method)
        ratios.extend(errors / initial)
        if single[(data, t)]:
            exact.extend(errors / masses[(data, t)][0])
    rows.append(
        claim(
            c.at_most, "spd.contraction", kind="derived", source=SOURCE_SPD, figure="cross",
            text=(
                "W1(SPD(t), exact(t)) <= W1(SPD(0), exact(0)) for every size: largest ratio over both SPDs, data and "
                "times"),
            tolerance=1.0 + c.ROUNDING, measured=float(max(ratios)))
    )
    rows.append(
        claim(
            c.at_most, "spd.collapse_exact", kind="derived", source=SOURCE_SPD, figure="cross",
            text="once all the mass sits in the Dirac mass ((4.4) at t > 1) both SPDs are exact: largest W1 / M",
            tolerance=c.ROUNDING * LENGTH, measured=float(max(exact)) if exact else math.nan)
    )

    blob = [f"blob, m = {m}" for m in p["blob"]["orders"]]
    rows.append(
        claim(
            c.between, "order.blob_before", kind="derived",
            source="blob paper Theorem 3.8 (trajectories O(h^{mq})); W1 of grid point masses is O(h)", figure="cross",
            text=f"W1 order of the blob method (m = {p['blob']['orders']}, "
                 f"q = {p['blob']['q']}) before the blow-up: point masses on a grid, O(h); worst fit",
            tolerance=rules["blob_order_before"],
            measured=c.farthest_from_centre(orders(d, rates, blob, before, window), rules["blob_order_before"]))
    )
    local, shown = [], []
    for data, t, method in cases(d):
        if method in blob and t in after:
            sizes, _, errors, _ = series(d, data, t, method)
            steps = -np.diff(np.log(np.maximum(errors, 1e-300))) / np.diff(np.log(sizes))
            local.extend(steps)
            shown.append(f"{method}, {data}, t = {t:g}: {', '.join(f'{v:.2f}' for v in steps)}")
    rows.append(
        claim(
            c.at_least, "order.blob_after", kind="check",
            source="blob paper Definition 2.2 (K_delta smooth: no Dirac mass forms); no rate is predicted",
            figure="cross",
            text="the blob method's W1 after the blow-up falls at least at this local order between every two "
                 "consecutive h (no theory gives its rate: where part of the mass is outside the cluster, as for "
                 "(4.3), the point masses give O(h); where all of it collapses, as for (4.4), the cluster contracts at "
                 f"the rate 1/delta and the error falls like exp(-c/delta)); local orders {'; '.join(shown)}; smallest",
            tolerance=rules["blob_order_after_min"], measured=min(local, default=math.nan))
    )
    rows.append(
        claim(
            c.between, "order.ltp", kind="derived",
            source="LTP paper (2.31), Theorem 1 (O(h^2) reconstruction); outside its assumptions", figure="cross",
            text="W1 order of LTP with W = |x|/2 before the blow-up (dt = h/2): a particle's velocity (M - 2F_h)/2 at "
                 "its centre carries only the O(h^2) error of the reconstruction; explicit Euler does not move the "
                 "centres exactly (its error is first order in dt where F_h is not smooth, as at the edges of (4.4)), "
                 "but stays below the reconstruction's at these h; worst fit",
            tolerance=rules["ltp_order"],
            measured=c.farthest_from_centre(orders(d, rates, ("LTP",), before, window), rules["ltp_order"]))
    )
    rows.append(
        claim(
            c.between, "order.sp_before", kind="derived", source="LTP paper section 2.1 (SP method)", figure="cross",
            text="W1 order of SP (eps = h) before the blow-up: O(eps^2) smoothing; worst fit",
            tolerance=rules["sp_order_before"],
            measured=c.farthest_from_centre(orders(d, rates, ("SP",), before, window), rules["sp_order_before"]))
    )
    rows.append(
        claim(
            c.between, "order.sp_after", kind="check",
            source="LTP paper section 2.1 (SP method); the prediction itself is sp_after.dirac_spread", figure="cross",
            text="W1 order of SP after the blow-up: the Dirac mass is reconstructed "
                 "as its mass times phi_eps, W1 of order eps = h (pushed above 1 at coarse h by the mass still "
                 "flowing into the Dirac mass, see sp_after.dirac_spread); worst fit",
            tolerance=rules["sp_order_after"],
            measured=c.farthest_from_centre(orders(d, rates, ("SP",), after, window), rules["sp_order_after"]))
    )
    rows.append(_sp_dirac_spread(d, masses, after, p))
    rows.append(
        claim(
            c.between, "order.godunov", kind="derived", source="Godunov (1959); LeVeque (2002) section 12",
            figure="cross",
            text="W1 order of Godunov's scheme for F (cells), every data and time "
                 "(single Dirac masses left out): first order; worst fit",
            tolerance=rules["godunov_order"],
            measured=c.farthest_from_centre(
                         orders(d, rates, ("Godunov for F",), p["times"], window, single), rules["godunov_order"]
                     ))
    )

    differences = d["spd_difference"][~np.isnan(d["spd_difference"])]
    rows.append(
        claim(
            c.at_most, "identity.particle_spd", kind="derived", source=SOURCE_IDENTITY, figure="cross",
            text="the particle method (DOP853, rtol 1e-12) equals the "
                 "weighted SPD before the first collision: largest |x_particle - x_SPD| over data and h",
            tolerance=c.ROUNDING * LENGTH, measured=float(np.max(differences)) if differences.size else math.nan)
    )

    widths = []
    for data, t, method in cases(d):
        if method.startswith("blob") and t > 1.0 and masses[(data, t)][1] > 0:
            sizes, width = series(d, data, t, method, ("size", "dirac_width"))
            widths.extend(width / (1.0 / sizes) ** p["blob"]["q"])
    rows.append(
        claim(
            c.at_most, "blob.no_dirac", kind="derived", source="blob paper Definition 2.2 (K_delta smooth)",
            figure="cross",
            text="after the blow-up the blob particles of the Dirac mass gather within delta = h^q of 0, where "
                 "K_delta' is linear: (largest |x| of them)/delta, largest over data and h (their positions stay "
                 "distinct, as for any ODE with a Lipschitz field: true by construction, not a claim; the smallest "
                 f"ratio is {min(widths, default=math.nan):.3g})",
            tolerance=1.0, measured=float(max(widths)) if widths and np.all(np.isfinite(widths)) else math.nan)
    )

    fastest = claim(
        c.at_least, "fastest", kind="check",
        source=(
            "sticky paper section 5.1.1: the hull costs O(n); a property of these implementations, not of the methods"),
        figure="cross",
        text="with these implementations an SPD is the fastest method at every W1 error the others reach: for every "
             "timed run of another method, the time the best SPD needs for the same W1 (interpolated between its runs) "
             f"over that run's time, smallest over data, times and runs (at least 1: faster); on {d['cpu']}",
        tolerance=1.0, measured=speed_ratio(d))
    disturbed = disturbance(d)
    rows.append(c.abstain(fastest, disturbed) if disturbed else fastest)
    return rows


def edge_collapse(b, proximity: float) -> tuple[float, int, int]:
    """(largest ratio, refusals explained, refusals early): over every data and h whose LTP refusal came more than
    one step early, (width of the densest LTP particle at the refusal) / (exact (1 - t) h), infinite where that
    particle is not at an end of the support (within ``proximity`` times its half-width): the explanation of an early
    refusal does not hold there; a ratio of 0 when no refusal came early (nothing to explain)."""
    dt, refusal = b["ltp_dt"][None, :], b["ltp_refusal"]
    with np.errstate(invalid="ignore"):
        early = (1.0 - dt - refusal) / dt > 1.0 + c.ROUNDING
    if not np.any(early):
        return 0.0, 0, 0
    half = np.abs(b["ltp_peak_edge"])
    with np.errstate(invalid="ignore"):
        at_edge = np.abs(np.abs(b["ltp_peak_position"]) - half) <= proximity * half
        ratios = np.where(at_edge, b["ltp_peak_width"] / (1.0 - refusal), np.inf)[early]
    return float(np.max(ratios)), int(np.sum(ratios <= 1.0)), int(ratios.size)


def behaviour_claims(b, p):
    """The particle method against the weighted SPD, its first collision, the stall of the ODE solver
    past it, the LTP refusal before the blow-up and the blob clusters after it."""
    # Past the collision the solver may stop at its budget before the end of the window: rates use
    # the time its accepted steps reached.
    rates = (b["stall_after"] / np.maximum(b["stall_reached"] - b["stall_collision"], 1e-300)) / (
        b["stall_before"] / b["stall_collision"]
    )
    dt = b["ltp_dt"]
    refusal = b["ltp_refusal"]
    # LTP: rho_h at the centre follows the exact 1/(1 - t) (max rho0 = 1), so dt rho_h reaches 1 at t = 1 - dt.
    refusal_miss = np.abs(refusal - (1.0 - dt[None, :])) / dt[None, :]
    rules = p["claims"]
    edge_ratio, explained, early = edge_collapse(b, rules["edge_proximity"])
    return [
        claim(
            c.at_most, "identity.first_collision", kind="derived", source=SOURCE_IDENTITY, figure="cross",
            text="the particle method stops at the first meeting of neighbours "
                 "moving at the SPD velocities: largest |event time - predicted time|",
            # a root of DOP853's dense output, exact for the constant velocities up to rounding (amplified
            # where neighbours approach slowly: 1.2e-11 on the full run)
            tolerance=c.ROUNDING * TIME,
            measured=float(np.max(np.abs(b["collision_measured"] - b["collision_predicted"])))),
        claim(
            c.at_least, "particle.stall", kind="check", source=SOURCE_IDENTITY, figure="cross",
            text="without the collision event DOP853 chatters past the collision (the velocities jump as "
                 "particles cross and recross): decades (log10) of the ratio of its right-hand sides per unit of the "
                 "time its accepted steps advance, after it over before it, smallest over data; at least "
                 f"log10({rules['stall_rate_min']:g})",
            # decades: the steps past the collision shrink to a scale that rounding sets, so the ratio moves by a
            # factor (0.97e9 over the quick run's robustness variants, at 2.5e9), not by an amount
            tolerance=float(np.log10(rules["stall_rate_min"])), measured=float(np.log10(np.min(rates)))),
        claim(
            c.at_most, "ltp.refusal", kind="derived",
            source="LTP paper (2.31)-(2.32); blob paper section 4.1 (blow-up)", figure="cross",
            text="LTP with W = |x|/2 is refused by the explicit Euler bound dt rho_h < 1 at "
                 "t = 1 - dt, to within one step, as rho_h(0) follows the exact 1/(1 - t): largest "
                 "|t_refused - (1 - dt)|/dt",
            tolerance=1.0 + c.ROUNDING, measured=float(np.max(refusal_miss))),
        claim(
            c.at_most, "ltp.edge_collapse", kind="check",
            source="LTP paper (2.31)-(2.32): the width update uses rho_h at the centre", figure="cross",
            text="why the refusal comes early where it does: at every refusal more than a step early (every data and "
                 "h) the densest LTP particle sits at an end of the support and is narrower than the exact flow's (1 - "
                 f"t) h: largest (its width / (1 - t) h), infinite if it is not within "
                 f"{100 * rules['edge_proximity']:g} % of the support's half-width from an end (explained at "
                 f"{explained} of {early} early refusals; 0 if none is early)",
            tolerance=rules["edge_width"], measured=edge_ratio),
    ]


SOURCE_AGGREGATES = ("sticky paper Remark 3.3 and section 1.1.3 (a cluster moves at (mass right - mass left)/2); "
                     "the exact solution by the continuous hull (particle_methods.cross.hull)")
IDENTITY = ("Every aggregate here holds whole bumps, or levels symmetric about a symmetric bump's middle level, so it "
            "sits at their centre of mass, which any method with odd pair forces moves at the exact speed: an "
            "identity, not a test of the method's aggregates.")
LEVELS = ("W1 per unit mass on those levels: raised by a wrong position and by any of those levels held elsewhere; "
          "mass gathered from beyond them is seen by W1")
#: The methods whose aggregates are measured, with the key of their claims.
AGGREGATE_METHODS = {"SPD, equal masses": "spd_equal", "SPD, grid weights": "spd_grid", "blob": "blob", "SP": "sp",
                     "Godunov for F": "godunov"}


def _method_rows(a, method):
    rows = np.flatnonzero(a["methods"] == method)
    return rows[np.argsort(a["size"][rows], kind="stable")]


def _listed(values, digits=3):
    return ", ".join(f"{v:.{digits}g}" for v in values)


def aggregate_claims(a, rates: Recorder, p, q, case: str):
    """Bump data whose aggregates move and merge (``case``: the claims' prefix; ``p`` the study's settings, ``q`` the
    case's, :func:`~particle_replication.registry.cross.aggregate_settings`), against the
    exact solution by the hull: W1 after t = 0 (the data's discretisation is the error at t = 0), the aggregates'
    levels (position and mass together) and centres at the fixed times, W1 around the merger, the SPDs' mergers
    and the blob's gap at the merger against its two-body prediction."""
    window = p["fit_points"]
    rules = q["claims"]
    out = []
    times = a["times"]
    later = times > 0
    mass, length = float(a["mass"]), float(np.diff(a["support"])[0])
    merger = float(a["merger"])
    blob_name = f"blob, m = {q['blob']['order']}"

    def fitted(key, method, values):
        """Order in the particle (or cell) count of ``values``, recorded; by count, as every figure's size axis."""
        rows = _method_rows(a, method)
        return -rates.add(order(f"{PAPER}.{case}.{key}", "particles or cells", a["count"][rows],
                                np.maximum(values, 1e-300), window, method))

    # The SPDs: W1 after t = 0 and its contraction.
    rows = _method_rows(a, "SPD, equal masses")
    largest = np.nanmax(a["error"][rows][:, later], axis=1)
    bound = mass * length / 2.0
    out.append(claim(
        c.at_most, f"{case}.spd_w1.equal_masses", kind="check", source=SOURCE_SPD, figure="aggregates",
        text=f"SPD, equal masses, {case}: n times the largest W1 over the times after 0 (through the blow-ups and the "
             f"merger), over M L/2 = {bound:.4g} (M the mass, L the support's length), largest over n = "
             f"{_listed(a['size'][rows])}: at most 1 at every n. Each particle sits at the median of its levels, whose "
             "positions span at most L in all, so W1 at t = 0 is at most (M/n) L/2, and the SPD, exact for its data, "
             f"contracts W1 (n W1 / (M L/2): {_listed(a['size'][rows] * largest / bound)}). A consequence of the "
             "construction and of the contraction (claimed by spd_contraction): a check",
        tolerance=1.0, measured=float(np.max(a["size"][rows] * largest / bound))))
    rows = _method_rows(a, "SPD, grid weights")
    out.append(claim(
        c.between, f"{case}.spd_order.grid_weights", kind="derived", source=SOURCE_SPD, figure="aggregates",
        text=f"SPD, grid weights, {case}: order in the particles of the largest W1 over the times after 0 (largest W1: "
             f"{_listed(np.nanmax(a['error'][rows][:, later], axis=1))}): the data's discretisation is O(h), and the "
             f"SPD contracts W1",
        tolerance=rules["spd_order"],
        measured=fitted("spd_order.grid_weights", "SPD, grid weights",
                       np.nanmax(a["error"][rows][:, later], axis=1))))
    ratios = np.concatenate([(a["error"][r] / a["error"][r, :1]) for m in SPD_METHODS for r in _method_rows(a, m)])
    out.append(claim(
        c.at_most, f"{case}.spd_contraction", kind="derived", source=SOURCE_SPD, figure="aggregates",
        text="both SPDs, every size: W1(SPD(t), exact(t)) / W1(SPD(0), exact(0)) over the time grid, largest (the "
             "entropy solution contracts W1, and the SPD is the entropy solution of its discrete data; a wrong exact "
             "solution after a blow-up or the merger, or a wrong cluster speed, breaks it)",
        tolerance=1.0 + rules["contraction_tolerance"], measured=float(np.max(ratios))))
    # The equal-mass SPD's merger: the envelope of its error over a block of consecutive n.
    block, mergers = a["spd_merger_n"], a["spd_merger"]
    envelope = np.max(np.abs(mergers - merger), axis=1)
    out.append(claim(
        c.at_least, f"{case}.spd_merger.equal_masses", kind="derived", source=SOURCE_AGGREGATES, figure="aggregates",
        text=f"SPD, equal masses, {case}: the time its two heavy clusters become one against the exact merger at "
             f"{merger:.10g}; the share of a particle on either side of the bumps' boundary level follows n m_1/M, so "
             f"the error changes sign and size from one n to the next: order in n of its largest value over the "
             f"{block.shape[1]} consecutive n from each n = {_listed(block[:, 0])} (n |error|, largest per block: "
             f"{_listed(np.max(np.abs(mergers - merger) * block, axis=1))})",
        tolerance=rules["merger_order_min"],
        measured=-rates.add(order(f"{PAPER}.{case}.spd_merger.equal_masses", "n", block[:, 0].astype(float),
                                  np.maximum(envelope, 1e-300), window, "SPD, equal masses"))))
    rows = _method_rows(a, "SPD, grid weights")
    error = np.abs(a["method_merger"][rows] - merger)
    identity = bool(np.all(a["exact_identity"][times < merger][np.isfinite(a["exact_positions"][times < merger])]))
    if identity:
        out.append(claim(
            c.at_most, f"{case}.spd_merger.grid_weights", kind="check", source=SOURCE_AGGREGATES, figure="aggregates",
            text=f"SPD, grid weights, {case}: the time its two heavy clusters become one, against the exact merger at "
                 f"{merger:.10g}: largest error on the {window} finest grids (errors {_listed(error)}). Both bumps "
                 f"have collapsed before they merge, so the merger is the time at which their centres of mass meet; "
                 f"the grid's masses and centres are O(h^4) from the exact ones (trapezoid rule, the bumps' ends on "
                 f"the grid): an identity, exact to rounding",
            tolerance=c.ROUNDING * TIME, measured=float(error[-window:].max())))
    else:
        out.append(claim(
            c.at_least, f"{case}.spd_merger.grid_weights", kind="derived", source=SOURCE_AGGREGATES,
            figure="aggregates",
            text=f"SPD, grid weights, {case}: the time its two heavy clusters become one, against the exact merger at "
                 f"{merger:.10g}: order in the particles of the error (errors {_listed(error)})",
            tolerance=rules["merger_order_min"],
            measured=fitted("spd_merger.grid_weights", "SPD, grid weights", error)))
    first_blowup = float(np.min(a["blowups"]))
    for method, key, when, band, why in (
            ("LTP", "ltp_order", later & (times < first_blowup), p["claims"]["ltp_order"],
             "the O(h^2) reconstruction of the data, carried by the flow, whose velocity (M - 2F_h)/2 errs by as "
             "much (the largest W1 falls at the first time after 0: the sampling of the data dominates)"),
            ("SP", "sp_order_after", times > first_blowup, p["claims"]["sp_order_after"],
             "each Dirac mass is reconstructed as its mass times phi_eps, eps = h"),
            ("Godunov for F", "godunov_order", later, rules["godunov_order"],
             "first order, through the blow-ups and the merger")):
        rows = _method_rows(a, method)
        largest = np.nanmax(a["error"][rows][:, when], axis=1)
        span = {"ltp_order": f"after 0 and before the first blow-up (t = {first_blowup:g})",
                "sp_order_after": f"after the first blow-up (t = {first_blowup:g})",
                "godunov_order": "after 0"}[key]
        out.append(claim(
            c.between, f"{case}.{key}", kind="derived",
            source="LTP paper (2.31) and section 2.1 (SP); outside their assumptions" if key != "godunov_order" else
                   "Godunov (1959); LeVeque (2002) section 12",
            figure="aggregates",
            text=f"{method}, {case}: order in the particles (cells) of the largest W1 over the times {span}: {why} "
                 f"(largest W1: {_listed(largest)})",
            tolerance=band, measured=fitted(key, method, largest)))
    rows = _method_rows(a, "particle method")
    out.append(claim(
        c.at_most, f"{case}.particle_spd", kind="check", source=SOURCE_IDENTITY, figure="aggregates",
        text=f"the particle method (DOP853, rtol 1e-12) on {case} equals the grid SPD of the same particles at every "
             f"time of the grid before its first collision (t < {first_blowup:g}), the first blow-up: largest "
             f"|x_particle - x_SPD| over 1/h = {', '.join(str(int(k)) for k in a['size'][rows])}",
        tolerance=c.ROUNDING * LENGTH, measured=float(np.max(a["spd_difference"][rows])) if rows.size else math.nan))
    # The aggregates at the fixed times: their levels (mass and position together) and centres.
    fixed = [int(np.argmin(np.abs(times - t))) for t in a["fixed_times"]]
    fixed = [i for i in fixed if np.any(np.isfinite(a["exact_positions"][i]))]
    at = ", ".join(f"{float(t):g}" for t in times[fixed])
    exact = a["exact_positions"][fixed]
    free = np.isfinite(exact) & ~a["exact_identity"][fixed]
    for method, key in AGGREGATE_METHODS.items():
        name = blob_name if key == "blob" else method
        rows = _method_rows(a, name)
        spreads = np.array([np.nanmax(a["spread"][r][fixed]) for r in rows])
        minimum = rules["levels_order_min"][key]
        if key == "spd_equal":
            # As its merger: the share of the particle straddling the bumps' boundary level sets the constant, so
            # the envelope over a block of consecutive n.
            envelope = np.max(a["spd_levels"], axis=1)
            out.append(claim(
                c.at_least, f"{case}.aggregate.spd_equal_levels", kind="derived", source=SOURCE_AGGREGATES,
                figure="aggregates",
                text=f"{name}, {case}: the mean distance of each exact aggregate's levels from its position in the SPD "
                     f"({LEVELS}), largest over "
                     f"the aggregates at t = {at} and over the {block.shape[1]} consecutive n from each n = "
                     f"{_listed(block[:, 0])} (the particle straddling the bumps' boundary level sets its constant; "
                     f"values {_listed(envelope)}): order in n at least {minimum:g}",
                tolerance=minimum,
                measured=-rates.add(order(f"{PAPER}.{case}.aggregate.spd_equal_levels", "n", block[:, 0].astype(float),
                                          np.maximum(envelope, 1e-300), window, name))))
            continue
        out.append(claim(
            c.at_least, f"{case}.aggregate.{key}_levels", kind="derived", source=SOURCE_AGGREGATES, figure="aggregates",
            text=f"{name}, {case}: the mean distance of each exact aggregate's levels from its position in the "
                 f"method's output ({LEVELS}), largest over "
                 f"the aggregates at t = {at} (values {_listed(spreads)}): order in the particles (cells) at least "
                 f"{minimum:g}",
            tolerance=minimum, measured=fitted(f"aggregate.{key}_levels", name, spreads)))
        if key.startswith("spd"):
            continue
        # Godunov has no pair forces: its centres are never identities (its errors are its numerical diffusion).
        which = np.isfinite(exact) if key == "godunov" else free if free.any() else np.isfinite(exact)
        errors = np.array([np.max(np.abs(a["centre"][r][fixed] - exact)[which]) for r in rows])
        measured = (f"{name}, {case}: the centre of each exact aggregate's levels (the mean of the method's quantile "
                    f"over them) against the aggregate's position, largest over the aggregates at t = {at}")
        if key == "godunov":
            out.append(claim(
                c.at_least, f"{case}.aggregate.godunov_centres", kind="derived", source=SOURCE_AGGREGATES,
                figure="aggregates",
                text=f"{measured} (errors {_listed(errors)}): a discrete shock of F smeared over a few cells, whose "
                     f"speed conservation fixes: order in the cells at least {rules['centre_order_min'][key]:g}",
                tolerance=rules["centre_order_min"][key], measured=fitted(f"aggregate.{key}_centres", name, errors)))
        elif free.any():
            out.append(claim(
                c.at_least, f"{case}.aggregate.{key}_centres", kind="derived", source=SOURCE_AGGREGATES,
                figure="aggregates",
                text=f"{measured} whose position is no centre-of-mass identity (errors {_listed(errors)}): order in "
                     f"the particles (cells) at least {rules['centre_order_min'][key]:g}",
                tolerance=rules["centre_order_min"][key], measured=fitted(f"aggregate.{key}_centres", name, errors)))
        elif key == "sp":
            out.append(claim(
                c.at_most, f"{case}.aggregate.sp_centres", kind="check", source=SOURCE_AGGREGATES, figure="aggregates",
                text=f"{measured}, largest over h (errors {_listed(errors)}): exact to rounding. {IDENTITY} SP's pair "
                     "forces (W' * phi_eps, odd) cancel within a bump, and the other bump, more than 4 eps away, pulls "
                     "it with exactly its mass/2 (B3 has compact support)",
                tolerance=c.ROUNDING * LENGTH, measured=float(np.max(errors))))
        else:
            out.append(claim(
                c.at_least, f"{case}.aggregate.blob_centres", kind="check", source=SOURCE_AGGREGATES,
                figure="aggregates",
                text=f"{measured} (errors {_listed(errors)}). {IDENTITY} The blob's bumps carry the trapezoid rule's "
                     f"masses and centres, O(h^4) from the exact ones: order at least "
                     f"{rules['blob_identity_order_min']:g}",
                tolerance=rules["blob_identity_order_min"], measured=fitted("aggregate.blob_centres", name, errors)))
    # W1 around the merger.
    around = np.isin(times, a["window_times"])
    for method, key in (("SPD, grid weights", "spd_grid"), (blob_name, "blob"), ("SP", "sp"),
                        ("Godunov for F", "godunov")):
        rows = _method_rows(a, method)
        largest = np.nanmax(a["error"][rows][:, around], axis=1)
        minimum = rules["merger_order_min_w1"][key]
        out.append(claim(
            c.at_least, f"{case}.merger_w1.{key}", kind="derived", source=SOURCE_AGGREGATES, figure="aggregates",
            text=f"{method}, {case}: the largest W1 over the times t* + ({_listed(a['window_times'] - merger)}) around "
                 f"the exact merger t* = {merger:.6g} (no threshold: a merger early or late by more than the method's "
                 f"error raises it; values {_listed(largest)}): order in the particles (cells) at least {minimum:g}",
            tolerance=minimum, measured=fitted(f"merger_w1.{key}", method, largest)))
    # What the data test: aggregates off their bumps' centres of mass, mass still free when they merge.
    before = times < merger
    offset = float(np.nanmax(a["exact_offsets"][before]))
    last = np.searchsorted(times, merger) - 1  # the last time of the grid before the merger
    merging = a["exact_masses"][last]
    free_share = 1.0 - float(np.nansum(merging)) / mass
    if free.any():
        out += [
            claim(
                c.at_least, f"{case}.data.off_centre", kind="check", source=SOURCE_AGGREGATES, figure="aggregates",
                text=f"{case}, exact: the largest distance of an aggregate from the centre of mass of the bump that "
                     f"holds its middle level (which moves at the mean speed of its levels), on the time grid before "
                     f"the merger: the data make the aggregates' positions more than a centre-of-mass identity",
                tolerance=rules["off_centre_min"], measured=offset),
            claim(
                c.at_least, f"{case}.data.free_at_merger", kind="check", source=SOURCE_AGGREGATES, figure="aggregates",
                text=f"{case}, exact: the share of the mass outside the two aggregates at t = "
                     f"{float(times[last]):.4g}, the last time of the grid before they merge (the merger is then no "
                     f"meeting of two bumps' centres of mass)",
                tolerance=rules["free_share_min"], measured=free_share),
        ]
    else:
        out.append(claim(
            c.at_most, f"{case}.data.off_centre", kind="check", source=SOURCE_AGGREGATES, figure="aggregates",
            text=f"{case}, exact: the largest distance of an aggregate from the centre of mass of the bump that holds "
                 f"its middle level, on the time grid before the merger: 0 to rounding, so every aggregate's position "
                 f"is a centre-of-mass identity on these data",
            tolerance=c.ROUNDING * LENGTH, measured=offset))
    # The blob's gap at the merger, where the two aggregates hold all the mass (a two-body problem).
    if free_share <= 1e-9:
        from particle_methods.cross.aggregates import two_body_gap

        predicted = two_body_gap(int(q["blob"]["order"]))
        rows = _method_rows(a, blob_name)
        gaps = a["merger_gap"][rows]
        out.append(claim(
            c.at_most, f"{case}.aggregate.blob_merger_gap", kind="derived", source=SOURCE_AGGREGATES,
            figure="aggregates",
            text=f"{blob_name}, {case}: the gap between its two aggregates (the centres of the exact aggregates' "
                 f"levels) at the exact merger, over delta, against {predicted:.5f}, the two-body prediction with no "
                 f"fitted parameter (both bumps have collapsed, so the two point masses approach at (M/2) "
                 f"f(gap/delta), f the mollified sign; particle_methods.cross.aggregates.two_body_gap): largest |ratio "
                 f"- 1| over 1/h = {_listed(a['size'][rows])} (gaps / delta {_listed(gaps, 5)})",
            tolerance=rules["merger_gap_tolerance"], measured=float(np.max(np.abs(gaps / predicted - 1.0)))))
    return out


def claims(results, cfg, recorder: Recorder) -> list:
    """Every claim of the comparison from its result files (``results``: file stem -> arrays) and the
    bands and tolerances of ``cfg``."""
    return [*study_claims(results["study"], recorder, cfg), *behaviour_claims(results["behaviour"], cfg),
            *(claim_ for case in cfg["aggregates"]["cases"]
              for claim_ in aggregate_claims(results[f"aggregates_{case}"], recorder, cfg,
                                             aggregate_settings(cfg["aggregates"], case), case))]
