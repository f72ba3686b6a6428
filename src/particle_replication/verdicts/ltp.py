"""Every checked claim of the LTP paper, measured from the cached results (section 6).

Each function takes the arrays of one result file (a dict), the rate recorder, the config section
that fixes its measure and ``rules``, the config's ``ltp.claims`` (the tolerances, thresholds and bands
no figure's section holds), and returns claims (see particle_replication.claims).
Kinds: ``paper`` for what section 6 states, ``derived`` for what we derive from its theorems,
``check`` for our own diagnostics. Identities exact by construction (conserved weights, the centre of
mass for W = x^2) get the shared rounding tolerance :data:`particle_replication.claims.ROUNDING` times
the scale of the quantity compared. The tests in tests/ltp/test_ltp_verdicts.py feed every paper claim
a plausible wrong outcome and show it fails.
"""

from __future__ import annotations

import functools
import math
import re

import numpy as np

from particle_methods.ltp.measures import collapse_times, shrink_rate_ratios

from .. import claims as c
from ..rates import Recorder, order
from ..steady import first_steady_time, holds_from

PAPER = "ltp"


claim = functools.partial(c.claim, PAPER)


def _last_exponent(label) -> float:
    """The exponent of a potential's last term, from its label (``|x|^3/3 - |x|^2.5/2.5``: 2.5)."""
    found = re.fullmatch(r".*\|x\|\^([0-9.e+-]+)/\1", str(label))
    if found is None:
        raise ValueError(f"label must end with a power term |x|^a/a, got {label!r}")
    return float(found.group(1))


def _extreme_cases(d) -> tuple[int, int]:
    """Indices of the cases with the smallest and the largest exponent of the last term (Figure 5's a, Figure 6's
    b): the roles of the paper's cases (a = 1.5 collapses in finite time, a = 2.5 does not; b = 2.5 concentrates),
    read from the labels of the run, so that the texts follow the config."""
    exponents = [_last_exponent(label) for label in d["labels"]]
    return int(np.argmin(exponents)), int(np.argmax(exponents))


def quadratic_claims(d, rates: Recorder, p, rules):
    """Figures 2 and 3, Theorems 1 and 2, for W = x^2 (exact solution (6.4))."""
    k = int(d["order_points"])
    h = d["h_values"]
    out = []
    jump = float(d["edge_jump"])
    for column, norm, theorem in ((0, "l1", "Theorem 1"), (1, "linf", "Theorem 2")):
        errors = d["ltp_errors"][:, column]
        slope = rates.add(order(f"{PAPER}.fig2.order_{norm}", "h", h, errors, k))
        out.append(claim(
            c.at_least, f"fig2.order_{norm}", kind="paper", source=f"Figure 2, {theorem}", figure="2",
            text=f"LTP {norm.upper()} error at least first order in h ({theorem}: C(error of the data + "
                 f"dt/h + h)); slope on the {k} finest h; {_floor(jump, h, errors, slope, norm)}",
            tolerance=1.0, measured=slope, published=f">= 1 ({theorem})"))
        affine = p["affine_order"]
        out.append(claim(
            c.close_to, f"fig2.affine_order_{norm}", kind="derived", source=f"{theorem} for an affine flow, (6.4)",
            figure="2",
            text=f"for W = x^2 the flow is affine and the Jacobian exp(-2 dt) exact, so only the O(h^2) "
                 f"B3 projection of the data is carried: order 2 in {norm.upper()} on the {k} finest h",
            published=affine["value"], measured=slope, tolerance=affine["tolerance"]))
    holes = p["sp_holes"]
    exact, grid = d["exact"], d["grid"]
    bulk = exact >= holes["bulk"] * exact.max()
    depth = float((d["sp_densities"][0][bulk] / exact[bulk]).min())
    sp_l1 = np.array([np.trapezoid(np.abs(density - exact), grid) for density in d["sp_densities"]])
    eps = d["sp_eps"]
    out += [
        claim(
            c.at_most, "fig2.sp_holes", kind="paper", source="Figure 2 (right), section 6.1", figure="2 (right)",
            text=f"SP with too small an eps (eps = {eps[0]:g}, h = {float(d['sp_h']):g}) vanishes between particles: "
                 f"smallest SP / exact density where the exact one exceeds {holes['bulk']:g} of its maximum",
            tolerance=holes["hole_depth"], measured=depth, published="holes"),
        claim(
            c.at_least, "fig2.sp_smeared", kind="paper", source="Figure 2 (right), section 6.1", figure="2 (right)",
            text=f"SP with too large an eps (eps = {eps[-1]:g}) is smeared out: its L1 error over the best of the "
                 f"plotted eps ({', '.join(f'{v:g}' for v in eps)}: L1 {', '.join(f'{v:.3g}' for v in sp_l1)})",
            tolerance=holes["smear_factor"], measured=float(sp_l1[-1] / sp_l1.min()), published="spread out"),
    ]
    lifetime = float(d["t"])
    width = float(d["scan_h"]) * math.exp(-2 * lifetime)
    factor = rules["best_sp_factor"]
    for suffix, scan_sp, scan_ltp, step in (("", d["scan_sp"], d["scan_ltp"], d["scan_dt"]),
                                            ("_fine", d["scan_sp_fine"], d["scan_ltp_fine"], d["fine_dt"])):
        for column, norm in ((0, "l1"), (1, "linf")):
            best = int(np.argmin(scan_sp[:, column]))
            ratio = scan_sp[best, column] / scan_ltp[column]
            out.append(claim(
                c.close_to, f"fig3.best_sp{suffix}_{norm}", kind="check",
                source="Figure 3 (left), section 6.1: an identity for W = x^2", figure="3 (left)",
                text=f"dt = {float(step):g}: the LTP error is that of SP at its best eps ({norm.upper()}; best "
                     f"eps {d['eps_values'][best]:.3g}). For W = x^2 every LTP width is h e^(-2t) = "
                     f"{width:.3g} and the centres move as SP's, so SP with that eps is LTP: an identity, "
                     "hence a check. log10(min_eps SP error / LTP error)",
                published=0.0, measured=float(np.log10(ratio)), tolerance=np.log10(factor)))
    out.append(claim(
        c.at_least, "fig3.time_error", kind="check", source="Figure 3 (left) at the paper's dt", figure="3 (left)",
        text=f"at the paper's dt = {float(d['scan_dt']):g} the LTP error is mostly time error: L1 error "
             f"at that dt over the L1 error at dt = {float(d['fine_dt']):g}",
        tolerance=rules["time_error_ratio_min"], measured=float(d["scan_ltp"][0] / d["scan_ltp_fine"][0])))
    ratio_below = float((d["ltp_errors"] / d["sp_errors"]).max())
    out.append(claim(
        c.at_most, "fig3.ltp_below_sp", kind="derived",
        source="our reading of Figure 3 (right), section 6.1 (the "
               "text states no comparison)",
        figure="3 (right)",
        text="LTP errors below SP errors with eps = h at every h, in L1 and Linf: largest LTP / SP ratio",
        tolerance=1.0, measured=ratio_below, published="LTP below SP"))
    out += dt_claims(d, rates, rules["dt_order_band"])
    out += [
        claim(
            c.at_most, "mass.quadrature", kind="check", source="conservation of mass, section 2.2 after (2.27)",
            figure="2", text="mass is conserved: |int rho_h^n - 1| by quadrature at the final time, largest over h",
            tolerance=rules["mass_quadrature"], measured=float(d["mass_error"].max()), published="exact"),
        # an identity: scale of sum omega_k x_k, unit mass on the grid's extent
        claim(
            c.at_most, "centre_of_mass.quadratic", kind="check",
            source="conservation of the centre of mass for W = x^2, section 6.1 before (6.4)", figure="2",
            text="centre of mass conserved for W = x^2 (W' linear: sum_k omega_k (W' * rho_h)(x_k) = 0 exactly): "
                 "largest drift of sum omega_k x_k over h",
            tolerance=c.ROUNDING * float(np.abs(d["grid"]).max()), measured=float(d["centre_drift"].max()),
            published="conserved"),
    ]
    return out


