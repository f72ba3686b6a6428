"""Craig and Bertozzi, the blob method: Figures 1-8 (1D and 2D), the reading of Figure 4's row
label and the study of the repulsive density error."""

from .records import Figure, Job, Paper, Plot, Result, listing


def _newtonian(name, label, caption, title):
    return Plot(
        "plot_newtonian.py",
        (Figure(name, label, caption, title),),
        data={"data": f"results/blob/{name}.npz"},
        params=lambda s: {"error_t": s[name]["error_t"]},
    )


def _compare(name, label, kernels, title):
    return Plot(
        "plot_compare.py",
        (
            Figure(
                name,
                label,
                lambda s: f"2D particle (top) and blob (bottom, delta = {s[name]['delta']}) end states for {kernels}.",
                lambda s: title,
            ),
        ),
        data={"data": f"results/blob/{name}.npz"},
    )


NEWTONIAN_KEYS = (
    "times",
    "positions",
    "densities",
    "exact_times",
    "exact_paths",
    "density_times",
    "density_index",
    "exact_densities",
    "masses",
    "energies",
    "h_values",
    "trajectory_errors",
    "density_errors",
    "evaluations",
    "mass_defect",
    "tight_errors",
    "method",
    "order",
    "q",
    "fit_points",
    "zoom",
    "h",
)

FIG4_KEYS = (
    "h_values",
    "kernels",
    "fit_points",
    "q",
    "*_particle_trajectory",
    "*_particle_density",
    "*_blob4_trajectory",
    "*_blob4_density",
    "*_blob6_trajectory",
    "*_blob6_density",
    "*_reference_error",
)

COMPARE_KEYS = (
    "h",
    "delta",
    "paper_tables",
    "labels",
    "case*_particle",
    "case*_blob",
    "case*_blob_paper_tables",
    "case*_times",
)


def _fig4_study(s, name):
    """Figure 4 (fig4), or the reading of its row label, K = -log|x|/(2 pi) (fig4log)."""
    if name == "fig4":
        return s["fig4"]
    return {**s["fig4"], **s["fig4"]["log_reading"], "kernels": ["log_repulsive"], "diagnostic_q": None}


def _newtonian_result(name):
    return Result(
        f"results/blob/{name}.npz",
        "newtonian_data.py",
        NEWTONIAN_KEYS,
        Job(
            "blob or particle runs against exact solutions, errors against h (Figures 1-3)", lambda s: {"cfg": s[name]}
        ),
    )


def _fig4_result(name, extra=()):
    return Result(
        f"results/blob/{name}.npz",
        "fig4_data.py",
        (*FIG4_KEYS, *extra),
        Job(
            "particle, m = 4 and m = 6 errors for two kernels (Figure 4), or for the row label's kernel",
            lambda s: {"cfg": _fig4_study(s, name)},
        ),
    )


def _compare_result(name, keys=COMPARE_KEYS):
    return Result(
        f"results/blob/{name}.npz",
        "compare_data.py",
        keys,
        Job("particle and blob runs for repulsive-attractive kernels in 2D (Figures 7, 8)", lambda s: {"cfg": s[name]}),
    )


RESULTS = (
    _newtonian_result("fig1"),
    _newtonian_result("fig2"),
    _newtonian_result("fig3"),
    _fig4_result("fig4", ("diagnostic_*",)),
    _fig4_result("fig4log"),
    Result(
        "results/blob/repulsive.npz",
        "repulsive_data.py",
        (
            "inverse_h",
            "base_count",
            "q",
            "t",
            "m*_total",
            "m*_quadrature",
            "m*_regularisation",
            "m*_combined",
            "m*_predicted",
        ),
        Job(
            "Figure 4, K = -|x|/2: the density error split into quadrature and regularisation parts, the runs "
            "extended to finer h",
            lambda s: {"cfg": {**s["fig4"], **s["fig4"]["repulsive"]}},
            inputs={"fig4": "results/blob/fig4.npz"},
        ),
    ),
    # Figure 5's runs are grouped into jobs by grid size: their rules are in rules/blob.smk.
    Result(
        "results/blob/fig5/case*.npz",
        "fig5_data.py",
        ("label", "inverse_h", "trajectory", "density", "particles", "evaluations"),
        hand_rule="blob_fig5_case",
    ),
    Result(
        "results/blob/fig5.npz",
        "fig5_merge.py",
        (
            "h_values",
            "fit_points",
            "q",
            "labels",
            "case*_trajectory",
            "case*_density",
            "case*_particles",
            "case*_evaluations",
        ),
        hand_rule="blob_fig5_data",
    ),
    Result(
        "results/blob/fig6.npz",
        "fig6_data.py",
        (
            "kernels",
            "times",
            "density_index",
            "star_t",
            "*_positions",
            "*_densities",
            "*_energies",
            "*_mass_defect",
            "*_star_positions",
            "*_star_densities",
        ),
        Job("2D blob runs for the Newtonian, quadratic and cubic kernels (Figure 6)", lambda s: {"cfg": s["fig6"]}),
    ),
    # Figure 7's ring kernels also run without the grid particle at the origin (config without_origin).
    _compare_result(
        "fig7", (*COMPARE_KEYS, "case*_particle_no_origin", "case*_blob_no_origin", "case*_times_no_origin")
    ),
    _compare_result("fig8"),
)

