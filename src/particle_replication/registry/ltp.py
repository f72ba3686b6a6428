"""Campos Pinto, Carrillo, Charles and Choi, linearly transformed particles: Figures 1-8 and our
long-time and non-affine studies."""

from .records import Figure, Job, Paper, Plot, Result, listing, power


def _rows(name, label, formula, parameter):
    """Figures 5 and 6: the potential's ``formula`` (a function of the section) for each case's ``parameter``."""
    return Plot(
        "plot_rows.py",
        (
            Figure(
                name,
                label,
                lambda s: (
                    f"W = {formula(s)} from (6.2), {parameter} = "
                    f"{listing(case[parameter] for case in s[name]['cases'])}, h = {s[name]['h']}, {s[name]['steps']} "
                    f"steps: potential, density, velocity and particle sizes."
                ),
                lambda s: f"LTP, W = {formula(s)} from (6.2), h = {s[name]['h']}, {s[name]['steps']} steps",
            ),
        ),
        data={"data": f"results/ltp/{name}.npz"},
    )


ROWS_KEYS = (
    "grid",
    "x_potential",
    "h",
    "steps",
    "labels",
    "case*_times",
    "case*_figure_t",
    "case*_centres",
    "case*_widths",
    "case*_velocities",
    "case*_weights",
    "case*_shown",
    "case*_densities",
    "case*_potential",
)


def _rows_result(name, extra=()):
    return Result(
        f"results/ltp/{name}.npz",
        "rows_data.py",
        (*ROWS_KEYS, *extra),
        Job(
            "LTP runs with power and attractive-repulsive potentials (Figures 5, 6)",
            lambda s: {"cfg": s[name], "concentration": s["concentration"]},
        ),
    )


RESULTS = (
    Result(
        "results/ltp/quadratic.npz",
        "quadratic_data.py",
        (
            "grid",
            "exact",
            "h_values",
            "ltp_errors",
            "sp_errors",
            "mass_error",
            "centre_drift",
            "plot_h",
            "plot_density",
            "sp_eps",
            "sp_densities",
            "eps_values",
            "scan_ltp",
            "scan_sp",
            "order_points",
            "t",
            "dt",
            "sp_h",
            "scan_dt",
            "scan_h",
            "fine_dt",
            "scan_ltp_fine",
            "scan_sp_fine",
            "dt_h",
            "dt_values",
            "dt_errors",
            "dt_gaps",
            "dt_fit_points",
            "edge_jump",
        ),
        Job(
            "LTP and SP runs for W = x^2 against the exact solution (6.4) (Figures 2, 3)",
            lambda s: {"cfg": s["quadratic"]},
        ),
    ),
    Result(
        "results/ltp/fig4.npz",
        "fig4_data.py",
        (
            "grid",
            "exact",
            "shapes",
            "eps_values",
            "h",
            "sp_eps",
            "*_ltp",
            "*_sp",
            "*_ltp_errors",
            "*_sp_errors",
            "*_scan_errors",
        ),
        Job("LTP and SP with hat and B3 shapes for W = x^2/2 (Figure 4)", lambda s: {"cfg": s["fig4"]}),
    ),
    _rows_result("fig5"),
    _rows_result("fig6", ("case*_concentration_widths", "case*_concentration_masses", "case*_edge_ratio",
                          "case*_profile_times", "case*_profile_changes", "edge_h", "edge_peaks", "edge_widths",
                          "edge_case")),
    Result(
        "results/ltp/fig7.npz",
        "fig7_data.py",
        (
            "grid",
            "times",
            "densities",
            "record_times",
            "concentration_widths",
            "concentration_masses",
            "weights",
            "label",
            "h",
            "dt",
            "steps",
        ),
        Job(
            "density snapshots from (6.3) (Figure 7)", lambda s: {"cfg": s["fig7"], "concentration": s["concentration"]}
        ),
    ),
    Result(
        "results/ltp/fig8.npz",
        "fig8_data.py",
        (
            "grid",
            "label",
            "h",
            "dt",
            "steps",
            "t",
            "sp_eps",
            "shifted_offset",
            "paper_time",
            "steady_time",
            "widest_centre",
            "widest_width",
            "widest_weight",
            "widest_share",
            *(
                f"{method}_{key}"
                for method in ("ltp", "sp", "shifted_ltp")
                for key in (
                    "times",
                    "peaks",
                    "oscillation",
                    "steady",
                    "centres",
                    "widths",
                    "weights",
                    "paper_x",
                    "paper_density",
                    "steady_x",
                    "steady_density",
                )
            ),
        ),
        Job("SP and LTP end states (Figure 8)", lambda s: {"cfg": s["fig8"]}),
    ),
    Result(
        "results/ltp/nonaffine.npz",
        "nonaffine_data.py",
        (
            "h_values",
            "errors",
            "reference_h",
            "reference_gap",
            "order_points",
            "label",
            "t",
            "dt",
            "grid",
            "reference",
            "centre_h",
            "centre_drift",
            "centre_label",
            "theorem1_h",
            "theorem1_dt",
            "theorem1_gaps",
            "theorem1_fit_points",
            "theorem1_t",
            "theorem1_label",
            "theorem4_h",
            "theorem4_dt",
            "theorem4_times",
            "theorem4_weights",
            "theorem4_label",
            "theorem4_*_differences",
            "theorem3_atomic_h",
            "theorem3_atomic_dt",
            "theorem3_atomic_times",
            "theorem3_atomic_label",
            "theorem3_atomic_distances",
            "theorem3_atomic_time_share",
            "theorem3_h",
            "theorem3_dt",
            "theorem3_times",
            "theorem3_reference_h",
            "theorem3_label",
            "theorem3_distances",
            "theorem3_reference_gap",
        ),
        Job(
            "convergence on a flow that is not affine; the centre of mass on asymmetric data; Theorems 1, 3 and 4",
            lambda s: {"cfg": s["nonaffine"]},
        ),
    ),
)