def _floor(jump, h, errors, slope, norm) -> str:
    """Where the cut-off of (6.1) at x = 1 stops the convergence of Figure 2: the exact density jumps by ``jump``
    at its support's end, so no continuous rho_h is within jump/2 of it in Linf, and the fitted term A h^slope
    (through the finest error) meets that floor at h = h_min (floor / (error_min - floor))^(1/slope); in L1 the
    smoothed jump adds a term of order jump h."""
    floor = 0.5 * jump
    if norm == "l1":
        return (f"data (6.1) jump by {jump:.2g} at the support's end (not in W^(1,1)): a term of order jump h "
                "joins the L1 error, which turns first order where it dominates")
    finest = float(errors[np.argmin(h)])
    above = finest - floor
    meets = float(h.min() * (floor / above) ** (1.0 / slope)) if above > 0 and slope > 0 else math.nan
    return (f"data (6.1) jump by {jump:.2g} at the support's end, a floor jump/2 = {floor:.2g} that no continuous "
            f"rho_h beats in Linf ({floor / finest:.0%} of the finest error): the fitted h term meets it at h = "
            f"{meets:.2g}, below which the Linf order falls to 0")


def dt_claims(d, rates: Recorder, order_band):
    """The time error for W = x^2 at fixed h: the distance of each run to the run with the smallest dt, whose
    order in dt must lie in ``order_band`` (a check of explicit Euler (2.31)); it does not depend on h there (an
    affine flow), so Theorem 1's dt/h term is measured on another potential (:func:`theorem1_claims`)."""
    dt, gaps, h = d["dt_values"][:-1], d["dt_gaps"][:, :, 0], d["dt_h"]
    k = int(d["dt_fit_points"])
    dt_orders = [rates.add(order(f"{PAPER}.thm1.dt_order", "dt", dt[:k], row[:k], k, f"h = {hv:g}"))
                 for hv, row in zip(h, gaps)]
    return [
        claim(
            c.between, "thm1.dt_order", kind="check", source="Theorem 1, explicit Euler (2.31)", figure="3",
            text=f"W = x^2: the time error is first order in dt: order of the L1 distance to the run with dt = "
                 f"{d['dt_values'][-1]:g} on the {k} largest dt, farthest from 1 over h = "
                 f"{', '.join(f'{v:g}' for v in h)} ({', '.join(f'{v:.3g}' for v in dt_orders)})",
            tolerance=order_band, measured=float(max(dt_orders, key=lambda v: abs(v - 1)))),
    ]