PAPER = Paper(
    id="blob",
    name="Blob",
    plots=(
        _newtonian(
            "fig1",
            lambda s: f"blob m = {s['fig1']['order']}, Newtonian, smooth data (A-D)",
            lambda s: (
                f"Blob method, m = {s['fig1']['order']}, delta = h^{s['fig1']['q']:g}, K = |x|/2, data "
                f"(4.3): trajectories, densities at t = {listing(s['fig1']['density_times'])}, zoom near "
                f"t = 1, and L1_h errors against h at t = {s['fig1']['error_t']}."
            ),
            lambda s: f"Blob method (m = {s['fig1']['order']}, delta = h^{s['fig1']['q']:g}), K = |x|/2, data (4.3)",
        ),
        _newtonian(
            "fig2",
            "particle method, same data",
            lambda s: (
                "Particle method (grad K(0) = 0), same data: trajectories (straight lines), zoom, and "
                "trajectory errors against h."
            ),
            lambda s: "Particle method (grad K(0) = 0), K = |x|/2, data (4.3)",
        ),
        _newtonian(
            "fig3",
            lambda s: f"blob m = {s['fig3']['order']}, discontinuous data",
            lambda s: (
                f"Blob method, m = {s['fig3']['order']}, delta = h^{s['fig3']['q']:g}, for the discontinuous data "
                f"(4.4): trajectories, rounded densities, zoom and slower convergence."
            ),
            lambda s: (
                f"Blob method (m = {s['fig3']['order']}, delta = h^{s['fig3']['q']:g}), K = |x|/2, discontinuous "
                "data (4.4)"
            ),
        ),
        Plot(
            "plot_fig4.py",
            (
                Figure(
                    "fig4",
                    "errors, two kernels x (particle, m = 4, m = 6)",
                    lambda s: (
                        f"L1_h errors at t = {s['fig4']['t']} for data (4.5): K = -|x|/2 and |x|^3/3; particle method, "
                        f"m = 4 and m = 6."
                    ),
                ),
            ),
            data={"data": "results/blob/fig4.npz"},
            params=lambda s: {"t": s["fig4"]["t"]},
        ),
        Plot(
            "plot_repulsive.py",
            (
                Figure(
                    "repulsive",
                    "the repulsive density error of Figure 4 split into quadrature and regularisation parts",
                    lambda s: (
                        f"K = -|x|/2, data (4.5), t = {s['fig4']['t']}, q = {s['fig4']['q']}: density error "
                        f"of the blob method (m = 4, 6) split into its quadrature and regularisation parts, with "
                        f"the model of the quadrature part fitted on the paper's h and the runs extended to h = "
                        f"1/{s['fig4']['repulsive']['extra_inverse_h'][-1]}."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/blob/repulsive.npz"},
        ),
        Plot(
            "plot_fig4.py",
            (
                Figure(
                    "fig4log",
                    "Figure 4's row label read as written, K = -log|x|/(2 pi)",
                    lambda s: (
                        f"Figure 4's first row read as its label writes it, K = -log|x|/(2 pi) (its caption and text "
                        f"say (-Delta)^(-1)): L1_h errors at t = {s['fig4']['t']} against an m = 6 reference on a grid "
                        f"{s['fig4']['log_reading']['reference_factor']} times finer."
                    ),
                    ours=True,
                ),
            ),
            data={"data": "results/blob/fig4log.npz"},
            params=lambda s: {"t": s["fig4"]["t"]},
        ),
        Plot(
            "plot_fig5.py",
            (
                Figure(
                    "fig5",
                    "2D errors, Newtonian kernel (blob, particle, disk)",
                    lambda s: (
                        f"2D, K = log|x|/(2 pi): L1_h errors at t = {s['fig5']['t']} for the blob method with regular "
                        f"data, the particle method, and the blob method with the indicator of the disk."
                    ),
                ),
            ),
            data={"data": "results/blob/fig5.npz"},
            params=lambda s: {"t": s["fig5"]["t"]},
        ),
        Plot(
            "plot_fig6.py",
            (
                Figure(
                    "fig6",
                    "2D trajectories, densities, star patch, three kernels",
                    lambda s: (
                        f"2D blob method for log|x|/(2 pi), |x|^2/2, |x|^3/3: {s['fig6']['top']['trajectories']} "
                        f"trajectories and the density at t = {s['fig6']['top']['t_density']} (bump data), star patch "
                        f"density at t = {s['fig6']['bottom']['t']} from the side and from above."
                    ),
                ),
            ),
            data={"data": "results/blob/fig6.npz"},
            params=lambda s: {"cfg": s["fig6"]},
        ),
        _compare(
            "fig7",
            "particle vs blob, power-law kernels (and on the paper's coarse radial tables)",
            "|x|^4/4 - log|x|/(2 pi), |x|^4/4 - |x|^1.5/1.5 and |x|^7/7 - |x|^1.5/1.5",
            "Repulsive-attractive power kernels, data (4.7): particle (top) and blob (bottom) methods",
        ),
        _compare(
            "fig8",
            "particle vs blob, Morse kernels, run until steady (and on the paper's coarse radial tables)",
            "the Morse kernels e^-|x| - 2e^-|x|/2 and 2e^-|x| - 2e^-|x|/2, data (4.7) and the star patch",
            "Morse kernels, data (4.7) and star patch (4.6): particle (top) and blob (bottom) methods",
        ),
    ),
    results=RESULTS,
    notebook=("results/blob/fig4.npz", "results/blob/fig5.npz", "results/blob/fig7.npz"),
)