PAPER = Paper(
    id="ltp",
    name="LTP",
    plots=(
        Plot(
            "plot_fig1.py",
            (
                Figure(
                    "fig1",
                    "hat shape and its bi-orthogonal kernel",
                    lambda s: "The hat shape function (2.12) and its bi-orthogonal kernel (dotted).",
                ),
            ),
            params=lambda s: {"cfg": s["fig1"]},
        ),
        Plot(
            "plot_quadratic.py",
            (
                Figure(
                    "fig2",
                    "exact vs LTP, errors vs h, SP with several eps",
                    lambda s: (
                        f"W = x^2 from (6.1), t = {s['quadratic']['t']}: exact against LTP densities for several "
                        f"h; LTP L1 and Linf errors against h; SP densities with h = {s['quadratic']['sp_h']} and "
                        f"fixed widths eps."
                    ),
                ),
                Figure(
                    "fig3",
                    "SP errors over eps; SP and LTP errors vs h",
                    lambda s: (
                        f"SP against LTP errors, W = x^2: (a) SP errors over eps with the LTP error as reference "
                        f"(h = {s['quadratic']['eps_scan']['h']}, dt = {s['quadratic']['eps_scan']['dt']}); (b) "
                        f"errors against h with eps = h (dt = {s['quadratic']['dt']})."
                    ),
                ),
            ),
            data={"data": "results/ltp/quadratic.npz"},
        ),
        Plot(
            "plot_fig4.py",
            (
                Figure(
                    "fig4",
                    "exact, LTP, SP with hat and B3 shapes",
                    lambda s: (
                        f"W = x^2/2 from (6.1), h = {s['fig4']['h']}, dt = {s['fig4']['dt']}: exact, LTP and SP "
                        f"densities with hat (left) and B3 (right) shapes."
                    ),
                ),
            ),
            data={"data": "results/ltp/fig4.npz"},
            params=lambda s: {"t": s["fig4"]["t"], "dt": s["fig4"]["dt"]},
        ),
        _rows("fig5", lambda s: f"abs(x)^a/a, a = {listing(case['a'] for case in s['fig5']['cases'])}",
              lambda s: "|x|^a/a", "a"),
        _rows("fig6", lambda s: (f"abs(x)^{s['fig6']['a']:g}/{s['fig6']['a']:g} - abs(x)^b/b, b = "
                                 f"{listing(case['b'] for case in s['fig6']['cases'])}"),
              lambda s: f"{power(s['fig6']['a'])} - |x|^b/b", "b"),
        Plot(
            "plot_fig7.py",
            (
                Figure(
                    "fig7",
                    "density snapshots from (6.3)",
                    lambda s: (
                        f"W = {power(s['fig7']['a'])} - {power(s['fig7']['b'])} from (6.3), {s['fig7']['steps']} "
                        f"steps: density snapshots, concentrating on two points."
                    ),
                ),
            ),
            data={"data": "results/ltp/fig7.npz"},
        ),
        Plot(
            "plot_fig8.py",
            (
                Figure(
                    "fig8",
                    "SP vs LTP at the paper's time and at the SP steady time, particle sizes",
                    lambda s: (
                        f"W = {power(s['fig8']['a'])} - {power(s['fig8']['b'])} from (6.2), h = {s['fig8']['h']}, "
                        f"{s['fig8']['steps']} steps up to t = {s['fig8']['t']}: SP (eps = {s['fig8']['sp_eps']}) and "
                        f"LTP densities at the paper's time and at the SP steady time, and particle sizes."
                    ),
                ),
            ),
            data={"data": "results/ltp/fig8.npz"},
        ),
        Plot(
            "plot_long_time.py",
            (
                Figure(
                    "long_time",
                    "long-time measures of Figures 5-8",
                    lambda s: (
                        f"Long-time measures: the collapse measure of Figure 5, the concentration of Figures 6-7 up to "
                        f"t = {s['fig6']['t_long']}, and the peaks of Figure 8 up to t = {s['fig8']['t_long']}."
                    ),
                    ours=True,
                ),
            ),
            data={name: f"results/ltp/{name}.npz" for name in ("fig5", "fig6", "fig7", "fig8")},
            params=lambda s: {"cfg": s},
        ),
        Plot(
            "plot_nonaffine.py",
            (
                Figure(
                    "nonaffine",
                    "convergence on a non-affine flow, centre-of-mass drift",
                    lambda s: (
                        f"W = {power(s['nonaffine']['a'])} from (6.1), t = {s['nonaffine']['t']}, dt = "
                        f"{s['nonaffine']['dt']}: LTP errors against h = {s['nonaffine']['reference_h']}; drift of the "
                        f"centre of mass for W = {power(s['nonaffine']['centre_of_mass']['a'])} - "
                        f"{power(s['nonaffine']['centre_of_mass']['b'])}."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/ltp/nonaffine.npz"},
        ),
    ),
    results=RESULTS,
    notebook=("results/ltp/quadratic.npz", "results/ltp/fig5.npz"),
)