def theorem1_claims(d, rates: Recorder):
    """Theorem 1's dt/h term, on a flow that is not affine: at fixed h, the distance of each run to the run with
    the smallest dt (the time error at that h) per unit dt, c(h); log c against log h has slope -1 for a dt/h term,
    0 for a dt term; at least -1 is the bound."""
    dt, gaps, h = d["theorem1_dt"][:-1], d["theorem1_gaps"][:, :, 0], d["theorem1_h"]
    k = int(d["theorem1_fit_points"])
    coefficient = (gaps[:, :k] / dt[:k]).mean(axis=1)
    slope = rates.add(order(f"{PAPER}.thm1.dt_over_h", "h", h, coefficient, len(h),
                            "time-error coefficient c(h): L1 distance to the smallest-dt run over dt"))
    return [claim(
        c.at_least, "thm1.dt_over_h", kind="paper", source="Theorem 1 (the dt/h term)", figure="(ours)",
        text=f"the time part of the error is at most C dt/h: W = {d['theorem1_label']}, t = "
             f"{float(d['theorem1_t']):g} (not affine: the Euler and Jacobian errors differ between particles, "
             f"unlike W = x^2, where the time error does not depend on h); slope of log c(h) against log h, "
             f"c(h) the L1 distance to the run with dt = {d['theorem1_dt'][-1]:g} per unit dt on the {k} largest "
             f"dt (c = {', '.join(f'{v:.4g}' for v in coefficient)} at h = "
             f"{', '.join(f'{v:g}' for v in h)}); -1 for a dt/h term, 0 for a dt term",
        tolerance=-1.0 - c.ROUNDING, measured=slope, published="C dt/h")]


def nonaffine_claims(d, rates: Recorder, p, rules):
    """Convergence in h on a singular power potential; the centre of mass on asymmetric data."""
    k = int(d["order_points"])
    h = d["h_values"]
    out = []
    for column, norm in ((0, "l1"), (1, "linf")):
        slope = rates.add(order(f"{PAPER}.nonaffine.order_{norm}", "h", h, d["errors"][:, column], k))
        out.append(claim(
            c.at_least, f"nonaffine.order_{norm}", kind="derived",
            source=f"Theorem 4 (W = {d['label']} satisfies (5.2), alpha = 1 - a = {1.0 - p['a']:g}, p = "
                   "infinity) without its dt <~ h^2",
            figure="(ours)",
            text=f"W = {d['label']} from (6.1), not an affine flow: LTP {norm.upper()} error at t = "
                 f"{float(d['t']):g} against a run with h = {float(d['reference_h']):g} at the same dt = "
                 f"{float(d['dt']):g} (above h^2 at every h here: the common time error cancels), at least "
                 f"first order; slope on the {k} finest h",
            tolerance=1.0, measured=slope, published=">= 1"))
    out += theorem1_claims(d, rates)
    out += theorem4_claims(d, rates, p, rules)
    out += theorem3_claims(d, rates, p, rules)
    share = float((d["reference_gap"] / d["errors"][-1]).max())
    out.append(claim(
        c.at_most, "nonaffine.reference", kind="check", source="our reference for the non-affine study",
        figure="(ours)",
        text="the reference's own error is small: its distance to a run with twice its h over the smallest "
             "measured error, largest of L1 and Linf",
        tolerance=p["reference_share"], measured=share))
    drift_order = rates.add(order(f"{PAPER}.centre_of_mass.drift", "h", d["centre_h"], d["centre_drift"],
                                  d["centre_h"].size))
    out.append(claim(
        c.between, "centre_of_mass.drift", kind="check", source="centre of mass, not claimed for LTP", figure="(ours)",
        text=f"W = {d['centre_label']} from (6.1) (asymmetric): LTP does not conserve the centre of mass; its "
             f"drift at t = {float(d['t']):g} is {', '.join(f'{v:.3g}' for v in d['centre_drift'])} at h = "
             f"{', '.join(f'{v:g}' for v in d['centre_h'])}: order in h (about 2: it vanishes with h)",
        tolerance=rules["centre_drift_band"], measured=drift_order, published="(not claimed)"))
    return out


def _local_orders(h, errors) -> np.ndarray:
    """Orders between neighbouring h: log(e_i / e_i+1) / log(h_i / h_i+1)."""
    return np.diff(np.log(errors)) / np.diff(np.log(h))


def theorem4_claims(d, rates: Recorder, p, rules):
    """Theorem 4 under its hypotheses (data (6.3) in W^{2,p}, dt <~ h^2, the norms L1 and Linf, the sup over the
    time steps) with the weights (2.14) and (2.16): the distances between the runs at h and h/2, whose local orders
    between neighbouring h must all be at least 1 - tolerance (an error C h^q gives distances C (1 - 2^-q) h^q)."""
    h, times = d["theorem4_h"], d["theorem4_times"]
    tolerance = float(rules["theorem4_tolerance"])
    setting = (f"W = {d['theorem4_label']} ((5.2) with alpha = 1 - a = {1.0 - p['theorem4']['a']:g}, so p = infinity; "
               "(6.3) is in W^(2,p)), dt = "
               f"{float(p['theorem4']['dt_over_h2']):g} h^2, distance between the runs at h and h/2 for h = "
               f"{', '.join(f'{v:g}' for v in h)}, largest over t = {', '.join(f'{v:g}' for v in times)}")
    out = []
    for weights, shape in (("cell", "(2.14), B3"), ("biorthogonal", "(2.16), hat")):
        differences = d[f"theorem4_{weights}_differences"]
        for column, norm in ((0, "l1"), (1, "linf")):
            values = differences[:, column]
            rates.add(order(f"{PAPER}.thm4.order_{norm}_{weights}", "h", h, values, h.size))
            local = _local_orders(h, values)
            relative = ", ".join(f"{v:.3g}" for v in values)
            out.append(claim(
                c.at_least, f"thm4.order_{norm}_{weights}", kind="paper", source="Theorem 4", figure="(ours)",
                text=f"sup_n ||rho_h^n - rho^n|| <= C h: {setting}; weights {shape}; {norm.upper()} "
                     f"distances {relative}; local orders between neighbouring h "
                     f"{', '.join(f'{v:.3g}' for v in local)}: the smallest at least 1 - {tolerance:g}",
                tolerance=1.0 - tolerance, measured=float(local.min()), published="O(h)"))
    return out


def theorem3_claims(d, rates: Recorder, p, rules):
    """Theorem 3 (any initial probability measure, grad W in W^{1,inf}): the bounded-Lipschitz distance at most
    C (d_BL(rho^0, rho_h^0) + h + dt), measured as W1 (within a factor 2 of d_BL on [-1, 1]). As stated: atomic
    data at one fixed small dt, against h, with the time error's share; and the combined error on a rough density
    with dt proportional to h, with the reference's own error."""
    tolerance = float(rules["theorem3_tolerance"])
    h, distances = d["theorem3_atomic_h"], d["theorem3_atomic_distances"]
    slope = rates.add(order(f"{PAPER}.thm3.atomic_order_w1", "h", h, distances, h.size))
    local = ", ".join(f"{v:.3g}" for v in _local_orders(h, distances))
    setting = (f"{d['theorem3_atomic_label']} (equal masses, golden-ratio positions on [-0.9, 0.9]), dt = "
               f"{float(d['theorem3_atomic_dt']):g} at every h = {', '.join(f'{v:g}' for v in h)}, W1 distance to the "
               f"exact atoms (the particle ODE) largest over t = "
               f"{', '.join(f'{v:g}' for v in d['theorem3_atomic_times'])}: {', '.join(f'{v:.3g}' for v in distances)} "
               f"(W1/h {', '.join(f'{v:.3g}' for v in distances / h)}; local orders {local})")
    band = rules["theorem3_atomic_band"]
    out = [
        claim(
            c.at_least, "thm3.atomic_order_w1", kind="paper", source="Theorem 3", figure="(ours)",
            text=f"max_n d_BL(rho^n, rho_h^n) <= C (d_BL(rho^0, rho_h^0) + h + dt) for an initial measure: {setting}; "
                 f"fitted order on every h, at least 1 - {tolerance:g}",
            tolerance=1.0 - tolerance, measured=slope, published="O(h + dt)"),
        claim(
            c.between, "thm3.atomic_order_sharp", kind="derived", source="Theorem 3 with Remark 4", figure="(ours)",
            text=f"for atoms the bound's first order is attained: the cell weights (2.14) move each atom to its cell's "
                 f"centre and spread it over a particle of width h, an O(h) error in d_BL (Remark 4) that the flow "
                 f"carries, not the O(h^2) of a smooth density: {setting}; fitted order in {band}",
            tolerance=band, measured=slope, published="order 1"),
        claim(
            c.at_most, "thm3.atomic_time_share", kind="check", source="our fixed dt for Theorem 3", figure="(ours)",
            text=f"the h term is what is measured: the distance at h = {h.min():g} changes by this share of the "
                 f"smallest distance when dt is divided by {p['theorem3_atomic']['dt_factor']}",
            tolerance=p["reference_share"], measured=float(d["theorem3_atomic_time_share"])),
    ]
    h, distances = d["theorem3_h"], d["theorem3_distances"]
    q = p["theorem3"]
    slope = rates.add(order(f"{PAPER}.thm3.order_w1", "h", h, distances, h.size))
    out.append(claim(
        c.at_least, "thm3.order_w1", kind="paper", source="Theorem 3 (dt proportional to h)", figure="(ours)",
        text=f"max_n d_BL(rho^n, rho_h^n) <= C (d_BL(rho^0, rho_h^0) + h + dt) with dt proportional to h, so "
             f"the combined space and time error: {d['theorem3_label']} (rough data; W'' bounded on [-2, 2], "
             f"where the differences of positions lie: the attractive flow keeps the mass in [-1, 1]), dt = "
             f"{float(q['dt_over_h']):g} h at h = {', '.join(f'{v:g}' for v in h)}, W1 distance to h = "
             f"{float(d['theorem3_reference_h']):g} (d_BL <= W1 <= 2 d_BL there), largest over t = "
             f"{', '.join(f'{v:g}' for v in d['theorem3_times'])}; the explicit Euler dt term dominates (at a "
             f"fixed small dt the h term of these smooth-inside data falls faster: thm3.atomic_order_w1 "
             f"measures the h term on a measure); order on every h, at least 1 - {tolerance:g}",
        tolerance=1.0 - tolerance, measured=slope, published="O(h + dt)"))
    out.append(claim(
        c.at_most, "thm3.reference", kind="check", source="our reference for Theorem 3", figure="(ours)",
        text="the reference's own error is small: its W1 distance to the run with twice its h over the "
             "smallest measured distance",
        tolerance=p["reference_share"], measured=float(d["theorem3_reference_gap"] / distances[-1])))
    return out


def fig4_claims(d, rules):
    """Figure 4: hat against B3 shapes, SP with eps = h (unstated) and at its best eps; "clearly below" is an
    LTP / SP ratio at most ``rules["clearly_below"]``."""
    ratio = {shape: d[f"{shape}_ltp_errors"][0] / d[f"{shape}_sp_errors"][0] for shape in ("hat", "b3")}
    best = {shape: d[f"{shape}_ltp_errors"][0] / d[f"{shape}_scan_errors"][:, 0].min() for shape in ("hat", "b3")}
    best_eps = {shape: d["eps_values"][np.argmin(d[f"{shape}_scan_errors"][:, 0])] for shape in ("hat", "b3")}
    eps = float(d["sp_eps"])
    below = rules["clearly_below"]
    return [
        claim(
            c.at_most, "fig4.hat", kind="paper", source="Figure 4, section 6.1", figure="4",
            text=f"with hat shapes the LTP L1 error is clearly below the SP one (SP with eps = {eps:g}, not stated in "
                 "the paper): LTP / SP ratio",
            tolerance=below, measured=float(ratio["hat"]), published="clearly below"),
        claim(
            c.at_most, "fig4.hat_gain_larger", kind="paper", source="Figure 4, section 6.1", figure="4",
            text=f"the gain of LTP over SP is larger with hat than with B3 shapes (eps = {eps:g}): (LTP/SP with hat) / "
                 "(LTP/SP with B3)",
            tolerance=1.0, measured=float(ratio["hat"] / ratio["b3"]), published="< 1"),
        claim(
            c.at_least, "fig4.hat_best_eps", kind="check", source="Figure 4: dependence on the unstated eps",
            figure="4",
            text=f"SP at its best eps ({best_eps['hat']:.3g}, L1) with hat shapes is as accurate as LTP: the LTP / SP "
                 f"ratio is no longer below {below:g}, so fig4.hat rests on eps = h",
            tolerance=below, measured=float(best["hat"])),
        claim(
            c.at_least, "fig4.b3_best_eps", kind="check", source="Figure 4: dependence on the unstated eps", figure="4",
            text=f"SP at its best eps ({best_eps['b3']:.3g}, L1) with B3 shapes beats LTP: LTP / SP ratio",
            tolerance=1.0, measured=float(best["b3"])),
    ]


def fig5_claims(d, p, rules):
    """Figure 5: finite-time collapse for the smaller a (the paper's 1.5), none for the larger (2.5), one Dirac mass
    for both."""
    collapse = p["collapse"]
    windows = [tuple(w) for w in collapse["windows"]]
    measured = {}
    cases = _extreme_cases(d)
    for i in cases:
        sizes = d[f"case{i}_widths"].min(axis=1)
        measured[i] = collapse_times(d[f"case{i}_times"], sizes, windows)
    blowup, smooth = (str(d["labels"][i]) for i in cases)
    slopes, times = measured[cases[0]]
    finite = times[np.isfinite(times)]
    spread = float(np.ptp(finite) / finite.mean()) if finite.size == times.size else math.inf
    shown = ", ".join(f"[{a:g}, {b:g}]" for a, b in windows)
    spread_ratio = [np.ptp(d[f"case{i}_centres"][-1]) / np.ptp(d[f"case{i}_centres"][0])
                    for i in range(len(d["labels"]))]
    return [
        claim(
            c.at_most, "fig5.blowup_a1.5", kind="paper", source="Figure 5, section 6.2", figure="5",
            text=f"W = {blowup}: finite-time blow-up. g = -1/(d log h_min/dt) (h_min the smallest particle width) "
                 f"falls linearly to 0 at the collapse time; largest slope of g over the windows {shown} of the run "
                 f"(extrapolated collapse times {', '.join(f'{v:.4g}' for v in times)}; 0 for exponential shrinking)",
            tolerance=collapse["slope_max"], measured=float(slopes.max()), published="finite-time blow-up"),
        claim(
            c.at_most, "fig5.collapse_time_stable", kind="check",
            source="Figure 5: the measure does not depend on the stop", figure="5",
            text=f"a = {_last_exponent(blowup):g}: the collapse times extrapolated from the successive windows "
                 "agree: their spread over their mean",
            tolerance=collapse["spread_max"], measured=spread),
        claim(
            c.at_least, "fig5.no_blowup_a2.5", kind="paper", source="Figure 5, section 6.2", figure="5",
            text=f"W = {smooth}: no finite-time blow-up in Linf: smallest slope of g over the windows {shown} (slopes "
                 f"{', '.join(f'{v:.3g}' for v in measured[cases[1]][0])}; negative would extrapolate to a collapse)",
            tolerance=0.0, measured=float(measured[cases[1]][0].min()), published="no blow-up"),
        claim(
            c.at_most, "fig5.dirac", kind="paper", source="Figure 5, section 6.2", figure="5",
            text="both tend to a single Dirac mass: final over initial spread of the particle centres, largest of the "
                 "two runs",
            tolerance=rules["dirac_spread"], measured=float(max(spread_ratio)), published="single Dirac"),
    ]


def _steady_time(times, widths, q) -> float:
    return first_steady_time(times, widths, q["window"], q["steady_tolerance"])


def _concentrating(times, widths, masses, q, name, figure, source, what):
    """The claims of Dirac masses forming in infinite time: the widths keep shrinking, at least algebraically (the
    paper: to 0, at no stated rate), and, our reading, at least exponentially; mass gathers near the peaks. Each
    window's local exponent (or shrink rate) is compared with the window before's (:func:`shrink_rate_ratios`,
    from the end of the transient on, both sides): no ratio depends on the run's length, which only adds ratios;
    the text lists them at every window's end."""
    floor = math.log1p(q["steady_tolerance"]) / q["window"]
    steady = _steady_time(times, widths, q)
    out = []
    for algebraic, suffix, kind, law, one, settling in (
            (True, "", "paper", "algebraically", "t^-p gives 1, exponential shrinking more",
             "a width settling to a positive limit: its exponent -> 0"),
            (False, "_exponentially", "derived", "exponentially", "exponential shrinking gives 1",
             "t^-p gives log(t/(t - w))/log((t - w)/(t - 2w)) < 1; a width settling to a positive limit: "
             "exp(-rate w) -> 0")):
        ends, ratios = zip(*(shrink_rate_ratios(times, widths[:, side], q["window"], q["transient"], floor,
                                                algebraic=algebraic) for side in range(2)))
        ends, ratios = ends[0], np.minimum(*ratios)
        marks = np.flatnonzero(np.isclose(np.remainder(ends - ends[0] + 1e-9, q["window"]), 0.0, atol=1e-6))
        listed = ", ".join(f"{ends[i]:g}: {ratios[i]:.2f}" for i in marks)
        holds = int(np.sum(ratios[marks] >= q["rate_ratio_min"]))
        measure = "local exponent -d log w / d log t" if algebraic else "shrink rate -d log w / dt"
        reading = ("the paper states Dirac masses in infinite time, at no rate" if algebraic
                   else "our reading: exponential, stronger than the paper's statement")
        out.append(claim(
            c.at_least, f"{name}concentrates{suffix}", kind=kind,
            source=source if algebraic else f"{source} (our exponential reading)", figure=figure,
            text=f"{what}: the width holding {q['fraction']:g} of each side's mass keeps shrinking at least "
                 f"{law} ({reading}; it is {widths[-1].max():.3g} at t = {times[-1]:g}; settled by the width "
                 f"criterion from t = {steady:g}): smallest ratio of its {measure} over a window of "
                 f"w = {q['window']:g} time units to that over the window before (a log-shrink below the "
                 f"steady one, log(1 + {q['steady_tolerance']:g}) per window, counts as that), from t = "
                 f"{q['transient']:g} on ({one}; {settling}); at the windows' ends (t: ratio) {listed}, at "
                 f"least {q['rate_ratio_min']:g} at {holds} of {marks.size}",
            tolerance=q["rate_ratio_min"], measured=float(ratios.min()),
            published="Dirac masses (t -> infinity)" if algebraic else "exponential (ours)"))
    out.append(claim(
        c.at_least, f"{name}dirac_mass", kind="paper", source=source, figure=figure,
        text=f"{what}: mass within {q['radius']:g} of the two peaks at t = {times[-1]:g} (an L1 profile keeps "
             "a share that shrinks with the radius)",
        tolerance=q["dirac_mass"], measured=float(masses[-1].sum()), published="Dirac masses"))
    return out


def fig6_claims(d, rates: Recorder, q, rules):
    """Figure 6: the largest b (the paper's 2.5) concentrates on two Dirac masses in infinite time; the case of the
    edge refinement (the paper's b = 1.5) settles on an L1 profile."""
    b25, b15 = _extreme_cases(d)[1], int(d["edge_case"])
    concentrating, profile = (f"b = {_last_exponent(d['labels'][i]):g}" for i in (b25, b15))
    times = d[f"case{b25}_times"]
    out = _concentrating(times, d[f"case{b25}_concentration_widths"], d[f"case{b25}_concentration_masses"], q,
                         "fig6.b2.5_", "6", "Figure 6, section 6.2", concentrating)
    centres, weights = d[f"case{b25}_centres"][-1], d[f"case{b25}_weights"]
    middle = c.ROUNDING * np.abs(centres).max()  # a particle at 0 by symmetry, to rounding
    left, right = weights[centres < -middle].sum(), weights[centres > middle].sum()
    out.append(claim(
        c.at_most, "fig6.b2.5_equal_split", kind="check", source="Figure 6: equal masses, by symmetry of (6.2)",
        figure="6",
        text=f"{concentrating}: the two masses are equal (symmetric data and even W: true by symmetry, "
             "hence a check): |left mass - right mass| (a particle at 0 counted on neither side)",
        tolerance=rules["equal_split"], measured=float(abs(left - right))))
    times = d[f"case{b15}_times"]
    masses = d[f"case{b15}_concentration_masses"]
    changes, checked = d[f"case{b15}_profile_changes"], d[f"case{b15}_profile_times"]
    steady = holds_from(checked, changes <= q["profile_tolerance"])
    at = int(np.searchsorted(times, steady)) if math.isfinite(steady) else times.size - 1
    marks = np.flatnonzero(np.isclose(np.remainder(checked - checked[0] + 1e-9, q["window"]), 0.0, atol=1e-6))
    listed = ", ".join(f"{checked[i]:g}: {changes[i]:.2g}" for i in marks)
    out += [
        claim(
            c.at_most, "fig6.b1.5_steady", kind="paper", source="Figure 6, section 6.2", figure="6",
            text=f"{profile}: convergence in time to a steady profile: first time from which the L1 change of the "
                 f"density over {q['window']:g} time units, ||rho_h(t) - rho_h(t - {q['window']:g})||_L1, stays at "
                 f"most {q['profile_tolerance']:g} (unit mass), up to t = {times[-1]:g}; at the windows' ends (t: "
                 f"change) {listed}",
            tolerance=float(times[-1]), measured=steady, published="steady"),
        claim(
            c.at_most, "fig6.b1.5_profile", kind="paper", source="Figure 6, section 6.2", figure="6",
            text=f"{profile}: the steady state is an L1 profile, not Dirac masses: mass within {q['radius']:g} of the "
                 f"two peaks at the steady time",
            tolerance=q["profile_mass"], measured=float(masses[at].sum()), published="L1 profile"),
        claim(
            c.at_least, "fig6.b1.5_edges", kind="derived",
            source="Figure 6, section 6.2 (our reading: the profile peaks at "
                   "its edges)",
            figure="6",
            text=f"{profile}: the steady profile is largest at the edges of its support: largest "
                 "density over the density at the centre, at the steady time",
            tolerance=rules["edge_growth"], measured=float(d[f"case{b15}_edge_ratio"][at]), published="edge growth"),
        _edges_diverge(d, times, rates, q, rules, profile),
    ]
    return out


def _edges_diverge(d, times, rates: Recorder, q, rules, case: str):
    """Figure 6, the ``case`` of the edge refinement (the paper's b = 1.5), "seemingly diverging at the boundary
    of the support": the largest density (at the centres) of the settled profile grows under refinement of h, at
    least like h^-edge_divergence_min (a bounded profile's peaks converge). Read at the end of the runs, a time
    common to every h once each has settled by the width criterion (the peaks still rise after it); unmeasured
    (-inf) if a run does not settle."""
    h, peaks = d["edge_h"], d["edge_peaks"]
    steady = [_steady_time(times, widths, q) for widths in d["edge_widths"]]
    if not all(math.isfinite(t) for t in steady):
        growth, listed = -math.inf, "a run does not settle"
    else:
        values = peaks[:, -1]
        growth = -rates.add(order(f"{PAPER}.fig6.b1.5_edges_diverge", "h", h, values, h.size))
        local = -np.diff(np.log(values)) / np.diff(np.log(h))
        at_steady = [row[int(np.searchsorted(times, t))] for row, t in zip(peaks, steady)]
        listed = (", ".join(f"{v:.3g} at h = {x:g}" for v, x in zip(values, h))
                  + "; exponents between neighbouring h " + ", ".join(f"{v:.2f}" for v in local)
                  + "; at each run's own settling time (t = " + ", ".join(f"{t:g}" for t in steady) + ") the peaks "
                  + ", ".join(f"{v:.3g}" for v in at_steady) + " were still rising")
    return claim(
        c.at_least, "fig6.b1.5_edges_diverge", kind="paper", source="Figure 6, section 6.2", figure="6",
        text=f"{case}: the steady L1 profile seemingly diverges at the boundary of its support: the largest "
             f"density at t = {float(times[-1]):g}, every run settled by the width criterion, grows as h is "
             f"refined ({listed}): its exponent -d log max rho_h / d log h, at least "
             f"{rules['edge_divergence_min']:g} (a bounded profile: 0)",
        tolerance=rules["edge_divergence_min"], measured=growth, published="seemingly diverging")


def fig7_claims(d, q):
    """Figure 7: from (6.3), concentration on finitely many Dirac masses (in infinite time)."""
    return _concentrating(d["record_times"], d["concentration_widths"], d["concentration_masses"], q, "fig7.", "7",
                          "Figure 7, section 6.2", f"data (6.3), W = {d['label']}")


def _shifted_smooth(d, steady, resolved, limit, measure):
    """The paper's "stationary state ... with no oscillations" on the shifted grid: the largest oscillation measure
    from the run's steady time (SP's is measured at its own steady time) to the last record at which every particle
    width is at least ``resolved`` times the rounding level of the positions (machine epsilon times the largest
    |x_k|), a rule fixed before reading the measure by it: below that, the density sampled at the centres reads
    the rounding of the positions, not a profile. Unmeasured (inf) if the run never settles or no record from
    its steady time on is resolved."""
    times, oscillation = d["sp_times"], d["shifted_ltp_oscillation"]
    widths, centres = d["shifted_ltp_widths"], d["shifted_ltp_centres"]
    level = np.finfo(float).eps * np.abs(centres).max(axis=1)
    unresolved = np.flatnonzero(widths.min(axis=1) < resolved * level)
    offset = float(d["shifted_offset"])
    end = float(times[unresolved[0]]) if unresolved.size else math.inf
    value, later = math.inf, "never steady"
    if math.isfinite(steady):
        start = int(np.argmin(np.abs(times - steady)))
        stop = int(unresolved[unresolved >= start][0]) if np.any(unresolved >= start) else times.size
        marks = np.unique(np.rint(np.linspace(start, times.size - 1, 6)).astype(int))
        later = ", ".join(f"{times[i]:g}: {oscillation[i]:.3g}" for i in marks)
        if stop > start:
            value = float(oscillation[start:stop].max())
    return claim(
        c.at_most, "fig8.shifted.ltp_smooth", kind="paper", source="Figure 8, section 6.2 (stationary state)",
        figure="8",
        text=f"the LTP stationary state on the grid (k + {offset:g}) h has no oscillations, largest from its "
             f"steady time t = {steady:g} to the last record before the smallest particle width falls below "
             f"{resolved:g} times the rounding level of the positions (first at t = {end:g}; at t = "
             f"{float(times[-1]):g} the widths run from {widths[-1].min():.2g} to {widths[-1].max():.2g}): "
             f"{measure}; the measure at the records (t: measure) {later}",
        tolerance=limit, measured=value, published="no oscillation")


def fig8_claims(d, p, rules):
    """Figure 8: the stationary states of SP and LTP; oscillations of SP only. LTP runs on two grids:
    centres k h as in (2.14) (a particle at x = 0) and (k + ``shifted_offset``) h (``shifted``, none at
    0 for the offset 1/2), with the same steadiness criterion and oscillation measure."""
    t_long = float(d["sp_times"][-1])
    steady_sp, steady_ltp = float(d["sp_steady"]), float(d["ltp_steady"])
    steady_shifted = float(d["shifted_ltp_steady"])
    at = int(np.argmin(np.abs(d["sp_times"] - steady_sp))) if math.isfinite(steady_sp) else -1
    paper = int(np.argmin(np.abs(d["sp_times"] - float(d["t"]))))
    steady = p["steady"]
    criterion = f"the centres change by at most {steady['tolerance']:g} (relative) over {steady['window']:g} time units"
    limit = p["oscillation"]
    sp_times, sp_oscillation = d["sp_times"], d["sp_oscillation"]
    shown = np.unique(np.rint(np.linspace(0, int(np.searchsorted(sp_times, 3 * float(d["t"]))), 7)).astype(int))
    transient = ", ".join(f"{sp_times[i]:g}: {sp_oscillation[i]:.3f}" for i in shown[1:])
    above = np.flatnonzero(sp_oscillation > limit)
    oscillating_until = float(sp_times[above[-1]]) if above.size else math.nan
    measure = ("excess total variation TV(rho) / (2 (max left + max right)) - 1 (0 for one peak per side; "
               f"oscillating above {limit:g})")
    return [
        claim(
            c.at_most, "fig8.sp_steady", kind="paper", source="Figure 8, section 6.2 (stationary state)", figure="8",
            text=f"the SP run reaches a stationary state: first time from which {criterion}, up to t = {t_long:g}",
            tolerance=t_long, measured=steady_sp, published="stationary"),
        claim(
            c.at_most, "fig8.ltp_steady", kind="paper", source="Figure 8, section 6.2 (stationary state)", figure="8",
            text=f"the LTP run reaches a stationary state: first time from which {criterion}, up to t = {t_long:g}",
            tolerance=t_long, measured=steady_ltp, published="stationary"),
        claim(
            c.at_least, "fig8.sp_oscillates", kind="paper", source="Figure 8, section 6.2", figure="8",
            text=f"the SP stationary state oscillates, at its steady time t = {float(d['sp_times'][at]):g}: {measure} "
                 f"(local maxima then: {int(d['sp_peaks'][at])})",
            tolerance=limit, measured=float(d["sp_oscillation"][at]), published="oscillations"),
        claim(
            c.at_most, "fig8.ltp_smooth", kind="paper", source="Figure 8, section 6.2", figure="8",
            text=f"the LTP state has no oscillations, largest over the run up to t = {t_long:g}: {measure}",
            tolerance=limit, measured=float(d["ltp_oscillation"].max()), published="no oscillation"),
        claim(
            c.at_most, "fig8.shifted.ltp_steady", kind="paper", source="Figure 8, section 6.2 (stationary state)",
            figure="8",
            text=f"the LTP run on the grid (k + {float(d['shifted_offset']):g}) h reaches a stationary state: first "
                 f"time from which {criterion}, up to t = {t_long:g}",
            tolerance=t_long, measured=steady_shifted, published="stationary"),
        _shifted_smooth(d, steady_shifted, float(p["resolved_widths"]), limit, measure),
        # Settled is steady time <= t_long, as in fig8.ltp_steady; the contrast holds when the shifted run
        # settles and the regular one does not (-inf otherwise, which fails).
        claim(
            c.at_least, "fig8.centre_particle", kind="check",
            source="Figure 8: the particle at x = 0 tested by removing it", figure="8",
            text=f"LTP settles once the grid has no particle at x = 0 and not with it: the regular grid is not "
                 f"steady by t = {t_long:g} (steady time {steady_ltp:g}), the grid (k + "
                 f"{float(d['shifted_offset']):g}) h is, from t = {steady_shifted:g} (largest width at t = "
                 f"{t_long:g}: {float(d['shifted_ltp_widths'][-1].max()):.3g}); time it has been steady at "
                 f"t = {t_long:g}, counted only when the regular grid has not settled",
            tolerance=0.0, measured=t_long - steady_shifted if steady_ltp > t_long else -math.inf),
        claim(
            c.at_least, "fig8.ltp_central_particle", kind="check", source="Figure 8: why LTP does not settle",
            figure="8",
            text=f"at t = {t_long:g} the LTP particle at x = {float(d['widest_centre']):.2g} (mass "
                 f"{float(d['widest_weight']):.2g}), where W'' * rho_h < 0, has widened to "
                 f"{float(d['widest_width']):.3g}; "
                 "its contribution to the velocity of the outermost particles over their whole velocity (above 1: the "
                 "other particles oppose it): it pulls the two concentrations together",
            tolerance=rules["central_share"], measured=float(d["widest_share"])),
        claim(
            c.at_least, "fig8.sp_transient", kind="check", source="Figure 8 at our time t (not stated in the paper)",
            figure="8",
            text=f"SP oscillates at t = {float(d['sp_times'][paper]):g}, the end of N = {int(d['steps'])} steps of our "
                 f"dt: {measure} (local maxima: {int(d['sp_peaks'][paper])}); the figure's time is ours: the measure "
                 f"at other times (t: measure) {transient}, above {limit:g} up to t = {oscillating_until:g} only",
            tolerance=limit, measured=float(d["sp_oscillation"][paper])),
    ]


def conservation_claims(runs):
    """Weights are constant in time: mass conserved exactly by construction (2.27)."""
    masses = [abs(d[f"{prefix}weights"].sum() - 1.0) for d, prefixes in runs for prefix in prefixes]
    return [claim(
        c.at_most, "mass.weights", kind="check", source="weights constant in time by construction, section 2.2 (2.27)",
        figure="5-8", text="mass is conserved exactly: |sum_k omega_k - 1|, largest over the runs of Figures 5-8",
        tolerance=c.ROUNDING * 1.0, measured=float(max(masses)),
        published="exact")]  # an identity; scale: the unit mass


def claims(results, p, recorder: Recorder) -> list:
    """Every claim of the LTP paper from its result files (``results``: file stem -> arrays), with the
    thresholds and bands of ``p["claims"]`` and the figures' sections of ``p``."""
    rules = p["claims"]
    d5, d6, d7 = results["fig5"], results["fig6"], results["fig7"]
    return [
        *quadratic_claims(results["quadratic"], recorder, p["quadratic"], rules),
        *nonaffine_claims(results["nonaffine"], recorder, p["nonaffine"], rules),
        *fig4_claims(results["fig4"], rules),
        *fig5_claims(d5, p["fig5"], rules),
        *fig6_claims(d6, recorder, p["concentration"], rules),
        *fig7_claims(d7, p["concentration"]),
        *fig8_claims(results["fig8"], p["fig8"], rules),
        *conservation_claims([
            (d5, [f"case{i}_" for i in range(len(d5["labels"]))]),
            (d6, [f"case{i}_" for i in range(len(d6["labels"]))]),
            (d7, [""]),
        ]),
    ]
